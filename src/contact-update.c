/* Shift (scaled multiplier) update and contact bookkeeping at Newton-iteration boundaries:
   active sets, the safeguards of method.md section 4, convergence, augmentation, statistics. */
#include <spcontact-impl.h>

/* Constraint error of point i: its penetration, and for an active point also an open gap (an
   active point carrying pressure across a gap, as after a shift overshoot, violates g = 0 too) */
static inline PetscReal GapError(PetscReal g, PetscBool active)
{
  return active ? PetscAbsReal(g) : PetscMax(0.0, -g);
}

static PetscErrorCode Reduce(SPContact c, PetscInt nloc[2], PetscReal rloc[3])
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)c->dm);
  PetscInt  nall[2];
  PetscReal rall[3];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(nloc, nall, 2, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(rloc, rall, 3, MPIU_REAL, MPI_MAX, comm));
  c->stats.activePoints   = nall[0];
  c->stats.activeChanged  = nall[1];
  c->stats.maxPenetration = rall[0];
  c->stats.maxShiftChange = rall[1];
  c->stats.gapError       = rall[2];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Active set and statistics of the state in c->gap with the current shift */
static PetscErrorCode Bookkeep(SPContact c, const PetscScalar s[], PetscReal maxDs, PetscBool compare)
{
  PetscInt  n[2] = {0, 0};
  PetscReal r[3] = {0.0, maxDs, 0.0};

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->n; ++i) {
    c->active[i] = SPContactLawActive(c->gap[i], PetscRealPart(s[i]));
    n[0] += c->active[i];
    if (compare) n[1] += c->active[i] != c->activePrev[i];
    c->activePrev[i] = c->active[i];
    r[0]             = PetscMax(r[0], -c->gap[i]);
    r[2]             = PetscMax(r[2], GapError(c->gap[i], c->active[i]));
  }
  PetscCall(Reduce(c, n, r));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode EvaluateGlobal(SPContact c, Vec X)
{
  Vec locX;

  PetscFunctionBeginUser;
  PetscCall(SPProblemGetLocalState(c->problem, X, &locX));
  PetscCall(SPContactEvaluate(c, locX));
  PetscCall(SPProblemRestoreLocalState(c->problem, &locX));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Before a Newton solve: active set of the initial iterate (it drives the first Jacobian) */
PetscErrorCode SPContactBeginSolve(SPContact c, Vec X)
{
  const PetscScalar *s;

  PetscFunctionBeginUser;
  PetscCall(EvaluateGlobal(c, X));
  PetscCall(VecGetArrayRead(c->shift, &s));
  PetscCall(Bookkeep(c, s, 0.0, PETSC_FALSE));
  PetscCall(VecRestoreArrayRead(c->shift, &s));
  c->setSettled = PETSC_FALSE;
  for (PetscInt i = 0; i < c->n; ++i) c->nhist[i] = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Record (s, g) of point i, newest last, at most regM pairs */
static void PushHistory(SPContact c, PetscInt i, PetscReal s, PetscReal g)
{
  PetscReal *hs = &c->histS[i * c->regM], *hg = &c->histG[i * c->regM];
  if (c->nhist[i] == c->regM) {
    for (PetscInt k = 1; k < c->regM; ++k) hs[k - 1] = hs[k], hg[k - 1] = hg[k];
    c->nhist[i]--;
  }
  hs[c->nhist[i]] = s;
  hg[c->nhist[i]] = g;
  c->nhist[i]++;
}

/* The in-Newton shift update for point i (method.md section 4, safeguards 1 and 2) */
static PetscReal UpdatePoint(SPContact c, PetscInt i, PetscReal s)
{
  const PetscBool activeNow = SPContactLawActive(c->gap[i], s);
  if ((c->activePrev[i] || !c->safeguard) && activeNow) { /* active in the solve that produced the iterate, and now */
    c->inactiveCount[i] = 0;
    PushHistory(c, i, s, c->gap[i]);
    return PetscMin(0.0, c->entry->shift(c->nhist[i], &c->histS[i * c->regM], &c->histG[i * c->regM]));
  }
  c->nhist[i] = 0;
  if (!activeNow) c->inactiveCount[i]++;
  else c->inactiveCount[i] = 0;
  return c->inactiveCount[i] >= 2 ? 0.0 : s; /* reset after two inactive iterates in a row */
}

/* Whether the in-Newton shift update applies at this boundary: not once the gap tolerance holds
   (an update then only perturbs a converged state), and, with -contact_shift_settled, only when
   no point changed its active state in the last iteration (the contraction k/(k+eps) of
   method.md section 2 needs a settled active set; an update during a change overshoots). */
static PetscErrorCode ShiftUpdateApplies(SPContact c, const PetscScalar s[], PetscBool *applies)
{
  PetscInt  n = 0, nall;
  PetscReal err = 0.0, errAll;
  MPI_Comm  comm = PetscObjectComm((PetscObject)c->dm);

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscBool active = SPContactLawActive(c->gap[i], PetscRealPart(s[i]));
    n += active != c->activePrev[i];
    err = PetscMax(err, GapError(c->gap[i], active));
  }
  PetscCallMPI(MPI_Allreduce(&n, &nall, 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&err, &errAll, 1, MPIU_REAL, MPI_MAX, comm));
  *applies = c->entry->updatesInNewton && errAll > c->gapTol && (nall == 0 || !c->settled) ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* At a Newton-iteration boundary, on the new iterate W: gaps, shift update (in-Newton methods),
   active-set change. *changed says the residual must be recomputed for the new shift. */
PetscErrorCode SPContactNewtonUpdate(SPContact c, Vec W, PetscBool *changed)
{
  PetscScalar *s;
  PetscReal    maxDs = 0.0, all;
  PetscBool    applies = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(EvaluateGlobal(c, W));
  PetscCall(VecGetArray(c->shift, &s));
  PetscCall(ShiftUpdateApplies(c, s, &applies));
  if (applies)
    for (PetscInt i = 0; i < c->n; ++i) {
      const PetscReal old = PetscRealPart(s[i]);
      s[i]                = UpdatePoint(c, i, old);
      maxDs               = PetscMax(maxDs, PetscAbsReal(PetscRealPart(s[i]) - old));
    }
  PetscCall(Bookkeep(c, s, maxDs, PETSC_TRUE));
  c->setSettled = c->stats.activeChanged == 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(VecRestoreArray(c->shift, &s));
  PetscCallMPI(MPI_Allreduce(&maxDs, &all, 1, MPIU_REAL, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  *changed = all > 0.0 ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Newton step control on the proposed iterate W = X - Y: scale the step so that no point that is
   not yet deep gets deeper than stepCap*h in one step (gaps interpolated linearly along the step).
   It matters when a load-controlled body touches at one point: its first step is otherwise
   sized by a single penalty spring. Inactive once penetrations are small. */
PetscErrorCode SPContactLimitStep(SPContact c, Vec X, Vec Y, Vec W, PetscBool *changed)
{
  PetscReal theta = 1.0, all;

  PetscFunctionBeginUser;
  *changed = PETSC_FALSE;
  if (c->stepCap <= 0.0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(EvaluateGlobal(c, X));
  for (PetscInt i = 0; i < c->n; ++i) c->gapStart[i] = c->gap[i];
  PetscCall(EvaluateGlobal(c, W));
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscReal cap = c->stepCap * c->h[i];
    if (c->gap[i] < -cap && c->gapStart[i] > -cap) theta = PetscMin(theta, (c->gapStart[i] + cap) / (c->gapStart[i] - c->gap[i]));
  }
  PetscCallMPI(MPI_Allreduce(&theta, &all, 1, MPIU_REAL, MPI_MIN, PetscObjectComm((PetscObject)c->dm)));
  if (all < 1.0) {
    PetscCall(VecWAXPY(W, -all, Y, X));
    *changed = PETSC_TRUE;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Uzawa step after a converged Newton solve (alm): s <- min(0, s + g). *done when the gap
   tolerance already holds (then nothing changes). */
PetscErrorCode SPContactAugment(SPContact c, Vec X, PetscBool *done)
{
  PetscScalar *s;
  PetscReal    maxDs = 0.0;

  PetscFunctionBeginUser;
  PetscCall(EvaluateGlobal(c, X));
  PetscCall(VecGetArray(c->shift, &s));
  PetscCall(Bookkeep(c, s, 0.0, PETSC_FALSE));
  *done = c->stats.gapError <= c->gapTol ? PETSC_TRUE : PETSC_FALSE;
  if (!*done) {
    for (PetscInt i = 0; i < c->n; ++i) {
      const PetscReal old = PetscRealPart(s[i]);
      s[i]                = PetscMin(0.0, old + c->gap[i]);
      maxDs               = PetscMax(maxDs, PetscAbsReal(PetscRealPart(s[i]) - old));
    }
    PetscCall(Bookkeep(c, s, maxDs, PETSC_FALSE));
    c->stats.augmentations++;
  }
  PetscCall(VecRestoreArray(c->shift, &s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Contact part of the convergence test (method.md section 4, safeguard 4) */
PetscErrorCode SPContactConverged(SPContact c, PetscBool *ok)
{
  PetscFunctionBeginUser;
  *ok = c->stats.activeChanged == 0 ? PETSC_TRUE : PETSC_FALSE;
  if (c->entry->checksGap && c->stats.gapError > c->gapTol) *ok = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Warm start across load steps is automatic (s persists); these support the cut-back. */
PetscErrorCode SPContactSaveState(SPContact c)
{
  PetscFunctionBeginUser;
  if (c->enabled) PetscCall(VecCopy(c->shift, c->shiftSaved));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactRestoreState(SPContact c)
{
  PetscFunctionBeginUser;
  if (!c->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecCopy(c->shiftSaved, c->shift));
  for (PetscInt i = 0; i < c->n; ++i) c->nhist[i] = 0, c->inactiveCount[i] = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Resultant contact force on the slave bodies (points of obstacle slaves and of the user's pairs'
   slave surfaces: with two passes it includes the force they receive as masters), peak recovered
   pressure, and the extent of the pressure zone measured from the peak point (reference
   coordinates). Uses the last evaluated state; collective. */
PetscErrorCode SPContactComputeStats(SPContact c, const PetscScalar s[])
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)c->dm);
  PetscReal f[3] = {0, 0, 0}, peak[2] = {-1.0, 0.0}, gpeak[2], xp[3] = {0, 0, 0}, rmax = 0.0;
  PetscMPIInt rank;
  PetscInt  ipeak = -1;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(SPContactRecoverForces(c, s));
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscReal p = c->press[i];
    if (c->primary[i])
      for (PetscInt d = 0; d < c->dim; ++d) f[d] += c->fpt[i * c->dim + d];
    if (p > peak[0]) peak[0] = p, ipeak = i;
  }
  PetscCallMPI(MPI_Allreduce(f, c->stats.force, 3, MPIU_REAL, MPI_SUM, comm));
  peak[1] = rank;
  PetscCallMPI(MPI_Allreduce(peak, gpeak, 1, MPI_2DOUBLE_PRECISION, MPI_MAXLOC, comm));
  if (ipeak >= 0 && (PetscMPIInt)gpeak[1] == rank)
    for (PetscInt d = 0; d < c->dim; ++d) xp[d] = c->coord[ipeak * c->dim + d];
  PetscCallMPI(MPI_Bcast(xp, 3, MPIU_REAL, (PetscMPIInt)gpeak[1], comm));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscReal dx[3] = {0, 0, 0};
    if (c->press[i] <= 0.0) continue;
    for (PetscInt d = 0; d < c->dim; ++d) dx[d] = c->coord[i * c->dim + d] - xp[d];
    rmax = PetscMax(rmax, SPNorm(c->dim, dx));
  }
  PetscCallMPI(MPI_Allreduce(&rmax, &c->stats.contactRadius, 1, MPIU_REAL, MPI_MAX, comm));
  c->stats.peakPressure = PetscMax(gpeak[0], 0.0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactGetStats(SPContact c, SPContactStats *stats)
{
  const PetscScalar *s;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(c->shift, &s));
  PetscCall(SPContactComputeStats(c, s));
  PetscCall(VecRestoreArrayRead(c->shift, &s));
  *stats = c->stats;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Contact pairs: one line per converged load step (force on the slave and on the master
   surfaces, max penetration, peak pressure), so load paths (sliding) can be checked step by step */
PetscErrorCode SPContactReportStep(SPContact c, Vec X, PetscInt step, PetscReal load)
{
  const PetscScalar *s;
  Vec                locX;
  PetscReal          pen = 0.0, all;

  PetscFunctionBeginUser;
  if (!c->enabled || !c->npair) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPProblemGetLocalState(c->problem, X, &locX));
  PetscCall(SPContactEvaluate(c, locX));
  PetscCall(SPProblemRestoreLocalState(c->problem, &locX));
  PetscCall(VecGetArrayRead(c->shift, &s));
  PetscCall(SPContactComputeStats(c, s));
  PetscCall(VecRestoreArrayRead(c->shift, &s));
  for (PetscInt i = 0; i < c->n; ++i)
    if (c->facet[i] != SP_ELEM_NONE) pen = PetscMax(pen, -c->gap[i]);
  PetscCallMPI(MPI_Allreduce(&pen, &all, 1, MPIU_REAL, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)c->dm), "contact_step %" PetscInt_FMT " load %.6f force %.12e %.12e master_force %.12e %.12e max_penetration %.6e peak_pressure %.10e\n", step, (double)load, (double)c->stats.force[0], (double)c->stats.force[1], (double)c->stats.forceMaster[0], (double)c->stats.forceMaster[1], (double)all, (double)c->stats.peakPressure));
  PetscFunctionReturn(PETSC_SUCCESS);
}
