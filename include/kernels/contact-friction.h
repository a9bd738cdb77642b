/* Coulomb friction with a tangential shift (friction.md): pure kernels, no PETSc calls beyond
   scalar types. In a load step the tangential relative displacement of a point is linear in u,
     Dg_T = B_T u + c   (nt = dim - 1 components in the committed tangent basis),
   the trial traction is y = -eps_T (Dg_T + s_T), and the return map onto the cone of radius
   r = mu p (p the normal pressure of the current iterate) gives
     stick |y| <= r:  t = y
     slip:            t = r y / |y|.
   The slave receives the force A t (in the tangent basis); the residual is r = -A B_T^T t. */
#ifndef SP_KERNELS_CONTACT_FRICTION_H
#define SP_KERNELS_CONTACT_FRICTION_H
#include <kernels/tensor.h>

/* Return map: t from the trial y (nt components) and the radius r >= 0; PETSC_TRUE: stick */
static inline PetscBool SPCoulombReturn(PetscInt nt, const PetscReal y[], PetscReal r, PetscReal t[])
{
  const PetscReal ny = SPNorm(nt, y);
  if (ny <= r) {
    for (PetscInt k = 0; k < nt; ++k) t[k] = y[k];
    return PETSC_TRUE;
  }
  for (PetscInt k = 0; k < nt; ++k) t[k] = r * y[k] / ny;
  return PETSC_FALSE;
}

/* Residual (nd) and tangent (nd x nd, row-major, non-symmetric in slip) of the friction part of one
   contact element: area A, tangential penalty epsT, friction coefficient mu, normal pressure p and
   its stiffness k = -dp/dg, BT = dDg_T/du (nt x nd, row-major), N = dg/du (nd), trial y, returned
   t, stick flag. Tangent: stick A epsT BT^T BT; slip A mu k BT^T m N^T + A (mu p epsT/|y|) BT^T (I - m m^T) BT,
   m = y/|y| (the second term vanishes in 2D). */
static inline void SPFrictionElement(PetscInt nd, PetscInt nt, PetscReal A, PetscReal epsT, PetscReal mu, PetscReal p, PetscReal k, const PetscReal BT[], const PetscReal N[], const PetscReal y[], const PetscReal t[], PetscBool stick, PetscReal r[], PetscReal K[])
{
  const PetscReal ny = SPNorm(nt, y);
  PetscReal       m[2] = {0, 0}, P[4] = {0, 0, 0, 0};
  if (r)
    for (PetscInt i = 0; i < nd; ++i) {
      r[i] = 0.0;
      for (PetscInt a = 0; a < nt; ++a) r[i] -= A * BT[a * nd + i] * t[a];
    }
  if (!K) return;
  if (!stick && ny > 0.0)
    for (PetscInt a = 0; a < nt; ++a) m[a] = y[a] / ny;
  for (PetscInt a = 0; a < nt; ++a) /* dt/dy: stick I; slip (mu p/|y|)(I - m m^T) */
    for (PetscInt b = 0; b < nt; ++b) P[a * nt + b] = stick ? (a == b) : (ny > 0.0 ? mu * p / ny * ((a == b) - m[a] * m[b]) : 0.0);
  for (PetscInt i = 0; i < nd; ++i)
    for (PetscInt j = 0; j < nd; ++j) {
      PetscReal v = 0.0;
      for (PetscInt a = 0; a < nt; ++a) {
        for (PetscInt b = 0; b < nt; ++b) v += epsT * BT[a * nd + i] * P[a * nt + b] * BT[b * nd + j];
        if (!stick) v += mu * k * BT[a * nd + i] * m[a] * N[j];
      }
      K[i * nd + j] = A * v;
    }
}
#endif
