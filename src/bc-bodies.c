/* Every body must be held on its own. bc-balance.c and bc-rotation.c check the mesh as one
   assembly: with contact pairs, whose forces are internal, that is right for bodies the pairs link,
   but a body in no pair (a third block, or a pair naming the wrong facets) that no Dirichlet
   condition holds passed, and its solve stalled into every cut-back (exit 2: the patch test with
   the pair's slave on the upper block's top, the upper block held in x only). So: the bodies are
   the connected components of the cells (sharing a vertex), the contact pairs join the bodies their
   slave and master facets lie on into groups, and each group must be held against every rigid
   motion by its own supports: the Dirichlet components at its vertices and, where their reaction
   directions are known (frictionless planes), the obstacles at its slave points (bc-rotation.c's
   rows; a group an obstacle can touch counts as held otherwise). The group reported is the first
   by its bounding box's lower corner, so the line is the same on any rank count. A pair holds
   only along its normals, so each body in a pair is then checked with the bodies it touches held
   still (CheckRelative): a disc on a frictionless pair, held by nothing else, turns. */
#include <spcontact-impl.h>

static PetscInt Find(PetscInt parent[], PetscInt i)
{
  while (parent[i] != i) parent[i] = parent[parent[i]], i = parent[i];
  return i;
}

static void Union(PetscInt parent[], PetscInt a, PetscInt b)
{
  a = Find(parent, a), b = Find(parent, b);
  if (a != b) parent[PetscMax(a, b)] = PetscMin(a, b);
}

