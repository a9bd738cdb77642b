/* Node-to-facet geometry (3D) for deformable-deformable contact: a slave vertex xs against a
   linear triangle (nv = 3) or a bilinear quadrilateral (nv = 4) master facet. Pure: no PETSc calls
   beyond scalar types.

   Surface x(xi) = sum_a N_a(xi) x_a, xi = (xi^1, xi^2):
     triangle  N = (1 - xi - eta, xi, eta)                         (barycentric: xi, eta >= 0, xi + eta <= 1)
     quad      N_a = (1 + xi xi_a)(1 + eta eta_a)/4, corners (-1,-1), (1,-1), (1,1), (-1,1)
   Covariant basis a_alpha = x_{,alpha}, metric m_ab = a_a . a_b, normal n = a_1 x a_2 / |a_1 x a_2|
   (the vertex order makes n point out of the master body), curvature b_ab = n . x_{,ab} (quad:
   only b_12 = b_21 = n . sum_a xi_a eta_a x_a / 4; triangle: 0).

   Projection: xi solves (xs - x(xi)) . a_alpha = 0 on the EXTENDED facet (no clamping), so
   xs - x(xi) = g n and the gap is g = (xs - x(xi)) . n. Triangle: closed form. Quad: Newton on
   f(xi) = |xs - x(xi)|^2 / 2 from the centre, Hessian m_ab - g b_ab, at most SP_FACET_NEWTON_MAX
   iterations, converged when |dxi| <= SP_FACET_NEWTON_TOL; fallback (Hessian not positive definite,
   no convergence, or |xi| > SP_FACET_XI_MAX): Gauss-Newton (Hessian m_ab) with steps limited to 0.5
   from the centre; if that fails too the facet is not a candidate.

   Variations (Wriggers, Computational Contact Mechanics, node-to-surface): with the relative
   variation du = dxs - sum_a N_a dx_a and da_alpha = sum_a N_a,alpha dx_a,
     dg   = n . du                                        (N = [n; -N_1 n; ...; -N_nv n])
     Dxi  = (m - g b)^-1 (a . Du + g n . Da)              (variation of the projection point)
     Dn   = -(n . Da_b + b_bc Dxi^c) a^b,  a^b = m^bc a_c (variation of the normal)
     DDg  = -(n . Da_b + b_bc Dxi^c) m^bd (a_d . du) - Dxi^a (n . da_a)
   which is the exact second derivative of g (symmetric), consistent for finite sliding. */
#ifndef SP_KERNELS_CONTACT_FACET_H
#define SP_KERNELS_CONTACT_FACET_H
#include <kernels/tensor.h>

#define SP_FACET_NEWTON_MAX 25
#define SP_FACET_NEWTON_TOL 1e-14
#define SP_FACET_XI_MAX     10.0

static inline void SPCross(const PetscReal a[], const PetscReal b[], PetscReal c[])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/* Shape functions, their derivatives dN[a*2+alpha] and mixed second derivatives ddN[a] */
static inline void SPFacetShape(PetscInt nv, const PetscReal xi[], PetscReal N[], PetscReal dN[], PetscReal ddN[])
{
  if (nv == 3) {
    N[0] = 1.0 - xi[0] - xi[1], N[1] = xi[0], N[2] = xi[1];
    dN[0] = -1.0, dN[1] = -1.0, dN[2] = 1.0, dN[3] = 0.0, dN[4] = 0.0, dN[5] = 1.0;
    ddN[0] = ddN[1] = ddN[2] = 0.0;
  } else {
    const PetscReal xa[4] = {-1, 1, 1, -1}, ea[4] = {-1, -1, 1, 1};
    for (PetscInt a = 0; a < 4; ++a) {
      N[a]          = 0.25 * (1 + xi[0] * xa[a]) * (1 + xi[1] * ea[a]);
      dN[a * 2 + 0] = 0.25 * xa[a] * (1 + xi[1] * ea[a]);
      dN[a * 2 + 1] = 0.25 * ea[a] * (1 + xi[0] * xa[a]);
      ddN[a]        = 0.25 * xa[a] * ea[a];
    }
  }
}

