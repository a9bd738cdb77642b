/* Unit checks of the header-only kernels (include/kernels/) against central finite differences at
   random states, 2D and 3D. PETSc is used for types, PetscInitialize and random numbers only
   (PETSCRANDER48, fixed seed: the same states on every machine).

     laws          F1 = dW/du_x (W the strain energy), G3 = dF1/du_x for small-strain elasticity
                   (SPElasticF1/G3) and Neo-Hookean (SPNeoHookeanF1/G3, |u_x| <= 0.3),
                   SPElasticElementStiffness = df/du, f the element internal force built from
                   SPElasticStress (P1 triangle/tet, Q1 quad/hex at 2^dim Gauss points, random sets)
     obstacles     n = dg/dx and Hg = dn/dx of SPObstacleGap (plane, sphere, cylinder)
     contact law   the law element (SPShiftedPenaltyTraction + SPContactElement): r = dE/du along directions, E = A eps/2 min(0, g + s)^2, and
                   K = dr/du, at penetrated, open and near-zero (g + s = +-100..1000 FD steps) states
     pair geometry SPPairGap (segment 2D, triangle and quad 3D): N = dg/du, H = dN/du at penetrated,
                   slid states, the projection recomputed by SPPairCandidate for every perturbed
                   state (as contact-pairs.c does), so the FD is of the true gap function; then the
                   contact law on these elements (r and K as above)

   Error of a check at one sample: max_i |ref_i - fd_i| / max(max_i |ref_i|, floor), floor the
   quantity's natural scale (it only matters where ref = 0, e.g. an open contact). FD step:
   -kernels_step (1e-7) times the state's length scale. A check passes when its largest error over
   all samples is <= -kernels_tol (1e-6) and it has at least one sample.

   The kink g + s = 0 of the law: no sample is taken within 100 FD steps of it. As a guard, a
   sample is skipped (and counted) if any perturbed state used by its FD has a different active
   state than the centre; a projection that fails or lands elsewhere than the constructed point
   is skipped the same way. The printed "skipped" counts are expected to be 0.

   Options: -kernels_samples N (400 per check), -kernels_seed S, -kernels_step, -kernels_tol.
   Exit code 0 when every check passes, 1 otherwise. */
#include <petscsys.h>
#include <kernels/tensor.h>
#include <kernels/elastic.h>
#include <kernels/neohookean.h>
#include <kernels/follower.h>
#include <kernels/contact-law.h>
#include <kernels/contact-pair.h>
#include <kernels/contact-friction.h>

/* The shifted-penalty law through the law interface: (p, k) from (g, s, eps), then the element */
static PetscBool LawActive(PetscReal g, PetscReal s)
{
  PetscReal p, k;
  SPShiftedPenaltyTraction(g, s, 1.0, &p, &k);
  return k > 0.0 ? PETSC_TRUE : PETSC_FALSE;
}
static void LawElement(PetscInt nd, PetscReal A, PetscReal eps, PetscReal g, PetscReal s, const PetscReal N[], const PetscReal Hg[], PetscReal r[], PetscReal K[])
{
  PetscReal p, k;
  SPShiftedPenaltyTraction(g, s, eps, &p, &k);
  SPContactElement(nd, A, p, k, N, Hg, r, K);
}

#if PETSC_VERSION_LT(3, 19, 0)
  #define PETSC_SUCCESS 0 /* as in include/spcontact.h */
#endif
#if defined(PETSC_USE_COMPLEX)
  #error "test-kernels checks real-valued kernels: build against a real-scalar PETSc"
#endif

static const char help[] = "Kernel unit checks against central finite differences (see the header of tests/unit/test-kernels.c)\n";

#define MAXE 24 /* dofs of the largest bulk element (hexahedron: 8 x 3) */
#define MAXQ 8  /* quadrature points */
#define MAXD 15 /* dofs of the largest contact element (quad facet: 3 (1 + 4)) */

typedef struct {
  PetscRandom rnd;
  PetscInt    samples;
  PetscReal   step, tol;
  PetscInt    nchecks, nfail;
} Ctx;

typedef struct {
  char      name[64];
  PetscInt  dim, samples, skipped;
  PetscReal maxerr;
} Stat;

static PetscReal Rnd(Ctx *c, PetscReal a, PetscReal b)
{
  PetscReal v;
  PetscCallAbort(PETSC_COMM_SELF, PetscRandomGetValueReal(c->rnd, &v));
  return a + (b - a) * v;
}

static void RndUnit(Ctx *c, PetscInt dim, PetscReal v[])
{
  PetscReal r;
  do {
    for (PetscInt d = 0; d < dim; ++d) v[d] = Rnd(c, -1.0, 1.0);
    r = SPNorm(dim, v);
  } while (r < 0.1 || r > 1.0);
  for (PetscInt d = 0; d < dim; ++d) v[d] /= r;
}

static PetscReal MaxAbs(PetscInt n, const PetscReal a[])
{
  PetscReal m = 0.0;
  for (PetscInt i = 0; i < n; ++i) m = PetscMax(m, PetscAbsReal(a[i]));
  return m;
}

/* max |ref - fd| / max(max |ref|, floor); NaN stays NaN (and fails the check) */
static PetscReal RelErr(PetscInt n, const PetscReal ref[], const PetscReal fd[], PetscReal floor)
{
  PetscReal d = 0.0;
  for (PetscInt i = 0; i < n; ++i) {
    const PetscReal e = PetscAbsReal(ref[i] - fd[i]);
    if (!(e <= d)) d = e;
  }
  return d / PetscMax(MaxAbs(n, ref), floor);
}

static void StatInit(Stat *s, PetscInt dim, const char name[])
{
  PetscCallAbort(PETSC_COMM_SELF, PetscStrncpy(s->name, name, sizeof(s->name)));
  s->dim = dim, s->samples = 0, s->skipped = 0, s->maxerr = 0.0;
}

static void StatAdd(Stat *s, PetscReal err)
{
  s->samples++;
  if (!(err <= s->maxerr)) s->maxerr = err;
}

