/* Shift (scaled multiplier) update and contact bookkeeping at Newton-iteration boundaries:
   active sets, the safeguards of method.md section 4, convergence, the update after a converged
   solve, statistics. When a method updates, and by which rule, comes from its table entry. */
#include <spcontact-impl.h>

/* Constraint error of point i: its penetration, and for an active point also an open gap (an
   active point carrying pressure across a gap, as after a shift overshoot, violates g = 0 too) */
static inline PetscReal GapError(PetscReal g, PetscBool active)
{
  return active ? PetscAbsReal(g) : PetscMax(0.0, -g);
}

static PetscErrorCode Reduce(SPContact c, PetscInt nloc[4], PetscReal rloc[4])
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)c->dm);
  PetscInt  nall[4];
  PetscReal rall[4];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(nloc, nall, 4, MPIU_INT, MPI_SUM, comm));
  if (nall[2]) c->activeVersion++; /* the contact tangent's structure changed (SPContactGetActiveVersion) */
  c->activeChanges += nall[2];
  c->chatterHolds += nall[3];
  PetscCallMPI(MPI_Allreduce(rloc, rall, 4, MPIU_REAL, MPI_MAX, comm));
  c->peakIterate          = rall[3];
  c->stats.activePoints   = nall[0];
  c->stats.activeChanged  = nall[1];
  c->stats.maxPenetration = rall[0];
  c->stats.maxShiftChange = rall[1];
  c->stats.gapError       = rall[2];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Active set and statistics of the evaluated state with the current shifts; with `compare`, the
   number of points whose active state changed since the last bookkeeping */
static PetscErrorCode Bookkeep(SPContact c, PetscReal maxDs, PetscBool compare)
{
  PetscInt  n[4] = {0, 0, 0, 0}; /* active, changed since the last bookkeeping, changed, closed by the chatter hold only */
  PetscReal r[4] = {0.0, maxDs, 0.0, 0.0}; /* penetration, shift change, gap error, pressure */

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->n; ++i) {
    SPPointState   *st     = &c->pt[i].st;
    const PetscReal g      = c->pt[i].geo.gap;
    const PetscBool active = SPContactPointActive(c, i);
    n[0] += active;
    if (compare) n[1] += active != st->active;
    n[2] += active != st->active;
    if (compare && active != st->active) st->flipsN++;
    if (active && c->pt[i].geo.elem == SP_ELEM_OBSTACLE) { /* a corner switching between two obstacles */
      if (compare && st->obstacle >= 0 && st->obstacle != c->pt[i].geo.obstacle) st->switchesN++, st->otherObstacle = st->obstacle;
      st->obstacle = c->pt[i].geo.obstacle;
    }
    if (compare && active && SPContactChatterHeld(c, i) && !(c->holding && st->held) && g + st->sN > 0.0) n[3]++;
    st->active = active;
    r[0]       = PetscMax(r[0], -g);
    r[2]       = PetscMax(r[2], GapError(g, active));
    r[3]       = PetscMax(r[3], -c->pt[i].eps * (g + st->sN));
  }
  PetscCall(Reduce(c, n, r));
  PetscCall(SPFrictionBookkeep(c, compare));
  /* no reuse of the tangent with friction (the stick/slip tangent moves with the state) or pairs
     (the projection and curvature terms move with every shift update: reusing them cost 3 Newton
     iterations on B6 at alpha 100) */
  if (c->friction || c->npair) c->activeVersion++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* An accelerator of the in-Newton update starts a new history at a new solve and whenever its
   set of points moves; alm's spans the augmentations of a load step (SPContactSaveState resets it) */
