/* Load stepping: the load factor goes 1/N, 2/N, ..., 1 and scales Neumann loads, Dirichlet values
   and obstacle motion; shifts carry over. Inside a step, methods that update their shifts after a
   converged solve (augmented Lagrangian) repeat the solve until their update is done or its budget
   is spent. A converged step whose state the material law does not admit (Neo-Hookean: det F <= 0
   at a cell vertex, SPProblemCheckState) fails too. A step that fails is halved, within a budget
   of cut-backs and above a floor on the increment, and grows back after a few converged steps;
   past either, or past the wall-time limit (checked before every step), the run stops with a
   one-line reason; converged steps keep their output. After every written step the
   restart data goes into the h5 and a pending SIGTERM/SIGINT (signals.c) stops the run there, on
   every rank. A restarted run (-restart) starts from the step, load factor and increment
   SPRestartLoad restored. */
#include <spcontact-impl.h>

/* The step's solve and, for methods that update after a converged solve, those updates and solves;
   *spent: the step failed because the method's update budget (-contact_alm_max) is spent */
static PetscErrorCode SolveAndUpdate(SPApp app, SNESConvergedReason *reason, PetscBool *spent)
{
  PetscFunctionBeginUser;
  *spent = PETSC_FALSE;
  PetscCall(SPSolverSolve(app->solver, app->u, reason));
  for (PetscInt k = 0; *reason > 0; ++k) { /* the method's update after a converged solve */
    PetscBool again, failed;
    PetscCall(SPContactSolveUpdate(app->contact, app->u, k, &again, &failed));
    if (failed) *reason = SNES_DIVERGED_MAX_IT, *spent = PETSC_TRUE;
    if (!again) break;
    PetscCall(SPSolverSolve(app->solver, app->u, reason));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ratio: the load increment over the last converged one where the load moves in proportion (the
   stuck points' predictor, contact-predict.c), else 0 */
static PetscErrorCode SolveStep(SPApp app, PetscReal load, PetscReal ratio, PetscInt step, Vec ubackup, PetscBool *ok)
{
  SNESConvergedReason reason;
  FILE               *fp;
  PetscBool           spent;
  char                why[128] = "";

  PetscFunctionBeginUser;
  PetscCall(VecCopy(app->u, ubackup));
  PetscCall(SPContactSaveState(app->contact));
  PetscCall(SPProblemSetLoadFactor(app->problem, load));
  PetscCall(SPOutputGetHistoryFile(app->output, &fp));
  PetscCall(SPSolverSetHistory(app->solver, fp, step));
  SPContactPredictNext(app->contact, ratio);
  PetscCall(SolveAndUpdate(app, &reason, &spent));
  for (PetscInt k = 0; k < 2 && reason < 0; ++k) { /* the recoveries (the direct solver and the GMRES */
    PetscBool retry = PETSC_FALSE;                  /* one once per run, the step cap up to twice per step): the step again, no cut-back */
    if (reason == SNES_DIVERGED_LINEAR_SOLVE) {
      PetscCall(SPSolverRecoverDirect(app->solver, &retry));
      if (!retry) PetscCall(SPSolverRecoverBreakdown(app->solver, &retry));
    } else if (!spent && (SPSolverStalled(app->solver) || reason == SNES_DIVERGED_MAX_IT)) PetscCall(SPContactTightenStepCap(app->contact, &retry)); /* a spent update budget: a smaller increment, not a tighter cap */
    if (!retry) break;
    PetscCall(VecCopy(ubackup, app->u));
    PetscCall(SPContactRestoreState(app->contact));
    SPContactPredictNext(app->contact, ratio);
    PetscCall(SolveAndUpdate(app, &reason, &spent));
  }
  *ok = reason > 0 ? PETSC_TRUE : PETSC_FALSE;
  /* a converged state the law does not admit (Neo-Hookean: a cell inside out at a vertex, which the
     quadrature points did not see) is cut back like a failed solve; no recovery can mend it */
  if (*ok) PetscCall(SPProblemCheckState(app->problem, app->u, ok, why, sizeof(why)));
  if (*ok) SPContactRestoreStepCap(app->contact); /* a failed step's cut-back keeps the tighter cap */
  if (!*ok) {
    if (why[0]) PetscCall(PetscPrintf(app->comm, "load step %" PetscInt_FMT " (load factor %g): %s: load step cut back\n", step, (double)load, why));
    else PetscCall(PetscPrintf(app->comm, "load step %" PetscInt_FMT " (load factor %g): solve did not converge (%s)\n", step, (double)load, spent ? "update budget spent" : SPSolverReasonName(app->solver, reason)));
    PetscCall(VecCopy(ubackup, app->u));
    PetscCall(SPContactRestoreState(app->contact));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The safe point after a written step: a SIGTERM/SIGINT caught on any rank stops the run on every
   rank, unless the load is complete (then the run ends normally) */
static PetscErrorCode Interrupted(SPApp app, PetscBool *stop)
{
  const char *prefix;

  PetscFunctionBeginUser;
  PetscCall(SPSignalsPending(app->comm, &app->signals, app->stepsDone, &app->interrupted));
  if (app->loadReached >= 1.0 - 1e-12) app->interrupted = 0;
  *stop = app->interrupted ? PETSC_TRUE : PETSC_FALSE;
  if (!*stop) PetscFunctionReturn(PETSC_SUCCESS);
  app->converged = PETSC_FALSE;
  PetscCall(SPOutputGetPrefix(app->output, &prefix));
  if (app->output->enabled) PetscCall(PetscPrintf(app->comm, "spcontact: interrupted by signal %d after load step %" PetscInt_FMT " (load factor %g); restart with -restart %s.h5.part and another -output_name\n", app->interrupted, app->stepsDone, (double)app->loadReached, prefix));
  else PetscCall(PetscPrintf(app->comm, "spcontact: interrupted by signal %d after load step %" PetscInt_FMT " (load factor %g); no restart data (-output_fields false)\n", app->interrupted, app->stepsDone, (double)app->loadReached));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A run stopped by -max_wall_time is resumable: how (or why not). step0: the step it started
   after (a restart's), so a restarted run with no step of its own points back to its file. */
static PetscErrorCode WallTimeHint(SPApp app, PetscInt step0, PetscInt step, PetscReal done)
{
  const char *prefix;

  PetscFunctionBeginUser;
  PetscCall(SPOutputGetPrefix(app->output, &prefix));
  if (step == 0) PetscCall(PetscPrintf(app->comm, "spcontact: stopped by -max_wall_time before any load step converged: nothing to restart from; raise -max_wall_time\n"));
  else if (step == step0) PetscCall(PetscPrintf(app->comm, "spcontact: stopped by -max_wall_time before a load step converged after the restart (load step %" PetscInt_FMT ", load factor %g); restart with -restart %s again, with a larger -max_wall_time\n", step, (double)done, app->restartFile));
  else if (app->output->enabled) PetscCall(PetscPrintf(app->comm, "spcontact: stopped by -max_wall_time after load step %" PetscInt_FMT " (load factor %g); restart with -restart %s.h5.part and another -output_name\n", step, (double)done, prefix));
  else PetscCall(PetscPrintf(app->comm, "spcontact: stopped by -max_wall_time after load step %" PetscInt_FMT " (load factor %g); no restart data (-output_fields false)\n", step, (double)done));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Why the run must stop before attempting load factor `load` after a failure (ok false) or at a
   safe point (ok true): the wall time, the cut-back budget, the cut-back floor. NULL: go on. */
static PetscErrorCode StopReason(SPApp app, PetscBool ok, PetscReal inc, char why[], size_t len, PetscBool *stop)
{
  PetscLogDouble t;

  PetscFunctionBeginUser;
  *stop = PETSC_TRUE;
  PetscCall(PetscTime(&t));
  PetscCallMPI(MPI_Bcast(&t, 1, MPI_DOUBLE, 0, app->comm)); /* one decision on every rank */
  app->wallStopped = PETSC_FALSE;
  if (app->maxWallTime > 0.0 && t - app->progress.t0 > app->maxWallTime) {
    app->wallStopped = PETSC_TRUE;
    PetscCall(PetscSNPrintf(why, len, "wall time %.3g s exceeds -max_wall_time %g", (double)(t - app->progress.t0), (double)app->maxWallTime));
  }
  else if (!ok && app->cutbacks >= app->maxCutbacks) PetscCall(PetscSNPrintf(why, len, "cut-back budget spent (%" PetscInt_FMT " cut-backs, -load_max_cutbacks)", app->cutbacks));
  else if (!ok && 0.5 * inc < app->minIncrement) PetscCall(PetscSNPrintf(why, len, "halving the increment %g would go below -load_min_increment %g", (double)inc, (double)app->minIncrement));
  else *stop = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After a cut-back the increment grows back: doubled (up to 1/N) after -load_grow_after converged
   steps in a row. A step that only converges at a tiny increment then spends the cut-back budget
   and stops, instead of crawling through thousands of steps. */
static PetscErrorCode Regrow(SPApp app, PetscReal *inc)
{
  const PetscReal nominal = 1.0 / app->loadSteps;

  PetscFunctionBeginUser;
  if (app->growAfter <= 0 || *inc >= nominal) PetscFunctionReturn(PETSC_SUCCESS);
  if (++app->streak < app->growAfter) PetscFunctionReturn(PETSC_SUCCESS);
  app->streak = 0;
  *inc        = PetscMin(2.0 * *inc, nominal);
  PetscCall(PetscPrintf(app->comm, "load increment doubled to %g after %" PetscInt_FMT " converged steps (-load_grow_after)\n", (double)*inc, app->growAfter));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPLoadingRun(SPApp app)
{
  PetscReal done = 0.0, inc = 1.0 / app->loadSteps;
  PetscInt  step = 0, step0;
  PetscBool halt = PETSC_FALSE;
  PetscInt  its0, lits0; /* solver counts before the step, for the progress line */
  Vec       ubackup;

  PetscFunctionBeginUser;
  if (app->debugErrorRank >= 0) { /* tests: an error on one rank alone must stop every rank (main.c) */
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(app->comm, &rank));
    PetscCheck(rank != app->debugErrorRank, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-debug_error_on_rank %d: a test error raised by this rank alone", rank);
  }
  PetscCall(VecDuplicate(app->u, &ubackup));
  PetscCall(SPSolverGetCounts(app->solver, &its0, &lits0, NULL));
  app->converged = PETSC_TRUE;
  if (app->restartFile[0]) done = app->loadReached, inc = app->loadInc, step = app->stepsDone; /* SPRestartLoad */
  step0 = step;
  while (done < 1.0 - 1e-12) {
    PetscReal load = PetscMin(1.0, done + inc);
    PetscBool ok = PETSC_TRUE, stop;
    char      why[256];
    PetscCall(StopReason(app, ok, inc, why, sizeof(why), &stop));
    if (!stop) {
      const PetscReal l[3] = {app->loadBefore, done, load};
      PetscCall(SolveStep(app, load, l[0] < 0.0 ? 0.0 : SPProblemLoadRatio(app->problem, l), step + 1, ubackup, &ok));
    }
    if (ok && !stop) {
      app->loadBefore = done, done = load;
      step++;
      PetscCall(SPContactCommitStep(app->contact, app->u));
      PetscCall(SPContactPredictRecord(app->contact));
      PetscCall(PetscLogStagePush(app->log.output)); /* stage times are exclusive: output leaves "SP solve" */
      PetscCall(SPOutputWriteStep(app->output, app->problem, app->u, app->contact));
      PetscCall(PetscLogStagePop());
      PetscCall(SPContactReportStep(app->contact, app->u, step, load, app->progress.quiet ? PETSC_FALSE : PETSC_TRUE));
      PetscCall(SPLogProgress(app, step, step + (PetscInt)PetscCeilReal((1.0 - done) / inc - 1e-6), load, its0, lits0));
      PetscCall(SPSolverGetCounts(app->solver, &its0, &lits0, NULL));
      app->stepsDone = step, app->loadReached = done;
      if (done < 1.0 - 1e-12) PetscCall(Regrow(app, &inc)); /* not after the last step */
      PetscCall(SPRestartWriteStep(app, inc));
      PetscCall(Interrupted(app, &halt));
      if (halt) break;
      continue;
    }
    if (!stop) PetscCall(StopReason(app, ok, inc, why, sizeof(why), &stop));
    if (stop) {
      app->converged = PETSC_FALSE;
      PetscCall(PetscPrintf(app->comm, "stopping: load factor %g not reached: %s; last converged load factor %g\n", (double)load, why, (double)done));
      if (app->wallStopped) PetscCall(WallTimeHint(app, step0, step, done));
      break;
    }
    app->cutbacks++;
    app->streak = 0;
    inc *= 0.5;
    PetscCall(PetscPrintf(app->comm, "cutting back: load increment halved to %g\n", (double)inc));
  }
  app->stepsDone   = step;
  app->loadReached = done;
  if (step > step0) PetscCall(SPFrictionWarnFresh(app->contact, step));
  PetscCall(SPProblemSetLoadFactor(app->problem, done));
  PetscCall(VecDestroy(&ubackup));
  PetscFunctionReturn(PETSC_SUCCESS);
}