static PetscErrorCode Report(Ctx *c, const Stat *s)
{
  const PetscBool ok = (s->samples > 0 && s->maxerr <= c->tol) ? PETSC_TRUE : PETSC_FALSE;

  PetscFunctionBeginUser;
  c->nchecks++;
  if (!ok) c->nfail++;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%-34s dim %" PetscInt_FMT " samples %5" PetscInt_FMT " skipped %" PetscInt_FMT " max_rel_err %.3e tol %.0e %s\n", s->name, s->dim, s->samples, s->skipped, (double)s->maxerr, (double)c->tol, ok ? "ok" : "FAILED"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The law's closed branch (the branch hold): equal to the law where it is closed (g + s <= 0),
   k = -dp/dg against central differences on both sides of the opening, continuous there */
static PetscErrorCode CheckClosedBranch(Ctx *c)
{
  Stat s;

  PetscFunctionBeginUser;
  StatInit(&s, 1, "law_closed_branch");
  for (PetscInt n = 0; n < c->samples; ++n) {
    const PetscReal eps = Rnd(c, 1.0, 1e4), sh = Rnd(c, -1e-2, 0.0), g = Rnd(c, -2e-2, 2e-2), dg = c->step * 1e-2;
    PetscReal       p, k, pl, kl, pp, pm, kk;
    SPShiftedPenaltyClosed(g, sh, eps, &p, &k);
    SPShiftedPenaltyClosed(g + dg, sh, eps, &pp, &kk);
    SPShiftedPenaltyClosed(g - dg, sh, eps, &pm, &kk);
    StatAdd(&s, PetscAbsReal(k + (pp - pm) / (2 * dg)) / eps);
    SPShiftedPenaltyTraction(g, sh, eps, &pl, &kl);
    if (g + sh <= 0.0) StatAdd(&s, (PetscAbsReal(p - pl) + PetscAbsReal(k - kl)) / (eps * 1e-2 + PetscAbsReal(pl)));
  }
  {
    PetscReal p, k; /* at the opening g + s = 0 both give p = 0 */
    SPShiftedPenaltyClosed(-1e-3, 1e-3, 1e3, &p, &k);
    StatAdd(&s, PetscAbsReal(p));
  }
  PetscCall(Report(c, &s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---------------------------------------------------------------- elasticity */

static PetscReal Det(PetscInt dim, const PetscReal J[])
{
  if (dim == 2) return J[0] * J[3] - J[1] * J[2];
  return J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) + J[2] * (J[3] * J[7] - J[4] * J[6]);
}

static void Inverse(PetscInt dim, const PetscReal J[], PetscReal Ji[])
{
  const PetscReal det = Det(dim, J);
  if (dim == 2) {
    Ji[0] = J[3] / det, Ji[1] = -J[1] / det, Ji[2] = -J[2] / det, Ji[3] = J[0] / det;
    return;
  }
  Ji[0] = (J[4] * J[8] - J[5] * J[7]) / det, Ji[1] = (J[2] * J[7] - J[1] * J[8]) / det, Ji[2] = (J[1] * J[5] - J[2] * J[4]) / det;
  Ji[3] = (J[5] * J[6] - J[3] * J[8]) / det, Ji[4] = (J[0] * J[8] - J[2] * J[6]) / det, Ji[5] = (J[2] * J[3] - J[0] * J[5]) / det;
  Ji[6] = (J[3] * J[7] - J[4] * J[6]) / det, Ji[7] = (J[1] * J[6] - J[0] * J[7]) / det, Ji[8] = (J[0] * J[4] - J[1] * J[3]) / det;
}

/* W = mu eps:eps + lambda/2 tr(eps)^2, eps = sym(u_x) */
static PetscReal ElasticEnergy(PetscInt dim, PetscReal lambda, PetscReal mu, const PetscReal ux[])
{
  PetscReal W = 0.0, tr = 0.0;
  for (PetscInt i = 0; i < dim; ++i) {
    tr += ux[i * dim + i];
    for (PetscInt j = 0; j < dim; ++j) {
      const PetscReal e = 0.5 * (ux[i * dim + j] + ux[j * dim + i]);
      W += mu * e * e;
    }
  }
  return W + 0.5 * lambda * tr * tr;
}

/* W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2 with F = I + u_x (2D: F_33 = 1), written out
   here independently of kernels/neohookean.h */
static PetscReal NeoHookeanEnergy(PetscInt dim, PetscReal lambda, PetscReal mu, const PetscReal ux[])
{
  PetscReal F[9], I1 = 3.0 - dim, J, lnJ;
  for (PetscInt i = 0; i < dim; ++i)
    for (PetscInt j = 0; j < dim; ++j) {
      F[i * dim + j] = ux[i * dim + j] + (i == j);
      I1 += F[i * dim + j] * F[i * dim + j];
    }
  J   = Det(dim, F);
  lnJ = PetscLogReal(J);
  return 0.5 * mu * (I1 - 3.0) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
}

/* A material law's pointwise kernels and its strain energy, for the FD checks */
typedef struct {
  const char *name;
  PetscReal (*energy)(PetscInt, PetscReal, PetscReal, const PetscReal[]);
  void (*f1)(SP_KERNEL_ARGS, const PetscReal[], PetscInt, const PetscScalar[], PetscScalar[]);
  void (*g3)(SP_KERNEL_ARGS, PetscReal, const PetscReal[], PetscInt, const PetscScalar[], PetscScalar[]);
  PetscReal gradient; /* random displacement gradients in [-gradient, gradient] (J > 0 for finite strain) */
} LawKernels;

static void LawF1(const LawKernels *law, PetscInt dim, const PetscScalar constants[], const PetscReal ux[], PetscReal f1[])
{
  const PetscInt  off[1] = {0};
  const PetscReal x[3]   = {0.0, 0.0, 0.0};
  PetscScalar     u[3]   = {0.0, 0.0, 0.0};
  law->f1(dim, 1, 0, off, off, u, NULL, ux, NULL, NULL, NULL, NULL, NULL, 0.0, x, SP_C_NUM, constants, f1);
}

/* F1 against the energy, G3 against F1 at random gradients and material constants */
static PetscErrorCode CheckLawPointwise(Ctx *c, PetscInt dim, const LawKernels *law)
{
  const PetscInt n = dim * dim;
  char           name[64];
  Stat           sf, sg;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(name, sizeof(name), "%s_f1_vs_energy", law->name));
  StatInit(&sf, dim, name);
  PetscCall(PetscSNPrintf(name, sizeof(name), "%s_g3_vs_f1", law->name));
  StatInit(&sg, dim, name);
  for (PetscInt k = 0; k < c->samples; ++k) {
    PetscScalar     constants[SP_C_NUM] = {0};
    PetscReal       ux[9], up[9], um[9], f1[9], fp[9], fm[9], fd[9], g3[81], g[81], gfd[81];
    const PetscInt  off[1] = {0};
    const PetscReal x[3]   = {0.0, 0.0, 0.0};
    PetscScalar     u[3]   = {0.0, 0.0, 0.0};
    PetscReal       lambda = Rnd(c, 0.1, 10.0), mu = Rnd(c, 0.1, 10.0), h;

    constants[SP_C_LAMBDA] = lambda, constants[SP_C_MU] = mu;
    for (PetscInt i = 0; i < n; ++i) ux[i] = Rnd(c, -law->gradient, law->gradient);
    h = c->step * PetscMax(1.0, MaxAbs(n, ux));
    LawF1(law, dim, constants, ux, f1);
    law->g3(dim, 1, 0, off, off, u, NULL, ux, NULL, NULL, NULL, NULL, NULL, 0.0, 0.0, x, SP_C_NUM, constants, g3);
    for (PetscInt j = 0; j < n; ++j) {
      for (PetscInt i = 0; i < n; ++i) up[i] = um[i] = ux[i];
      up[j] += h, um[j] -= h;
      fd[j] = (law->energy(dim, lambda, mu, up) - law->energy(dim, lambda, mu, um)) / (2.0 * h);
      LawF1(law, dim, constants, up, fp);
      LawF1(law, dim, constants, um, fm);
      for (PetscInt i = 0; i < n; ++i) gfd[i * n + j] = (fp[i] - fm[i]) / (2.0 * h); /* d f1[i] / d u_x[j] */
    }
    /* g3[((c * dim + e) * dim + d) * dim + f] = d f1[c * dim + d] / d u_x[e * dim + f] */
    for (PetscInt cc = 0; cc < dim; ++cc)
      for (PetscInt d = 0; d < dim; ++d)
        for (PetscInt e = 0; e < dim; ++e)
          for (PetscInt f = 0; f < dim; ++f) g[(cc * dim + d) * n + e * dim + f] = g3[((cc * dim + e) * dim + d) * dim + f];
    StatAdd(&sf, RelErr(n, f1, fd, lambda + 2.0 * mu));
    StatAdd(&sg, RelErr(n * n, g, gfd, lambda + 2.0 * mu));
  }
  PetscCall(Report(c, &sf));
  PetscCall(Report(c, &sg));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Follower pressure: the load stiffness g1 against central differences of f0 = p cof(F) N at
   random gradients (|grad u| <= 0.3), unit normals and pressures */
static PetscErrorCode CheckFollower(Ctx *c, PetscInt dim)
{
  const PetscInt n = dim * dim;
  Stat           s;

  PetscFunctionBeginUser;
  StatInit(&s, dim, "follower_pressure_g1_vs_f0");
  for (PetscInt k = 0; k < c->samples; ++k) {
    PetscReal   N[3], p = Rnd(c, -2.0, 2.0), h;
    PetscScalar ux[9], up[9], um[9], fp[3], fm[3], g1[27];
    PetscReal   g[27], gfd[27];
    RndUnit(c, dim, N);
    for (PetscInt i = 0; i < n; ++i) ux[i] = Rnd(c, -0.3, 0.3);
    h = c->step;
    SPFollowerTangent(dim, p, ux, N, g1);
    for (PetscInt j = 0; j < n; ++j) { /* j = (trial component) dim + (direction) */
      for (PetscInt i = 0; i < n; ++i) up[i] = um[i] = ux[i];
      up[j] += h, um[j] -= h;
      SPFollowerTraction(dim, p, NULL, up, N, fp);
      SPFollowerTraction(dim, p, NULL, um, N, fm);
      for (PetscInt i = 0; i < dim; ++i) gfd[i * n + j] = PetscRealPart(fp[i] - fm[i]) / (2.0 * h);
    }
    for (PetscInt i = 0; i < dim * n; ++i) g[i] = PetscRealPart(g1[i]);
    StatAdd(&s, RelErr(dim * n, g, gfd, PetscAbsReal(p)));
  }
  PetscCall(Report(c, &s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const LawKernels lawKernels[] = {
  {"elastic",     ElasticEnergy,    SPElasticF1,    SPElasticG3,    1.0},
  {"neo_hookean", NeoHookeanEnergy, SPNeoHookeanF1, SPNeoHookeanG3, 0.3},
};

/* f[(a,i)] = sum_q w_q sum_d sigma_id(u_x^q) G_qad, u_x^q[i][d] = sum_b u[(b,i)] G_qbd */
static void InternalForce(PetscInt dim, PetscInt nb, PetscInt nq, const PetscReal G[], const PetscReal w[], PetscReal lambda, PetscReal mu, const PetscReal u[], PetscReal f[])
{
  for (PetscInt k = 0; k < nb * dim; ++k) f[k] = 0.0;
  for (PetscInt q = 0; q < nq; ++q) {
    const PetscReal *Gq = &G[q * nb * dim];
    PetscReal        ux[9] = {0}, s[9];
    for (PetscInt i = 0; i < dim; ++i)
      for (PetscInt d = 0; d < dim; ++d)
        for (PetscInt b = 0; b < nb; ++b) ux[i * dim + d] += u[b * dim + i] * Gq[b * dim + d];
    SPElasticStress(dim, lambda, mu, ux, s);
    for (PetscInt a = 0; a < nb; ++a)
      for (PetscInt i = 0; i < dim; ++i)
        for (PetscInt d = 0; d < dim; ++d) f[a * dim + i] += w[q] * s[i * dim + d] * Gq[a * dim + d];
  }
}

/* Random P1 simplex: gradients of the barycentric coordinates, one point, weight = volume */
static void SimplexGradients(Ctx *c, PetscInt dim, PetscInt *nb, PetscInt *nq, PetscReal G[], PetscReal w[])
{
  PetscReal J[9], Ji[9], det, L;
  do {
    L = Rnd(c, 0.5, 2.0);
    for (PetscInt i = 0; i < dim; ++i)
      for (PetscInt j = 0; j < dim; ++j) J[i * dim + j] = L * ((i == j) + Rnd(c, -0.3, 0.3)); /* column j: edge v_{j+1} - v_0 */
    det = Det(dim, J);
  } while (PetscAbsReal(det) < 0.1 * PetscPowRealInt(L, dim));
  Inverse(dim, J, Ji);
  *nb = dim + 1, *nq = 1;
  for (PetscInt d = 0; d < dim; ++d) {
    G[d] = 0.0;
    for (PetscInt k = 1; k <= dim; ++k) G[k * dim + d] = Ji[(k - 1) * dim + d], G[d] -= Ji[(k - 1) * dim + d];
  }
  w[0] = PetscAbsReal(det) / (dim == 2 ? 2.0 : 6.0);
}

/* Random distorted Q1 quad/hex: physical gradients and det J at the 2^dim Gauss points */
static void TensorGradients(Ctx *c, PetscInt dim, PetscInt *nb, PetscInt *nq, PetscReal G[], PetscReal w[])
{
  const PetscInt  n  = 1 << dim;
  const PetscReal gp = 1.0 / PetscSqrtReal(3.0);
  PetscReal       X[8 * 3], L;
  PetscBool       good;
  *nb = *nq = n;
  do {
    L    = Rnd(c, 0.5, 2.0);
    good = PETSC_TRUE;
    for (PetscInt a = 0; a < n; ++a)
      for (PetscInt i = 0; i < dim; ++i) X[a * dim + i] = L * (((a >> i) & 1) + Rnd(c, -0.15, 0.15));
    for (PetscInt q = 0; q < n && good; ++q) {
      PetscReal xq[3], dN[8 * 3], J[9] = {0}, Ji[9], det;
      for (PetscInt k = 0; k < dim; ++k) xq[k] = ((q >> k) & 1) ? gp : -gp;
      for (PetscInt a = 0; a < n; ++a)
        for (PetscInt k = 0; k < dim; ++k) {
          dN[a * dim + k] = 0.5 * (((a >> k) & 1) ? 1.0 : -1.0);
          for (PetscInt l = 0; l < dim; ++l)
            if (l != k) dN[a * dim + k] *= 0.5 * (1.0 + (((a >> l) & 1) ? 1.0 : -1.0) * xq[l]);
        }
      for (PetscInt i = 0; i < dim; ++i)
        for (PetscInt k = 0; k < dim; ++k)
          for (PetscInt a = 0; a < n; ++a) J[i * dim + k] += X[a * dim + i] * dN[a * dim + k];
      det = Det(dim, J);
      if (det < 0.1 * PetscPowRealInt(0.5 * L, dim)) {
        good = PETSC_FALSE;
        break;
      }
      Inverse(dim, J, Ji);
      for (PetscInt a = 0; a < n; ++a)
        for (PetscInt i = 0; i < dim; ++i) {
          G[(q * n + a) * dim + i] = 0.0;
          for (PetscInt k = 0; k < dim; ++k) G[(q * n + a) * dim + i] += dN[a * dim + k] * Ji[k * dim + i];
        }
      w[q] = det; /* Gauss weight 1 on [-1,1]^dim */
    }
  } while (!good);
}

/* Arbitrary gradient sets: 2..8 functions, 1..8 points, random weights */
static void RandomGradients(Ctx *c, PetscInt dim, PetscInt *nb, PetscInt *nq, PetscReal G[], PetscReal w[])
{
  *nb = 2 + (PetscInt)Rnd(c, 0.0, 6.999);
  *nq = 1 + (PetscInt)Rnd(c, 0.0, 7.999);
  for (PetscInt k = 0; k < (*nq) * (*nb) * dim; ++k) G[k] = Rnd(c, -1.0, 1.0);
  for (PetscInt q = 0; q < *nq; ++q) w[q] = Rnd(c, 0.1, 1.0);
}

typedef void (*GradientSet)(Ctx *, PetscInt, PetscInt *, PetscInt *, PetscReal[], PetscReal[]);

static PetscErrorCode CheckElasticElement(Ctx *c, PetscInt dim, const char name[], GradientSet set)
{
  Stat s;

  PetscFunctionBeginUser;
  StatInit(&s, dim, name);
  for (PetscInt k = 0; k < c->samples; ++k) {
    PetscReal   G[MAXQ * MAXE], w[MAXQ], u[MAXE], up[MAXE], um[MAXE], fp[MAXE], fm[MAXE], Kfd[MAXE * MAXE], K[MAXE * MAXE], h;
    PetscReal   lambda = Rnd(c, 0.1, 10.0), mu = Rnd(c, 0.1, 10.0);
    PetscInt    nb, nq, n;
    set(c, dim, &nb, &nq, G, w);
    n = nb * dim;
    for (PetscInt i = 0; i < n; ++i) u[i] = Rnd(c, -1.0, 1.0);
    h = c->step * PetscMax(1.0, MaxAbs(n, u));
    SPElasticElementStiffness(dim, nb, nq, G, w, lambda, mu, K);
    for (PetscInt j = 0; j < n; ++j) {
      for (PetscInt i = 0; i < n; ++i) up[i] = um[i] = u[i];
      up[j] += h, um[j] -= h;
      InternalForce(dim, nb, nq, G, w, lambda, mu, up, fp);
      InternalForce(dim, nb, nq, G, w, lambda, mu, um, fm);
      for (PetscInt i = 0; i < n; ++i) Kfd[i * n + j] = (fp[i] - fm[i]) / (2.0 * h);
    }
    StatAdd(&s, RelErr(n * n, K, Kfd, PETSC_SMALL));
  }
  PetscCall(Report(c, &s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---------------------------------------------------------------- obstacles and the contact law */

static const char *const obstacleName[] = {"plane", "sphere", "cylinder"};
static const char *const stateName[]    = {"penetrated", "open", "near_zero"};

static void RandomObstacle(Ctx *c, PetscInt dim, SPObstacleType type, SPObstacle *ob, PetscReal *load)
{
  PetscReal nrm[3] = {0.0, 0.0, 0.0};
  ob->type = type;
  RndUnit(c, dim, nrm);
  for (PetscInt d = 0; d < 3; ++d) {
    ob->point[d]  = d < dim ? Rnd(c, -1.0, 1.0) : 0.0;
    ob->motion[d] = d < dim ? Rnd(c, -0.2, 0.2) : 0.0;
    ob->normal[d] = nrm[d];
  }
  ob->radius = Rnd(c, 0.5, 2.0);
  *load      = Rnd(c, 0.0, 1.0);
}

/* A point x where the obstacle's gap is gt */
static void PlaceAtGap(Ctx *c, PetscInt dim, const SPObstacle *ob, PetscReal load, PetscReal gt, PetscReal x[])
{
  PetscReal ctr[3], w[3], wa, r;
  for (PetscInt d = 0; d < dim; ++d) ctr[d] = ob->point[d] + load * ob->motion[d];
  if (ob->type == SP_OBSTACLE_PLANE) {
    RndUnit(c, dim, w);
    wa = SPDot(dim, w, ob->normal);
    for (PetscInt d = 0; d < dim; ++d) x[d] = ctr[d] + (w[d] - wa * ob->normal[d]) + gt * ob->normal[d];
    return;
  }
  if (ob->type == SP_OBSTACLE_CYLINDER && dim == 3) {
    do { /* radial direction: perpendicular to the axis */
      RndUnit(c, dim, w);
      wa = SPDot(dim, w, ob->normal);
      for (PetscInt d = 0; d < dim; ++d) w[d] -= wa * ob->normal[d];
      r = SPNorm(dim, w);
    } while (r < 0.1);
    for (PetscInt d = 0; d < dim; ++d) w[d] /= r;
    wa = Rnd(c, -1.0, 1.0);
    for (PetscInt d = 0; d < dim; ++d) x[d] = ctr[d] + (ob->radius + gt) * w[d] + wa * ob->normal[d];
    return;
  }
  RndUnit(c, dim, w);
  for (PetscInt d = 0; d < dim; ++d) x[d] = ctr[d] + (ob->radius + gt) * w[d];
}

/* Obstacle geometry (n, Hg) and the law on an obstacle element (r, K), per state class */
static PetscErrorCode CheckObstacle(Ctx *c, PetscInt dim, SPObstacleType type)
{
  char name[64];
  Stat sn, sH, sr[3], sK[3];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(name, sizeof(name), "obstacle_%s_normal", obstacleName[type]));
  StatInit(&sn, dim, name);
  PetscCall(PetscSNPrintf(name, sizeof(name), "obstacle_%s_curvature", obstacleName[type]));
  StatInit(&sH, dim, name);
  for (PetscInt cls = 0; cls < 3; ++cls) {
    PetscCall(PetscSNPrintf(name, sizeof(name), "law_%s_%s_residual", obstacleName[type], stateName[cls]));
    StatInit(&sr[cls], dim, name);
    PetscCall(PetscSNPrintf(name, sizeof(name), "law_%s_%s_tangent", obstacleName[type], stateName[cls]));
    StatInit(&sK[cls], dim, name);
    for (PetscInt k = 0; k < c->samples; ++k) {
      SPObstacle ob;
      PetscReal  load, Lc, h, t, s, A, eps, x[3], g, n[3], Hg[9], r[3], K[9], D[5][3], rd[5], rdfd[5];
      PetscReal  nfd[3], Hfd[9], Kfd[9];
      PetscBool  active, skip = PETSC_FALSE;
      const PetscInt nD = dim + 2;

      RandomObstacle(c, dim, type, &ob, &load);
      Lc  = type == SP_OBSTACLE_PLANE ? 1.0 : ob.radius;
      h   = c->step * Lc;
      t   = cls == 0 ? -Rnd(c, 0.01, 0.3) * Lc : (cls == 1 ? Rnd(c, 0.01, 0.3) * Lc : (Rnd(c, 0.0, 1.0) < 0.5 ? -1.0 : 1.0) * Rnd(c, 100.0, 1000.0) * h);
      s   = Rnd(c, 0.0, 1.0) < 1.0 / 3.0 ? 0.0 : -Rnd(c, 0.0, 0.05) * Lc; /* shift <= 0; 0 = plain penalty */
      A   = Rnd(c, 0.1, 2.0);
      eps = Rnd(c, 1.0, 100.0);
      PlaceAtGap(c, dim, &ob, load, t - s, x);
      SPObstacleGap(&ob, dim, load, x, &g, n, Hg);
      active = LawActive(g, s);
      /* directions: the coordinate axes and two random unit vectors */
      for (PetscInt j = 0; j < nD; ++j) {
        for (PetscInt d = 0; d < dim; ++d) D[j][d] = (d == j);
        if (j >= dim) RndUnit(c, dim, D[j]);
      }
      for (PetscInt j = 0; j < nD && !skip; ++j)
        for (PetscInt sg = -1; sg <= 1; sg += 2) {
          PetscReal xp[3], gp, np[3], Hp[9];
          for (PetscInt d = 0; d < dim; ++d) xp[d] = x[d] + sg * h * D[j][d];
          SPObstacleGap(&ob, dim, load, xp, &gp, np, Hp);
          if (LawActive(gp, s) != active) skip = PETSC_TRUE;
        }
      if (skip) {
        sr[cls].skipped++, sK[cls].skipped++;
        continue;
      }
      LawElement(dim, A, eps, g, s, n, Hg, r, K);
      for (PetscInt j = 0; j < nD; ++j) {
        PetscReal E[2];
        for (PetscInt sg = 0; sg < 2; ++sg) {
          PetscReal xp[3], gp, np[3], Hp[9], m;
          for (PetscInt d = 0; d < dim; ++d) xp[d] = x[d] + (sg ? -h : h) * D[j][d];
          SPObstacleGap(&ob, dim, load, xp, &gp, np, Hp);
          m     = PetscMin(0.0, gp + s);
          E[sg] = 0.5 * A * eps * m * m;
        }
        rd[j]   = SPDot(dim, r, D[j]);
        rdfd[j] = (E[0] - E[1]) / (2.0 * h);
      }
      for (PetscInt j = 0; j < dim; ++j) {
        PetscReal gpm[2], npm[2][3], rpm[2][3];
        for (PetscInt sg = 0; sg < 2; ++sg) {
          PetscReal xp[3], Hp[9];
          for (PetscInt d = 0; d < dim; ++d) xp[d] = x[d] + (d == j ? (sg ? -h : h) : 0.0);
          SPObstacleGap(&ob, dim, load, xp, &gpm[sg], npm[sg], Hp);
          LawElement(dim, A, eps, gpm[sg], s, npm[sg], Hp, rpm[sg], NULL);
        }
        nfd[j] = (gpm[0] - gpm[1]) / (2.0 * h);
        for (PetscInt i = 0; i < dim; ++i) {
          Hfd[i * dim + j] = (npm[0][i] - npm[1][i]) / (2.0 * h);
          Kfd[i * dim + j] = (rpm[0][i] - rpm[1][i]) / (2.0 * h);
        }
      }
      StatAdd(&sn, RelErr(dim, n, nfd, 1.0));
      StatAdd(&sH, RelErr(dim * dim, Hg, Hfd, 1.0 / Lc));
      StatAdd(&sr[cls], RelErr(nD, rd, rdfd, A * eps * h));
      StatAdd(&sK[cls], RelErr(dim * dim, K, Kfd, A * eps));
    }
  }
  PetscCall(Report(c, &sn));
  PetscCall(Report(c, &sH));
  for (PetscInt cls = 0; cls < 3; ++cls) {
    PetscCall(Report(c, &sr[cls]));
    PetscCall(Report(c, &sK[cls]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---------------------------------------------------------------- contact pairs */

static const char *FacetName(PetscInt dim, PetscInt nv)
{
  return dim == 2 ? "segment" : (nv == 3 ? "triangle" : "quad");
}

/* The true gap function of v = [xs; x_1; ...; x_nv]: the projection recomputed by SPPairCandidate
   (as SPContactPairsProject does), then SPPairGap at it. PETSC_FALSE: no projection. */
static PetscBool PairEval(PetscInt dim, PetscInt nv, const PetscReal v[], PetscReal xi[], PetscReal *g, PetscReal N[], PetscReal H[])
{
  PetscReal d, e, n[3];
  if (!SPPairCandidate(dim, nv, &v[dim], v, xi, &d, &e)) return PETSC_FALSE;
  SPPairGap(dim, nv, &v[dim], v, xi, g, n, N, H);
  return PETSC_TRUE;
}

/* A random master facet of size about L: a rotated, stretched segment (2D); a perturbed triangle
   or a warped (non-planar) bilinear quad in a random frame (3D) */
static void RandomFacet(Ctx *c, PetscInt dim, PetscInt nv, PetscReal X[], PetscReal *L)
{
  *L = Rnd(c, 0.5, 2.0);
  if (dim == 2) {
    const PetscReal th = Rnd(c, 0.0, 2.0 * PETSC_PI);
    X[0] = Rnd(c, -1.0, 1.0), X[1] = Rnd(c, -1.0, 1.0);
    X[2] = X[0] + *L * PetscCosReal(th), X[3] = X[1] + *L * PetscSinReal(th);
    return;
  }
  for (;;) {
    PetscReal e1[3], e2[3], e3[3], o[3], P[4][3];
    PetscBool ok = PETSC_TRUE;
    RndUnit(c, 3, e1);
    do {
      PetscReal a;
      RndUnit(c, 3, e2);
      a = SPDot(3, e1, e2);
      for (PetscInt k = 0; k < 3; ++k) e2[k] -= a * e1[k];
    } while (SPNorm(3, e2) < 0.1);
    {
      const PetscReal r = SPNorm(3, e2);
      for (PetscInt k = 0; k < 3; ++k) e2[k] /= r;
    }
    SPCross(e1, e2, e3);
    for (PetscInt k = 0; k < 3; ++k) o[k] = Rnd(c, -1.0, 1.0);
    if (nv == 3) {
      const PetscReal ref[3][2] = {{0, 0}, {1, 0}, {0, 1}};
      for (PetscInt a = 0; a < 3; ++a) P[a][0] = *L * (ref[a][0] + Rnd(c, -0.2, 0.2)), P[a][1] = *L * (ref[a][1] + Rnd(c, -0.2, 0.2)), P[a][2] = 0.0;
    } else {
      const PetscReal ref[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (PetscInt a = 0; a < 4; ++a)
        for (PetscInt k = 0; k < 3; ++k) P[a][k] = *L * ((k < 2 ? 0.5 * ref[a][k] : 0.0) + Rnd(c, -0.15, 0.15)); /* z: the warp */
    }
    for (PetscInt a = 0; a < nv; ++a)
      for (PetscInt k = 0; k < 3; ++k) X[a * 3 + k] = o[k] + P[a][0] * e1[k] + P[a][1] * e2[k] + P[a][2] * e3[k];
    /* reject badly shaped facets: small area element somewhere on [-1.1, 1.1]^2 (quad), folded */
    if (nv == 4)
      for (PetscInt q = 0; q < 4; ++q) {
        const PetscReal xq[2] = {q % 2 ? 1.1 : -1.1, q / 2 ? 1.1 : -1.1}, x0[2] = {0.0, 0.0};
        SPFacetGeom     G, G0;
        SPFacetGeometry(4, X, xq, &G);
        SPFacetGeometry(4, X, x0, &G0);
        if (G.J < 0.1 * 0.25 * (*L) * (*L) || SPDot(3, G.n, G0.n) < 0.8) ok = PETSC_FALSE;
      }
    else {
      SPFacetGeom G;
      const PetscReal x0[2] = {1.0 / 3.0, 1.0 / 3.0};
      SPFacetGeometry(3, X, x0, &G);
      if (G.J < 0.2 * (*L) * (*L)) ok = PETSC_FALSE;
    }
    if (ok) return;
  }
}

/* Pair geometry N, H and the contact law on the pair element, at penetrated, slid states */
static PetscErrorCode CheckPair(Ctx *c, PetscInt dim, PetscInt nv)
{
  const PetscInt nd = dim * (1 + nv);
  char           name[64];
  Stat           sN, sH, sr, sK;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(name, sizeof(name), "pair_%s_N", FacetName(dim, nv)));
  StatInit(&sN, dim, name);
  PetscCall(PetscSNPrintf(name, sizeof(name), "pair_%s_H", FacetName(dim, nv)));
  StatInit(&sH, dim, name);
  PetscCall(PetscSNPrintf(name, sizeof(name), "law_pair_%s_residual", FacetName(dim, nv)));
  StatInit(&sr, dim, name);
  PetscCall(PetscSNPrintf(name, sizeof(name), "law_pair_%s_tangent", FacetName(dim, nv)));
  StatInit(&sK, dim, name);
  for (PetscInt k = 0; k < c->samples; ++k) {
    PetscReal v[MAXD], X[12], L, xt[2] = {0.0, 0.0}, gt, xi[2], g, N[MAXD], H[MAXD * MAXD], h, s, A, eps;
    PetscReal r[MAXD], K[MAXD * MAXD], Nfd[MAXD], Hfd[MAXD * MAXD], rfd[MAXD], Kfd[MAXD * MAXD];
    PetscBool skip = PETSC_FALSE;

    RandomFacet(c, dim, nv, X, &L);
    /* slid: the projection anywhere on the facet, slightly beyond its sides included */
    if (dim == 2) xt[0] = Rnd(c, -0.1, 1.1);
    else if (nv == 3) do {
        xt[0] = Rnd(c, -0.1, 1.1), xt[1] = Rnd(c, -0.1, 1.1);
      } while (xt[0] + xt[1] > 1.1);
    else xt[0] = Rnd(c, -1.1, 1.1), xt[1] = Rnd(c, -1.1, 1.1);
    gt = -Rnd(c, 0.01, 0.2) * L; /* penetrated */
    if (dim == 2) {
      const PetscReal t[2] = {X[2] - X[0], X[3] - X[1]}, n[2] = {t[1] / L, -t[0] / L};
      for (PetscInt d = 0; d < 2; ++d) v[d] = X[d] + xt[0] * t[d] + gt * n[d];
    } else {
      SPFacetGeom G;
      SPFacetGeometry(nv, X, xt, &G);
      for (PetscInt d = 0; d < 3; ++d) v[d] = G.x[d] + gt * G.n[d];
    }
    for (PetscInt i = 0; i < nv * dim; ++i) v[dim + i] = X[i];
    h = c->step * L;
    if (!PairEval(dim, nv, v, xi, &g, N, H) || PetscAbsReal(xi[0] - xt[0]) + PetscAbsReal(xi[1] - xt[1]) > 1e-8) {
      sN.skipped++, sH.skipped++, sr.skipped++, sK.skipped++;
      continue;
    }
    s   = Rnd(c, 0.0, 1.0) < 1.0 / 3.0 ? 0.0 : -Rnd(c, 0.0, 0.05) * L;
    A   = Rnd(c, 0.1, 2.0);
    eps = Rnd(c, 1.0, 100.0);
    LawElement(nd, A, eps, g, s, N, H, r, K);
    for (PetscInt j = 0; j < nd && !skip; ++j) {
      PetscReal gpm[2], Npm[2][MAXD], rpm[2][MAXD], E[2];
      for (PetscInt sg = 0; sg < 2; ++sg) {
        PetscReal vp[MAXD], xp[2], m;
        for (PetscInt i = 0; i < nd; ++i) vp[i] = v[i];
        vp[j] += sg ? -h : h;
        if (!PairEval(dim, nv, vp, xp, &gpm[sg], Npm[sg], NULL) || LawActive(gpm[sg], s) != LawActive(g, s)) {
          skip = PETSC_TRUE;
          break;
        }
        LawElement(nd, A, eps, gpm[sg], s, Npm[sg], NULL, rpm[sg], NULL);
        m     = PetscMin(0.0, gpm[sg] + s);
        E[sg] = 0.5 * A * eps * m * m;
      }
      if (skip) break;
      Nfd[j] = (gpm[0] - gpm[1]) / (2.0 * h);
      rfd[j] = (E[0] - E[1]) / (2.0 * h);
      for (PetscInt i = 0; i < nd; ++i) {
        Hfd[i * nd + j] = (Npm[0][i] - Npm[1][i]) / (2.0 * h);
        Kfd[i * nd + j] = (rpm[0][i] - rpm[1][i]) / (2.0 * h);
      }
    }
    if (skip) {
      sN.skipped++, sH.skipped++, sr.skipped++, sK.skipped++;
      continue;
    }
    StatAdd(&sN, RelErr(nd, N, Nfd, 1.0));
    StatAdd(&sH, RelErr(nd * nd, H, Hfd, 1.0 / L));
    StatAdd(&sr, RelErr(nd, r, rfd, A * eps * h));
    StatAdd(&sK, RelErr(nd * nd, K, Kfd, A * eps));
  }
  PetscCall(Report(c, &sN));
  PetscCall(Report(c, &sH));
  PetscCall(Report(c, &sr));
  PetscCall(Report(c, &sK));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---------------------------------------------------------------- friction */

/* Friction residual of a random element at u: normal pressure p = law(g0 + N.u), trial
   y = -epsT (BT u + c), return map, r = -A BT^T t (kernels/contact-friction.h) */
typedef struct {
  PetscInt  nd, nt;
  PetscReal A, eps, epsT, mu, g0, s, N[MAXD], BT[2 * MAXD], c[2];
} FricElem;

static void FrictionResidual(const FricElem *e, const PetscReal u[], PetscReal r[], PetscReal K[], PetscBool *stick)
{
  PetscReal g = e->g0 + e->s, p, k, y[2], t[2];
  for (PetscInt j = 0; j < e->nd; ++j) g += e->N[j] * u[j];
  SPShiftedPenaltyTraction(g - e->s, e->s, e->eps, &p, &k);
  for (PetscInt a = 0; a < e->nt; ++a) {
    y[a] = e->c[a];
    for (PetscInt j = 0; j < e->nd; ++j) y[a] += e->BT[a * e->nd + j] * u[j];
    y[a] *= -e->epsT;
  }
  *stick = SPCoulombReturn(e->nt, y, e->mu * p, t);
  SPFrictionElement(e->nd, e->nt, e->A, e->epsT, e->mu, p, k, e->BT, e->N, y, t, *stick, r, K);
}

/* K of SPFrictionElement against central differences of its residual, at penetrated states in
   stick (|y| < 0.5 mu p) and slip (|y| > 2 mu p), away from the cone and the kink by many steps */
static PetscErrorCode CheckFriction(Ctx *c, PetscInt dim, PetscInt nd)
{
  Stat st[2];

  PetscFunctionBeginUser;
  StatInit(&st[0], dim, nd == dim ? "friction_stick_tangent_obstacle" : "friction_stick_tangent_pair");
  StatInit(&st[1], dim, nd == dim ? "friction_slip_tangent_obstacle" : "friction_slip_tangent_pair");
  for (PetscInt cls = 0; cls < 2; ++cls)
    for (PetscInt smp = 0; smp < c->samples; ++smp) {
      FricElem  e;
      PetscReal u[MAXD] = {0}, r0[MAXD], K[MAXD * MAXD], Kfd[MAXD * MAXD], rp[MAXD], rm[MAXD], y0 = 0.0, p0;
      PetscBool stick, sp, sm, skip = PETSC_FALSE;
      e.nd = nd, e.nt = dim - 1, e.A = Rnd(c, 0.5, 2.0), e.eps = Rnd(c, 10, 1000), e.epsT = Rnd(c, 10, 1000), e.mu = Rnd(c, 0.1, 0.8);
      e.g0 = -Rnd(c, 1e-3, 1e-2), e.s = 0.0;
      for (PetscInt j = 0; j < nd; ++j) e.N[j] = Rnd(c, -1, 1); /* u = 0: the state is set by g0 and c */
      for (PetscInt j = 0; j < e.nt * nd; ++j) e.BT[j] = Rnd(c, -1, 1);
      p0 = e.eps * (-e.g0);
      for (PetscInt a = 0; a < e.nt; ++a) e.c[a] = Rnd(c, -1, 1);
      y0 = e.epsT * SPNorm(e.nt, e.c);
      for (PetscInt a = 0; a < e.nt; ++a) e.c[a] *= (cls == 0 ? 0.3 : 3.0) * e.mu * p0 / y0;
      FrictionResidual(&e, u, r0, K, &stick);
      if (stick != (cls == 0)) skip = PETSC_TRUE;
      for (PetscInt j = 0; j < nd && !skip; ++j) {
        const PetscReal h = c->step * 1e-3;
        u[j] += h;
        FrictionResidual(&e, u, rp, NULL, &sp);
        u[j] -= 2 * h;
        FrictionResidual(&e, u, rm, NULL, &sm);
        u[j] += h;
        if (sp != stick || sm != stick) skip = PETSC_TRUE;
        for (PetscInt i = 0; i < nd; ++i) Kfd[i * nd + j] = (rp[i] - rm[i]) / (2 * h);
      }
      if (skip) {
        st[cls].skipped++;
        continue;
      }
      StatAdd(&st[cls], RelErr(nd * nd, K, Kfd, 1e-300));
    }
  PetscCall(Report(c, &st[0]));
  PetscCall(Report(c, &st[1]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  Ctx      c    = {NULL, 400, 1e-7, 1e-6, 0, 0};
  PetscInt seed = 20240607;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-kernels_samples", &c.samples, NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-kernels_seed", &seed, NULL));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-kernels_step", &c.step, NULL));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-kernels_tol", &c.tol, NULL));
  PetscCall(PetscRandomCreate(PETSC_COMM_SELF, &c.rnd));
  PetscCall(PetscRandomSetType(c.rnd, PETSCRANDER48));
  PetscCall(PetscRandomSetSeed(c.rnd, (unsigned long)seed));
  PetscCall(PetscRandomSeed(c.rnd));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "test-kernels: seed %" PetscInt_FMT ", %" PetscInt_FMT " samples per check, central FD step %.0e x the state's length, tol %.0e (max relative error)\n", seed, c.samples, (double)c.step, (double)c.tol));
  for (PetscInt dim = 2; dim <= 3; ++dim) {
    for (size_t l = 0; l < sizeof(lawKernels) / sizeof(lawKernels[0]); ++l) PetscCall(CheckLawPointwise(&c, dim, &lawKernels[l]));
    PetscCall(CheckFollower(&c, dim));
    PetscCall(CheckElasticElement(&c, dim, dim == 2 ? "elastic_stiffness_p1_triangle" : "elastic_stiffness_p1_tet", SimplexGradients));
    PetscCall(CheckElasticElement(&c, dim, dim == 2 ? "elastic_stiffness_q1_quad" : "elastic_stiffness_q1_hex", TensorGradients));
    PetscCall(CheckElasticElement(&c, dim, "elastic_stiffness_random_sets", RandomGradients));
  }
  PetscCall(CheckClosedBranch(&c));
  for (PetscInt dim = 2; dim <= 3; ++dim)
    for (PetscInt t = SP_OBSTACLE_PLANE; t <= SP_OBSTACLE_CYLINDER; ++t) PetscCall(CheckObstacle(&c, dim, (SPObstacleType)t));
  PetscCall(CheckPair(&c, 2, 2));
  PetscCall(CheckPair(&c, 3, 3));
  PetscCall(CheckPair(&c, 3, 4));
  for (PetscInt dim = 2; dim <= 3; ++dim) {
    PetscCall(CheckFriction(&c, dim, dim));           /* against an obstacle: slave dofs only */
    PetscCall(CheckFriction(&c, dim, dim * (1 + dim))); /* a pair element (segment / triangle) */
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "test-kernels: %" PetscInt_FMT " checks, %" PetscInt_FMT " failed\n", c.nchecks, c.nfail));
  PetscCall(PetscRandomDestroy(&c.rnd));
  PetscCall(PetscFinalize());
  return c.nfail ? 1 : 0;
}
