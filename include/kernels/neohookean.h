/* Pointwise compressible Neo-Hookean law, total Lagrangian, one path for 2D (plane strain) and 3D.

   W(F) = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,  I1 = tr(F^T F), J = det F,
   with F = I + grad u (2D: F_33 = 1, so I1 - 3 = tr(C_2D) - 2).

   Why this form: it is stress-free at F = I and its linearisation there is small-strain elasticity
   with the same (lambda, mu), so a Neo-Hookean run at a small load reproduces the linear one and
   the material data (E, nu) keep their meaning; W -> infinity as J -> 0 (the (ln J)^2 term), and
   it is the form FEBio, Ratel and most finite-strain texts call "compressible Neo-Hookean".

   First Piola-Kirchhoff stress (f1 of the weak form, P[i * dim + J] = dW/dF_iJ):
     P = mu (F - F^-T) + lambda ln J F^-T
   Tangent A_iJkL = dP_iJ / dF_kL:
     A = mu d_ik d_JL + (mu - lambda ln J) Fi_Li Fi_Jk + lambda Fi_Ji Fi_Lk,  Fi = F^-1
   A cell turned inside out (J <= 0) has no energy: the stress is NaN, so SNES stops with
   DIVERGED_FNORM_NAN and the load step is cut back; no NaN reaches a written step. The quadrature
   points miss a Q1 cell inverted at a corner only, so a converged state is also checked at the
   cells' vertices (materials/neo_hookean-check.c) and cut back if J <= 0 there. */
#ifndef SP_KERNELS_NEOHOOKEAN_H
#define SP_KERNELS_NEOHOOKEAN_H
#include <kernels/elastic.h>

/* F = I + u_x, its determinant and inverse; returns J */
static inline PetscReal SPDeformation(PetscInt dim, const PetscScalar u_x[], PetscReal F[], PetscReal Fi[])
{
  PetscReal J;

  for (PetscInt i = 0; i < dim; ++i)
    for (PetscInt j = 0; j < dim; ++j) F[i * dim + j] = PetscRealPart(u_x[i * dim + j]) + (i == j ? 1.0 : 0.0);
  if (dim == 2) {
    J     = F[0] * F[3] - F[1] * F[2];
    Fi[0] = F[3] / J, Fi[1] = -F[1] / J, Fi[2] = -F[2] / J, Fi[3] = F[0] / J;
    return J;
  }
  Fi[0] = F[4] * F[8] - F[5] * F[7], Fi[1] = F[2] * F[7] - F[1] * F[8], Fi[2] = F[1] * F[5] - F[2] * F[4];
  Fi[3] = F[5] * F[6] - F[3] * F[8], Fi[4] = F[0] * F[8] - F[2] * F[6], Fi[5] = F[2] * F[3] - F[0] * F[5];
  Fi[6] = F[3] * F[7] - F[4] * F[6], Fi[7] = F[1] * F[6] - F[0] * F[7], Fi[8] = F[0] * F[4] - F[1] * F[3];
  J = F[0] * Fi[0] + F[1] * Fi[3] + F[2] * Fi[6];
  for (PetscInt i = 0; i < 9; ++i) Fi[i] /= J;
  return J;
}

static inline void SPNeoHookeanStress(PetscInt dim, PetscReal lambda, PetscReal mu, const PetscScalar u_x[], PetscScalar P[])
{
  PetscReal F[9], Fi[9], J = SPDeformation(dim, u_x, F, Fi), lnJ;

  if (!(J > 0.0)) {
    for (PetscInt i = 0; i < dim * dim; ++i) P[i] = NAN;
    return;
  }
  lnJ = PetscLogReal(J);
  for (PetscInt i = 0; i < dim; ++i)
    for (PetscInt j = 0; j < dim; ++j) P[i * dim + j] = mu * F[i * dim + j] + (lambda * lnJ - mu) * Fi[j * dim + i];
}

/* g3[((i * dim + k) * dim + J) * dim + L] = A_iJkL (PETSc's layout: test comp, trial comp, test
   derivative, trial derivative) */
static inline void SPNeoHookeanTangent(PetscInt dim, PetscReal lambda, PetscReal mu, const PetscScalar u_x[], PetscScalar g3[])
{
  PetscReal F[9], Fi[9], J = SPDeformation(dim, u_x, F, Fi), lnJ = J > 0.0 ? PetscLogReal(J) : NAN;

  for (PetscInt i = 0; i < dim; ++i)
    for (PetscInt k = 0; k < dim; ++k)
      for (PetscInt a = 0; a < dim; ++a)
        for (PetscInt b = 0; b < dim; ++b)
          g3[((i * dim + k) * dim + a) * dim + b] = (i == k && a == b ? mu : 0.0) + (mu - lambda * lnJ) * Fi[b * dim + i] * Fi[a * dim + k] + lambda * Fi[a * dim + i] * Fi[b * dim + k];
}

static inline void SPNeoHookeanF1(SP_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f1[])
{
  SPNeoHookeanStress(dim, PetscRealPart(constants[SP_C_LAMBDA]), PetscRealPart(constants[SP_C_MU]), u_x, f1);
}

static inline void SPNeoHookeanG3(SP_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g3[])
{
  SPNeoHookeanTangent(dim, PetscRealPart(constants[SP_C_LAMBDA]), PetscRealPart(constants[SP_C_MU]), u_x, g3);
}

/* Manufactured solution (u = A phi(x) e of kernels/elastic.h): f0 = Div P(F(u)) =
   A_iJkL(F) u_k,JL balances the weak form, with u_k,J = A (k+1) phi_,J and u_k,JL = A (k+1) phi_,JL */
static inline PetscReal SPMMSPhiGradient(PetscInt dim, const PetscReal x[], PetscInt j)
{
  PetscReal v = PETSC_PI;
  for (PetscInt k = 0; k < dim; ++k) v *= k == j ? PetscCosReal(PETSC_PI * x[k]) : PetscSinReal(PETSC_PI * x[k]);
  return v;
}

static inline void SPNeoHookeanF0MMS(SP_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  const PetscReal amp = PetscRealPart(constants[SP_C_MMS]);
  PetscScalar     ux[9], A[81];

  for (PetscInt c = 0; c < dim; ++c)
    for (PetscInt d = 0; d < dim; ++d) ux[c * dim + d] = amp * (c + 1) * SPMMSPhiGradient(dim, x, d);
  SPNeoHookeanTangent(dim, PetscRealPart(constants[SP_C_LAMBDA]), PetscRealPart(constants[SP_C_MU]), ux, A);
  for (PetscInt i = 0; i < dim; ++i) {
    f0[i] = 0.0;
    for (PetscInt k = 0; k < dim; ++k)
      for (PetscInt a = 0; a < dim; ++a)
        for (PetscInt b = 0; b < dim; ++b) f0[i] += A[((i * dim + k) * dim + a) * dim + b] * amp * (k + 1) * SPMMSPhiHessian(dim, x, a, b);
  }
}

/* The same with per-cell parameters (region materials) from the auxiliary field */
static inline void SPNeoHookeanF1Aux(SP_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f1[])
{
  SPNeoHookeanStress(dim, PetscRealPart(a[aOff[0] + SP_A_LAMBDA]), PetscRealPart(a[aOff[0] + SP_A_MU]), u_x, f1);
}

static inline void SPNeoHookeanG3Aux(SP_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g3[])
{
  SPNeoHookeanTangent(dim, PetscRealPart(a[aOff[0] + SP_A_LAMBDA]), PetscRealPart(a[aOff[0] + SP_A_MU]), u_x, g3);
}
#endif
