/* Zavarise's shifted penalty: Delta s = g at every Newton-iteration boundary (the seed's update).
   The shift converges to -p/eps, so the gap goes to zero with no new unknowns. */
#include <spcontact-impl.h>

/* s_new = s_k + g_k */
PetscReal SPShiftIncrement(PetscInt nh, const PetscReal hs[], const PetscReal hg[])
{
  return hs[nh - 1] + hg[nh - 1];
}

/* The plain rule, optionally accelerated over all active points (contact-accel.c). Two-pass
   pairs default to Anderson: their redundant constraints make the plain update contract by
   about 0.92 per iteration at alpha 10 (B6 two-pass: 3029 Newton iterations and 20 cut-backs
   without converging, against 44 with Anderson; B5 two-pass 102950 against 10) */
static PetscErrorCode SetFromOptions(PetscOptionItems *PetscOptionsObject, SPMethodParams *p)
{
  PetscInt  type    = (PetscInt)p->accel;
  PetscBool twoPass = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-contact_two_pass", &twoPass, NULL));
  if (twoPass) type = SP_ACCEL_ANDERSON;
  PetscCall(PetscOptionsEList("-contact_shift_accel", "shifted: acceleration of the shift update on a settled active set: none (Delta s = g) or anderson (Anderson mixing of the last m updates over all active points; plain update when ill-conditioned or when the gap residual grew). Default: none, anderson with -contact_two_pass", "SPContactSetFromOptions", SPShiftAccelTypes, 2, SPShiftAccelTypes[type], &type, NULL));
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