/* The vertices (vStart-relative) in point p's closure: out[*n] (at most 27) */
static PetscErrorCode ClosureVertices(DM dm, PetscInt p, PetscInt vStart, PetscInt vEnd, PetscInt out[], PetscInt *n)
{
  PetscFunctionBeginUser;
  PetscCall(SPMeshPointVertices(dm, p, vStart, vEnd, n, out, 27));
  for (PetscInt k = 0; k < *n; ++k) out[k] -= vStart;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: lab[v - vStart] = the smallest global vertex number of v's body (-1: in no cell).
   Bodies within a rank by union-find over the cells, then across ranks through the point SF until
   no label falls. */
static PetscErrorCode VertexLabels(DM dm, PetscInt lab[])
{
  PetscInt        vStart, vEnd, cStart, cEnd, pStart, pEnd, *parent, *low, *a, *b, vs[27], nvs;
  const PetscInt *gn;
  IS              is;
  PetscSF         sf;
  PetscBool       changed = PETSC_TRUE;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(DMPlexGetVertexNumbering(dm, &is));
  PetscCall(ISGetIndices(is, &gn));
  PetscCall(PetscMalloc4(vEnd - vStart + 1, &parent, vEnd - vStart + 1, &low, pEnd - pStart + 1, &a, pEnd - pStart + 1, &b));
  for (PetscInt v = 0; v < vEnd - vStart; ++v) parent[v] = v, low[v] = PETSC_MAX_INT, lab[v] = -1;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscCall(ClosureVertices(dm, c, vStart, vEnd, vs, &nvs));
    for (PetscInt k = 0; k < nvs; ++k) Union(parent, vs[0], vs[k]), lab[vs[k]] = 0;
  }
  for (PetscInt v = 0; v < vEnd - vStart; ++v) {
    const PetscInt r = Find(parent, v), g = gn[v] < 0 ? -(gn[v] + 1) : gn[v];
    if (lab[v] == 0) low[r] = PetscMin(low[r], g);
  }
  while (changed) {
    PetscBool any = PETSC_FALSE;
    for (PetscInt p = 0; p < pEnd - pStart; ++p) a[p] = PETSC_MAX_INT;
    for (PetscInt v = 0; v < vEnd - vStart; ++v) a[vStart - pStart + v] = low[Find(parent, v)];
    PetscCall(PetscArraycpy(b, a, pEnd - pStart));
    PetscCall(PetscSFReduceBegin(sf, MPIU_INT, a, b, MPI_MIN));
    PetscCall(PetscSFReduceEnd(sf, MPIU_INT, a, b, MPI_MIN));
    PetscCall(PetscArraycpy(a, b, pEnd - pStart));
    PetscCall(PetscSFBcastBegin(sf, MPIU_INT, b, a, MPI_REPLACE));
    PetscCall(PetscSFBcastEnd(sf, MPIU_INT, b, a, MPI_REPLACE));
    for (PetscInt v = 0; v < vEnd - vStart; ++v) {
      const PetscInt r = Find(parent, v), x = a[vStart - pStart + v];
      if (x < low[r]) low[r] = x, any = PETSC_TRUE;
    }
    PetscCallMPI(MPI_Allreduce(&any, &changed, 1, MPIU_BOOL, MPI_LOR, PetscObjectComm((PetscObject)dm)));
  }
  for (PetscInt v = 0; v < vEnd - vStart; ++v)
    if (lab[v] == 0) lab[v] = low[Find(parent, v)];
  PetscCall(ISRestoreIndices(is, &gn));
  PetscCall(PetscFree4(parent, low, a, b));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: the labels numbered 0..*n-1 in the same order on every rank (vb[v]: -1 kept) */
static PetscErrorCode NumberBodies(DM dm, PetscInt nv, PetscInt vb[], PetscInt *n)
{
  MPI_Comm     comm = PetscObjectComm((PetscObject)dm);
  PetscInt    *mine, nmine = 0, *all, nall = 0;
  PetscMPIInt  size, cnt, *counts, *displs;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscMalloc1(nv + 1, &mine));
  for (PetscInt v = 0; v < nv; ++v)
    if (vb[v] >= 0) mine[nmine++] = vb[v];
  PetscCall(PetscSortRemoveDupsInt(&nmine, mine));
  PetscCall(PetscMPIIntCast(nmine, &cnt));
  PetscCall(PetscMalloc2(size, &counts, size + 1, &displs));
  PetscCallMPI(MPI_Allgather(&cnt, 1, MPI_INT, counts, 1, MPI_INT, comm));
  displs[0] = 0;
  for (PetscMPIInt r = 0; r < size; ++r) displs[r + 1] = displs[r] + counts[r];
  nall = displs[size];
  PetscCall(PetscMalloc1(nall + 1, &all));
  PetscCallMPI(MPI_Allgatherv(mine, cnt, MPIU_INT, all, counts, displs, MPIU_INT, comm));
  PetscCall(PetscSortRemoveDupsInt(&nall, all));
  for (PetscInt v = 0; v < nv; ++v)
    if (vb[v] >= 0) PetscCall(PetscFindInt(vb[v], nall, all, &vb[v]));
  *n = nall;
  PetscCall(PetscFree(mine));
  PetscCall(PetscFree(all));
  PetscCall(PetscFree2(counts, displs));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: the bodies each contact pair's facets lie on, joined (parent[nb]: union-find) */
static PetscErrorCode JoinByPairs(DM dm, SPContact c, const PetscInt vb[], PetscInt nb, PetscInt parent[])
{
  PetscInt vStart, vEnd, *hit, *any;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(PetscMalloc2(nb, &hit, nb, &any));
  for (PetscInt k = 0; c && c->enabled && k < c->npair; ++k) {
    const SPPair *pr = &c->pair[k];
    PetscInt      first = -1;
    PetscCall(PetscArrayzero(hit, nb));
    for (PetscInt side = 0; side < 2; ++side) {
      PetscInt n, *facets, vs[27], nvs;
      PetscCall(SPMeshGetLabelFacets(dm, pr->label, side ? pr->nmaster : pr->nslave, side ? pr->master : pr->slave, &n, &facets));
      for (PetscInt f = 0; f < n; ++f) {
        PetscCall(ClosureVertices(dm, facets[f], vStart, vEnd, vs, &nvs));
        for (PetscInt j = 0; j < nvs; ++j)
          if (vb[vs[j]] >= 0) hit[vb[vs[j]]] = 1;
      }
      PetscCall(PetscFree(facets));
    }
    PetscCallMPI(MPI_Allreduce(hit, any, (PetscMPIInt)nb, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)dm)));
    for (PetscInt i = 0; i < nb; ++i)
      if (any[i]) first < 0 ? (void)(first = i) : Union(parent, first, i);
  }
  PetscCall(PetscFree2(hit, any));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* What each group is: bounding box, cells (each at its owner), bodies, whether a slave point of the
   obstacles lies on it. Collective; info[g] = {lo[3], hi[3], cells, bodies, touched}. */
