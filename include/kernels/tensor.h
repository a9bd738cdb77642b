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
#endif
