/* The Neo-Hookean law's admissible states: det F > 0 at every cell's vertices. Where J <= 0 the
   stress is NaN and the Newton solve stops (kernels/neohookean.h), but only the quadrature points
   see it: a Q1 cell can be inside out at a corner with J > 0 at every Gauss point, and its solve
   converges (QA: block3d 4^3, q = 1.2, friction 0.3 wrote two such steps). So a converged state is
   checked once more, at the reference vertices xi_v: with x = X + u,
   J = det(dx/dxi) / det(dX/dxi), dx/dxi = dX/dxi + du/dxi; for Q1 the columns of dx/dxi at a
   corner are the cell's deformed edges from it, so J = det[deformed edges] / det[reference edges].
   du/dxi comes from the displacement FE tabulated at the reference vertices (any degree; Q2/P2
   are checked at the vertices only), dX/dxi from the coordinate field tabulated there
   (SPMeshCoordinateTabulation; PETSc per cell when the coordinates are no PetscFE, as from gmsh).
   The tabulations are made once. P1's J is constant per cell and the quadrature saw it already;
   it is checked all the same (one code path for every cell type, 2D and 3D). */
#include <spcontact-impl.h>
#include <kernels/tensor.h>

struct _n_SPCornerCheck {
  DM              dm; /* not owned */
  PetscInt        dim, nv;
  PetscQuadrature q;      /* the reference cell's nv vertices (unit weights) */
  PetscTabulation Tu, Tx; /* displacement FE and coordinate field at q (Tx NULL: PETSc per cell) */
};

/* The reference vertices of cell type ct as a quadrature (coordinates of PETSc's reference cell) */
static PetscErrorCode VertexPoints(PetscInt dim, DMPolytopeType ct, PetscQuadrature *q)
{
  DM                 ref;
  Vec                coords;
  const PetscScalar *a;
  PetscReal         *x, *w;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateReferenceCell(PETSC_COMM_SELF, ct, &ref));
  PetscCall(DMGetCoordinatesLocal(ref, &coords));
  PetscCall(VecGetLocalSize(coords, &n));
  PetscCall(PetscMalloc1(n, &x));
  PetscCall(PetscMalloc1(n / dim, &w));
  PetscCall(VecGetArrayRead(coords, &a));
  for (PetscInt i = 0; i < n; ++i) x[i] = PetscRealPart(a[i]);
  for (PetscInt i = 0; i < n / dim; ++i) w[i] = 1.0;
  PetscCall(VecRestoreArrayRead(coords, &a));
  PetscCall(DMDestroy(&ref));
  PetscCall(PetscQuadratureCreate(PETSC_COMM_SELF, q));
  PetscCall(PetscQuadratureSetData(*q, dim, 1, n / dim, x, w));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective (the coordinates' set-up); fe: the displacement's */
PetscErrorCode SPCornerCheckCreate(DM dm, PetscFE fe, SPCornerCheck *check)
{
  SPCornerCheck   k;
  PetscInt        cStart, cEnd;
  DMPolytopeType  ct;
  const PetscReal *pts;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&k));
  k->dm = dm;
  PetscCall(DMGetDimension(dm, &k->dim));
  PetscCall(DMGetCoordinatesLocalSetUp(dm));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  if (cEnd > cStart) { /* one cell type (one FE serves every cell) */
    PetscCall(DMPlexGetCellType(dm, cStart, &ct));
    PetscCall(VertexPoints(k->dim, ct, &k->q));
    PetscCall(PetscQuadratureGetData(k->q, NULL, NULL, &k->nv, &pts, NULL));
    PetscCall(PetscFECreateTabulation(fe, 1, k->nv, pts, 1, &k->Tu));
    PetscCall(SPMeshCoordinateTabulation(dm, k->q, &k->Tx));
  }
  *check = k;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The smallest corner J of cell c from its closure displacements u[] and reference Jacobians Jx[] */
static PetscReal CellCornerJ(SPCornerCheck k, const PetscScalar u[], const PetscReal Jx[], const PetscReal detX[])
{
  const PetscInt dim = k->dim, nb = k->Tu->Nb, nc = k->Tu->Nc;
  PetscReal      jmin = PETSC_MAX_REAL;

  for (PetscInt p = 0; p < k->nv; ++p) {
    PetscReal A[9];
    for (PetscInt i = 0; i < dim; ++i)
      for (PetscInt d = 0; d < dim; ++d) {
        PetscReal v = Jx[(p * dim + i) * dim + d];
        for (PetscInt b = 0; b < nb; ++b) v += PetscRealPart(u[b]) * k->Tu->T[1][((p * nb + b) * nc + i) * dim + d];
        A[i * dim + d] = v;
      }
    jmin = PetscMin(jmin, SPDeterminant(dim, A) / detX[p]);
  }
  return jmin;
}

/* Over every cell of every rank: the smallest det F at a vertex and the cells with one <= 0 (NaN
   counts). locX: the local state, Dirichlet values included (SPProblemGetLocalState). Collective. */
PetscErrorCode SPCornerCheckEvaluate(SPCornerCheck k, Vec locX, PetscReal *minJ, PetscInt *inverted)
{
  Vec       coords;
  PetscInt  cStart, cEnd;
  PetscReal Jx[9 * 8], detX[8];

  PetscFunctionBeginUser;
  *minJ = PETSC_MAX_REAL, *inverted = 0;
  PetscCall(DMGetCoordinatesLocal(k->dm, &coords));
  PetscCall(DMPlexGetHeightStratum(k->dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscScalar *u = NULL;
    PetscInt     n;
    PetscReal    j;
    PetscCall(SPMeshCellJacobians(k->dm, coords, k->Tx, k->q, c, Jx, detX));
    PetscCall(DMPlexVecGetClosure(k->dm, NULL, locX, c, &n, &u));
    PetscCheck(n == k->Tu->Nb, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cell %" PetscInt_FMT ": %" PetscInt_FMT " closure dofs for %" PetscInt_FMT " basis functions", c, n, k->Tu->Nb);
    j = CellCornerJ(k, u, Jx, detX);
    PetscCall(DMPlexVecRestoreClosure(k->dm, NULL, locX, c, &n, &u));
    if (!(j > 0.0)) ++*inverted;
    *minJ = PetscMin(*minJ, j); /* a NaN leaves it, the count has it */
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, minJ, 1, MPIU_REAL, MPIU_MIN, PetscObjectComm((PetscObject)k->dm)));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, inverted, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)k->dm)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPCornerCheckDestroy(SPCornerCheck *check)
{
  PetscFunctionBeginUser;
  if (!*check) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscTabulationDestroy(&(*check)->Tu));
  PetscCall(PetscTabulationDestroy(&(*check)->Tx));
  PetscCall(PetscQuadratureDestroy(&(*check)->q));
  PetscCall(PetscFree(*check));
  PetscFunctionReturn(PETSC_SUCCESS);
}
