/* Zavarise's shifted penalty: Delta s = g at every Newton-iteration boundary (the seed's update).
   The shift converges to -p/eps, so the gap goes to zero with no new unknowns. */
#include <spcontact-impl.h>

/* s_new = s_k + g_k */
PetscReal SPShiftIncrement(PetscInt nh, const PetscReal hs[], const PetscReal hg[])
{
  return hs[nh - 1] + hg[nh - 1];
}

const SPMethod SPMethodShifted = {
  .name   = "shifted",
  .help   = "shifted penalty: Delta s = g before each Newton iteration",
  .timing = SP_UPDATE_NEWTON,
  .law    = &SPLawShiftedPenalty,
  .friction = PETSC_TRUE,
  .update = SPShiftIncrement,
};
