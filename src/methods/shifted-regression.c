/* Shifted penalty with the 2015-style regression update: least-squares fit g = a + b s over the
   last m (s, g) pairs of a point, next shift where the fit predicts g = 0. */
#include <spcontact-impl.h>

/* Falls back to Delta s = g while fewer than 3 pairs exist or when the fit is ill-conditioned
   (shifts too close, or b >= 0) */
static PetscReal ShiftRegression(PetscInt nh, const PetscReal hs[], const PetscReal hg[])
{
  PetscReal ms = 0, mg = 0, sss = 0, ssg = 0, b, a, scale = 0;
  if (nh < 3) return SPShiftIncrement(nh, hs, hg);
  for (PetscInt k = 0; k < nh; ++k) ms += hs[k] / nh, mg += hg[k] / nh, scale = PetscMax(scale, PetscAbsReal(hs[k]));
  for (PetscInt k = 0; k < nh; ++k) sss += (hs[k] - ms) * (hs[k] - ms), ssg += (hs[k] - ms) * (hg[k] - mg);
  if (sss <= PetscSqr(1e-8 * scale) * nh || sss == 0.0) return SPShiftIncrement(nh, hs, hg);
  b = ssg / sss;
  a = mg - b * ms;
  if (!(b < -1e-3) || b < -1e3) return SPShiftIncrement(nh, hs, hg);
  return -a / b;
}

static PetscErrorCode SetFromOptions(PetscOptionItems *PetscOptionsObject, SPMethodParams *p)
{
  PetscFunctionBeginUser;
  p->history = 4;
  PetscCall(PetscOptionsInt("-contact_regression_m", "shifted_regression: number of (shift, gap) pairs in the fit (>= 3)", "SPContactSetFromOptions", p->history, &p->history, NULL));
  PetscCheck(p->history >= 3, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-contact_regression_m %" PetscInt_FMT ": the fit needs at least 3 pairs", p->history);
  PetscFunctionReturn(PETSC_SUCCESS);
}

const SPMethod SPMethodShiftedRegression = {
  .name           = "shifted_regression",
  .help           = "shifted penalty, least-squares shift over the last m iterates",
  .timing         = SP_UPDATE_NEWTON,
  .law            = &SPLawShiftedPenalty,
  .update         = ShiftRegression,
  .setFromOptions = SetFromOptions,
};