typedef struct {
  PetscReal lo[3], hi[3], cells, bodies, touched;
} SPGroupInfo;

static PetscErrorCode GroupInfo(DM dm, SPContact c, const PetscInt vg[], const PetscInt bg[], PetscInt nb, PetscInt ng, SPGroupInfo info[])
{
  PetscInt           vStart, vEnd, cStart, cEnd, cdim, nleaves, vs[27], nvs;
  const PetscInt    *leaves;
  PetscSection       cs;
  Vec                coords;
  const PetscScalar *x;
  PetscSF            sf;
  PetscReal         *mx, *sm, *gmx, *gsm; /* per group: -lo, hi (MAX); cells, bodies, touched (SUM) */
  PetscBool         *leaf;
  MPI_Comm           comm = PetscObjectComm((PetscObject)dm);

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscCall(DMGetCoordinateDim(dm, &cdim));
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, NULL, &nleaves, &leaves, NULL));
  PetscCall(PetscMalloc4(6 * ng, &mx, 3 * ng, &sm, 6 * ng, &gmx, 3 * ng, &gsm));
  PetscCall(PetscCalloc1(cEnd - cStart + 1, &leaf));
  for (PetscInt i = 0; i < 6 * ng; ++i) mx[i] = PETSC_MIN_REAL;
  PetscCall(PetscArrayzero(sm, 3 * ng));
  for (PetscInt l = 0; l < (nleaves > 0 ? nleaves : 0); ++l) {
    const PetscInt p = leaves ? leaves[l] : l;
    if (p >= cStart && p < cEnd) leaf[p - cStart] = PETSC_TRUE;
  }
  PetscCall(VecGetArrayRead(coords, &x));
  for (PetscInt v = 0; v < vEnd - vStart; ++v) {
    PetscInt off;
    if (vg[v] < 0) continue;
    PetscCall(PetscSectionGetOffset(cs, v + vStart, &off));
    for (PetscInt d = 0; d < cdim; ++d) {
      const PetscReal y = PetscRealPart(x[off + d]);
      mx[6 * vg[v] + d] = PetscMax(mx[6 * vg[v] + d], -y), mx[6 * vg[v] + 3 + d] = PetscMax(mx[6 * vg[v] + 3 + d], y);
    }
  }
  PetscCall(VecRestoreArrayRead(coords, &x));
  for (PetscInt cell = cStart; cell < cEnd; ++cell) {
    if (leaf[cell - cStart]) continue;
    PetscCall(ClosureVertices(dm, cell, vStart, vEnd, vs, &nvs));
    if (nvs && vg[vs[0]] >= 0) sm[3 * vg[vs[0]]] += 1.0;
  }
  for (PetscInt i = 0; c && c->enabled && i < c->n; ++i)
    if (c->pt[i].onObstacle && vg[c->pt[i].vertex - vStart] >= 0) sm[3 * vg[c->pt[i].vertex - vStart] + 2] = 1.0;
  PetscCallMPI(MPI_Allreduce(mx, gmx, (PetscMPIInt)(6 * ng), MPIU_REAL, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(sm, gsm, (PetscMPIInt)(3 * ng), MPIU_REAL, MPI_SUM, comm));
  for (PetscInt g = 0; g < ng; ++g) {
    for (PetscInt d = 0; d < 3; ++d) info[g].lo[d] = d < cdim ? -gmx[6 * g + d] : 0.0, info[g].hi[d] = d < cdim ? gmx[6 * g + 3 + d] : 0.0;
    info[g].cells = gsm[3 * g], info[g].bodies = 0.0, info[g].touched = gsm[3 * g + 2];
  }
  for (PetscInt i = 0; i < nb; ++i) info[bg[i]].bodies += 1.0; /* every rank knows every body's group */
  PetscCall(PetscFree4(mx, sm, gmx, gsm));
  PetscCall(PetscFree(leaf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Each group's centre and size (its box's largest extent; 1 if flat): the rows' scaled positions */
static void BoxScales(PetscInt ng, const SPGroupInfo info[], PetscReal centre[][3], PetscReal size[])
{
  for (PetscInt g = 0; g < ng; ++g) {
    size[g] = 0.0;
    for (PetscInt d = 0; d < 3; ++d) centre[g][d] = 0.5 * (info[g].lo[d] + info[g].hi[d]), size[g] = PetscMax(size[g], info[g].hi[d] - info[g].lo[d]);
    if (size[g] <= 0.0) size[g] = 1.0;
  }
}

/* Whether group a comes before group b: by the lower corner of its box, then its upper corner */
static PetscBool Before(PetscInt dim, const SPGroupInfo *a, const SPGroupInfo *b)
{
  for (PetscInt d = 0; d < dim; ++d)
    if (a->lo[d] != b->lo[d]) return a->lo[d] < b->lo[d] ? PETSC_TRUE : PETSC_FALSE;
  for (PetscInt d = 0; d < dim; ++d)
    if (a->hi[d] != b->hi[d]) return a->hi[d] < b->hi[d] ? PETSC_TRUE : PETSC_FALSE;
  return PETSC_FALSE;
}

static PetscBool Pairs(SPContact c)
{
  return c && c->enabled && c->npair > 0 ? PETSC_TRUE : PETSC_FALSE;
}

static void Format(PetscInt dim, const PetscReal v[3], char s[], size_t len)
{
  (void)PetscSNPrintf(s, len, dim == 2 ? "(%.6g, %.6g)" : "(%.6g, %.6g, %.6g)", (double)v[0], (double)v[1], (double)v[2]);
}

/* Whether the obstacles' reactions are known before the solve: frictionless planes only */
static PetscBool KnownReactions(SPContact c)
{
  for (PetscInt k = 0; c && c->enabled && k < c->nob; ++k)
    if (c->ob[k].type != SP_OBSTACLE_PLANE) return PETSC_FALSE;
  return c && c->enabled && c->friction ? PETSC_FALSE : PETSC_TRUE;
}

/* The one line for free group info (G: its rows; nfree: groups found free) */
static PetscErrorCode Refuse(DM dm, SPContact c, PetscInt dim, const SPGroupInfo *info, PetscReal G[][SP_RIGID_MAX], PetscInt nfree)
{
  const PetscBool group = info->bodies > 1 ? PETSC_TRUE : PETSC_FALSE;
  const char     *its = group ? "their" : "its", *it = group ? "them" : "it", *they = group ? "they" : "it";
  PetscReal       centre[3] = {0, 0, 0}, size = 0.0, t[3], axis[3], point[3], rows = 0.0;
  PetscInt        nrot;
  PetscBool       trans;
  char            lo[64], hi[64], what[160], cause[320], many[64] = "", sup[96], motion[160];

  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < dim; ++d) centre[d] = 0.5 * (info->lo[d] + info->hi[d]), size = PetscMax(size, info->hi[d] - info->lo[d]);
  for (PetscInt i = 0; i < SP_RIGID_MAX; ++i) rows += G[i][i];
  PetscCall(SPBCRigidKernel(dim, G, centre, size, 0.0, &trans, t, &nrot, axis, point));
  Format(dim, info->lo, lo, sizeof(lo));
  Format(dim, info->hi, hi, sizeof(hi));
  if (group) PetscCall(PetscSNPrintf(what, sizeof(what), "the %d bodies that contact pairs link in the box %s..%s (%.0f cells)", (int)info->bodies, lo, hi, (double)info->cells));
  else PetscCall(PetscSNPrintf(what, sizeof(what), "the body in the box %s..%s (%.0f cells)", lo, hi, (double)info->cells));
  if (nfree > 1) PetscCall(PetscSNPrintf(many, sizeof(many), " (one of %" PetscInt_FMT " bodies or groups held by nothing)", nfree));
  PetscCall(PetscSNPrintf(sup, sizeof(sup), "%s supports (Dirichlet components%s%s%s)", its, info->touched > 0 ? ", frictionless planes at " : "", info->touched > 0 ? its : "", info->touched > 0 ? " slave points" : ""));
  if (trans) {
    char dir[64];
    Format(dim, t, dir, sizeof(dir));
    PetscCall(PetscSNPrintf(motion, sizeof(motion), "move along %s", dir));
  } else {
    char at[64], ax[64];
    Format(dim, point, at, sizeof(at));
    Format(dim, axis, ax, sizeof(ax));
    if (dim == 2) PetscCall(PetscSNPrintf(motion, sizeof(motion), "turn about the point %s", at));
    else PetscCall(PetscSNPrintf(motion, sizeof(motion), "turn about the axis %s through %s", ax, at));
  }
  if (rows == 0.0 && c && c->enabled && c->nob) PetscCall(PetscSNPrintf(cause, sizeof(cause), "no Dirichlet condition acts on %s and no obstacle can touch %s (none of %s facets is in -contact_values)", it, it, its));
  else if (rows == 0.0) PetscCall(PetscSNPrintf(cause, sizeof(cause), "no Dirichlet condition acts on %s and there is no obstacle", it));
  else PetscCall(PetscSNPrintf(cause, sizeof(cause), "%s leave %s free to %s", sup, it, motion));
  SETERRQ(PetscObjectComm((PetscObject)dm), PETSC_ERR_USER_INPUT, "nothing holds %s%s: %s, and %s, so %s can move rigidly and the solution is not unique. Give %s a Dirichlet condition (-bc_<i>_values on %s faces), or a contact pair with a body that is held (check that -contact_pair_<k>_slave_values and _master_values name the facets where the two bodies meet)", what, many, cause, group ? "no contact pair links them to a held body" : Pairs(c) ? "no contact pair names its facets" : "there are no contact pairs", they, it, its);
}

/* A body's mode is held through its pairs only if G's eigenvalue exceeds this, in units of one
   support at the scaled distance 1: a frictionless disc's normals all point through its centre
   but for the facets' angles, which left its rotation an eigenvalue of 1e-3 (1e-5 of the largest,
   B6 without the disc's symmetry condition; it stalled), where every held body of the inputs has
   0.75 or more */
#define SP_PAIR_HOLD_MIN 1e-2

/* Collective: pair k's master body mb[k], the one body its master facets lie on (-1: several) */
static PetscErrorCode MasterBodies(DM dm, SPContact c, const PetscInt vb[], PetscInt mb[])
{
  PetscInt vStart, vEnd, lo[2 * 2 * SP_MAX_PAIRS], all[2 * 2 * SP_MAX_PAIRS]; /* per pair (mirrors included): min body, -(max body) */

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  for (PetscInt k = 0; k < c->npair; ++k) {
    const SPPair *pr = &c->pair[k];
    PetscInt      n, *facets, vs[27], nvs;
    lo[2 * k] = lo[2 * k + 1] = PETSC_MAX_INT;
    PetscCall(SPMeshGetLabelFacets(dm, pr->label, pr->nmaster, pr->master, &n, &facets));
    for (PetscInt f = 0; f < n; ++f) {
      PetscCall(ClosureVertices(dm, facets[f], vStart, vEnd, vs, &nvs));
      for (PetscInt j = 0; j < nvs; ++j)
        if (vb[vs[j]] >= 0) lo[2 * k] = PetscMin(lo[2 * k], vb[vs[j]]), lo[2 * k + 1] = PetscMin(lo[2 * k + 1], -vb[vs[j]]);
    }
    PetscCall(PetscFree(facets));
  }
  PetscCallMPI(MPI_Allreduce(lo, all, (PetscMPIInt)(2 * c->npair), MPIU_INT, MPI_MIN, PetscObjectComm((PetscObject)dm)));
  for (PetscInt k = 0; k < c->npair; ++k) mb[k] = all[2 * k] == -all[2 * k + 1] ? all[2 * k] : -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* This rank's pair rows, each body holding the bodies it touches still: a pair's slave point
   pushes along its normal (every direction with friction on the pair) at its position, on its own
   body and on the pair's master body (G[b], positions scaled by the body's centre and size). A
   two-pass mirror's point pushes on its own body only: on the master side it would stand for the
   user pair's contact at a place that contact has a row of its own, with the other body's normal
   (B6's block top, counted as touching the disc everywhere, held the disc's rotation, which
   stalled) */
static void AddPairRows(SPContact c, PetscInt dim, PetscInt vStart, const PetscInt vb[], const PetscInt mb[], const PetscReal centre[][3], const PetscReal size[], PetscReal G[][SP_RIGID_MAX][SP_RIGID_MAX])
{
  for (PetscInt i = 0; i < c->n; ++i) {
    const SPContactPoint *pt = &c->pt[i];
    for (PetscInt k = 0; k < c->npair; ++k) {
      const PetscInt  body[2] = {vb[pt->vertex - vStart], c->pair[k].mirror ? -1 : mb[k]};
      const PetscBool mu      = c->friction && c->pair[k].mu > 0.0 ? PETSC_TRUE : PETSC_FALSE;
      if (!(pt->pairMask & (1 << k))) continue;
      for (PetscInt s = 0; s < 2; ++s) {
        PetscReal y[3] = {0, 0, 0};
        if (body[s] < 0 || (s && body[1] == body[0])) continue;
        for (PetscInt d = 0; d < dim; ++d) y[d] = (pt->X[d] - centre[body[s]][d]) / size[body[s]];
        for (PetscInt r = 0; r < (mu ? dim : 1); ++r) {
          PetscReal e[3] = {0, 0, 0};
          if (mu) e[r] = 1.0;
          SPBCRigidAddRow(dim, y, mu ? e : pt->nIn, G[body[s]]);
        }
      }
    }
  }
}

/* The one line for a body free against the bodies it touches */
static PetscErrorCode RefuseRelative(DM dm, PetscInt dim, const SPGroupInfo *info, PetscReal G[][SP_RIGID_MAX], const PetscReal centre[3], PetscReal size)
{
  PetscReal t[3], axis[3], point[3];
  PetscInt  nrot;
  PetscBool trans;
  char      lo[64], hi[64], motion[160], at[64], ax[64];

  PetscFunctionBeginUser;
  PetscCall(SPBCRigidKernel(dim, G, centre, size, SP_PAIR_HOLD_MIN, &trans, t, &nrot, axis, point));
  Format(dim, info->lo, lo, sizeof(lo));
  Format(dim, info->hi, hi, sizeof(hi));
  Format(dim, trans ? t : point, at, sizeof(at));
  Format(dim, axis, ax, sizeof(ax));
  if (trans) PetscCall(PetscSNPrintf(motion, sizeof(motion), "move along %s", at));
  else if (dim == 2) PetscCall(PetscSNPrintf(motion, sizeof(motion), "turn about the point %s", at));
  else PetscCall(PetscSNPrintf(motion, sizeof(motion), "turn about the axis %s through %s", ax, at));
  SETERRQ(PetscObjectComm((PetscObject)dm), PETSC_ERR_USER_INPUT, "nothing holds the body in the box %s..%s (%.0f cells) against the bodies it touches: its Dirichlet components and its contact pairs, which push along their normals only (frictionless), leave it free, or all but free, to %s even with those bodies held still (a disc on a frictionless pair turns about its centre), so the solution is not unique. Fix a component that this motion moves (-bc_<i>_values on its faces; friction does not hold it in the step where it first touches)", lo, hi, (double)info->cells, motion);
}

/* Collective: each body in a pair must be held with the bodies it touches held still (a pair holds
   only along its normals: the group check above sees the linked bodies as one rigid whole, so a
   disc whose only condition was on the block it rests on passed, and stalled) */
static PetscErrorCode CheckRelative(DM dm, SPContact c, PetscInt dim, const PetscInt vb[], PetscInt nb, PetscBool planes)
{
  PetscInt     vStart, vEnd, *id, mb[2 * SP_MAX_PAIRS], first = -1;
  SPGroupInfo *info;
  PetscReal(*centre)[3], *size, (*G)[SP_RIGID_MAX][SP_RIGID_MAX], (*loc)[SP_RIGID_MAX][SP_RIGID_MAX], (*P)[SP_RIGID_MAX][SP_RIGID_MAX];

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(PetscMalloc4(nb, &info, nb, &centre, nb, &size, nb, &id));
  PetscCall(PetscMalloc1(nb, &G));
  PetscCall(PetscCalloc2(nb, &loc, nb, &P));
  for (PetscInt b = 0; b < nb; ++b) id[b] = b;
  PetscCall(GroupInfo(dm, c, vb, id, nb, nb, info));
  BoxScales(nb, info, centre, size);
  PetscCall(MasterBodies(dm, c, vb, mb));
  PetscCall(SPBCRigidSupports(dm, c, planes, vb, nb, centre, size, G));
  AddPairRows(c, dim, vStart, vb, mb, centre, size, loc);
  PetscCallMPI(MPI_Allreduce(&loc[0][0][0], &P[0][0][0], (PetscMPIInt)(nb * SP_RIGID_MAX * SP_RIGID_MAX), MPIU_REAL, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  for (PetscInt b = 0; b < nb; ++b) {
    PetscReal Gc[SP_RIGID_MAX][SP_RIGID_MAX], t[3], axis[3], point[3];
    PetscInt  nrot;
    PetscBool trans;
    if (info[b].touched > 0 && !planes) continue; /* an obstacle may hold it, in directions the solve finds */
    for (PetscInt i = 0; i < SP_RIGID_MAX; ++i)
      for (PetscInt j = 0; j < SP_RIGID_MAX; ++j) G[b][i][j] += P[b][i][j], Gc[i][j] = G[b][i][j];
    PetscCall(SPBCRigidKernel(dim, Gc, centre[b], size[b], SP_PAIR_HOLD_MIN, &trans, t, &nrot, axis, point));
    if ((trans || nrot) && (first < 0 || Before(dim, &info[b], &info[first]))) first = b;
  }
  if (first >= 0) PetscCall(RefuseRelative(dm, dim, &info[first], G[first], centre[first], size[first]));
  PetscCall(PetscFree2(loc, P));
  PetscCall(PetscFree(G));
  PetscCall(PetscFree4(info, centre, size, id));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective, after the contact set-up: one line if a body, or a group of bodies that contact pairs
   link, is not held against every rigid motion by its own supports (a single body: bc-balance.c) */
PetscErrorCode SPBCCheckBodies(DM dm, SPContact c)
{
  PetscInt     vStart, vEnd, nv, dim, nb = 0, ng = 0, *vb, *vg, *parent, *bg, nfree = 0, first = -1;
  PetscBool    planes = KnownReactions(c);
  SPGroupInfo *info;
  PetscReal(*centre)[3], *size, (*G)[SP_RIGID_MAX][SP_RIGID_MAX];

  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDim(dm, &dim));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  nv = vEnd - vStart;
  PetscCall(PetscMalloc2(nv + 1, &vb, nv + 1, &vg));
  PetscCall(VertexLabels(dm, vb));
  PetscCall(NumberBodies(dm, nv, vb, &nb));
  if (nb < 2) {
    PetscCall(PetscFree2(vb, vg));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscMalloc2(nb, &parent, nb, &bg));
  for (PetscInt i = 0; i < nb; ++i) parent[i] = i;
  PetscCall(JoinByPairs(dm, c, vb, nb, parent));
  for (PetscInt i = 0; i < nb; ++i) bg[i] = Find(parent, i) == i ? ng++ : -1;
  for (PetscInt i = 0; i < nb; ++i) bg[i] = bg[Find(parent, i)];
  for (PetscInt v = 0; v < nv; ++v) vg[v] = vb[v] >= 0 ? bg[vb[v]] : -1;
  if (ng < 2) { /* one group: the whole assembly, which bc-balance.c checks with the loads */
    PetscCall(PetscFree2(parent, bg));
    PetscCall(PetscFree2(vb, vg));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscMalloc4(ng, &info, ng, &centre, ng, &size, ng, &G));
  PetscCall(GroupInfo(dm, c, vg, bg, nb, ng, info));
  BoxScales(ng, info, centre, size);
  PetscCall(SPBCRigidSupports(dm, c, planes, vg, ng, centre, size, G));
  for (PetscInt g = 0; g < ng; ++g) {
    PetscReal Gc[SP_RIGID_MAX][SP_RIGID_MAX], t[3], axis[3], point[3];
    PetscInt  nrot;
    PetscBool trans;
    if (info[g].touched > 0 && !planes) continue; /* an obstacle may hold it, in directions the solve finds */
    PetscCall(PetscArraycpy(&Gc[0][0], &G[g][0][0], SP_RIGID_MAX * SP_RIGID_MAX));
    PetscCall(SPBCRigidKernel(dim, Gc, centre[g], size[g], 0.0, &trans, t, &nrot, axis, point));
    if (!trans && !nrot) continue;
    nfree++;
    if (first < 0 || Before(dim, &info[g], &info[first])) first = g;
  }
  if (nfree) PetscCall(Refuse(dm, c, dim, &info[first], G[first], nfree));
  PetscCall(PetscFree4(info, centre, size, G));
  PetscCall(PetscFree2(parent, bg));
  PetscCall(PetscFree2(vb, vg));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective, after bc-balance.c's whole-assembly check (whose lines are the more general ones):
   one line if a body in a contact pair is not held with the bodies it touches held still */
PetscErrorCode SPBCCheckBodiesInPairs(DM dm, SPContact c)
{
  PetscInt vStart, vEnd, nv, dim, nb = 0, *vb;

  PetscFunctionBeginUser;
  if (!Pairs(c)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(DMGetCoordinateDim(dm, &dim));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  nv = vEnd - vStart;
  PetscCall(PetscMalloc1(nv + 1, &vb));
  PetscCall(VertexLabels(dm, vb));
  PetscCall(NumberBodies(dm, nv, vb, &nb));
  if (nb >= 2) PetscCall(CheckRelative(dm, c, dim, vb, nb, KnownReactions(c)));
  PetscCall(PetscFree(vb));
  PetscFunctionReturn(PETSC_SUCCESS);
}
