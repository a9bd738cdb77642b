/* The linear bulk stiffness K kept inside the Jacobian, J = K + C, without a second full matrix.
   Contact changes only the rows of the dofs it can touch (slave vertices, master facet vertices:
   SPContactMarkRows). Their K values are kept exactly in the small matrix Ks (same layout as J,
   only those rows), and the contact part of the last assembly in C (the same rows and pattern).
   Then K X is J X with the contact rows taken from Ks X (exactly K X, whatever contact part J
   holds: the residual does not depend on the history), and a new Jacobian restores those rows
   of J from Ks and adds the new C. Both small matrices take J's row pattern, so no assembly ever
   mallocs. */
#include <spcontact-impl.h>

struct _n_SPStiffness {
  Mat Ks, C;     /* K on the contact rows; the contact part of J */
  Vec w, z, mark; /* J X, Ks X; 1 on the contact rows */
};

/* A matrix with J's layout holding J's marked rows (values copied, or zeros with the pattern) */
static PetscErrorCode RowsMatrix(Mat J, Vec mark, PetscBool copy, Mat *A)
{
  PetscInt           m, n, rstart, rend, cstart, cend, *dnz, *onz;
  const PetscScalar *mk;

  PetscFunctionBeginUser;
  PetscCall(MatGetLocalSize(J, &m, &n));
  PetscCall(MatGetOwnershipRange(J, &rstart, &rend));
  PetscCall(MatGetOwnershipRangeColumn(J, &cstart, &cend));
  PetscCall(PetscCalloc2(m, &dnz, m, &onz));
  PetscCall(VecGetArrayRead(mark, &mk));
  for (PetscInt r = rstart; r < rend; ++r) {
    PetscInt        nc;
    const PetscInt *cols;
    if (mk[r - rstart] == 0.0) continue;
    PetscCall(MatGetRow(J, r, &nc, &cols, NULL));
    for (PetscInt k = 0; k < nc; ++k) (cols[k] >= cstart && cols[k] < cend) ? dnz[r - rstart]++ : onz[r - rstart]++;
    PetscCall(MatRestoreRow(J, r, &nc, &cols, NULL));
  }
  PetscCall(MatCreate(PetscObjectComm((PetscObject)J), A));
  PetscCall(MatSetSizes(*A, m, n, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetType(*A, MATAIJ));
  PetscCall(MatXAIJSetPreallocation(*A, 1, dnz, onz, NULL, NULL));
  PetscCall(MatSetOption(*A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  for (PetscInt r = rstart; r < rend; ++r) {
    PetscInt           nc;
    const PetscInt    *cols;
    const PetscScalar *vals;
    if (mk[r - rstart] == 0.0) continue;
    PetscCall(MatGetRow(J, r, &nc, &cols, &vals));
    if (!copy) {
      PetscScalar *z;
      PetscCall(PetscCalloc1(nc, &z));
      PetscCall(MatSetValues(*A, 1, &r, nc, cols, z, INSERT_VALUES));
      PetscCall(PetscFree(z));
    } else PetscCall(MatSetValues(*A, 1, &r, nc, cols, vals, INSERT_VALUES));
    PetscCall(MatRestoreRow(J, r, &nc, &cols, &vals));
  }
  PetscCall(VecRestoreArrayRead(mark, &mk));
  PetscCall(PetscFree2(dnz, onz));
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* J holds K (and nothing of contact): take its contact rows. Called again after the contact
   pattern of J grew (J then holds K again). */
PetscErrorCode SPStiffnessSetUp(SPStiffness *st, Mat J, SPContact contact)
{
  SPStiffness t;

  PetscFunctionBeginUser;
  if (*st) PetscCall(SPStiffnessDestroy(st));
  PetscCall(PetscNew(&t));
  PetscCall(MatCreateVecs(J, &t->mark, &t->w));
  PetscCall(VecDuplicate(t->w, &t->z));
  PetscCall(VecZeroEntries(t->mark));
  PetscCall(VecSetOption(t->mark, VEC_IGNORE_NEGATIVE_INDICES, PETSC_TRUE)); /* constrained dofs */
  PetscCall(SPContactMarkRows(contact, t->mark));
  PetscCall(RowsMatrix(J, t->mark, PETSC_TRUE, &t->Ks));
  PetscCall(RowsMatrix(J, t->mark, PETSC_FALSE, &t->C));
  *st = t;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* F += K X: J X, its contact rows replaced by Ks X */
PetscErrorCode SPStiffnessMultAdd(SPStiffness st, Mat J, Vec X, Vec F)
{
  PetscInt           n;
  PetscScalar       *w;
  const PetscScalar *z, *mk;

  PetscFunctionBeginUser;
  PetscCall(MatMult(J, X, st->w));
  PetscCall(MatMult(st->Ks, X, st->z));
  PetscCall(VecGetLocalSize(st->w, &n));
  PetscCall(VecGetArray(st->w, &w));
  PetscCall(VecGetArrayRead(st->z, &z));
  PetscCall(VecGetArrayRead(st->mark, &mk));
  for (PetscInt i = 0; i < n; ++i)
    if (mk[i] != 0.0) w[i] = z[i];
  PetscCall(VecRestoreArrayRead(st->mark, &mk));
  PetscCall(VecRestoreArrayRead(st->z, &z));
  PetscCall(VecRestoreArray(st->w, &w));
  PetscCall(VecAXPY(F, 1.0, st->w));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* J = K + the contact Jacobian at X (none if contact is NULL) */
PetscErrorCode SPStiffnessAssemble(SPStiffness st, Mat J, SPContact contact, Vec X)
{
  PetscInt rstart, rend;

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(st->Ks, &rstart, &rend));
  for (PetscInt r = rstart; r < rend; ++r) {
    PetscInt           nc;
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscCall(MatGetRow(st->Ks, r, &nc, &cols, &vals));
    if (nc) PetscCall(MatSetValues(J, 1, &r, nc, cols, vals, INSERT_VALUES));
    PetscCall(MatRestoreRow(st->Ks, r, &nc, &cols, &vals));
  }
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatZeroEntries(st->C));
  if (!contact) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPContactAddJacobian(contact, X, st->C));
  PetscCall(MatAXPY(J, 1.0, st->C, SUBSET_NONZERO_PATTERN));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPStiffnessDestroy(SPStiffness *st)
{
  PetscFunctionBeginUser;
  if (!*st) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MatDestroy(&(*st)->Ks));
  PetscCall(MatDestroy(&(*st)->C));
  PetscCall(VecDestroy(&(*st)->w));
  PetscCall(VecDestroy(&(*st)->z));
  PetscCall(VecDestroy(&(*st)->mark));
  PetscCall(PetscFree(*st));
  PetscFunctionReturn(PETSC_SUCCESS);
}
