/* Load stepping: the load factor goes 1/N, 2/N, ..., 1 and scales Neumann loads, Dirichlet values
   and obstacle motion; shifts carry over. Inside a step, methods that update their shifts after a
   converged solve (augmented Lagrangian) repeat the solve until their update is done or its budget
   is spent. A step that fails either way is halved (bounded), then the run stops with a clear
   message; converged steps keep their output. */
#include <spcontact-impl.h>

static PetscErrorCode SolveStep(SPApp app, PetscReal load, PetscInt step, Vec ubackup, PetscBool *ok)
{
  SNESConvergedReason reason;
  FILE               *fp;

  PetscFunctionBeginUser;
  PetscCall(VecCopy(app->u, ubackup));
  PetscCall(SPContactSaveState(app->contact));
  PetscCall(SPProblemSetLoadFactor(app->problem, load));
  PetscCall(SPOutputGetHistoryFile(app->output, &fp));
  PetscCall(SPSolverSetHistory(app->solver, fp, step));
  PetscCall(SPSolverSolve(app->solver, app->u, &reason));
  for (PetscInt k = 0; reason > 0; ++k) { /* the method's update after a converged solve */
    PetscBool again, failed;
    PetscCall(SPContactSolveUpdate(app->contact, app->u, k, &again, &failed));
    if (failed) reason = SNES_DIVERGED_MAX_IT;
    if (!again) break;
    PetscCall(SPSolverSolve(app->solver, app->u, &reason));
  }
  *ok = reason > 0 ? PETSC_TRUE : PETSC_FALSE;
  if (!*ok) {
    PetscCall(PetscPrintf(app->comm, "load step %" PetscInt_FMT " (load factor %g): solve did not converge (%s)\n", step, (double)load, SNESConvergedReasons[reason]));
    PetscCall(VecCopy(ubackup, app->u));
    PetscCall(SPContactRestoreState(app->contact));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPLoadingRun(SPApp app)
{
  PetscReal done = 0.0, inc = 1.0 / app->loadSteps;
  PetscInt  step = 0, cuts = 0;
  PetscInt  its0, lits0; /* solver counts before the step, for the progress line */
  Vec       ubackup;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(app->u, &ubackup));
  PetscCall(SPSolverGetCounts(app->solver, &its0, &lits0, NULL));
  app->converged = PETSC_TRUE;
  while (done < 1.0 - 1e-12) {
    PetscReal load = PetscMin(1.0, done + inc);
    PetscBool ok = PETSC_FALSE;
    PetscCall(SolveStep(app, load, step + 1, ubackup, &ok));
    if (!ok) {
      if (cuts >= app->maxCutbacks) {
        app->converged = PETSC_FALSE;
        PetscCall(PetscPrintf(app->comm, "stopping: load factor %g not reached after %" PetscInt_FMT " cut-backs; last converged load factor %g\n", (double)load, cuts, (double)done));
        break;
      }
      cuts++;
      app->cutbacks++;
      inc *= 0.5;
      PetscCall(PetscPrintf(app->comm, "cutting back: load increment halved to %g\n", (double)inc));
      continue;
    }
    done = load;
    step++;
    cuts = 0;
    PetscCall(SPContactCommitStep(app->contact, app->u));
    PetscCall(PetscLogStagePush(app->log.output)); /* stage times are exclusive: output leaves "SP solve" */
    PetscCall(SPOutputWriteStep(app->output, app->problem, app->u, app->contact));
    PetscCall(PetscLogStagePop());
    PetscCall(SPContactReportStep(app->contact, app->u, step, load));
    PetscCall(SPLogProgress(app, step, load, its0, lits0));
    PetscCall(SPSolverGetCounts(app->solver, &its0, &lits0, NULL));
  }
  app->stepsDone   = step;
  app->loadReached = done;
  PetscCall(SPProblemSetLoadFactor(app->problem, done));
  PetscCall(VecDestroy(&ubackup));
  PetscFunctionReturn(PETSC_SUCCESS);
}
