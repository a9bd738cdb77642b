/* Zavarise's shifted penalty: Delta s = g at every Newton-iteration boundary (the seed's update).
   The shift converges to -p/eps, so the gap goes to zero with no new unknowns. */
#include <spcontact-impl.h>

/* s_new = s_k + g_k */
PetscReal SPShiftIncrement(PetscInt nh, const PetscReal hs[], const PetscReal hg[])
{
  return hs[nh - 1] + hg[nh - 1];
}

/* The plain rule, optionally accelerated over all active points (contact-accel.c) */
static PetscErrorCode SetFromOptions(PetscOptionItems *PetscOptionsObject, SPMethodParams *p)
{
  PetscInt type = (PetscInt)p->accel;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsEList("-contact_shift_accel", "shifted: acceleration of the shift update on a settled active set: none (Delta s = g) or anderson (Anderson mixing of the last m updates over all active points; plain update when ill-conditioned or when the gap residual grew)", "SPContactSetFromOptions", SPShiftAccelTypes, 2, SPShiftAccelTypes[type], &type, NULL));
  p->accel = (SPShiftAccelType)type;
  PetscCall(PetscOptionsInt("-contact_shift_accel_depth", "shifted with -contact_shift_accel anderson: number m of past updates combined (1..50)", "SPContactSetFromOptions", p->accelDepth, &p->accelDepth, NULL));
  PetscCheck(p->accelDepth >= 1 && p->accelDepth <= 50, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-contact_shift_accel_depth %" PetscInt_FMT ": give 1..50 past updates", p->accelDepth);
  PetscFunctionReturn(PETSC_SUCCESS);
}

const SPMethod SPMethodShifted = {
  .name   = "shifted",
  .help   = "shifted penalty: Delta s = g before each Newton iteration",
  .timing = SP_UPDATE_NEWTON,
  .law    = &SPLawShiftedPenalty,
  .friction = PETSC_TRUE,
  .update = SPShiftIncrement,
  .setFromOptions = SetFromOptions,
};
