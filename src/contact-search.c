/* Contact search: for each contact point, the deformed position x = X + u and its contact element:
   the closest master facet of its pairs (contact-pairs.c) or the most penetrating rigid obstacle,
   whichever gives the smaller gap; the element's gap and normal go into the point's record. */
#include <spcontact-impl.h>

/* Whether a slave vertex with Dirichlet-fixed dofs (sdof < 0) cannot move along n: its gap to that
   obstacle is prescribed, so contact cannot act there (the condition's reaction carries its force);
   enforced, its penetration would never close (a clamped corner under a rigid plate) */
static PetscBool Pinned(PetscInt dim, const PetscInt sdof[], const PetscReal n[])
{
  PetscReal free = 0.0;

  for (PetscInt d = 0; d < dim; ++d)
    if (sdof[d] >= 0) free += n[d] * n[d];
  return free <= 1e-12 ? PETSC_TRUE : PETSC_FALSE;
}

/* The most penetrating obstacle at point i's x that it can move against: index, gap, normal;
   *pinned: one it penetrates and cannot move against (-1: none) */
static void ObstacleGap(SPContact c, PetscReal load, PetscInt i, PetscInt *k, PetscReal *g, PetscReal n[], PetscInt *pinned)
{
  *g      = PETSC_MAX_REAL;
  *pinned = -1;
  for (PetscInt j = 0; j < c->nob; ++j) {
    PetscReal gj, nj[3], Hj[9];
    SPObstacleGap(&c->ob[j], c->dim, load, c->pt[i].geo.x, &gj, nj, Hj);
    if (Pinned(c->dim, c->pt[i].sdof, nj)) {
      if (gj < 0.0) *pinned = j;
      continue;
    }
    if (gj < *g) {
      *g = gj;
      *k = j;
      for (PetscInt d = 0; d < c->dim; ++d) n[d] = nj[d];
    }
  }
}

/* Gaps, normals and contact elements of every point at the local displacement u (a local vector's
   array). Collective when there are contact pairs (the master geometry is exchanged). */
PetscErrorCode SPContactSearch(SPContact c, const PetscScalar u[], PetscReal load)
{
  PetscSection ls;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(c->dm, &ls));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(ls, c->pt[i].vertex, &off));
    for (PetscInt d = 0; d < c->dim; ++d) c->pt[i].geo.u[d] = PetscRealPart(u[off + d]), c->pt[i].geo.x[d] = c->pt[i].X[d] + c->pt[i].geo.u[d];
  }
  if (c->npair) PetscCall(SPContactPairsExchange(c, u));
  c->pinnedCount = 0;
  for (PetscInt i = 0; i < c->n; ++i) {
    SPPointGeometry *geo = &c->pt[i].geo;
    for (PetscInt d = 0; d < 3; ++d) geo->normal[d] = 0.0;
    geo->gap  = PETSC_MAX_REAL;
    geo->elem = SP_ELEM_NONE;
    if (c->pt[i].pairMask) PetscCall(SPContactPairsProject(c, i, &geo->elem, geo->xi, &geo->gap, geo->normal));
    if (c->pt[i].onObstacle) {
      PetscReal g, no[3];
      PetscInt  k = -1;
      PetscInt  pinned;
      ObstacleGap(c, load, i, &k, &g, no, &pinned);
      if (pinned >= 0 && !c->pinnedCount++) c->pinnedPoint = i, c->pinnedObstacle = pinned;
      if (g < geo->gap) {
        geo->gap      = g;
        geo->elem     = SP_ELEM_OBSTACLE;
        geo->obstacle = k;
        for (PetscInt d = 0; d < c->dim; ++d) geo->normal[d] = no[d];
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective, at the set-up: a warning where a slave vertex touches two rigid obstacles at the
   start (a block's corner on a floor and against a wall). A point holds one obstacle at a time, the
   most penetrating, so such a corner switches between them from one Newton iterate to the next and
   the solve can cycle (the active-set stall, then cut-backs). Touching: a gap within 1e-6 of the
   point's facet size (a relative test). */
PetscErrorCode SPContactWarnCorners(SPContact c)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)c->dm);
  PetscInt n[2] = {0, -1}, all[2];

  PetscFunctionBeginUser;
  if (!c->enabled || c->nob < 2) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt touch = 0, first = -1;
    if (!c->pt[i].onObstacle) continue;
    for (PetscInt j = 0; j < c->nob; ++j) {
      PetscReal gj, nj[3], Hj[9];
      SPObstacleGap(&c->ob[j], c->dim, 0.0, c->pt[i].X, &gj, nj, Hj);
      if (gj > 1e-6 * c->pt[i].h) continue;
      if (++touch == 2) n[0]++, n[1] = PetscMax(n[1], first * SP_MAX_OBSTACLES + j);
      first = first < 0 ? j : first;
    }
  }
  all[0] = n[0];
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, all, 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&n[1], &all[1], 1, MPIU_INT, MPI_MAX, comm));
  if (all[0]) PetscCall(PetscFPrintf(comm, PETSC_STDERR, "spcontact: warning: %" PetscInt_FMT " contact point(s) touch two obstacles at the start (e.g. obstacles %" PetscInt_FMT " and %" PetscInt_FMT "), and the solve can cycle between them: " SP_CORNER_ADVICE "\n", all[0], all[1] / SP_MAX_OBSTACLES, all[1] % SP_MAX_OBSTACLES));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Points that start inside an obstacle or a pair's master surface by more than their facet size h:
   their count, the largest depth, and the largest depth over h with its obstacle or pair */
