/* Contact search: for each contact point, the deformed position x = X + u and its contact element:
   the closest master facet of its pairs (contact-pairs.c) or the most penetrating rigid obstacle,
   whichever gives the smaller gap; the element's gap, normal, dg/du and d2g/du2. */
#include <spcontact-impl.h>

/* Displacement dofs of contact point i in the local vector */
PetscErrorCode SPContactPointDofs(SPContact c, PetscInt i, PetscInt dofs[])
{
  PetscSection ls;
  PetscInt     off;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(c->dm, &ls));
  PetscCall(PetscSectionGetOffset(ls, c->vertex[i], &off));
  for (PetscInt d = 0; d < c->dim; ++d) dofs[d] = off + d;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The most penetrating obstacle at x: gap, normal, curvature term */
static void ObstacleGap(SPContact c, PetscReal load, const PetscReal x[], PetscReal *g, PetscReal n[], PetscReal Hg[])
{
  *g = PETSC_MAX_REAL;
  for (PetscInt k = 0; k < c->nob; ++k) {
    PetscReal gk, nk[3], Hk[9];
    SPObstacleGap(&c->ob[k], c->dim, load, x, &gk, nk, Hk);
    if (gk < *g) {
      *g = gk;
      for (PetscInt d = 0; d < c->dim; ++d) n[d] = nk[d];
      for (PetscInt d = 0; d < c->dim * c->dim; ++d) Hg[d] = Hk[d];
    }
  }
}

/* Gaps, normals and contact elements of every point at the local displacement locX.
   Collective when there are contact pairs (the master geometry is exchanged). */
PetscErrorCode SPContactEvaluate(SPContact c, Vec locX)
{
  const PetscScalar *u;
  PetscReal          load, Hg[9];

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(c->searchEvent, 0, 0, 0, 0));
  PetscCall(SPProblemGetLoadFactor(c->problem, &load));
  PetscCall(VecGetArrayRead(locX, &u));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt dofs[3];
    PetscCall(SPContactPointDofs(c, i, dofs));
    for (PetscInt d = 0; d < c->dim; ++d) c->xs[i * c->dim + d] = c->coord[i * c->dim + d] + PetscRealPart(u[dofs[d]]);
  }
  if (c->npair) PetscCall(SPContactPairsExchange(c, u));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscReal *x = &c->xs[i * c->dim], *n = &c->normal[i * c->dim];
    for (PetscInt d = 0; d < c->dim; ++d) n[d] = 0.0;
    c->gap[i]   = PETSC_MAX_REAL;
    c->facet[i] = SP_ELEM_NONE;
    if (c->pairMask[i]) PetscCall(SPContactPairsProject(c, i, &c->facet[i], &c->xi[2 * i], &c->gap[i], n));
    if (c->onObstacle[i]) {
      PetscReal g, no[3];
      ObstacleGap(c, load, x, &g, no, Hg);
      if (g < c->gap[i]) {
        c->gap[i]   = g;
        c->facet[i] = SP_ELEM_OBSTACLE;
        for (PetscInt d = 0; d < c->dim; ++d) n[d] = no[d];
      }
    }
  }
  PetscCall(VecRestoreArrayRead(locX, &u));
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

/* Contact element of point i at the last evaluated state: *nd dofs (global indices, constrained
   ones negative), effective area A, gap g, N = dg/du and Hg = d2g/du2. *nd = 0: no element. */
PetscErrorCode SPContactPointElement(SPContact c, PetscInt i, PetscInt *nd, PetscInt dofs[], PetscReal *A, PetscReal *g, PetscReal N[], PetscReal Hg[])
{
  const PetscInt   dim = c->dim;
  const PetscReal *x   = &c->xs[i * dim];

  PetscFunctionBeginUser;
  *nd = 0;
  *g  = c->gap[i];
  *A  = c->area[i];
  if (c->facet[i] == SP_ELEM_NONE) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt d = 0; d < dim; ++d) dofs[d] = c->sdof[i * dim + d];
  if (c->facet[i] == SP_ELEM_OBSTACLE) {
    PetscReal load, H[9];
    PetscCall(SPProblemGetLoadFactor(c->problem, &load));
    ObstacleGap(c, load, x, g, N, Hg ? Hg : H);
    if (Hg && !SPContactGeometricTangent(c))
      for (PetscInt k = 0; k < dim * dim; ++k) Hg[k] = 0.0;
    *nd = dim;
  } else {
    const SPMasterFacet *f = &c->mf[c->facet[i]];
    const PetscInt       ne = dim * (1 + f->nv);
    PetscReal            n[3];
    SPPairGap(dim, f->nv, f->x, x, &c->xi[2 * i], g, n, N, Hg);
    if (Hg && !SPContactGeometricTangent(c))
      for (PetscInt k = 0; k < ne * ne; ++k) Hg[k] = 0.0;
    for (PetscInt k = 0; k < f->nv * dim; ++k) dofs[dim + k] = f->dof[k];
    *nd = ne;
    if (c->twoPass) *A *= 0.5; /* two-pass: each pass carries half of the point's area */
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
