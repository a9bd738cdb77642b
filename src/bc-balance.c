/* A static problem needs its loads held: the net applied force must lie in the span of the forces
   its supports can react. Checked before the solve where that span follows from the options
   alone: Dirichlet conditions react along their components, frictionless rigid planes along
   their normals, and no friction, curved obstacle or follower pressure is present (those react,
   or load, in directions that depend on the solution); contact pairs only pass forces between the
   bodies, so with them the bodies are checked together (one of them free alone is not seen). A net force outside the span (a
   shear on a block on a frictionless plane with no condition fixing that direction) has no
   equilibrium: the solve would stall and cut back to -load_min_increment without saying why.
   A plane only pushes: its reaction is a non-negative multiple of its normal, so a load pulling
   the body off its planes (a suction on B1's top) is refused too, and so is a body that nothing
   holds against a rigid translation, or a rigid rotation (bc-rotation.c), whatever the loads. A
   necessary condition only: the loads' moments are not checked. */
#include <spcontact-impl.h>

/* This rank's part of the net force of Neumann condition bc at full amplitude, and of its scale
   (the sum of the facets' force magnitudes) */
static PetscErrorCode AddNetForce(DM dm, PetscInt dim, const SPBC *bc, PetscReal F[3], PetscReal *scale)
{
  PetscInt  n, *facets;
  PetscReal measure = 0.0;

  PetscFunctionBeginUser;
  PetscCall(SPMeshGetLabelFacets(dm, bc->label, bc->nvalues, bc->values, &n, &facets));
  for (PetscInt k = 0; k < n; ++k) {
    PetscReal nf[3] = {0, 0, 0}, x[3] = {0, 0, 0}, area, p = bc->value[0];
    PetscCall(SPMeshFacetGeometry(dm, dim, facets[k], nf, x, &area));
    measure += area;
    if (bc->type != SP_BC_PRESSURE) continue;
    for (PetscInt d = 0; d < dim; ++d) p += bc->gradient[d] * x[d];
    for (PetscInt d = 0; d < dim; ++d) F[d] -= p * nf[d] * area;
    *scale += PetscAbsReal(p) * area;
  }
  PetscCall(PetscFree(facets));
  if (bc->type == SP_BC_TRACTION)
    for (PetscInt d = 0; d < dim; ++d) F[d] += bc->value[d] * measure, *scale += PetscAbsReal(bc->value[d]) * measure;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* q[*nq]: orthonormal, with v's part outside their span added if it is not negligible */
static void AddDirection(PetscInt dim, const PetscReal v[], PetscReal q[][3], PetscInt *nq)
{
  PetscReal w[3] = {0, 0, 0}, len = 0.0;

  for (PetscInt d = 0; d < dim; ++d) w[d] = v[d];
  for (PetscInt k = 0; k < *nq; ++k) {
    PetscReal dot = 0.0;
    for (PetscInt d = 0; d < dim; ++d) dot += w[d] * q[k][d];
    for (PetscInt d = 0; d < dim; ++d) w[d] -= dot * q[k][d];
  }
  for (PetscInt d = 0; d < dim; ++d) len += w[d] * w[d];
  if (len < 1e-20) return;
  for (PetscInt d = 0; d < dim; ++d) q[*nq][d] = w[d] / PetscSqrtReal(len);
  (*nq)++;
}

/* Whether the check applies: every support's reaction direction is known before the solve, or,
   with friction (*pullOnly), only whether the loads pull the body off its planes */
static PetscBool Applies(SPProblem p, SPContact c, PetscBool *pullOnly)
{
  *pullOnly = PETSC_FALSE;
  if (p->mmsAmp != 0.0) return PETSC_FALSE; /* a body force */
  for (PetscInt i = 0; i < p->nbc; ++i)
    if (p->bc[i].follower) return PETSC_FALSE;
  if (!c || !c->enabled) return PETSC_TRUE;
  /* pairs: their forces are internal (the master's equals minus the slave's) and a rigid motion of
     every body together leaves their gaps and slips unchanged, so the net force and the whole
     assembly's rigid motions are checked against the Dirichlet conditions and obstacles alone */
  for (PetscInt k = 0; k < c->nob; ++k)
    if (c->ob[k].type != SP_OBSTACLE_PLANE) return PETSC_FALSE;
  *pullOnly = c->friction;
  return PETSC_TRUE;
}

/* The Dirichlet components: an orthonormal basis q[*nq] of the reactions of either sign */
static void Reactions(SPProblem p, PetscReal q[][3], PetscInt *nq)
{
  *nq = 0;
  for (PetscInt i = 0; i < p->nbc; ++i)
    for (PetscInt k = 0; p->bc[i].type == SP_BC_DIRICHLET && k < p->bc[i].ncomps; ++k) {
      PetscReal e[3] = {0, 0, 0};
      e[p->bc[i].comps[k]] = 1.0;
      AddDirection(p->dim, e, q, nq);
    }
}

/* v with its part in the span of q[nq] removed */
static void RemoveSpan(PetscInt dim, PetscReal v[3], PetscReal q[][3], PetscInt nq)
{
  for (PetscInt k = 0; k < nq; ++k) {
    PetscReal dot = 0.0;
    for (PetscInt d = 0; d < dim; ++d) dot += v[d] * q[k][d];
    for (PetscInt d = 0; d < dim; ++d) v[d] -= dot * q[k][d];
  }
}

/* With friction a plane's reaction is its push along n plus any tangential force: only the pull
   along n is refused, where every plane has the same normal n and no Dirichlet direction has a
   part along n (then n . (every reaction) >= 0). nhat: that unit normal; false if not so. */
static PetscBool CommonNormal(PetscInt dim, PetscReal n[][3], PetscInt nn, PetscReal q[][3], PetscInt nq, PetscReal nhat[3])
{
  PetscReal len = 0.0, w[3];

  if (nn == 0) return PETSC_FALSE;
  for (PetscInt d = 0; d < dim; ++d) len += n[0][d] * n[0][d];
  for (PetscInt d = 0; d < 3; ++d) nhat[d] = d < dim ? n[0][d] / PetscSqrtReal(len) : 0.0;
  for (PetscInt k = 1; k < nn; ++k) {
    PetscReal dot = 0.0, lk = 0.0;
    for (PetscInt d = 0; d < dim; ++d) dot += n[k][d] * nhat[d], lk += n[k][d] * n[k][d];
    if (dot < (1.0 - 1e-12) * PetscSqrtReal(lk)) return PETSC_FALSE;
  }
  for (PetscInt d = 0; d < 3; ++d) w[d] = nhat[d];
  RemoveSpan(dim, w, q, nq);
  len = 0.0;
  for (PetscInt d = 0; d < dim; ++d) len += w[d] * w[d];
  return len >= 1.0 - 1e-12 ? PETSC_TRUE : PETSC_FALSE;
}

/* x = a^-1 b for m <= 3 (a symmetric positive definite: Gaussian elimination without pivoting) */
static void SolveSmall(PetscInt m, PetscReal a[][3], PetscReal b[], PetscReal x[])
{
  for (PetscInt k = 0; k < m; ++k)
    for (PetscInt i = k + 1; i < m; ++i) {
      const PetscReal l = a[i][k] / a[k][k];
      for (PetscInt j = k; j < m; ++j) a[i][j] -= l * a[k][j];
      b[i] -= l * b[k];
    }
  for (PetscInt i = m - 1; i >= 0; --i) {
    x[i] = b[i];
    for (PetscInt j = i + 1; j < m; ++j) x[i] -= a[i][j] * x[j];
    x[i] /= a[i][i];
  }
}

/* r = f + sum lambda_k n_k over the columns n_k in `set`, lambda the least-squares multipliers;
   false if the columns are dependent or a multiplier is negative (a plane that would pull) */
static PetscBool ConeResidual(PetscInt dim, const PetscReal f[3], PetscReal n[][3], PetscInt nn, PetscInt set, PetscReal r[3])
{
  PetscReal qs[3][3], a[3][3], b[3], lam[3] = {0, 0, 0};
  PetscInt  idx[3], m = 0, nq = 0;

  for (PetscInt k = 0; k < nn; ++k)
    if (set >> k & 1) {
      if (m == dim) return PETSC_FALSE;
      idx[m++] = k;
    }
  for (PetscInt i = 0; i < m; ++i) { /* dependent columns: their cone is reached by a smaller set */
    AddDirection(dim, n[idx[i]], qs, &nq);
    if (nq != i + 1) return PETSC_FALSE;
  }
  for (PetscInt i = 0; i < m; ++i) { /* the normal equations N^T N lambda = -N^T f */
    b[i] = 0.0;
    for (PetscInt d = 0; d < dim; ++d) b[i] -= n[idx[i]][d] * f[d];
    for (PetscInt j = 0; j < m; ++j) {
      a[i][j] = 0.0;
      for (PetscInt d = 0; d < dim; ++d) a[i][j] += n[idx[i]][d] * n[idx[j]][d];
    }
  }
  SolveSmall(m, a, b, lam);
  for (PetscInt d = 0; d < dim; ++d) r[d] = f[d];
  for (PetscInt i = 0; i < m; ++i) {
    if (lam[i] < 0.0) return PETSC_FALSE;
    for (PetscInt d = 0; d < dim; ++d) r[d] += lam[i] * n[idx[i]][d];
  }
  return PETSC_TRUE;
}

/* f minus its projection on the cone of the planes' pushes n[nn] (non-negative multiples):
   the smallest residual over the sets of independent normals whose multipliers are all >= 0,
   which is the projection (Caratheodory: the nearest point of a cone lies in the cone of at most
   dim independent generators) */
static void RemoveCone(PetscInt dim, PetscReal f[3], PetscReal n[][3], PetscInt nn)
{
  PetscReal best[3] = {f[0], f[1], f[2]}, bestLen = PETSC_MAX_REAL;

  for (PetscInt set = 0; set < (1 << nn); ++set) {
    PetscReal r[3] = {0, 0, 0}, len = 0.0;
    if (!ConeResidual(dim, f, n, nn, set, r)) continue;
    for (PetscInt d = 0; d < dim; ++d) len += r[d] * r[d];
    if (len < bestLen) bestLen = len, best[0] = r[0], best[1] = r[1], best[2] = r[2];
  }
  for (PetscInt d = 0; d < dim; ++d) f[d] = best[d];
}

/* Net force of every Neumann condition at full amplitude (F[4 i + 0..2]) and its scale (F[4 i + 3]),
   summed over the ranks */
static PetscErrorCode ConditionForces(DM dm, SPProblem p, PetscReal F[])
{
  PetscReal loc[4 * SP_MAX_BC];

  PetscFunctionBeginUser;
  PetscCall(PetscArrayzero(loc, 4 * SP_MAX_BC));
  for (PetscInt i = 0; i < p->nbc; ++i)
    if (p->bc[i].type == SP_BC_TRACTION || p->bc[i].type == SP_BC_PRESSURE) PetscCall(AddNetForce(dm, p->dim, &p->bc[i], &loc[4 * i], &loc[4 * i + 3]));
  PetscCallMPI(MPI_Allreduce(loc, F, 4 * SP_MAX_BC, MPIU_REAL, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  for (PetscInt i = 0; i < p->nbc; ++i) /* a force condition is its total, the same on every rank */
    for (PetscInt d = 0; p->bc[i].type == SP_BC_FORCE && d < p->dim; ++d) F[4 * i + d] = p->bc[i].value[d], F[4 * i + 3] += PetscAbsReal(p->bc[i].value[d]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The part of the net force at load factor `load` that no support can hold: outside the span of
   the Dirichlet directions q[nq] and the cone of the planes' pushes n[nn] (both with the span
   removed); with friction (pull: the common normal) its pull along that normal. False if
   negligible. */
static PetscBool Unheld(SPProblem p, const PetscReal F[], PetscReal load, PetscReal q[][3], PetscInt nq, PetscReal n[][3], PetscInt nn, const PetscReal *pull, PetscReal perp[3])
{
  PetscReal scale = 0.0, len = 0.0, along = 0.0;

  perp[0] = perp[1] = perp[2] = 0.0;
  for (PetscInt i = 0; i < p->nbc; ++i) {
    const PetscReal a = SPBCAmplitude(&p->bc[i], load);
    for (PetscInt d = 0; d < p->dim; ++d) perp[d] += a * F[4 * i + d];
    scale += a * F[4 * i + 3];
  }
  if (pull) {
    for (PetscInt d = 0; d < p->dim; ++d) along += perp[d] * pull[d];
    for (PetscInt d = 0; d < p->dim; ++d) perp[d] = along > 0.0 ? along * pull[d] : 0.0;
  } else {
    RemoveSpan(p->dim, perp, q, nq);
    RemoveCone(p->dim, perp, n, nn);
  }
  for (PetscInt d = 0; d < p->dim; ++d) len += perp[d] * perp[d];
  return PetscSqrtReal(len) > 1e-8 * scale ? PETSC_TRUE : PETSC_FALSE;
}

/* Whether the unheld part perp pulls away from some plane (a part along its normal, which points
   towards the body): then the loads pull the body off, and friction would not hold it either */
static PetscBool PullsOff(PetscInt dim, const PetscReal perp[3], PetscReal n[][3], PetscInt nn)
{
  PetscReal lp = 0.0;

  for (PetscInt d = 0; d < dim; ++d) lp += perp[d] * perp[d];
  for (PetscInt k = 0; k < nn; ++k) {
    PetscReal dot = 0.0, ln = 0.0;
    for (PetscInt d = 0; d < dim; ++d) dot += perp[d] * n[k][d], ln += n[k][d] * n[k][d];
    if (dot > 1e-8 * PetscSqrtReal(lp * ln)) return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

/* A rigid translation v that neither a Dirichlet component (q[nq]) nor a plane's normal (n[nn])
   has a part along: the stiffness is singular whatever the loads (a block on a frictionless floor
   with nothing fixing x), and the solver returns one of infinitely many answers, different on
   different rank counts. v: the unit axis direction least held. */
static PetscBool FreeTranslation(PetscInt dim, PetscReal q[][3], PetscInt nq, PetscReal n[][3], PetscInt nn, PetscReal v[3])
{
  PetscReal b[3][3], best = 0.0;
  PetscInt  nb = 0;

  for (PetscInt k = 0; k < nq; ++k) AddDirection(dim, q[k], b, &nb);
  for (PetscInt k = 0; k < nn && nb < dim; ++k) AddDirection(dim, n[k], b, &nb);
  if (nb == dim) return PETSC_FALSE;
  for (PetscInt a = 0; a < dim; ++a) {
    PetscReal e[3] = {0, 0, 0}, len = 0.0;
    e[a] = 1.0;
    RemoveSpan(dim, e, b, nb);
    for (PetscInt d = 0; d < dim; ++d) len += e[d] * e[d];
    if (len <= best) continue;
    best = len;
    for (PetscInt d = 0; d < 3; ++d) v[d] = d < dim ? e[d] / PetscSqrtReal(len) : 0.0;
  }
  return PETSC_TRUE;
}

/* Dirichlet-fixed components as "x, z" (empty: none) */
static PetscErrorCode FixedComponents(SPProblem p, char fixed[], size_t len)
{
  PetscFunctionBeginUser;
  fixed[0] = 0;
  for (PetscInt i = 0; i < p->nbc; ++i)
    for (PetscInt k = 0; p->bc[i].type == SP_BC_DIRICHLET && k < p->bc[i].ncomps; ++k) {
      const char name[2] = {"xyz"[p->bc[i].comps[k]], 0};
      if (strstr(fixed, name)) continue;
      PetscCall(PetscStrlcat(fixed, fixed[0] ? ", " : "", len));
      PetscCall(PetscStrlcat(fixed, name, len));
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void FormatVector(PetscInt dim, const PetscReal v[3], char s[], size_t len)
{
  (void)PetscSNPrintf(s, len, dim == 2 ? "(%.4g, %.4g)" : "(%.4g, %.4g, %.4g)", (double)v[0], (double)v[1], (double)v[2]);
}

/* Whether the run has rigid obstacles (planes, where the check applies) / contact pairs */
static PetscBool Planes(SPContact c)
{
  return c && c->enabled && c->nob > 0 ? PETSC_TRUE : PETSC_FALSE;
}

static PetscBool Pairs(SPContact c)
{
  return c && c->enabled && c->npair > 0 ? PETSC_TRUE : PETSC_FALSE;
}

/* Collective: one line if the supports leave a rigid rotation free (bc-rotation.c) */
static PetscErrorCode FreeRotation(DM dm, SPContact c, PetscInt dim, const char fixed[])
{
  PetscInt  nfree;
  PetscReal axis[3], point[3];
  char      about[160], where[96], many[64] = "";

  PetscFunctionBeginUser;
  PetscCall(SPBCFreeRotation(dm, c, &nfree, axis, point));
  if (!nfree) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(where, sizeof(where), dim == 2 ? "(%.8g, %.8g)" : "(%.8g, %.8g, %.8g)", (double)point[0], (double)point[1], (double)point[2])); /* a place: more digits than a direction */
  if (dim == 2) PetscCall(PetscSNPrintf(about, sizeof(about), "the point %s", where));
  else {
    char dir[96];
    FormatVector(dim, axis, dir, sizeof(dir));
    PetscCall(PetscSNPrintf(about, sizeof(about), "the axis %s through %s", dir, where));
  }
  if (nfree > 1) PetscCall(PetscSNPrintf(many, sizeof(many), " (one of %" PetscInt_FMT " independent free rotations)", nfree));
  SETERRQ(PetscObjectComm((PetscObject)dm), PETSC_ERR_USER_INPUT, "nothing holds the body against a rigid rotation about %s%s: the Dirichlet conditions (on %s) leave it free%s, so the solution is not unique. Fix a component that the rotation moves (a roller fixes the component normal to its face: check -bc_<i>_components; conditions on one line or at one point do not hold a rotation about it)", about, many, fixed[0] ? fixed : "no component", Planes(c) ? ", and so do the slave points on the frictionless planes, all counted as touching" : Pairs(c) ? " (the contact pairs only pass forces between the bodies)" : " and there is no contact");
}

/* Collective, after the contact set-up: one line if the loads cannot be held. The net force is
   linear in the load factor between the ends of the load curves, so those and 1 are checked. */
PetscErrorCode SPBCCheckBalance(DM dm, SPProblem p, SPContact c)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)dm);
  PetscInt  dim  = p->dim, nq;
  PetscReal F[4 * SP_MAX_BC], q[3][3], n[SP_MAX_OBSTACLES][3], orig[SP_MAX_OBSTACLES][3], perp[3] = {0, 0, 0}, nhat[3], load = 1.0;
  PetscInt  nn = 0;
  PetscBool unheld, pullOnly;
  char      fixed[64] = "", force[96];

  PetscFunctionBeginUser;
  if (!Applies(p, c, &pullOnly)) PetscFunctionReturn(PETSC_SUCCESS);
  Reactions(p, q, &nq);
  for (PetscInt k = 0; c && c->enabled && k < c->nob; ++k, ++nn) { /* the planes' pushes, the span removed */
    for (PetscInt d = 0; d < 3; ++d) orig[nn][d] = n[nn][d] = d < dim ? c->ob[k].normal[d] : 0.0;
    RemoveSpan(dim, n[nn], q, nq);
  }
  PetscCall(FixedComponents(p, fixed, sizeof(fixed)));
  if (pullOnly && !CommonNormal(dim, orig, nn, q, nq, nhat)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(ConditionForces(dm, p, F));
  unheld = Unheld(p, F, load, q, nq, n, nn, pullOnly ? nhat : NULL, perp);
  for (PetscInt i = 0; i < p->nbc && !unheld; ++i)
    for (PetscInt e = 0; e < 2 && !unheld; ++e) load = p->bc[i].ramp[e], unheld = load > 0.0 && Unheld(p, F, load, q, nq, n, nn, pullOnly ? nhat : NULL, perp);
  if (!unheld) { /* the loads are held; the body must be too, against every rigid translation and rotation */
    if (pullOnly) PetscFunctionReturn(PETSC_SUCCESS);
    if (FreeTranslation(dim, q, nq, orig, nn, perp)) {
      FormatVector(dim, perp, force, sizeof(force));
      SETERRQ(comm, PETSC_ERR_USER_INPUT, "nothing holds the body against a rigid translation along %s (Dirichlet conditions fix %s; %s): the solution is not unique. Add a Dirichlet condition on that component (a symmetry plane, or a face that is held)%s", force, fixed[0] ? fixed : "no component", Planes(c) ? "no frictionless plane's normal has a part along it" : Pairs(c) ? "the contact pairs only pass forces between the bodies" : "there is no contact", Planes(c) ? ", or friction (-contact_friction_mu)" : "");
    }
    PetscCall(FreeRotation(dm, c, dim, fixed));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  FormatVector(dim, perp, force, sizeof(force));
  PetscCheck(!PullsOff(dim, perp, n, nn), comm, PETSC_ERR_USER_INPUT, "the loads' net force at load factor %.6g has a part %s that pulls the body off its obstacles (Dirichlet conditions fix %s; a plane only pushes, along its normal%s): no equilibrium exists. Reverse that load, or add a Dirichlet condition in that direction (if the load is right, check that each -contact_obstacle_<k>_normal points towards the body)", (double)load, force, fixed[0] ? fixed : "no component", pullOnly ? ", and its friction does not hold a body pulled off" : "");
  SETERRQ(comm, PETSC_ERR_USER_INPUT, "the loads' net force at load factor %.6g has a part %s that no support can hold (Dirichlet conditions fix %s; %s): no equilibrium exists. %s", (double)load, force, fixed[0] ? fixed : "no component", Planes(c) ? "the obstacles are frictionless planes, which only push, along their normals" : Pairs(c) ? "the contact pairs only pass forces between the bodies" : "there is no contact", Planes(c) ? "Add friction (-contact_friction_mu), a Dirichlet condition in that direction, or loads that balance" : "Add a Dirichlet condition in that direction, or loads that balance");
}