/* Point x(xi), basis a[alpha*3+k], mixed derivative x12, metric m (2x2), its inverse mi, normal n */
typedef struct {
  PetscReal N[4], dN[8], ddN[4];
  PetscReal x[3], a[6], x12[3], m[4], mi[4], n[3], J;
} SPFacetGeom;

static inline void SPFacetGeometry(PetscInt nv, const PetscReal X[], const PetscReal xi[], SPFacetGeom *G)
{
  PetscReal det, c[3];
  SPFacetShape(nv, xi, G->N, G->dN, G->ddN);
  for (PetscInt k = 0; k < 3; ++k) {
    G->x[k] = G->a[k] = G->a[3 + k] = G->x12[k] = 0.0;
    for (PetscInt a = 0; a < nv; ++a) {
      G->x[k] += G->N[a] * X[a * 3 + k];
      G->a[k] += G->dN[a * 2] * X[a * 3 + k];
      G->a[3 + k] += G->dN[a * 2 + 1] * X[a * 3 + k];
      G->x12[k] += G->ddN[a] * X[a * 3 + k];
    }
  }
  G->m[0] = SPDot(3, &G->a[0], &G->a[0]);
  G->m[1] = G->m[2] = SPDot(3, &G->a[0], &G->a[3]);
  G->m[3] = SPDot(3, &G->a[3], &G->a[3]);
  det     = G->m[0] * G->m[3] - G->m[1] * G->m[2];
  G->mi[0] = G->m[3] / det, G->mi[1] = G->mi[2] = -G->m[1] / det, G->mi[3] = G->m[0] / det;
  SPCross(&G->a[0], &G->a[3], c);
  G->J = SPNorm(3, c);
  for (PetscInt k = 0; k < 3; ++k) G->n[k] = c[k] / G->J;
}

/* Unclamped local coordinates of the closest point of the extended facet; PETSC_FALSE if the
   quad projection (Newton, then Gauss-Newton) failed */
static inline PetscBool SPFacetLocal(PetscInt nv, const PetscReal X[], const PetscReal xs[], PetscReal xi[])
{
  xi[0] = xi[1] = nv == 3 ? 1.0 / 3.0 : 0.0;
  for (PetscInt pass = 0; pass < 2; ++pass) {
    const PetscInt maxit = nv == 3 ? 1 : (pass == 0 ? SP_FACET_NEWTON_MAX : 4 * SP_FACET_NEWTON_MAX);
    for (PetscInt it = 0; it < maxit; ++it) {
      SPFacetGeom G;
      PetscReal   d[3], r[2], K[4], det, dx[2], len;
      SPFacetGeometry(nv, X, xi, &G);
      for (PetscInt k = 0; k < 3; ++k) d[k] = xs[k] - G.x[k];
      r[0] = SPDot(3, d, &G.a[0]);
      r[1] = SPDot(3, d, &G.a[3]);
      K[0] = G.m[0], K[1] = G.m[1] - (pass == 0 ? SPDot(3, d, G.x12) : 0.0), K[3] = G.m[3];
      det  = K[0] * K[3] - K[1] * K[1];
      if (!(det > 0.0 && K[0] > 0.0)) break; /* not a minimum: fallback */
      dx[0] = (K[3] * r[0] - K[1] * r[1]) / det;
      dx[1] = (K[0] * r[1] - K[1] * r[0]) / det;
      len   = PetscSqrtReal(dx[0] * dx[0] + dx[1] * dx[1]);
      if (pass == 1 && len > 0.5) dx[0] *= 0.5 / len, dx[1] *= 0.5 / len;
      xi[0] += dx[0], xi[1] += dx[1];
      if (nv == 3) return PETSC_TRUE;
      if (PetscAbsReal(xi[0]) > SP_FACET_XI_MAX || PetscAbsReal(xi[1]) > SP_FACET_XI_MAX) break;
      if (len <= SP_FACET_NEWTON_TOL * (1.0 + PetscAbsReal(xi[0]) + PetscAbsReal(xi[1]))) return PETSC_TRUE;
    }
    xi[0] = xi[1] = 0.0;
  }
  return PETSC_FALSE;
}

/* How far xi lies beyond side s of the facet (side s joins vertices s and s+1), in units of the
   facet's parameter extent (0: on or inside) */
