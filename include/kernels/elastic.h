/* Pointwise small-strain isotropic linear elasticity (plane strain in 2D), one path for 2D/3D.
   Kernels read material and loads from constants[] through the SPConstant slots; with region
   materials the Lame constants come per cell from the auxiliary field (SP_A_* components). */
#ifndef SP_KERNELS_ELASTIC_H
#define SP_KERNELS_ELASTIC_H
#include <petscsys.h>

/* Named constants[] slots, shared by problem setup and kernels. */
enum {
  SP_C_LAMBDA = 0, /* Lame lambda */
  SP_C_MU,         /* shear modulus */
  SP_C_LOAD,       /* load factor (the Neumann slots hold loads already scaled by it) */
  SP_C_MMS,        /* amplitude of the manufactured solution (0: off) */
  SP_C_BC0,        /* Neumann slot k: [pressure, t_x, t_y, t_z, dp/dx, dp/dy, dp/dz] at SP_C_BC0 + SP_C_BCW k */
  SP_C_BCW = 7,    /* width of a Neumann slot */
  SP_C_NUM = SP_C_BC0 + SP_C_BCW * 8
};

/* Components of the auxiliary cell field (region materials): the law's per-cell parameters */
enum {
  SP_A_LAMBDA = 0, /* Lame lambda */
  SP_A_MU,         /* shear modulus */
  SP_A_NUM
};

#define SP_KERNEL_ARGS \
  PetscInt dim, PetscInt Nf, PetscInt NfAux, const PetscInt uOff[], const PetscInt uOff_x[], const PetscScalar u[], \
    const PetscScalar u_t[], const PetscScalar u_x[], const PetscInt aOff[], const PetscInt aOff_x[], const PetscScalar a[], \
    const PetscScalar a_t[], const PetscScalar a_x[], PetscReal t

/* sigma = lambda tr(eps) I + 2 mu eps; f1 = sigma (test-function gradient term) */
static inline void SPElasticStress(PetscInt dim, PetscReal lambda, PetscReal mu, const PetscScalar u_x[], PetscScalar s[])
{
  PetscScalar tr = 0.0;
  for (PetscInt d = 0; d < dim; ++d) tr += u_x[d * dim + d];
  for (PetscInt c = 0; c < dim; ++c)
    for (PetscInt d = 0; d < dim; ++d) s[c * dim + d] = mu * (u_x[c * dim + d] + u_x[d * dim + c]) + (c == d ? lambda * tr : 0.0);
}

static inline void SPElasticF1(SP_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f1[])
{
  SPElasticStress(dim, PetscRealPart(constants[SP_C_LAMBDA]), PetscRealPart(constants[SP_C_MU]), u_x, f1);
}

/* d sigma_cd / d u_e,f = mu (d_ce d_df + d_cf d_de) + lambda d_cd d_ef, stored in PETSc's layout
   g3[((c * Nc + e) * dim + d) * dim + f] (test comp, trial comp, test deriv, trial deriv) */
static inline void SPElasticG3Lame(PetscInt dim, PetscReal lambda, PetscReal mu, PetscScalar g3[])
{
  for (PetscInt c = 0; c < dim; ++c)
    for (PetscInt d = 0; d < dim; ++d)
      for (PetscInt e = 0; e < dim; ++e)
        for (PetscInt f = 0; f < dim; ++f)
          g3[((c * dim + e) * dim + d) * dim + f] = mu * ((c == e && d == f) + (c == f && d == e)) + lambda * (c == d && e == f);
}

static inline void SPElasticG3(SP_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g3[])
{
  SPElasticG3Lame(dim, PetscRealPart(constants[SP_C_LAMBDA]), PetscRealPart(constants[SP_C_MU]), g3);
}

/* The same with per-cell Lame constants (region materials) from the auxiliary field */
static inline void SPElasticF1Aux(SP_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f1[])
{
  SPElasticStress(dim, PetscRealPart(a[aOff[0] + SP_A_LAMBDA]), PetscRealPart(a[aOff[0] + SP_A_MU]), u_x, f1);
}

static inline void SPElasticG3Aux(SP_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g3[])
{
  SPElasticG3Lame(dim, PetscRealPart(a[aOff[0] + SP_A_LAMBDA]), PetscRealPart(a[aOff[0] + SP_A_MU]), g3);
}

/* Element stiffness of the same law for one cell, with the structure of B^T D B written out:
   K[(a,i),(b,j)] = sum_q wdetJ_q (lambda dNa_i dNb_j + mu dNa_j dNb_i + mu delta_ij dNa.dNb),
   dof (a,i) = a * dim + i (node-major, as the closure). G: physical gradients of the nb scalar
   basis functions at the nq points, G[(q * nb + a) * dim + i]. K is (nb dim)^2, row-major. */
