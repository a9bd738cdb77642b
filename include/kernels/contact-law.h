/* Pure contact law and rigid-obstacle geometry. No PETSc calls beyond scalar types.
   Sign convention: gap g < 0 is penetration, pressure p >= 0 is compressive.
   Shifted penalty energy per unit area: 1/2 eps <-(g + s)>^2, so with the point's area A
     force on the body      A p n,   p = -eps min(0, g + s)
     residual contribution  r = A eps min(0, g + s) dg/du,  dg/du = n
     tangent                K = A eps [ H(-(g+s)) n n^T + min(0, g + s) d2g/du2 ]
   A point is active when g + s <= 0 (so a point that just touches carries stiffness).
   Laws are apart from methods: a law maps (g, s, eps) to (p, k); the element below only needs those. */
#ifndef SP_KERNELS_CONTACT_LAW_H
#define SP_KERNELS_CONTACT_LAW_H
#include <kernels/tensor.h>

/* A normal contact law: pressure p(g, s) >= 0 for penalty eps, and its stiffness k = -dp/dg. A
   point is active (carries stiffness) where k > 0. `closed`: the law's closed branch extended
   past its opening (p may be negative there), which the branch hold linearises on after a shift
   update (contact-update.c). Methods pick a law (SPMethod.law). */
typedef struct {
  const char *name;
  void (*traction)(PetscReal g, PetscReal s, PetscReal eps, PetscReal *p, PetscReal *k);
  void (*closed)(PetscReal g, PetscReal s, PetscReal eps, PetscReal *p, PetscReal *k);
} SPNormalLaw;

/* The shifted penalty law p = -eps min(0, g + s); plain penalty is s = 0 */
static inline void SPShiftedPenaltyTraction(PetscReal g, PetscReal s, PetscReal eps, PetscReal *p, PetscReal *k)
{
  *p = -eps * PetscMin(0.0, g + s);
  *k = g + s <= 0.0 ? eps : 0.0;
}

/* Its closed branch: p = -eps (g + s) for every g */
static inline void SPShiftedPenaltyClosed(PetscReal g, PetscReal s, PetscReal eps, PetscReal *p, PetscReal *k)
{
  *p = -eps * (g + s);
  *k = eps;
}

typedef enum { SP_OBSTACLE_PLANE, SP_OBSTACLE_SPHERE, SP_OBSTACLE_CYLINDER } SPObstacleType;

typedef struct {
  SPObstacleType type;
  PetscReal      point[3];  /* plane: a point on it; sphere/cylinder: centre (on the axis) */
  PetscReal      normal[3]; /* plane: unit normal pointing into the body side; cylinder: unit axis */
  PetscReal      radius;
  PetscReal      motion[3]; /* rigid displacement at load factor 1 */
} SPObstacle;

/* Signed distance g of x to the obstacle moved by load*motion, unit normal n = dg/dx pointing
   away from the obstacle, and the curvature term Hg = d2g/dx2 (dim x dim, row-major). */
static inline void SPObstacleGap(const SPObstacle *ob, PetscInt dim, PetscReal load, const PetscReal x[], PetscReal *g, PetscReal n[], PetscReal Hg[])
{
  PetscReal d[3] = {0, 0, 0}, r, P[9];
  for (PetscInt i = 0; i < dim; ++i) d[i] = x[i] - (ob->point[i] + load * ob->motion[i]);
  for (PetscInt i = 0; i < dim * dim; ++i) Hg[i] = 0.0;
  if (ob->type == SP_OBSTACLE_PLANE) {
    *g = SPDot(dim, d, ob->normal);
    for (PetscInt i = 0; i < dim; ++i) n[i] = ob->normal[i];
    return;
  }
  /* P projects out the cylinder axis (3D only; a 2D cylinder is a circle, like a sphere) */
  for (PetscInt i = 0; i < dim; ++i)
    for (PetscInt j = 0; j < dim; ++j) P[i * dim + j] = (i == j) - ((ob->type == SP_OBSTACLE_CYLINDER && dim == 3) ? ob->normal[i] * ob->normal[j] : 0.0);
  {
    PetscReal dp[3] = {0, 0, 0};
    for (PetscInt i = 0; i < dim; ++i)
      for (PetscInt j = 0; j < dim; ++j) dp[i] += P[i * dim + j] * d[j];
    r  = SPNorm(dim, dp);
    *g = r - ob->radius;
    for (PetscInt i = 0; i < dim; ++i) n[i] = r > 0.0 ? dp[i] / r : (i == dim - 1);
  }
  if (r > 0.0)
    for (PetscInt i = 0; i < dim; ++i)
      for (PetscInt j = 0; j < dim; ++j) Hg[i * dim + j] = (P[i * dim + j] - n[i] * n[j]) / r;
}

/* Residual (nd) and tangent (nd x nd) of one contact element of area A carrying pressure p with
   stiffness k = -dp/dg: the dofs it touches are the slave vertex (and, for a contact pair, the
   master facet's vertices); N = dg/du (nd) and Hg = d2g/du2 (nd x nd). Against a rigid obstacle
   nd = dim and N = n.  r = -A p N,  K = A (k N N^T - p Hg). */
static inline void SPContactElement(PetscInt nd, PetscReal A, PetscReal p, PetscReal k, const PetscReal N[], const PetscReal Hg[], PetscReal r[], PetscReal K[])
{
  for (PetscInt i = 0; i < nd; ++i) {
    if (r) r[i] = -A * p * N[i];
    if (K)
      for (PetscInt j = 0; j < nd; ++j) K[i * nd + j] = A * (k * N[i] * N[j] - p * Hg[i * nd + j]);
  }
}
#endif