typedef struct {
  PetscInt n;
  double   depth;
  struct {
    double ratio;
    int    which;
  } deep;
} SPDeepTally;

static void TallyDeep(SPDeepTally *t, PetscReal g, PetscReal h, PetscInt which)
{
  t->n++;
  t->depth = PetscMax(t->depth, (double)-g);
  if (-g / h > t->deep.ratio) t->deep.ratio = (double)(-g / h), t->deep.which = (int)which;
}

/* Collective: one warning line for a tally (inside "an obstacle", named "obstacle" k; the options to check) */
static PetscErrorCode WarnDeep(MPI_Comm comm, SPDeepTally *t, const char inside[], const char noun[], const char check[])
{
  char advice[256];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &t->n, 1, MPIU_INT, MPI_SUM, comm));
  if (!t->n) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &t->deep, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &t->depth, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCall(PetscSNPrintf(advice, sizeof(advice), check, t->deep.which, t->deep.which));
  PetscCall(PetscFPrintf(comm, PETSC_STDERR, "spcontact: warning: %" PetscInt_FMT " contact point(s) start inside %s by more than their facet size (up to %.3g, %.3g facet sizes, %s %d): check %s; the solve will try to push them out to the surface\n", t->n, inside, t->depth, t->deep.ratio, noun, t->deep.which, advice));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective, at the set-up: a warning where a slave vertex starts inside a rigid obstacle by more
   than its facet size h. An overlap of a few elements is no contact to resolve but an obstacle
   placed wrongly: its point or normal's sign, or a mesh in other units than the options (a mesh in
   mm against a plane at y = -0.001 in m). The solve would push the body out without a word. The
   obstacles at their start positions (load factor 0: no motion yet). */