static inline void SPElasticElementStiffness(PetscInt dim, PetscInt nb, PetscInt nq, const PetscReal G[], const PetscReal wdetJ[], PetscReal lambda, PetscReal mu, PetscScalar K[])
{
  const PetscInt n = nb * dim;
  for (PetscInt k = 0; k < n * n; ++k) K[k] = 0.0;
  for (PetscInt q = 0; q < nq; ++q) {
    const PetscReal *Gq = &G[q * nb * dim], l = lambda * wdetJ[q], m = mu * wdetJ[q];
    for (PetscInt a = 0; a < nb; ++a) {
      const PetscReal *Ga = &Gq[a * dim];
      for (PetscInt b = 0; b < nb; ++b) {
        const PetscReal *Gb  = &Gq[b * dim];
        PetscReal        dot = 0.0;
        for (PetscInt d = 0; d < dim; ++d) dot += Ga[d] * Gb[d];
        for (PetscInt i = 0; i < dim; ++i) {
          PetscScalar *Krow = &K[(a * dim + i) * n + b * dim];
          for (PetscInt j = 0; j < dim; ++j) Krow[j] += l * Ga[i] * Gb[j] + m * Ga[j] * Gb[i];
          Krow[i] += m * dot;
        }
      }
    }
  }
}

/* Manufactured solution u = A phi(x) e, phi = prod_d sin(pi x_d), e_c = c + 1. Zero on the unit box. */
static inline PetscReal SPMMSPhiHessian(PetscInt dim, const PetscReal x[], PetscInt i, PetscInt j)
{
  PetscReal v = PETSC_PI * PETSC_PI * (i == j ? -1.0 : 1.0);
  for (PetscInt k = 0; k < dim; ++k) v *= (k != i && k != j) || i == j ? PetscSinReal(PETSC_PI * x[k]) : PetscCosReal(PETSC_PI * x[k]);
  return v;
}

static inline PetscErrorCode SPMMSExact(PetscInt dim, PetscReal time, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *ctx)
{
  const PetscReal amp = *(const PetscReal *)ctx;
  PetscReal       phi = amp;
  for (PetscInt d = 0; d < dim; ++d) phi *= PetscSinReal(PETSC_PI * x[d]);
  for (PetscInt c = 0; c < Nc; ++c) u[c] = phi * (c + 1);
  return 0;
}

/* f0 = -b with b = (lambda + mu) grad div u + mu lap u, i.e. -div sigma(u) = -b is balanced */
static inline void SPElasticF0MMS(SP_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  const PetscReal lambda = PetscRealPart(constants[SP_C_LAMBDA]), mu = PetscRealPart(constants[SP_C_MU]);
  const PetscReal amp    = PetscRealPart(constants[SP_C_MMS]);
  for (PetscInt c = 0; c < dim; ++c) {
    PetscReal graddiv = 0.0, lap = 0.0;
    for (PetscInt d = 0; d < dim; ++d) {
      graddiv += SPMMSPhiHessian(dim, x, c, d) * (d + 1);
      lap += SPMMSPhiHessian(dim, x, d, d);
    }
    f0[c] = amp * ((lambda + mu) * graddiv + mu * lap * (c + 1));
  }
}

/* Neumann load on slot k: traction t and pressure p(x) = p0 + grad p . x (compressive, along -n),
   already scaled by the condition's load curve (SPBCSetLoad). Residual term -int v.t_total with
   t_total = t - p n, so f0 = p n - t. */
static inline void SPNeumann(PetscInt k, PetscInt dim, const PetscReal x[], const PetscReal n[], const PetscScalar constants[], PetscScalar f0[])
{
  const PetscScalar *c = &constants[SP_C_BC0 + SP_C_BCW * k];
  PetscScalar        p = c[0];
  for (PetscInt d = 0; d < dim; ++d) p += c[4 + d] * x[d];
  for (PetscInt d = 0; d < dim; ++d) f0[d] = p * n[d] - c[1 + d];
}

#define SP_NEUMANN_KERNEL(k) \
  static inline void SPNeumannF0_##k(SP_KERNEL_ARGS, const PetscReal x[], const PetscReal n[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[]) \
  { \
    SPNeumann(k, dim, x, n, constants, f0); \
  }
SP_NEUMANN_KERNEL(0)
SP_NEUMANN_KERNEL(1)
SP_NEUMANN_KERNEL(2)
SP_NEUMANN_KERNEL(3)
SP_NEUMANN_KERNEL(4)
SP_NEUMANN_KERNEL(5)
SP_NEUMANN_KERNEL(6)
SP_NEUMANN_KERNEL(7)

typedef void (*SPBdKernel)(SP_KERNEL_ARGS, const PetscReal[], const PetscReal[], PetscInt, const PetscScalar[], PetscScalar[]);
static const SPBdKernel SPNeumannKernels[8] = {SPNeumannF0_0, SPNeumannF0_1, SPNeumannF0_2, SPNeumannF0_3,
                                               SPNeumannF0_4, SPNeumannF0_5, SPNeumannF0_6, SPNeumannF0_7};
#endif
