/* Follower pressure at finite strain (total Lagrangian): the pressure p acts on the deformed face,
   p n da = p J F^-T N dA = p cof(F) N dA, so the reference boundary term is f0 = p cof(F) N (the
   dead-load kernel SPNeumann has f0 = p N). Its linearisation (the load stiffness, not symmetric):
     d cof(F)_il / dF_jk = J (F^-1_kj F^-1_li - F^-1_ki F^-1_lj),
   g1[(i dim + j) dim + k] = p sum_l d cof_il / dF_jk N_l. 2D is plane strain (F_33 = 1): the
   same formulas with the 2x2 F. Slot k reads the Neumann constants of kernels/elastic.h. */
#ifndef SPCONTACT_KERNELS_FOLLOWER_H
#define SPCONTACT_KERNELS_FOLLOWER_H
#include <kernels/elastic.h>

/* F = I + grad u, its inverse and determinant (dim 2 or 3) */
static inline PetscReal SPFollowerInverse(PetscInt dim, const PetscScalar u_x[], PetscReal Fi[])
{
  PetscReal F[9], J;
  for (PetscInt i = 0; i < dim; ++i)
    for (PetscInt j = 0; j < dim; ++j) F[i * dim + j] = (i == j ? 1.0 : 0.0) + PetscRealPart(u_x[i * dim + j]);
  if (dim == 2) {
    J     = F[0] * F[3] - F[1] * F[2];
    Fi[0] = F[3] / J, Fi[1] = -F[1] / J, Fi[2] = -F[2] / J, Fi[3] = F[0] / J;
  } else {
    J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
    Fi[0] = (F[4] * F[8] - F[5] * F[7]) / J, Fi[1] = (F[2] * F[7] - F[1] * F[8]) / J, Fi[2] = (F[1] * F[5] - F[2] * F[4]) / J;
    Fi[3] = (F[5] * F[6] - F[3] * F[8]) / J, Fi[4] = (F[0] * F[8] - F[2] * F[6]) / J, Fi[5] = (F[2] * F[3] - F[0] * F[5]) / J;
    Fi[6] = (F[3] * F[7] - F[4] * F[6]) / J, Fi[7] = (F[1] * F[6] - F[0] * F[7]) / J, Fi[8] = (F[0] * F[4] - F[1] * F[3]) / J;
  }
  return J;
}

/* The pressure of slot k at x (value + gradient . x, scaled by the load curve) */
static inline PetscReal SPFollowerPressure(PetscInt k, PetscInt dim, const PetscReal x[], const PetscScalar constants[])
{
  const PetscScalar *c = &constants[SP_C_BC0 + SP_C_BCW * k];
  PetscReal          p = PetscRealPart(c[0]);
  for (PetscInt d = 0; d < dim; ++d) p += PetscRealPart(c[4 + d]) * x[d];
  return p;
}

/* f0 = p cof(F) N - t (the slot's traction part stays a dead load) */
static inline void SPFollowerTraction(PetscInt dim, PetscReal p, const PetscScalar t[], const PetscScalar u_x[], const PetscReal N[], PetscScalar f0[])
{
  PetscReal Fi[9];
  const PetscReal J = SPFollowerInverse(dim, u_x, Fi);
  for (PetscInt i = 0; i < dim; ++i) {
    PetscReal s = 0.0;
    for (PetscInt l = 0; l < dim; ++l) s += J * Fi[l * dim + i] * N[l];
    f0[i] = p * s - (t ? t[i] : 0.0);
  }
}

static inline void SPFollowerTangent(PetscInt dim, PetscReal p, const PetscScalar u_x[], const PetscReal N[], PetscScalar g1[])
{
  PetscReal Fi[9];
  const PetscReal J = SPFollowerInverse(dim, u_x, Fi);
  for (PetscInt i = 0; i < dim; ++i)
    for (PetscInt j = 0; j < dim; ++j)
      for (PetscInt k = 0; k < dim; ++k) {
        PetscReal s = 0.0;
        for (PetscInt l = 0; l < dim; ++l) s += (Fi[k * dim + j] * Fi[l * dim + i] - Fi[k * dim + i] * Fi[l * dim + j]) * N[l];
        g1[(i * dim + j) * dim + k] = p * J * s;
      }
}

#define SP_FOLLOWER_KERNELS(k) \
  static inline void SPFollowerF0_##k(SP_KERNEL_ARGS, const PetscReal x[], const PetscReal n[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[]) \
  { \
    SPFollowerTraction(dim, SPFollowerPressure(k, dim, x, constants), &constants[SP_C_BC0 + SP_C_BCW * k + 1], u_x, n, f0); \
  } \
  static inline void SPFollowerG1_##k(SP_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], const PetscReal n[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g1[]) \
  { \
    SPFollowerTangent(dim, SPFollowerPressure(k, dim, x, constants), u_x, n, g1); \
  }
SP_FOLLOWER_KERNELS(0)
SP_FOLLOWER_KERNELS(1)
SP_FOLLOWER_KERNELS(2)
SP_FOLLOWER_KERNELS(3)
SP_FOLLOWER_KERNELS(4)
SP_FOLLOWER_KERNELS(5)
SP_FOLLOWER_KERNELS(6)
SP_FOLLOWER_KERNELS(7)

typedef void (*SPBdJacobianKernel)(SP_KERNEL_ARGS, PetscReal, const PetscReal[], const PetscReal[], PetscInt, const PetscScalar[], PetscScalar[]);
static const SPBdKernel SPFollowerF0[8] = {SPFollowerF0_0, SPFollowerF0_1, SPFollowerF0_2, SPFollowerF0_3, SPFollowerF0_4, SPFollowerF0_5, SPFollowerF0_6, SPFollowerF0_7};
static const SPBdJacobianKernel SPFollowerG1[8] = {SPFollowerG1_0, SPFollowerG1_1, SPFollowerG1_2, SPFollowerG1_3, SPFollowerG1_4, SPFollowerG1_5, SPFollowerG1_6, SPFollowerG1_7};
#endif
