/* GAMG's graph of the system matrix without a copy of it.
   PETSc 3.18's MatCreateGraph for a point-block-size-1 AIJ matrix duplicates the matrix whenever it
   is asked for a symmetric graph, which GAMG always asks for, even when the matrix is known to be
   symmetric and neither filtered nor scaled: the copy is then the matrix itself, values and all
   (with a block size > 1 it collapses the blocks, a much smaller graph, and that stays).
   For the system matrix of a frictionless small-strain run (MAT_SYMMETRIC, eternal) that copy was
   one more matrix at the peak of the first PCSetUp. Here the graph is the matrix itself, shared
   by reference, in exactly that case (block size 1); every other case (friction, finite strain,
   -pc_gamg_threshold, which is 0 by default with contact pairs or friction (solver.c), HEM
   coarsening) takes PETSc's own path. GAMG reads the graph and destroys
   its reference; nothing in it writes the graph's values. The hook is Mat's creategraph
   operation, which 3.18 keeps in the private ops table and does not name in MatOperation. */
#include <spcontact-impl.h>
#include <petsc/private/matimpl.h>

typedef PetscErrorCode (*CreateGraphFn)(Mat, PetscBool, PetscBool, PetscReal, Mat *);

static PetscErrorCode CreateGraphShared(Mat A, PetscBool sym, PetscBool scale, PetscReal filter, Mat *graph)
{
  PetscBool     set, issym;
  PetscInt      bs;
  CreateGraphFn petscGraph = NULL;

  PetscFunctionBeginUser;
  PetscCall(MatIsSymmetricKnown(A, &set, &issym));
  PetscCall(MatGetBlockSize(A, &bs));
  if (set && issym && bs == 1 && !scale && filter < 0.0) {
    PetscCall(PetscInfo(A, "GAMG graph: the system matrix itself (symmetric, not filtered or scaled), no copy\n"));
    PetscCall(PetscObjectReference((PetscObject)A));
    *graph = A;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscObjectQueryFunction((PetscObject)A, "SPCreateGraphPETSc_C", &petscGraph));
  PetscCheck(petscGraph, PetscObjectComm((PetscObject)A), PETSC_ERR_PLIB, "the system matrix lost PETSc's graph operation");
  PetscCall(petscGraph(A, sym, scale, filter, graph));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Install the shared graph on J (an AIJ matrix whose type is set); other types keep theirs */
PetscErrorCode SPMatrixShareGraph(Mat J)
{
  PetscBool aij;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)J, MATSEQAIJ, &aij));
  if (!aij) PetscCall(PetscObjectBaseTypeCompare((PetscObject)J, MATMPIAIJ, &aij));
  if (!aij || !J->ops->creategraph || J->ops->creategraph == CreateGraphShared) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscObjectComposeFunction((PetscObject)J, "SPCreateGraphPETSc_C", J->ops->creategraph));
  J->ops->creategraph = CreateGraphShared;
  PetscFunctionReturn(PETSC_SUCCESS);
}
