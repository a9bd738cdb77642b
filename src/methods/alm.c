/* Nested augmented Lagrangian (Uzawa): the shift (a scaled multiplier) is frozen during a Newton
   solve and updated s <- min(0, s + g) after each converged solve, until the gap tolerance holds.
   The outer loop runs in loading.c, inside the load step, so a failure cuts the step back. */
#include <spcontact-impl.h>

static PetscErrorCode SetFromOptions(PetscOptionItems *PetscOptionsObject, SPMethodParams *p)
{
  PetscFunctionBeginUser;
  p->maxUpdates = 50; /* two-pass B6 at alpha 10 needs 40 (30: 515 Newton iterations, 3 cut-backs -> 58, none); every other input at most 18 */
  p->maxOption  = "-contact_alm_max";
  PetscCall(PetscOptionsInt("-contact_alm_max", "alm: maximum number of augmentations per load step", "SPContactSetFromOptions", p->maxUpdates, &p->maxUpdates, NULL));
  PetscCheck(p->maxUpdates >= 1, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-contact_alm_max %" PetscInt_FMT ": need at least 1 augmentation", p->maxUpdates);
  PetscFunctionReturn(PETSC_SUCCESS);
}

const SPMethod SPMethodALM = {
  .name           = "alm",
  .help           = "nested augmented Lagrangian: s <- s + g after each converged Newton solve",
  .timing         = SP_UPDATE_SOLVE,
  .law            = &SPLawShiftedPenalty,
  .friction       = PETSC_TRUE,
  .update         = SPShiftIncrement,
  .setFromOptions = SetFromOptions,
};
