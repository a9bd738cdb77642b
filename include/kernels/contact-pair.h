/* Node-to-segment geometry (2D) for deformable-deformable contact, and the dispatch to the 3D
   node-to-facet kernels (kernels/contact-facet.h). Pure: no PETSc calls beyond
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
#include <kernels/contact-facet.h>

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

/* One code path for segments (2D) and triangles/quads (3D), used by the search and the elements */

/* How far the unclamped projection xi lies beyond side s of a facet (2D: side s = vertex s;
   3D: side s = edge from vertex s to s+1), in units of the facet's parameter extent */
static inline PetscReal SPPairBeyond(PetscInt dim, PetscInt nv, const PetscReal xi[], PetscInt s)
{
  if (dim == 2) return s == 0 ? PetscMax(0.0, -xi[0]) : PetscMax(0.0, xi[0] - 1.0);
  return SPFacetBeyond(nv, xi, s);
}

/* Candidate data of slave xs against a master facet (nv vertices X): unclamped projection xi,
   distance d to the closest point of the (clamped) facet, excess e = max_s beyond(s).
   PETSC_FALSE: no projection (quad Newton and its fallback failed). */
static inline PetscBool SPPairCandidate(PetscInt dim, PetscInt nv, const PetscReal X[], const PetscReal xs[], PetscReal xi[], PetscReal *d, PetscReal *e)
{
  *e = 0.0;
  if (dim == 2) {
    SPSegmentProject(xs, &X[0], &X[2], &xi[0], d);
    xi[1] = 0.0;
    *e    = PetscMax(SPPairBeyond(2, 2, xi, 0), SPPairBeyond(2, 2, xi, 1));
    return PETSC_TRUE;
  }
  if (!SPFacetLocal(nv, X, xs, xi)) return PETSC_FALSE;
  for (PetscInt s = 0; s < nv; ++s) *e = PetscMax(*e, SPFacetBeyond(nv, xi, s));
  if (*e == 0.0) { /* inside: the closest point itself */
    SPFacetGeom G;
    PetscReal   r[3];
    SPFacetGeometry(nv, X, xi, &G);
    for (PetscInt k = 0; k < 3; ++k) r[k] = xs[k] - G.x[k];
    *d = SPNorm(3, r);
  } else { /* outside: the nearest boundary edge (straight for both facet types) */
    *d = PETSC_MAX_REAL;
    for (PetscInt s = 0; s < nv; ++s) *d = PetscMin(*d, SPSegmentDistance3(xs, &X[3 * s], &X[3 * ((s + 1) % nv)]));
  }
  return PETSC_TRUE;
}

/* Gap, normal, N = dg/du (dim (1 + nv)) and, if H, d2g/du2 at the projection xi (3D) */
static inline void SPPairGap(PetscInt dim, PetscInt nv, const PetscReal X[], const PetscReal xs[], const PetscReal xi[], PetscReal *g, PetscReal n[], PetscReal N[], PetscReal H[])
{
  if (dim == 2) {
    PetscReal t;
    SPSegmentGap(xs, &X[0], &X[2], g, n, &t, N, H);
  } else SPFacetGap(nv, X, xs, xi, g, n, N, H);
}

/* Unit normal of a facet at its centre (orientation check at set-up) */
static inline void SPPairCentreNormal(PetscInt dim, PetscInt nv, const PetscReal X[], PetscReal n[])
{
  if (dim == 2) {
    const PetscReal t[2] = {X[2] - X[0], X[3] - X[1]}, L = SPNorm(2, t);
    n[0] = t[1] / L, n[1] = -t[0] / L;
  } else {
    const PetscReal xi[2] = {nv == 3 ? 1.0 / 3.0 : 0.0, nv == 3 ? 1.0 / 3.0 : 0.0};
    SPFacetGeom     G;
    SPFacetGeometry(nv, X, xi, &G);
    for (PetscInt k = 0; k < 3; ++k) n[k] = G.n[k];
  }
}
#endif
