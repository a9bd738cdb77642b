/* Contact search against rigid obstacles: for each contact point, the deformed position x = X + u,
   the closest (most penetrating) obstacle, its signed gap, normal and curvature term. */
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

/* Gap g, normal n and d2g/du2 of point i at the local displacement array u */
static PetscErrorCode PointGap(SPContact c, PetscInt i, const PetscScalar u[], PetscReal load, PetscReal *g, PetscReal n[], PetscReal Hg[])
{
  PetscInt  dofs[3];
  PetscReal x[3] = {0, 0, 0};

  PetscFunctionBeginUser;
  PetscCall(SPContactPointDofs(c, i, dofs));
  for (PetscInt d = 0; d < c->dim; ++d) x[d] = c->coord[i * c->dim + d] + PetscRealPart(u[dofs[d]]);
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
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Gaps and normals of every point at the local displacement locX; Hg (n*dim*dim) if wanted */
PetscErrorCode SPContactEvaluate(SPContact c, Vec locX)
{
  const PetscScalar *u;
  PetscReal          load, Hg[9];

  PetscFunctionBeginUser;
  PetscCall(SPProblemGetLoadFactor(c->problem, &load));
  PetscCall(VecGetArrayRead(locX, &u));
  for (PetscInt i = 0; i < c->n; ++i) PetscCall(PointGap(c, i, u, load, &c->gap[i], &c->normal[i * c->dim], Hg));
  PetscCall(VecRestoreArrayRead(locX, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Residual (r, dim) and tangent (K, dim x dim) of point i at local displacement u with shift s */
PetscErrorCode SPContactPointLaw(SPContact c, PetscInt i, const PetscScalar u[], PetscReal s, PetscReal r[], PetscReal K[])
{
  PetscReal load, g, n[3], Hg[9];

  PetscFunctionBeginUser;
  PetscCall(SPProblemGetLoadFactor(c->problem, &load));
  PetscCall(PointGap(c, i, u, load, &g, n, Hg));
  SPContactLawPoint(c->dim, c->area[i], c->eps[i], g, s, n, Hg, r, K);
  PetscFunctionReturn(PETSC_SUCCESS);
}