static PetscErrorCode ResetInNewton(SPContact c, SPShiftAccel a)
{
  PetscFunctionBeginUser;
  if (c->method->timing == SP_UPDATE_NEWTON) PetscCall(SPShiftAccelReset(a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Before a Newton solve: active set of the initial iterate (it drives the first Jacobian) */
PetscErrorCode SPContactBeginSolve(SPContact c, Vec X)
{
  PetscFunctionBeginUser;
  c->holding  = c->holdNext;
  c->holdNext = PETSC_FALSE;
  for (PetscInt i = 0; i < c->n; ++i) { /* before the bookkeeping: no chatter hold or obstacle switch from the last solve */
    SPPointState *st = &c->pt[i].st;
    c->nhist[i] = 0, st->flipsN = st->switchesN = 0, st->holdOff = PETSC_FALSE;
    st->obstacle = st->otherObstacle = -1;
  }
  PetscCall(SPContactEvaluate(c, X));
  PetscCall(SPFrictionAnchor(c, PETSC_FALSE));
  PetscCall(SPContactPredictApply(c));
  PetscCall(Bookkeep(c, 0.0, PETSC_FALSE));
  c->setSettled = PETSC_FALSE;
  c->boundary   = 0;
  PetscCall(ResetInNewton(c, c->accel));
  PetscCall(ResetInNewton(c, c->accelT));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Record (s, g) of point i, newest last, at most params.history pairs */
static void PushHistory(SPContact c, PetscInt i, PetscReal s, PetscReal g)
{
  const PetscInt m  = c->params.history;
  PetscReal     *hs = &c->hist[2 * m * i], *hg = hs + m;
  if (c->nhist[i] == m) {
    for (PetscInt k = 1; k < m; ++k) hs[k - 1] = hs[k], hg[k - 1] = hg[k];
    c->nhist[i]--;
  }
  hs[c->nhist[i]] = s;
  hg[c->nhist[i]] = g;
  c->nhist[i]++;
}

/* The in-Newton shift update for point i (method.md section 4, safeguards 1 and 2); *rule: the
   method's rule gave it (the point is active in both iterates), else it is kept */
static PetscReal UpdatePoint(SPContact c, PetscInt i, PetscBool *rule)
{
  SPPointState   *st        = &c->pt[i].st;
  const PetscBool activeNow = SPContactPointActive(c, i);
  const PetscInt  m         = c->params.history;
  *rule                     = PETSC_FALSE;
  if ((st->active || !c->safeguard) && activeNow) { /* active in the solve that produced the iterate, and now */
    *rule = PETSC_TRUE;
    PushHistory(c, i, st->sN, c->pt[i].geo.gap);
    return PetscMin(0.0, c->method->update(c->nhist[i], &c->hist[2 * m * i], &c->hist[2 * m * i + m]));
  }
  c->nhist[i] = 0;
  return st->sN; /* kept (ResetStaleShifts zeroed it after two inactive iterates) */
}

/* method.md safeguard 2: a point inactive at two Newton iterates in a row loses its shift, at every
   boundary (*maxDs: the largest reset). When the iterates were counted only at the boundaries that
   update the shifts, a point that opened while the active set moved kept its shift s < 0 until two
   updates later: active wherever g < -s, it pushed at a positive gap like an obstacle raised by
   |s|. F1c (the block driven over the plane, alpha 10), step 2: the rear edge opened with s about
   -7.6e-5 (the penalty's penetration of the normal step), and after the first update lifted the
   block 26 points closed again at gaps up to 5.6e-5; 20 Newton iterations in that step, 15 with
   the reset (75 -> 70 over the run; 57 -> 55 and 50 -> 49 at alpha 100 and 1000). A reset never
   activates a point (g + 0 >= g + s >= 0). */
static void ResetStaleShifts(SPContact c, PetscReal *maxDs)
{
  for (PetscInt i = 0; i < c->n; ++i) {
    SPPointState *st = &c->pt[i].st;
    st->inactiveCount = SPContactPointActive(c, i) ? 0 : st->inactiveCount + 1;
    if (st->inactiveCount < 2 || st->sN == 0.0) continue;
    *maxDs = PetscMax(*maxDs, PetscAbsReal(st->sN));
    st->sN = 0.0;
  }
}

/* Whether the in-Newton shift update applies at this boundary: only for methods that update at
   Newton-iteration boundaries, not once the gap tolerance holds (an update then only perturbs a
   converged state), and, with -contact_shift_settled, only when no point changed its active
   state in the last iteration (the contraction k/(k+eps) of method.md section 2 needs a settled
   active set; an update during a change overshoots); with friction, not after a Newton step that
   jumped across stick/slip branches (SPFrictionJumped). *settled false holds the tangential
   update back too. */
static PetscErrorCode ShiftUpdateApplies(SPContact c, PetscBool *applies, PetscBool *settled)
{
  PetscInt  n = 0, nall;
  PetscReal err = 0.0, errAll;
  MPI_Comm  comm = PetscObjectComm((PetscObject)c->dm);

  PetscFunctionBeginUser;
  *applies = *settled = PETSC_FALSE;
  if (c->method->timing != SP_UPDATE_NEWTON) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscBool active = SPContactPointActive(c, i);
    n += active != c->pt[i].st.active;
    err = PetscMax(err, GapError(c->pt[i].geo.gap, active));
  }
  PetscCallMPI(MPI_Allreduce(&n, &nall, 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&err, &errAll, 1, MPIU_REAL, MPI_MAX, comm));
  *settled = nall == 0 || !c->settled ? PETSC_TRUE : PETSC_FALSE;
  if (*settled) {
    PetscBool jumped;
    PetscCall(SPFrictionJumped(c, errAll, &jumped));
    if (jumped) *settled = PETSC_FALSE, c->jumpWaits++;
  }
  *applies = errAll > c->gapTol && *settled ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* With an accelerator, its step over the points the rule updated (c->accIn), from the shifts
   before the update (c->accS), clipped to s <= 0 like the rule; *maxDs becomes its largest change */
static PetscErrorCode Accelerate(SPContact c, PetscReal *maxDs)
{
  PetscBool used = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (!c->accel) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPShiftAccelUpdate(c->accel, c->accIn, c->accS, c->accG, c->accNew, &used));
  if (!used) PetscFunctionReturn(PETSC_SUCCESS);
  *maxDs = 0.0;
  for (PetscInt i = 0; i < c->n; ++i) {
    if (c->accIn[i]) c->pt[i].st.sN = PetscMin(0.0, c->accNew[i]);
    *maxDs = PetscMax(*maxDs, PetscAbsReal(c->pt[i].st.sN - c->accS[i]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Point i's shift went from s to its rule's value (rule: the rule applied): the accelerator's record */
static void Record(SPContact c, PetscInt i, PetscReal s, PetscBool rule)
{
  if (c->params.accel == SP_ACCEL_NONE) return;
  c->accS[i] = s, c->accG[i] = c->pt[i].geo.gap, c->accIn[i] = rule, c->accNew[i] = c->pt[i].st.sN;
}

/* Every point's shift at an applying boundary: the method's rule per point, then the accelerator */
static PetscErrorCode UpdateShifts(SPContact c, PetscReal *maxDs, PetscInt *released)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscBool       rule;
    const PetscReal s    = c->pt[i].st.sN;
    const PetscBool held = SPContactChatterHeld(c, i);
    c->pt[i].st.sN       = UpdatePoint(c, i, &rule);
    *maxDs               = PetscMax(*maxDs, PetscAbsReal(c->pt[i].st.sN - s));
    Record(c, i, s, rule);
    /* a held point whose shift is at its clip (s = 0) with an open gap: no update can close it (that
       would take s > 0, a tension the hold only tolerates on the way), so its gap error would stay
       and the solve stall (F1c on a 10 x 10 x 5 mesh, step 2: gap error 2.6e-7 over 15 Newton
       iterations, twice, then the step-cap retries; QA helper 22). It opens, and is not held again
       in this solve */
    if (held && c->pt[i].st.sN == 0.0 && c->pt[i].geo.gap > c->gapTol) c->pt[i].st.holdOff = PETSC_TRUE, (*released)++;
  }
  PetscCall(Accelerate(c, maxDs));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -contact_branch_hold: before the shift update at a boundary, every point's branch at the iterate
   (closed or open, stuck or slipping); until the next boundary (the residual and the Jacobian of
   this Newton step) the laws keep a closed point on its closed branch and the friction status
   (SPContactPointTraction, SPFrictionTraction). The update moves the shifts at an unchanged
   displacement, and there it opens points near the edge of the contact whose gap was positive
   (s <- s + g lowers their pressure) and turns stuck points near the cone's edge to slip (the
   stuck ones' tangential update, and the lower pressure): the Newton step from those branches
   pulled them back over several iterations (F1b at alpha 1000, step 4: 0 of 7 stuck points left
   after the update; 74 / 57 / 54 Newton iterations at alpha 10 / 100 / 1000, 58 / 45 / 40 held).
   The Newton step from the held branches is the step of the linear problem the update defines.
   A boundary with an update is never a converged one (its gap error is above the tolerance), and
   the next boundary evaluates the laws unheld. alm holds in the first Newton step of the solve
   after an augmentation (SPContactSolveUpdate, SPContactBeginSolve): B4 32^3 12 -> 11 Newton
   iterations, F1b 73 / 55 / 53 -> 67 / 47 / 44, F2 199 / 117 / 197 -> 196 / 109 / 191. Not with
   an accelerator (-contact_shift_accel anderson, two-pass's default): B6 two-pass at alpha 10
   took 369 Newton iterations and 2 cut-backs with the hold against 44 without, and 49 when held
   only where Anderson took no step. */
static void HoldBranches(SPContact c)
{
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscReal y[2], t[2];
    PetscBool stick;
    c->pt[i].st.held = SPContactPointActive(c, i);
    SPFrictionTraction(c, i, y, t, &stick);
    c->pt[i].st.heldStick = stick;
  }
  c->holding = PETSC_TRUE;
}

/* At a Newton-iteration boundary, on the new iterate W: gaps, shift update (in-Newton methods),
   active-set change. *changed says the residual must be recomputed for the new shift. */
PetscErrorCode SPContactNewtonUpdate(SPContact c, Vec W, PetscBool *changed)
{
  PetscReal       maxDs = 0.0, all, dsT = 0.0;
  PetscInt        released = 0, rall;
  PetscBool       applies, settled, fsettled, fupdate = PETSC_FALSE;
  const PetscBool hold = c->branchHold && !c->accel ? PETSC_TRUE : PETSC_FALSE;

  PetscFunctionBeginUser;
  c->holding = PETSC_FALSE;
  PetscCall(SPContactEvaluate(c, W));
  SPContactPairsKeepFacets(c);
  PetscCall(ShiftUpdateApplies(c, &applies, &settled));
  /* A step cut by the tangential step control (friction only) ends at a point that no Newton step
     produced: updating the shifts there (normal and tangential) would lock its imbalance in */
  if (c->slipLimited) applies = settled = PETSC_FALSE;
  c->slipLimited = PETSC_FALSE;

  if (applies && hold) HoldBranches(c);
  if (c->method->timing == SP_UPDATE_NEWTON) ResetStaleShifts(c, &maxDs);
  if (applies) PetscCall(UpdateShifts(c, &maxDs, &released));
  else PetscCall(ResetInNewton(c, c->accel)); /* the active set moved (or the gaps hold): a new map */
  /* the tangential shift, after the normal one. Without the branch hold only on a settled stick/slip
     set (an update during a change overshoots). With it the update need not wait: where the normal
     shifts are updated too the step after it keeps the statuses (F1b 58 / 45 / 40 -> 53 / 41 / 36
     Newton iterations, F3 78 -> 75, F5 113 -> 111; F1a and F4 unchanged). Where only the tangential
     shifts move (the gaps already hold) nothing is held; holding there too gave the same counts on
     F1a, F1b, F1c and F2 at alpha 10 */
  if (settled && c->method->timing == SP_UPDATE_NEWTON) {
    if (hold || !c->settled) fupdate = PETSC_TRUE;
    else {
      PetscCall(SPFrictionSettled(c, &fsettled));
      fupdate = fsettled;
    }
  }
  /* stuck points may keep their shifts only where the normal ones hold: a normal update moves them
     after the test (F2 rigid edge: creep 6.2e-13 > 1e-10 h_c = 4.9e-13 when it did not count) */
  if (fupdate) PetscCall(SPFrictionUpdate(c, applies ? PETSC_FALSE : PETSC_TRUE, &dsT));
  else PetscCall(ResetInNewton(c, c->accelT)); /* the stick/slip set moved: a new map */
  PetscCall(SPContactSchurUpdate(c, applies, fupdate, &maxDs, &dsT)); /* -contact_shift_accel schur: over both rules' shifts */
  PetscCall(Bookkeep(c, maxDs, PETSC_TRUE));
  c->boundary++;
  c->setSettled = c->stats.activeChanged == 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscCallMPI(MPI_Allreduce(&maxDs, &all, 1, MPIU_REAL, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  PetscCallMPI(MPI_Allreduce(&released, &rall, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  if (rall) PetscCall(PetscInfo(c->dm, "chatter hold: %" PetscInt_FMT " points held at a zero shift with an open gap let go\n", rall));
  *changed = all > 0.0 || dsT > 0.0 || rall > 0 ? PETSC_TRUE : PETSC_FALSE; /* a let-go point's force changed too */
  if (*changed) c->shiftUpdates++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Newton step control on the proposed iterate W = X - Y: scale the step so that no point that is
   not yet deep gets deeper than stepCap*h in one step (gaps interpolated linearly along the step).
   It matters when a load-controlled body touches at one point: its first step is otherwise
   sized by a single penalty spring. Inactive once penetrations are small. With friction, the
   tangential counterpart (SPFrictionStepLimit): no slipping point is carried in one step across
   its stick cone into reverse slip; it stops at the centre of the cone. -contact_step_cap 0 turns
   both off. */
PetscErrorCode SPContactLimitStep(SPContact c, Vec X, Vec Y, Vec W, PetscBool *changed)
{
  PetscReal theta = 1.0, all;

  PetscFunctionBeginUser;
  *changed = PETSC_FALSE;
  c->holding = PETSC_FALSE;
  if (c->stepCap <= 0.0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPContactEvaluate(c, X));
  for (PetscInt i = 0; i < c->n; ++i) c->gapStart[i] = c->pt[i].geo.gap;
  SPFrictionStepStart(c);
  PetscCall(SPContactEvaluate(c, W));
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscReal cap = c->stepCap * c->pt[i].h, g = c->pt[i].geo.gap, g0 = c->gapStart[i];
    if (g < -cap && g0 > -cap) theta = PetscMin(theta, (g0 + cap) / (g0 - g));
  }
  if (c->friction) {
    const PetscReal thetaT = SPFrictionStepLimit(c);
    PetscReal       tall;
    PetscCallMPI(MPI_Allreduce(&thetaT, &tall, 1, MPIU_REAL, MPI_MIN, PetscObjectComm((PetscObject)c->dm)));
    c->slipLimited = tall < 1.0 ? PETSC_TRUE : PETSC_FALSE;
    theta          = PetscMin(theta, tall);
  }
  PetscCallMPI(MPI_Allreduce(&theta, &all, 1, MPIU_REAL, MPI_MIN, PetscObjectComm((PetscObject)c->dm)));
  if (all < 1.0) {
    PetscCall(VecWAXPY(W, -all, Y, X));
    *changed = PETSC_TRUE;
    c->stepLimits++;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A load step whose Newton iteration stalled or ran out of iterations is solved again with a step
   cap ten times smaller (*retry), and if that stalls too, with a hundredth; if that fails as well
   the step is cut back with the hundredth kept. SPContactRestoreStepCap puts the user's cap back
   once a load step converges, so the tighter cap costs nothing where nothing stalls. At alpha ~
   1000 one h of new penetration per Newton step lets the active set of a curved pair cycle: B6 took
   146 Newton iterations and 3 cut-backs, with the retry at a tenth 41 and none. Where h is large
   against the penetrations of the cycle, a tenth does not bite: slide3d at alpha 1000 (h = 0.2,
   points swinging 0.013 in and out) took 549 / 577 / 745 Newton iterations (penalty / shifted /
   alm) and 11 to 13 cut-backs, on tetrahedra shifted did not converge (15 cut-backs); with the
   hundredth 91 / 100 / 107 and 1 cut-back, tetrahedra 91 / 96 / 95; slide2d at alpha 1000 6 -> 0
   cut-backs (332 / 356 / 374 -> 256 / 268 / 280). The cut-back keeps the tighter cap because with the
   user's cap the cut-back steps stalled again (slide3d's 11 to 13 cut-backs). 0.1 as the default
   costs B2 and B3 two or three iterations. With friction only where the chatter hold acts (on by default;
   -contact_chatter_flips, shifted and alm; SPContactChatterHeld): on F2 at alpha 1000 the
   retried normal step (50 Newton iterations instead of 98 and 2 cut-backs) led to shear steps in
   which one contact-edge point opened and closed at every iteration (441 Newton iterations, 7
   cut-backs, against 163 and 2 without the retry); with the hold 73 and none (alm 191 -> 124,
   F5 205 -> 92 and 199 -> 135, none cut back; shifted's F2 and F5 retried no step, alm's F2 one).
   A hold with a fixed opening (1e-6 h) instead, without the retry, did not help (shifted 319, 6
   cut-backs). */
PetscErrorCode SPContactTightenStepCap(SPContact c, PetscBool *retry)
{
  const PetscInt maxLevel = 2; /* the tightest cap: a hundredth of the user's */

  PetscFunctionBeginUser;
  *retry = PETSC_FALSE;
  if (!c->enabled || (c->friction && !SPContactChatterHolds(c)) || c->stepCap <= 0.0 || c->capLevel >= maxLevel) PetscFunctionReturn(PETSC_SUCCESS);
  if (!c->capLevel) c->capSaved = c->stepCap;
  c->capLevel++;
  c->stepCap *= 0.1;
  c->capRetries++;
  *retry = PETSC_TRUE;
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)c->dm), "Newton did not converge: the load step again with -contact_step_cap %g until a load step converges\n", (double)c->stepCap));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void SPContactRestoreStepCap(SPContact c)
{
  if (c->capLevel) c->stepCap = c->capSaved;
  c->capLevel = 0;
}

/* After a converged Newton solve at X, for methods that update then (Uzawa): s <- min(0, rule(s, g))
   at every point unless the gap tolerance already holds. *again: solve once more with the new
   shifts. Fails (PETSC_ERR_NOT_CONVERGED is not used: *again false and *failed true) when the
   method's update budget for the load step is spent. */
PetscErrorCode SPContactSolveUpdate(SPContact c, Vec X, PetscInt done, PetscBool *again, PetscBool *failed)
{
  PetscReal maxDs = 0.0, dsT;
  PetscBool doneN, creepOK;

  PetscFunctionBeginUser;
  *again = *failed = PETSC_FALSE;
  if (!c->enabled || c->method->timing != SP_UPDATE_SOLVE) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPContactEvaluate(c, X));
  PetscCall(Bookkeep(c, 0.0, PETSC_FALSE));
  doneN   = c->stats.gapError <= c->gapTol ? PETSC_TRUE : PETSC_FALSE;
  creepOK = c->creepRel <= c->creepRtol ? PETSC_TRUE : PETSC_FALSE;
  if (doneN && !c->friction) PetscFunctionReturn(PETSC_SUCCESS);
  if (done >= c->params.maxUpdates) {
    PetscCall(PetscPrintf(PetscObjectComm((PetscObject)c->dm), "%s: gap tolerance %g not reached after %" PetscInt_FMT " updates (gap error %g); raise %s\n", c->method->name, (double)c->gapTol, done, (double)c->stats.gapError, c->params.maxOption));
    *failed = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (!doneN && c->branchHold && !c->accel) { /* the next solve's first Newton step (SPContactBeginSolve) */
    HoldBranches(c);
    c->holdNext = PETSC_TRUE;
  }
  for (PetscInt i = 0; i < c->n && !doneN; ++i) {
    SPPointState   *st  = &c->pt[i].st;
    const PetscReal old = st->sN, g = c->pt[i].geo.gap;
    st->sN              = PetscMin(0.0, c->method->update(1, &old, &g));
    maxDs               = PetscMax(maxDs, PetscAbsReal(st->sN - old));
    Record(c, i, old, SPContactPointActive(c, i));
  }
  if (!doneN) PetscCall(Accelerate(c, &maxDs)); /* across the augmentations of the load step */
  PetscCall(SPFrictionUpdate(c, PETSC_FALSE, &dsT)); /* alm lost with the hold: F1b 67 -> 70 at alpha 100 */
  PetscCall(SPContactSchurUpdate(c, !doneN, PETSC_TRUE, &maxDs, &dsT));
  if (doneN && creepOK && c->stats.maxSlipShiftResidual <= c->slipRtol) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(Bookkeep(c, maxDs, PETSC_FALSE));
  c->stats.augmentations++;
  c->shiftUpdates++;
  *again = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Contact part of the convergence test (method.md section 4, safeguard 4): a settled active set
   and, for methods that update the shift, the gap tolerance */
PetscErrorCode SPContactConverged(SPContact c, PetscBool *ok)
{
  PetscFunctionBeginUser;
  *ok = c->stats.activeChanged == 0 ? PETSC_TRUE : PETSC_FALSE;
  if (c->method->timing == SP_UPDATE_NEWTON && c->stats.gapError > c->gapTol) *ok = PETSC_FALSE;
  if (!SPFrictionConverged(c)) *ok = PETSC_FALSE;
  if (*ok) { /* a chattering point's frozen slip direction must be the return map's */
    PetscBool released, off;
    PetscCall(SPFrictionReleaseFrozen(c, &released, &off));
    if (released || off) *ok = PETSC_FALSE;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The contact centre: the point of first contact, i.e. the smallest gap at the first evaluation
   (u = 0); ties (a flat contact) go to the lexicographically smallest reference position, so the
   choice does not depend on the partition. Collective, once. */
static PetscErrorCode ContactCentre(SPContact c)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)c->dm);
  PetscReal gmin = PETSC_MAX_REAL, all, tol;
  PetscBool *cand;

  PetscFunctionBeginUser;
  if (c->centreSet) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) gmin = PetscMin(gmin, c->pt[i].gap0);
  PetscCallMPI(MPI_Allreduce(&gmin, &all, 1, MPIU_REAL, MPI_MIN, comm));
  tol = 1e-12 * (1.0 + PetscAbsReal(all));
  PetscCall(PetscMalloc1(c->n + 1, &cand));
  for (PetscInt i = 0; i < c->n; ++i) cand[i] = c->pt[i].gap0 <= all + tol ? PETSC_TRUE : PETSC_FALSE;
  for (PetscInt d = 0; d < c->dim; ++d) {
    PetscReal xmin = PETSC_MAX_REAL;
    for (PetscInt i = 0; i < c->n; ++i)
      if (cand[i]) xmin = PetscMin(xmin, c->pt[i].X[d]);
    PetscCallMPI(MPI_Allreduce(&xmin, &c->centre[d], 1, MPIU_REAL, MPI_MIN, comm));
    for (PetscInt i = 0; i < c->n; ++i)
      if (cand[i] && c->pt[i].X[d] != c->centre[d]) cand[i] = PETSC_FALSE;
  }
  PetscCall(PetscFree(cand));
  c->centreSet = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Resultant contact force on the slave bodies (points of obstacle slaves and of the user's pairs'
   slave surfaces: with two passes it includes the force they receive as masters), peak recovered
   pressure, and the contact radius: the largest reference distance from the contact centre to a
   point carrying pressure. Uses the last evaluated state; collective. */
PetscErrorCode SPContactComputeStats(SPContact c)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)c->dm);
  PetscReal f[3] = {0, 0, 0}, ft[3] = {0, 0, 0}, peak = 0.0, rmax = 0.0;

  PetscFunctionBeginUser;
  PetscCall(SPContactRecoverForces(c));
  PetscCall(ContactCentre(c));
  for (PetscInt i = 0; i < c->n; ++i) {
    const SPContactPoint *pt = &c->pt[i];
    PetscReal             dx[3] = {0, 0, 0};
    if (pt->primary) {
      const PetscReal *n = SPContactPointNormal(c, i), fn = SPDot(c->dim, pt->f, n);
      for (PetscInt d = 0; d < c->dim; ++d) f[d] += pt->f[d], ft[d] += pt->f[d] - fn * n[d];
    }
    peak = PetscMax(peak, pt->press);
    if (pt->press <= 0.0) continue;
    for (PetscInt d = 0; d < c->dim; ++d) dx[d] = pt->X[d] - c->centre[d];
    rmax = PetscMax(rmax, SPNorm(c->dim, dx));
  }
  PetscCallMPI(MPI_Allreduce(f, c->stats.force, 3, MPIU_REAL, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(ft, c->stats.tangentialForce, 3, MPIU_REAL, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&peak, &c->stats.peakPressure, 1, MPIU_REAL, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(&rmax, &c->stats.contactRadius, 1, MPIU_REAL, MPI_MAX, comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A run that stopped on a failure: the contact at its restored displacement and state (the last
   converged step), so the summary's active points, penetration, gap error and stick/slip counts
   are those of the state it reports, not of the failed iterate the last evaluation saw */
PetscErrorCode SPContactEvaluateFinal(SPContact c, Vec X)
{
  PetscFunctionBeginUser;
  if (!c->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPContactEvaluate(c, X));
  PetscCall(Bookkeep(c, 0.0, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Figures of the final state (forces recovered): for the summary */
PetscErrorCode SPContactGetStats(SPContact c, SPContactStats *stats)
{
  PetscFunctionBeginUser;
  PetscCall(SPContactComputeStats(c));
  *stats = c->stats;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Figures of the last Newton-iteration boundary (no recomputation): for monitors and history */
PetscErrorCode SPContactGetIterationStats(SPContact c, SPContactStats *stats)
{
  PetscFunctionBeginUser;
  *stats = c->stats;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -contact_monitor: one line per Newton iteration */
PetscErrorCode SPContactMonitor(SPContact c, PetscInt it, PetscReal fnorm)
{
  const SPContactStats *st = &c->stats;

  PetscFunctionBeginUser;
  if (!c->monitor) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)c->dm), "  contact %3" PetscInt_FMT " |F| %.6e active %" PetscInt_FMT " changed %" PetscInt_FMT " max_penetration %.6e gap_error %.6e max_shift_change %.6e\n", it, (double)fnorm, st->activePoints, st->activeChanged, (double)st->maxPenetration, (double)st->gapError, (double)st->maxShiftChange));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Contact pairs: one line per converged load step (force on the slave and on the master
   surfaces, dim components each, max penetration, peak pressure), so load paths (sliding) can be
   checked step by step; print false (-quiet): the same evaluation, no line */
PetscErrorCode SPContactReportStep(SPContact c, Vec X, PetscInt step, PetscReal load, PetscBool print)
{
  PetscReal pen = 0.0, all;
  MPI_Comm  comm;
  char      fs[128] = "", fm[128] = "";

  PetscFunctionBeginUser;
  if (!c->enabled || !c->npair) PetscFunctionReturn(PETSC_SUCCESS);
  comm = PetscObjectComm((PetscObject)c->dm);
  PetscCall(SPContactEvaluate(c, X));
  PetscCall(SPContactComputeStats(c));
  for (PetscInt i = 0; i < c->n; ++i)
    if (c->pt[i].geo.elem != SP_ELEM_NONE) pen = PetscMax(pen, -c->pt[i].geo.gap);
  PetscCallMPI(MPI_Allreduce(&pen, &all, 1, MPIU_REAL, MPI_MAX, comm));
  if (!print) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt d = 0; d < c->dim; ++d) {
    PetscCall(PetscSNPrintf(fs + strlen(fs), sizeof(fs) - strlen(fs), " %.12e", (double)c->stats.force[d]));
    PetscCall(PetscSNPrintf(fm + strlen(fm), sizeof(fm) - strlen(fm), " %.12e", (double)c->stats.forceMaster[d]));
  }
  PetscCall(PetscPrintf(comm, "contact_step %" PetscInt_FMT " load %.6f force%s master_force%s max_penetration %.6e peak_pressure %.10e\n", step, (double)load, fs, fm, (double)all, (double)c->stats.peakPressure));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* At a converged load step: commit the friction state (anchors, traction, slip) of the state X */
PetscErrorCode SPContactCommitStep(SPContact c, Vec X)
{
  PetscFunctionBeginUser;
  if (!c->enabled || !c->friction) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPContactEvaluate(c, X));
  PetscCall(SPFrictionAnchor(c, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the contact tangent is a function of the active set alone: frictionless contact with
   rigid planes only (n fixed, no curvature term, k = eps on every active point). A Jacobian of an
   unchanged active version is then exact, not a chord (no contact: the bulk alone). */
PetscBool SPContactTangentFixed(SPContact c)
{
  if (!c || !c->enabled) return PETSC_TRUE;
  if (c->friction || c->npair) return PETSC_FALSE;
  for (PetscInt o = 0; o < c->nob; ++o)
    if (c->ob[o].type != SP_OBSTACLE_PLANE) return PETSC_FALSE;
  return PETSC_TRUE;
}

/* A counter that moves whenever a point's active state changes (with friction: at every
   bookkeeping, the stick/slip tangent changes without it) or the tangent switches its curvature
   terms on or off (-contact_tangent auto): the Jacobian of an unchanged version differs from the
   last assembled one only through the geometry (normals, projections, pressures) */
PetscErrorCode SPContactGetActiveVersion(SPContact c, PetscInt *version)
{
  PetscFunctionBeginUser;
  *version = c && c->enabled ? 2 * c->activeVersion + (SPContactGeometricTangent(c) && !SPContactTangentFixed(c) ? 1 : 0) : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The active points of the last bookkeeping, and the changes of active state summed over the run
   (a point that closes and opens again counts twice): the number of points whose state differs
   between two moments of the run is at most the difference of the sums */
PetscErrorCode SPContactGetActiveChanges(SPContact c, PetscInt *active, PetscInt *changes)
{
  PetscFunctionBeginUser;
  *active  = c && c->enabled ? c->stats.activePoints : 0;
  *changes = c && c->enabled ? c->activeChanges : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The expected contraction of the shift per update, k/(k + eps) with the structure's stiffness at
   a contact point k ~ E/h (method.md section 2): 1/(1 + alpha) for the largest effective alpha;
   1 without contact */
PetscErrorCode SPContactGetShiftContraction(SPContact c, PetscReal *rho)
{
  PetscFunctionBeginUser;
  *rho = c && c->enabled ? 1.0 / (1.0 + c->alphaMax) : 1.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* For methods that update the shifts after a converged solve (alm), frictionless: the 2-norm of
   the nodal forces eps A ds that the update would add at the evaluated state (the next solve's
   first residual). 0 where no update follows (the gap tolerance holds), with friction and for the
   other methods. Collective. */
PetscErrorCode SPContactGetUpdateForce(SPContact c, PetscReal *fnext)
{
  PetscReal loc = 0.0;

  PetscFunctionBeginUser;
  *fnext = 0.0;
  if (!c || !c->enabled || c->method->timing != SP_UPDATE_SOLVE || c->friction || c->stats.gapError <= c->gapTol) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) {
    const SPContactPoint *pt = &c->pt[i];
    const PetscReal       s = pt->st.sN, g = pt->geo.gap;
    const PetscReal       f = pt->eps * pt->area * (PetscMin(0.0, c->method->update(1, &s, &g)) - s);
    loc += f * f;
  }
  PetscCallMPI(MPI_Allreduce(&loc, fnext, 1, MPIU_REAL, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  *fnext = PetscSqrtReal(*fnext);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The residual the coordinates' round-off alone can leave: a gap or a slip is a difference of
   positions, so it carries about machine epsilon x |X| (X the contact point's position; + h for a
   point at the origin), and each point's force eps A (or eps_T A) times that; summed over the
   points in 2-norm (an upper estimate: friction's slips come from the displacements, without X's
   round-off). A run whose load is small against E (friction_slide2d at 1e-4 of its load: |F|
   stayed at 2e-15 against a target of 1.6e-17, every step stalled into the cut-back floor) has
   its residual floor there, whatever the load. 0 without contact. Collective. */
PetscErrorCode SPContactGetRoundOffForce(SPContact c, PetscReal *fro)
{
  PetscReal loc = 0.0;

  PetscFunctionBeginUser;
  *fro = 0.0;
  if (!c || !c->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  if (c->roundOff >= 0.0) {
    *fro = c->roundOff;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (PetscInt i = 0; i < c->n; ++i) {
    const SPContactPoint *pt = &c->pt[i];
    const PetscReal       f  = PETSC_MACHINE_EPSILON * (SPNorm(c->dim, pt->X) + pt->h) * PetscMax(pt->eps, pt->epsT) * pt->area;
    loc += f * f;
  }
  PetscCallMPI(MPI_Allreduce(&loc, fro, 1, MPIU_REAL, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  *fro = c->roundOff = PetscSqrtReal(*fro);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the shifts would move at the proposed iterate W (in-Newton methods: a settled active set,
   the gap tolerance not met), without moving them: the solver then refines a step it solved loosely
   (solver.c, RefineStep). Collective. */
PetscErrorCode SPContactStepFeedsUpdate(SPContact c, Vec W, PetscBool *feeds)
{
  PetscBool settled;

  PetscFunctionBeginUser;
  *feeds = PETSC_FALSE;
  if (!c || !c->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPContactEvaluate(c, W));
  PetscCall(ShiftUpdateApplies(c, feeds, &settled));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the method updates the shifts at the Newton-iteration boundary (shifted) */
PetscErrorCode SPContactShiftsInNewton(SPContact c, PetscBool *on)
{
  PetscFunctionBeginUser;
  *on = c && c->enabled && c->method->timing == SP_UPDATE_NEWTON ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The gap tolerance in use, and whether the shift update is the plain one (no -contact_shift_accel):
   what a stalled solve's advice depends on */
PetscErrorCode SPContactGetGapTolerance(SPContact c, PetscReal *gapTol, PetscBool *plain)
{
  PetscFunctionBeginUser;
  *gapTol = c && c->enabled ? c->gapTol : 0.0;
  *plain  = c && c->enabled && c->params.accel == SP_ACCEL_NONE ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Accelerated shift updates of the run (a restarted run's included) */
PetscErrorCode SPContactGetAccelSteps(SPContact c, PetscInt *steps)
{
  PetscFunctionBeginUser;
  PetscCall(SPShiftAccelGetSteps(c->accel, steps));
  *steps += c->schurSteps + c->accelStepsBefore;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The solve with the last Newton step's Jacobian that -contact_shift_accel schur back-substitutes
   with (the solver's; NULL vectors ask whether it can: a factorization) */
void SPContactSetJacobianSolve(SPContact c, PetscErrorCode (*solve)(void *, Vec, Vec, PetscBool *), void *ctx)
{
  c->jsolve = solve, c->jctx = ctx;
}

/* Whether the method updates the shifts at all (shifted, alm; not penalty) */
PetscErrorCode SPContactUpdatesShifts(SPContact c, PetscBool *on)
{
  PetscFunctionBeginUser;
  *on = c && c->enabled && c->method->timing != SP_UPDATE_NONE ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactHasFriction(SPContact c, PetscBool *on)
{
  PetscFunctionBeginUser;
  *on = c && c->enabled && c->friction ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the run has contact pairs (deformable-deformable) */
PetscErrorCode SPContactHasPairs(SPContact c, PetscBool *on)
{
  PetscFunctionBeginUser;
  *on = c && c->enabled && c->npair > 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The contact length scale h_c: the smallest mean slave facet size at a contact point (the mesh
   size where contact is resolved; a minimum, so the same on any rank count). The gap tolerance is
   gap_rtol x h_c unless -contact_gap_tol gave an absolute one. It must be at least SP_RTOL_MIN
   x h_c, about 5 round-offs of a coordinate of the facet's size: below it a gap is not resolved in
   double precision, and the solve stalled (B1 at 1e-20: 15 Newton iterations at round-off, then
   cut-backs and exit 2 with advice about the shift update; every 2D benchmark converges at 1e-15).
   Collective, once, after the areas. */
PetscErrorCode SPContactSetGapTolerance(SPContact c)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)c->dm);
  PetscReal hmin = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->n; ++i) hmin = PetscMin(hmin, c->pt[i].h);
  PetscCallMPI(MPI_Allreduce(&hmin, &c->lengthScale, 1, MPIU_REAL, MPI_MIN, comm));
  if (!c->gapTolSet) c->gapTol = c->gapRtol * c->lengthScale;
  if (c->method->timing == SP_UPDATE_NONE || c->lengthScale == PETSC_MAX_REAL || c->gapTol >= SP_RTOL_MIN * c->lengthScale) PetscFunctionReturn(PETSC_SUCCESS); /* penalty: no gap test */
  if (c->gapTolSet) SETERRQ(comm, PETSC_ERR_USER_INPUT, "-contact_gap_tol %g: below %g of the contact facet size h_c = %g, finer than double precision resolves a gap; give at least %g", (double)c->gapTol, SP_RTOL_MIN, (double)c->lengthScale, SP_RTOL_MIN * (double)c->lengthScale);
  SETERRQ(comm, PETSC_ERR_USER_INPUT, "-contact_gap_rtol %g: below %g, finer than double precision resolves a gap (a fraction of the contact facet size h_c = %g); give at least %g", (double)c->gapRtol, SP_RTOL_MIN, (double)c->lengthScale, SP_RTOL_MIN);
}
