/* Small dense helpers for pointwise kernels. No PETSc calls beyond scalar types. */
#ifndef SP_KERNELS_TENSOR_H
#define SP_KERNELS_TENSOR_H
#include <petscsys.h>

static inline PetscReal SPDot(PetscInt dim, const PetscReal a[], const PetscReal b[])
{
  PetscReal s = 0.0;
  for (PetscInt d = 0; d < dim; ++d) s += a[d] * b[d];
  return s;
}

static inline PetscReal SPNorm(PetscInt dim, const PetscReal a[])
{
  return PetscSqrtReal(SPDot(dim, a, a));
}

/* det A of a dim x dim matrix (dim 1 to 3), row-major */
static inline PetscReal SPDeterminant(PetscInt dim, const PetscReal A[])
{
  if (dim == 1) return A[0];
  if (dim == 2) return A[0] * A[3] - A[1] * A[2];
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) + A[2] * (A[3] * A[7] - A[4] * A[6]);
}
#endif
