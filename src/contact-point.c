/* The contact-point records: which vertices are contact points, their fixed data, and their
   geometry, evaluated once per iterate. SPContactEvaluate remembers the displacement and load
   factor of its last evaluation (a copy of the vector) and returns at once when asked again for
   the same state, so the residual, Jacobian, shift update,
   convergence test and output share one evaluation and, for contact pairs, one master exchange.
   The state part of a record (shifts, status) is saved at the start of a load step and restored
   on a cut-back. */
#include <spcontact-impl.h>

/* dmC: a clone of the mesh with one dof on every vertex of the (completed) slave label */
static PetscErrorCode CreatePointDM(SPContact c, DMLabel slave)
{
  PetscSection s;
  PetscInt     pStart, pEnd, vStart, vEnd;

  PetscFunctionBeginUser;
  PetscCall(DMClone(c->dm, &c->dmC));
  PetscCall(DMPlexGetChart(c->dm, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(c->dm, 0, &vStart, &vEnd));
  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)c->dm), &s));
  PetscCall(PetscSectionSetChart(s, pStart, pEnd));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt val;
    PetscCall(DMLabelGetValue(slave, v, &val));
    if (val == 1) PetscCall(PetscSectionSetDof(s, v, 1));
  }
  PetscCall(PetscSectionSetUp(s));
  PetscCall(DMSetLocalSection(c->dmC, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The owned slave vertices, in the order of the global contact-point layout, and their coordinates */
static PetscErrorCode CollectPoints(SPContact c)
{
  PetscSection       gs, cs;
  PetscInt           vStart, vEnd;
  Vec                coords, v;
  const PetscScalar *ca;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(c->dmC, &gs));
  PetscCall(DMPlexGetDepthStratum(c->dm, 0, &vStart, &vEnd));
  PetscCall(DMCreateGlobalVector(c->dmC, &v));
  PetscCall(VecGetLocalSize(v, &c->n));
  PetscCall(VecGetOwnershipRange(v, &c->rstart, NULL));
  PetscCall(VecDestroy(&v));
  PetscCall(PetscCalloc4(c->n, &c->pt, c->n, &c->saved, c->n, &c->gapStart, 3 * c->n, &c->slipStart));
  PetscCall(PetscCalloc1(2 * c->n * SP_KNOWN_FACETS, &c->known));
  for (PetscInt i = 0; i < 2 * c->n * SP_KNOWN_FACETS; ++i) c->known[i] = -1;
  PetscCall(DMGetCoordinatesLocal(c->dm, &coords));
  PetscCall(DMGetCoordinateSection(c->dm, &cs));
  PetscCall(VecGetArrayRead(coords, &ca));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt dof, off, coff, k;
    PetscCall(PetscSectionGetDof(gs, v, &dof));
    PetscCall(PetscSectionGetOffset(gs, v, &off));
    if (dof <= 0 || off < 0) continue; /* not a slave vertex, or owned by another rank */
    k                = off - c->rstart;
    c->pt[k].vertex  = v;
    c->pt[k].geo.elem = SP_ELEM_NONE;
    SPContactPairsForgetFacets(&c->pt[k]);
    PetscCall(PetscSectionGetOffset(cs, v, &coff));
    for (PetscInt d = 0; d < c->dim; ++d) c->pt[k].X[d] = PetscRealPart(ca[coff + d]);
  }
  PetscCall(VecRestoreArrayRead(coords, &ca));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Which slave sets each point belongs to: the obstacles' and each pair's (bit k of pairMask) */
static PetscErrorCode MarkPoints(SPContact c)
{
  DMLabel lab;

  PetscFunctionBeginUser;
  if (c->nob) {
    PetscCall(SPMeshCreateCompletedLabel(c->dm, c->label, c->nvalues, c->values, "spcontact_obstacle_slave", &lab));
    for (PetscInt i = 0; i < c->n; ++i) {
      PetscInt val;
      PetscCall(DMLabelGetValue(lab, c->pt[i].vertex, &val));
      c->pt[i].onObstacle = c->pt[i].primary = val == 1 ? PETSC_TRUE : PETSC_FALSE;
    }
    PetscCall(DMRemoveLabel(c->dm, "spcontact_obstacle_slave", NULL));
  }
  for (PetscInt k = 0; k < c->npair; ++k) {
    const SPPair *p = &c->pair[k];
    PetscCall(SPMeshCreateCompletedLabel(c->dm, p->label, p->nslave, p->slave, "spcontact_pair_slave", &lab));
    for (PetscInt i = 0; i < c->n; ++i) {
      PetscInt val;
      PetscCall(DMLabelGetValue(lab, c->pt[i].vertex, &val));
      if (val != 1) continue;
      c->pt[i].pairMask |= (PetscInt)1 << k;
      if (!p->mirror) c->pt[i].primary = PETSC_TRUE;
    }
    PetscCall(DMRemoveLabel(c->dm, "spcontact_pair_slave", NULL));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Global dofs of each point's vertex (constrained ones negative) */
static PetscErrorCode PointGlobalDofs(SPContact c)
{
  PetscSection ls, gs;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(c->dm, &ls));
  PetscCall(DMGetGlobalSection(c->dm, &gs));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt *idx = NULL, nidx;
    PetscCall(DMPlexGetClosureIndices(c->dm, ls, gs, c->pt[i].vertex, PETSC_TRUE, &nidx, &idx, NULL, NULL));
    PetscCheck(nidx == c->dim, PETSC_COMM_SELF, PETSC_ERR_PLIB, "vertex with %" PetscInt_FMT " dofs", nidx);
    for (PetscInt d = 0; d < c->dim; ++d) c->pt[i].sdof[d] = idx[d];
    PetscCall(DMPlexRestoreClosureIndices(c->dm, ls, gs, c->pt[i].vertex, PETSC_TRUE, &nidx, &idx, NULL, NULL));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The contact points of the slave label `slave` (the union of every slave surface) */
PetscErrorCode SPContactPointsSetUp(SPContact c, DMLabel slave)
{
  PetscFunctionBeginUser;
  PetscCall(CreatePointDM(c, slave));
  PetscCall(CollectPoints(c));
  PetscCall(MarkPoints(c));
  PetscCall(PointGlobalDofs(c));
  PetscCall(PetscCalloc2(c->n * 2 * c->params.history, &c->hist, c->n, &c->nhist));
  if (c->params.accel != SP_ACCEL_NONE) {
    PetscCall(PetscCalloc4(c->n + 1, &c->accS, c->n + 1, &c->accG, c->n + 1, &c->accNew, c->n + 1, &c->accIn));
    PetscCall(PetscCalloc4(2 * c->n + 1, &c->accTS, 2 * c->n + 1, &c->accTG, 2 * c->n + 1, &c->accTNew, 2 * c->n + 1, &c->accTIn));
  }
  if (c->params.accel == SP_ACCEL_SCHUR) PetscCall(PetscCalloc1(c->n + 1, &c->accTSlip));
  if (c->params.accel == SP_ACCEL_ANDERSON) {
    PetscCall(SPShiftAccelCreate(PetscObjectComm((PetscObject)c->dm), c->n, c->params.accelDepth, &c->accel));
    PetscCall(SPShiftAccelCreate(PetscObjectComm((PetscObject)c->dm), 2 * c->n, c->params.accelDepth, &c->accelT));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactPointsDestroy(SPContact c)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree4(c->pt, c->saved, c->gapStart, c->slipStart));
  PetscCall(PetscFree(c->known));
  PetscCall(PetscFree2(c->hist, c->nhist));
  PetscCall(SPShiftAccelDestroy(&c->accel));
  PetscCall(PetscFree4(c->accS, c->accG, c->accNew, c->accIn));
  PetscCall(SPShiftAccelDestroy(&c->accelT));
  PetscCall(PetscFree4(c->accTS, c->accTG, c->accTNew, c->accTIn));
  PetscCall(PetscFree(c->accTSlip));
  PetscCall(VecDestroy(&c->evalX));
  PetscCall(DMDestroy(&c->dmC));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* An orthonormal tangent basis of the plane normal to n (dim - 1 vectors) */
static void TangentBasis(PetscInt dim, const PetscReal n[], PetscReal t[2][3])
{
  if (dim == 2) {
    t[0][0] = -n[1], t[0][1] = n[0], t[0][2] = 0.0;
    return;
  }
  { /* t0: the coordinate axis least aligned with n, made orthogonal to n; t1 = n x t0 */
    PetscInt  k = 0;
    PetscReal e[3] = {0, 0, 0}, dn, len;
    for (PetscInt d = 1; d < 3; ++d)
      if (PetscAbsReal(n[d]) < PetscAbsReal(n[k])) k = d;
    e[k] = 1.0;
    dn   = SPDot(3, e, n);
    for (PetscInt d = 0; d < 3; ++d) t[0][d] = e[d] - dn * n[d];
    len = SPNorm(3, t[0]);
    for (PetscInt d = 0; d < 3; ++d) t[0][d] /= len;
    t[1][0] = n[1] * t[0][2] - n[2] * t[0][1];
    t[1][1] = n[2] * t[0][0] - n[0] * t[0][2];
    t[1][2] = n[0] * t[0][1] - n[1] * t[0][0];
  }
}

/* Friction at a slave point held by a Dirichlet condition in exactly one component k (a symmetry
   plane or a roller) acts only across that direction: when e_k lies mostly in the tangent plane,
   its tangential part is removed from the basis t (3D: one direction left, n x e_k; 2D: none; the
   removed one is a zero vector). The relative motion along e_k is zero on a symmetry plane and the
   traction along it is the reaction's; kept, it would give the stick constraint a component along
   the normal wherever the facet normal tilts out of the plane (a discretised curved surface), and
   the tangential shift would then hold the normal gap open against the normal shift. */
static void DropHeldDirection(PetscInt dim, const PetscInt sdof[], const PetscReal n[], PetscReal t[2][3])
{
  PetscInt  k = -1, nheld = 0;
  PetscReal v[3] = {0, 0, 0}, len;

  for (PetscInt d = 0; d < dim; ++d)
    if (sdof[d] < 0) k = d, nheld++;
  if (nheld != 1) return;
  for (PetscInt d = 0; d < dim; ++d) v[d] = (d == k ? 1.0 : 0.0) - n[k] * n[d];
  len = SPNorm(dim, v);
  if (len <= 0.5) return; /* e_k mostly normal: the held component is not a tangential one */
  for (PetscInt d = 0; d < dim; ++d) v[d] /= len;
  for (PetscInt a = 0; a < dim - 1; ++a) { /* project v out, then Gram-Schmidt; a dependent vector becomes 0 */
    PetscReal tv = SPDot(dim, t[a], v), l;
    for (PetscInt d = 0; d < dim; ++d) t[a][d] -= tv * v[d];
    for (PetscInt b = 0; b < a; ++b) {
      const PetscReal tb = SPDot(dim, t[a], t[b]);
      for (PetscInt d = 0; d < dim; ++d) t[a][d] -= tb * t[b][d];
    }
    l = SPNorm(dim, t[a]);
    for (PetscInt d = 0; d < dim; ++d) t[a][d] = l > 1e-6 ? t[a][d] / l : 0.0;
  }
}

/* Whether X at load factor `load` is the state of the last evaluation: same load factor and the
   same values (the line search evaluates its work vector W and then copies it into the solution,
   so the vector's identity says little; comparing the owned values costs one pass). Collective. */
static PetscErrorCode SameState(SPContact c, Vec X, PetscReal load, PetscBool *same)
{
  PetscBool mine = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (c->evalX && load == c->evalLoad) {
    const PetscScalar *a, *b;
    PetscInt           n;
    PetscCall(VecGetLocalSize(X, &n));
    PetscCall(VecGetArrayRead(X, &a));
    PetscCall(VecGetArrayRead(c->evalX, &b));
    PetscCall(PetscMemcmp(a, b, (size_t)n * sizeof(PetscScalar), &mine));
    PetscCall(VecRestoreArrayRead(X, &a));
    PetscCall(VecRestoreArrayRead(c->evalX, &b));
  }
  PetscCallMPI(MPI_Allreduce(&mine, same, 1, MPIU_BOOL, MPI_LAND, PetscObjectComm((PetscObject)c->dm)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Geometry of every point at the global displacement X: deformed position, contact element
   (closest master facet of its pairs, or the most penetrating obstacle, whichever gives the
   smaller gap), gap, normal, tangent basis. Collective. */
PetscErrorCode SPContactEvaluate(SPContact c, Vec X)
{
  const PetscScalar *u;
  PetscReal          load;
  PetscBool          same;
  Vec                locX;

  PetscFunctionBeginUser;
  PetscCall(SPProblemGetLoadFactor(c->problem, &load));
  PetscCall(SameState(c, X, load, &same));
  if (same) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(c->searchEvent, 0, 0, 0, 0));
  if (!c->evalX) PetscCall(VecDuplicate(X, &c->evalX));
  PetscCall(VecCopy(X, c->evalX));
  c->evalLoad = load;
  c->evaluations++;
  PetscCall(SPProblemGetLocalState(c->problem, X, &locX));
  PetscCall(VecGetArrayRead(locX, &u));
  PetscCall(SPContactSearch(c, u, load));
  PetscCall(SPContactWarnPinned(c));
  PetscCall(VecRestoreArrayRead(locX, &u));
  PetscCall(SPProblemRestoreLocalState(c->problem, &locX));
  for (PetscInt i = 0; i < c->n; ++i) {
    TangentBasis(c->dim, c->pt[i].geo.normal, c->pt[i].geo.tangent);
    if (c->friction) DropHeldDirection(c->dim, c->pt[i].sdof, c->pt[i].geo.normal, c->pt[i].geo.tangent);
    SPFrictionKinematics(c, i);
  }
  if (c->evaluations == 1) {
    for (PetscInt i = 0; i < c->n; ++i) c->pt[i].gap0 = c->pt[i].geo.gap;
    PetscCall(SPContactWarnDeepPairs(c));
  }
  PetscCall(PetscLogEventEnd(c->searchEvent, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the tangent includes the second variation of the gap (obstacle curvature; for pairs the
   variation of the projection point and of the normal). With a penetration of the order of the
   element size (the start of a load step, or a load-controlled start) that part is strongly
   indefinite (about -A eps |g + s| / R against the bulk stiffness): CG stops and Newton wanders.
   Near a solution it gives quadratic convergence. auto: included once a Newton iteration of the
   current solve left the active set unchanged. */
PetscBool SPContactGeometricTangent(SPContact c)
{
  if (c->tangent == SP_TANGENT_FULL) return PETSC_TRUE;
  if (c->tangent == SP_TANGENT_FROZEN) return PETSC_FALSE;
  return c->setSettled;
}

/* The normal of point i's recovered force: its contact element's, or with none (a two-pass vertex
   that receives force only as a master) its own surface's into its body */
const PetscReal *SPContactPointNormal(SPContact c, PetscInt i)
{
  return c->pt[i].geo.elem != SP_ELEM_NONE ? c->pt[i].geo.normal : c->pt[i].nIn;
}

/* Contact element of point i at the last evaluated state: *nd dofs (global indices, constrained
   ones negative), effective area A, N = dg/du and (if Hg) d2g/du2. *nd = 0: no element. */
PetscErrorCode SPContactPointElement(SPContact c, PetscInt i, PetscInt *nd, PetscInt dofs[], PetscReal *A, PetscReal N[], PetscReal Hg[])
{
  const PetscInt         dim = c->dim;
  const SPContactPoint  *p   = &c->pt[i];
  PetscReal              g, n[3];

  PetscFunctionBeginUser;
  *nd = 0;
  *A  = p->area;
  if (p->geo.elem == SP_ELEM_NONE) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt d = 0; d < dim; ++d) dofs[d] = p->sdof[d];
  if (p->geo.elem == SP_ELEM_OBSTACLE) {
    PetscReal H[9];
    SPObstacleGap(&c->ob[p->geo.obstacle], dim, c->evalLoad, p->geo.x, &g, N, Hg ? Hg : H);
    *nd = dim;
  } else {
    const SPMasterFacet *f = &c->mf[p->geo.elem];
    for (PetscInt k = 0; k < f->nv * dim; ++k) dofs[dim + k] = f->dof[k];
    SPPairGap(dim, f->nv, f->x, p->geo.x, p->geo.xi, &g, n, N, Hg);
    *nd = dim * (1 + f->nv);
    if (c->twoPass) *A *= 0.5; /* two-pass: each pass carries half of the point's area */
  }
  if (Hg && !SPContactGeometricTangent(c))
    for (PetscInt k = 0; k < *nd * *nd; ++k) Hg[k] = 0.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Warm start across load steps is automatic (the state persists); these support the cut-back. */
PetscErrorCode SPContactSaveState(SPContact c)
{
  PetscFunctionBeginUser;
  if (!c->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) c->saved[i] = c->pt[i].st, SPContactPairsForgetFacets(&c->pt[i]);
  PetscCall(SPShiftAccelReset(c->accel)); /* a new load step: a new map */
  PetscCall(SPShiftAccelReset(c->accelT));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactRestoreState(SPContact c)
{
  PetscFunctionBeginUser;
  if (!c->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) {
    c->pt[i].st               = c->saved[i];
    c->pt[i].st.inactiveCount = 0;
    SPContactPairsForgetFacets(&c->pt[i]);
    c->nhist[i]               = 0;
  }
  PetscCall(SPShiftAccelReset(c->accel));
  PetscCall(SPShiftAccelReset(c->accelT));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Restart: every point's state as SP_POINT_NPACK reals (reference position, first gap, then the
   state record), one field list for both directions */
static void Reals(PetscBool pack, PetscReal v[], PetscInt n, PetscReal b[], PetscInt *k)
{
  for (PetscInt j = 0; j < n; ++j, ++*k) {
    if (pack) b[*k] = v[j];
    else v[j] = b[*k];
  }
}

/* anchor: the friction anchor's name in the file (facets: SPContact.mfKey; obstacles: -(k + 1)) */
static PetscInt PointState(PetscBool pack, SPContactPoint *p, PetscReal *anchor, PetscReal b[])
{
  SPPointState *st = &p->st;
  PetscReal     pv = (PetscReal)p->prev.status;
  PetscReal     e[6] = {(PetscReal)st->status, (PetscReal)st->active, (PetscReal)st->inactiveCount, (PetscReal)st->flips, (PetscReal)st->reversed, st->anchored ? (st->fresh ? 2.0 : 1.0) + (st->basisStale ? 4.0 : 0.0) : 0.0}; /* anchored, 2: fresh; + 4: the committed basis is refreshed at the next solve's start (files before it: 0-2) */
  PetscReal     X[3] = {p->X[0], p->X[1], p->X[2]};
  PetscInt      k = 0;

  Reals(pack, X, 3, b, &k);
  Reals(pack, &p->gap0, 1, b, &k);
  Reals(pack, &st->sN, 1, b, &k);
  Reals(pack, st->sT, 2, b, &k);
  Reals(pack, st->slip, 3, b, &k);
  Reals(pack, st->creep, 3, b, &k);
  Reals(pack, st->tCommit, 3, b, &k);
  Reals(pack, e, 6, b, &k);
  Reals(pack, st->dir, 2, b, &k);
  Reals(pack, anchor, 1, b, &k);
  Reals(pack, st->anchorXi, 2, b, &k);
  Reals(pack, st->us, 3, b, &k);
  Reals(pack, st->um, 3, b, &k);
  Reals(pack, st->n, 3, b, &k);
  Reals(pack, st->T[0], 3, b, &k);
  Reals(pack, st->T[1], 3, b, &k);
  Reals(pack, st->tT, 2, b, &k);
  Reals(pack, &pv, 1, b, &k);
  Reals(pack, p->prev.tCommit, 3, b, &k);
  if (!pack) {
    p->prev.status    = (SPPointStatus)pv;
    st->status        = (SPPointStatus)e[0];
    st->active        = e[1] != 0.0 ? PETSC_TRUE : PETSC_FALSE;
    st->inactiveCount = (PetscInt)e[2];
    st->flips         = (PetscInt)e[3];
    st->reversed      = e[4] != 0.0 ? PETSC_TRUE : PETSC_FALSE;
    st->basisStale    = e[5] >= 4.0 ? PETSC_TRUE : PETSC_FALSE;
    if (st->basisStale) e[5] -= 4.0;
    st->anchored      = e[5] != 0.0 ? PETSC_TRUE : PETSC_FALSE;
    st->fresh         = e[5] == 2.0 ? PETSC_TRUE : PETSC_FALSE;
  }
  return k;
}

PetscErrorCode SPContactPackPoints(SPContact c, PetscReal buf[])
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscInt g      = c->pt[i].st.anchor;
    PetscReal      anchor = (PetscReal)(g >= 0 && g < c->nmfAll && c->mfKey ? c->mfKey[g] : g);
    PetscCheck(PointState(PETSC_TRUE, &c->pt[i], &anchor, &buf[i * SP_POINT_NPACK]) == SP_POINT_NPACK, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SP_POINT_NPACK does not match the packed fields");
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The master facet gid of a file's anchor name (-1: none has it) */
static PetscInt AnchorGid(SPContact c, PetscInt key)
{
  for (PetscInt g = 0; c->mfKey && g < c->nmfAll; ++g)
    if (c->mfKey[g] == key) return g;
  return -1;
}

/* *same: every point's reference position is the packed one, and every anchor facet exists (same
   mesh; the points come in this run's order, whatever the partition that wrote them) */
PetscErrorCode SPContactUnpackPoints(SPContact c, const PetscReal buf[], PetscBool *same)
{
  PetscFunctionBeginUser;
  *same = PETSC_TRUE;
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscReal b[SP_POINT_NPACK], X[3] = {c->pt[i].X[0], c->pt[i].X[1], c->pt[i].X[2]}, anchor;
    for (PetscInt k = 0; k < SP_POINT_NPACK; ++k) b[k] = buf[i * SP_POINT_NPACK + k];
    for (PetscInt d = 0; d < c->dim; ++d)
      if (PetscAbsReal(b[d] - X[d]) > 1e-12 * (1.0 + PetscAbsReal(X[d]))) *same = PETSC_FALSE;
    (void)PointState(PETSC_FALSE, &c->pt[i], &anchor, b);
    c->pt[i].st.anchor = anchor < 0.0 ? (PetscInt)anchor : AnchorGid(c, (PetscInt)anchor);
    if (anchor >= 0.0 && c->pt[i].st.anchor < 0) { /* no such facet here */
      if (c->pt[i].st.anchored) *same = PETSC_FALSE;
      c->pt[i].st.anchor = 0;
    }
    for (PetscInt d = 0; d < 3; ++d) c->pt[i].X[d] = X[d]; /* keep this run's positions */
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