static inline PetscReal SPFacetBeyond(PetscInt nv, const PetscReal xi[], PetscInt s)
{
  if (nv == 3) {
    const PetscReal lam[3] = {1.0 - xi[0] - xi[1], xi[0], xi[1]};
    return PetscMax(0.0, -lam[(s + 2) % 3]);
  } else {
    const PetscReal v[4] = {-1.0 - xi[1], xi[0] - 1.0, xi[1] - 1.0, -1.0 - xi[0]};
    return PetscMax(0.0, 0.5 * v[s]);
  }
}

/* Distance of x to the segment p -> q (3D) */
static inline PetscReal SPSegmentDistance3(const PetscReal x[], const PetscReal p[], const PetscReal q[])
{
  PetscReal t[3], d[3], L2, s;
  for (PetscInt k = 0; k < 3; ++k) t[k] = q[k] - p[k], d[k] = x[k] - p[k];
  L2 = SPDot(3, t, t);
  s  = L2 > 0.0 ? PetscMin(1.0, PetscMax(0.0, SPDot(3, d, t) / L2)) : 0.0;
  for (PetscInt k = 0; k < 3; ++k) d[k] -= s * t[k];
  return SPNorm(3, d);
}

/* Gap g, normal n, N = dg/du (3 (1 + nv)) and, if H, H = d2g/du2 (row-major) at the local
   coordinates xi (a converged projection) */
static inline void SPFacetGap(PetscInt nv, const PetscReal X[], const PetscReal xs[], const PetscReal xi[], PetscReal *g, PetscReal n[], PetscReal N[], PetscReal H[])
{
  const PetscInt nd = 3 * (1 + nv);
  SPFacetGeom    G;
  PetscReal      d[3], b12, A[4], Ai[4], det, cu[5], ca[10];
  PetscReal      P[2][15], Q[2][15], U[2][15], D[2][15], MU[2][15];

  SPFacetGeometry(nv, X, xi, &G);
  for (PetscInt k = 0; k < 3; ++k) d[k] = xs[k] - G.x[k], n[k] = G.n[k];
  *g  = SPDot(3, d, n);
  cu[0] = 1.0, ca[0] = ca[1] = 0.0;
  for (PetscInt a = 0; a < nv; ++a) cu[1 + a] = -G.N[a], ca[2 * (1 + a)] = G.dN[2 * a], ca[2 * (1 + a) + 1] = G.dN[2 * a + 1];
  for (PetscInt k = 0; k < nd; ++k) N[k] = n[k % 3] * cu[k / 3];
  if (!H) return;
  b12  = SPDot(3, n, G.x12);
  A[0] = G.m[0], A[1] = A[2] = G.m[1] - (*g) * b12, A[3] = G.m[3];
  det  = A[0] * A[3] - A[1] * A[2];
  Ai[0] = A[3] / det, Ai[1] = Ai[2] = -A[1] / det, Ai[3] = A[0] / det;
  for (PetscInt k = 0; k < nd; ++k) {
    const PetscInt v = k / 3, i = k % 3;
    for (PetscInt al = 0; al < 2; ++al) {
      U[al][k] = G.a[3 * al + i] * cu[v];  /* a_alpha . du_k */
      Q[al][k] = n[i] * ca[2 * v + al];    /* n . da_alpha,k */
      P[al][k] = U[al][k] + (*g) * Q[al][k];
    }
    for (PetscInt al = 0; al < 2; ++al) {
      D[al][k]  = Ai[2 * al] * P[0][k] + Ai[2 * al + 1] * P[1][k];  /* Dxi^alpha */
      MU[al][k] = G.mi[2 * al] * U[0][k] + G.mi[2 * al + 1] * U[1][k]; /* m^ab a_b . du */
    }
  }
  for (PetscInt j = 0; j < nd; ++j)
    for (PetscInt k = 0; k < nd; ++k) {
      /* b_bc Dxi^c: b has only the off-diagonal b12 */
      const PetscReal w0 = Q[0][k] + b12 * D[1][k], w1 = Q[1][k] + b12 * D[0][k];
      H[j * nd + k] = -(w0 * MU[0][j] + w1 * MU[1][j]) - (D[0][k] * Q[0][j] + D[1][k] * Q[1][j]);
    }
}
#endif
