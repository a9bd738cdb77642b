/* The stuck points' tangential shifts predicted across load steps (-contact_shift_predict,
   friction, shifted): a load step whose load increment is a multiple r of the last converged one
   (every condition's amplitude and the obstacles' motion move in proportion), after a step that
   changed no point's status (open / stuck / slipping), starts each stuck point from the secant
   extrapolation of its committed traction over the last two converged steps,
     s_T <- -t_T/eps_T with t_T = t_T,commit + r (t_T,commit - t_T,prev),
   instead of the last step's traction. Where the load moves in proportion and the statuses stay,
   the tractions do too, and the in-Newton update starts from an error of second order in the
   increment instead of first: F1a takes one Newton iteration per shear step (12 -> 8 at alpha 10),
   F4 36 instead of 103. Not the normal shifts: predicting the stuck points' too took F4 36 / 17 /
   15 -> 38 / 21 / 19 at alpha 10 / 100 / 1000, and in a frictionless run stalled a Neo-Hookean
   block at the edge of its increment (finite_strain_load_regrow). Not the slipping points: with
   them F1b's one-iteration steps of steady sliding broke (a decaying transient extrapolated: 53 ->
   65 at alpha 10; 77 without the status condition). Not alm: its multipliers are its
   augmentations' to move. */
#include <spcontact-impl.h>

/* At a converged load step: the state at its start (c->saved, the previous converged step) becomes
   the predictor's older point */
PetscErrorCode SPContactPredictRecord(SPContact c)
{
  PetscFunctionBeginUser;
  if (!c->enabled || !c->friction) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) {
    SPPointPrev *prev = &c->pt[i].prev;
    prev->status      = c->saved[i].status;
    for (PetscInt d = 0; d < 3; ++d) prev->tCommit[d] = c->saved[i].tCommit[d];
  }
  c->havePrev = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The next solve starts from the predicted shifts with ratio r (0: no prediction) */
void SPContactPredictNext(SPContact c, PetscReal r)
{
  if (!c || !c->enabled) return;
  c->predictRatio = c->predict && c->friction && c->havePrev && c->method->timing == SP_UPDATE_NEWTON ? r : 0.0;
}

/* Stuck point i's extrapolated tangential shift, in its current basis (SPFrictionAnchor ran),
   clipped to its cone; whether it is stuck (predicted) */
static PetscBool PredictPoint(SPContact c, PetscInt i, PetscReal r)
{
  SPContactPoint    *pt   = &c->pt[i];
  SPPointState      *st   = &pt->st;
  const SPPointPrev *prev = &pt->prev;
  PetscReal          tp[3];

  if (st->status != SP_POINT_STICK || pt->geo.mu <= 0.0 || !st->anchored || st->fresh) return PETSC_FALSE;
  for (PetscInt d = 0; d < 3; ++d) tp[d] = st->tCommit[d] + r * (st->tCommit[d] - prev->tCommit[d]);
  for (PetscInt a = 0; a < c->dim - 1; ++a) st->sT[a] = -SPDot(c->dim, tp, st->T[a]) / pt->epsT;
  SPFrictionClipShift(c, i);
  return PETSC_TRUE;
}

/* At the start of a solve (SPContactBeginSolve, after the anchors): the pending prediction, once,
   where the last step changed no point's status. Counts the steps in which some point was
   predicted. Collective. */
PetscErrorCode SPContactPredictApply(SPContact c)
{
  const PetscReal r     = c->predictRatio;
  PetscInt        moved = 0, stuck = 0, all;

  PetscFunctionBeginUser;
  c->predictRatio = 0.0;
  if (r <= 0.0) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) moved += c->pt[i].st.status != c->pt[i].prev.status;
  PetscCallMPI(MPI_Allreduce(&moved, &all, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  if (all) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) stuck += PredictPoint(c, i, r);
  PetscCallMPI(MPI_Allreduce(&stuck, &all, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  if (all) c->predictions++;
  PetscFunctionReturn(PETSC_SUCCESS);
}