PetscErrorCode SPContactWarnDeepStart(SPContact c)
{
  SPDeepTally t = {0, 0.0, {0.0, -1}};

  PetscFunctionBeginUser;
  if (!c->enabled || !c->nob) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscReal g = 0.0, gj, nj[3], Hj[9];
    PetscInt  k = -1;
    if (!c->pt[i].onObstacle) continue;
    for (PetscInt j = 0; j < c->nob; ++j) {
      SPObstacleGap(&c->ob[j], c->dim, 0.0, c->pt[i].X, &gj, nj, Hj);
      if (gj < g) g = gj, k = j;
    }
    if (g < -c->pt[i].h) TallyDeep(&t, g, c->pt[i].h, k);
  }
  PetscCall(WarnDeep(PetscObjectComm((PetscObject)c->dm), &t, "an obstacle", "obstacle", "-contact_obstacle_%d_point and _normal (a sign, or the mesh's units)"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective, after the run's first search: the same for the points of pairs, inside their master
   surface by more than h (a slave or master label value that names another surface, or two
   bodies' meshes placed over each other) */
PetscErrorCode SPContactWarnDeepPairs(SPContact c)
{
  SPDeepTally t = {0, 0.0, {0.0, -1}};

  PetscFunctionBeginUser;
  if (!c->enabled || !c->npair) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i)
    if (c->pt[i].geo.elem >= 0 && c->pt[i].geo.gap < -c->pt[i].h) TallyDeep(&t, c->pt[i].geo.gap, c->pt[i].h, c->mf[c->pt[i].geo.elem].pair);
  PetscCall(WarnDeep(PetscObjectComm((PetscObject)c->dm), &t, "a master surface", "pair", "-contact_pair_%d_slave_values and -contact_pair_%d_master_values, and where the bodies' meshes lie"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: the points that switched between two rigid obstacles at least twice in this Newton
   solve (*n; pair: two such obstacles), the cause of an active-set cycle at a corner that reached
   a second obstacle during the run (SPContactWarnCorners sees only those touching at the start) */
PetscErrorCode SPContactObstacleCycle(SPContact c, PetscInt *n, PetscInt pair[2])
{
  MPI_Comm comm = PetscObjectComm((PetscObject)c->dm);
  PetscInt m[2] = {0, -1}, all[2];

  PetscFunctionBeginUser;
  *n      = 0;
  pair[0] = pair[1] = -1;
  if (!c->enabled || c->nob < 2) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i)
    if (c->pt[i].st.switchesN >= 2) {
      const PetscInt a = c->pt[i].st.obstacle, b = c->pt[i].st.otherObstacle;
      m[0]++;
      m[1] = PetscMax(m[1], PetscMin(a, b) * SP_MAX_OBSTACLES + PetscMax(a, b));
    }
  PetscCallMPI(MPI_Allreduce(&m[0], &all[0], 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&m[1], &all[1], 1, MPIU_INT, MPI_MAX, comm));
  *n = all[0];
  if (*n) pair[0] = all[1] / SP_MAX_OBSTACLES, pair[1] = all[1] % SP_MAX_OBSTACLES;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective, after a search, until it has warned once: the points that penetrate an obstacle
   along whose normal a Dirichlet condition fixes them (a clamped corner under a rigid plate, a face
   pushed into a plane by a prescribed displacement). They are left out of that contact: their gap
   is prescribed, and enforced it would never close (shifted: the stall and every cut-back). */
PetscErrorCode SPContactWarnPinned(SPContact c)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)c->dm);
  PetscMPIInt rank, who, mine;
  PetscInt    n;
  PetscReal   x[4] = {0, 0, 0, 0};
  char        at[96];

  PetscFunctionBeginUser;
  if (c->pinnedWarned || !c->nob) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  mine = c->pinnedCount ? rank : PETSC_MPI_INT_MAX;
  PetscCallMPI(MPI_Allreduce(&mine, &who, 1, MPI_INT, MPI_MIN, comm));
  if (who == PETSC_MPI_INT_MAX) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Allreduce(&c->pinnedCount, &n, 1, MPIU_INT, MPI_SUM, comm));
  if (rank == who)
    for (PetscInt d = 0; d < c->dim; ++d) x[d] = c->pt[c->pinnedPoint].X[d], x[3] = (PetscReal)c->pinnedObstacle;
  PetscCallMPI(MPI_Bcast(x, 4, MPIU_REAL, who, comm));
  c->pinnedWarned = PETSC_TRUE;
  PetscCall(PetscSNPrintf(at, sizeof(at), c->dim == 2 ? "(%.6g, %.6g)" : "(%.6g, %.6g, %.6g)", (double)x[0], (double)x[1], (double)x[2]));
  PetscCall(PetscFPrintf(comm, PETSC_STDERR, "spcontact: warning: %" PetscInt_FMT " contact point(s) penetrate an obstacle along whose normal a Dirichlet condition fixes them (e.g. the vertex at %s, obstacle %d): they are left out of that contact, since their gap is prescribed (the condition's reaction carries their force)\n", n, at, (int)x[3]));
  PetscFunctionReturn(PETSC_SUCCESS);
}
