/* Node-to-segment geometry (2D) for deformable-deformable contact. Pure: no PETSc calls beyond
   scalar types.  A contact element is a slave vertex xs and a linear master segment x1 -> x2 whose
   vertex order makes n = (t_y, -t_x)/L (t = x2 - x1, L = |t|) point out of the master body.
     projection  xi = (xs - x1).t / L^2     (unclamped: an extended segment near junctions)
     gap         g  = (xs - x1).n            (< 0: penetration)
     variation   dg = N.du,  N = [n; -(1-xi) n; -xi n]      (slave, master 1, master 2)
     second var. ddg = -(T N0^T + N0 T^T)/L - g/L^2 N0 N0^T
                 T = [e; -(1-xi) e; -xi e], N0 = [0; -n; n], e = t/L
   The second variation includes the variation of the projection xi and of the master normal, so
   the tangent is consistent for finite sliding (derivation in the README). */
#ifndef SP_KERNELS_CONTACT_PAIR_H
#define SP_KERNELS_CONTACT_PAIR_H
#include <kernels/tensor.h>

/* Parameter, clamped distance: used by the search to pick the master segment */
static inline void SPSegmentProject(const PetscReal xs[], const PetscReal x1[], const PetscReal x2[], PetscReal *xi, PetscReal *dist)
{
  const PetscReal t[2] = {x2[0] - x1[0], x2[1] - x1[1]}, L2 = t[0] * t[0] + t[1] * t[1];
  PetscReal       c, d[2];
  *xi = L2 > 0.0 ? ((xs[0] - x1[0]) * t[0] + (xs[1] - x1[1]) * t[1]) / L2 : 0.0;
  c   = PetscMin(1.0, PetscMax(0.0, *xi));
  d[0] = xs[0] - x1[0] - c * t[0];
  d[1] = xs[1] - x1[1] - c * t[1];
  *dist = SPNorm(2, d);
}

/* Gap, normal, N (6) and second variation H (6x6, row-major) of slave xs against x1 -> x2 */
static inline void SPSegmentGap(const PetscReal xs[], const PetscReal x1[], const PetscReal x2[], PetscReal *g, PetscReal n[], PetscReal *xiOut, PetscReal N[], PetscReal H[])
{
  const PetscReal t[2] = {x2[0] - x1[0], x2[1] - x1[1]}, L = SPNorm(2, t);
  const PetscReal e[2] = {t[0] / L, t[1] / L}, d[2] = {xs[0] - x1[0], xs[1] - x1[1]};
  PetscReal       xi, T[6], N0[6];
  n[0]   = e[1];
  n[1]   = -e[0];
  xi     = SPDot(2, d, e) / L;
  *g     = SPDot(2, d, n);
  *xiOut = xi;
  for (PetscInt k = 0; k < 2; ++k) {
    N[k]      = n[k];
    N[2 + k]  = -(1.0 - xi) * n[k];
    N[4 + k]  = -xi * n[k];
    T[k]      = e[k];
    T[2 + k]  = -(1.0 - xi) * e[k];
    T[4 + k]  = -xi * e[k];
    N0[k]     = 0.0;
    N0[2 + k] = -n[k];
    N0[4 + k] = n[k];
  }
  if (H)
    for (PetscInt a = 0; a < 6; ++a)
      for (PetscInt b = 0; b < 6; ++b) H[a * 6 + b] = -(T[a] * N0[b] + N0[a] * T[b]) / L - (*g) / (L * L) * N0[a] * N0[b];
}
#endif
