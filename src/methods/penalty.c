/* Plain penalty: the shifted-penalty law with s = 0, never updated. Leaves a penetration ~ p/eps. */
#include <spcontact-impl.h>

const SPMethod SPMethodPenalty = {
  .name   = "penalty",
  .help   = "plain penalty p = -eps min(0, g)",
  .timing = SP_UPDATE_NONE,
  .law    = &SPLawShiftedPenalty,
  .friction = PETSC_TRUE,
};
