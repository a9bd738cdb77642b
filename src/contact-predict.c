/* Shift predictor across load steps (-contact_shift_predict): at the first Newton iteration of a
   load step whose load increment is a multiple r of the last converged one (every condition's
   amplitude and the obstacles' motion move in proportion), each point's shifts start from the
   secant extrapolation of the last two converged steps instead of the last one:
     s_N <- min(0, s_N + r (s_N - s_N,prev)),  t_T <- t_T,commit + r (t_T,commit - t_T,prev),
   the tangential shift being -t_T/eps_T. The in-Newton update then starts from an error of second
   order in the increment. Only for methods that update the shifts at Newton-iteration boundaries:
   penalty has no shift, and alm's multipliers are its augmentations' to move. */
#include <spcontact-impl.h>

/* At a converged load step: the state at its start (the previous converged step) becomes the
   predictor's older point. Before SPContactCommitStep overwrites nothing of it: c->saved holds it. */
PetscErrorCode SPContactPredictRecord(SPContact c)
{
  PetscFunctionBeginUser;
  if (!c->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) {
    SPPointPrev *prev = &c->pt[i].prev;
    prev->sN          = c->saved[i].sN;
    prev->status      = c->saved[i].status;
    for (PetscInt d = 0; d < 3; ++d) prev->tCommit[d] = c->saved[i].tCommit[d];
  }
  c->havePrev = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The next solve starts from the extrapolated shifts with ratio r (0: no prediction) */
void SPContactPredictNext(SPContact c, PetscReal r)
{
  if (c && c->enabled) c->predictRatio = c->predict && c->havePrev && c->method->timing == SP_UPDATE_NEWTON ? r : 0.0;
}

/* Point i's extrapolated shifts (its friction basis is the current one: SPFrictionAnchor ran) */
static void PredictPoint(SPContact c, PetscInt i, PetscReal r)
{
  SPContactPoint *pt = &c->pt[i];
  SPPointState   *st = &pt->st;
  const SPPointPrev *prev = &pt->prev;
  PetscReal        tp[3];

  if (st->status != SP_POINT_STICK) return;
  st->sN = PetscMin(0.0, st->sN + r * (st->sN - prev->sN));
  if (!c->friction || !st->anchored || st->fresh) return;
  for (PetscInt d = 0; d < 3; ++d) tp[d] = st->tCommit[d] + r * (st->tCommit[d] - prev->tCommit[d]);
  for (PetscInt a = 0; a < c->dim - 1; ++a) st->sT[a] = -SPDot(c->dim, tp, st->T[a]) / pt->epsT;
}

/* At the start of a solve (SPContactBeginSolve, after the anchors): the pending prediction, once */
PetscErrorCode SPContactPredictApply(SPContact c)
{
  const PetscReal r = c->predictRatio;

  PetscInt        moved = 0, all;

  PetscFunctionBeginUser;
  c->predictRatio = 0.0;
  if (r <= 0.0) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) moved += c->pt[i].st.status != c->pt[i].prev.status;
  PetscCallMPI(MPI_Allreduce(&moved, &all, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  if (all) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) PredictPoint(c, i, r);
  PetscCall(SPFrictionClipShifts(c));
  c->predictions++;
  PetscFunctionReturn(PETSC_SUCCESS);
}
