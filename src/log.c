/* Named log stages and events, so -log_view shows where the time goes; the progress lines (per load
   step, and per -progress_interval within a step). */
#include <spcontact-impl.h>

PetscErrorCode SPLogRegister(SPLog *log)
{
  PetscClassId id;

  PetscFunctionBeginUser;
  PetscCall(PetscClassIdRegister("spcontact", &id));
  PetscCall(PetscLogStageRegister("SP mesh", &log->mesh));
  PetscCall(PetscLogStageRegister("SP setup", &log->setup));
  PetscCall(PetscLogStageRegister("SP solve", &log->solve));
  PetscCall(PetscLogStageRegister("SP output", &log->output));
  PetscCall(PetscLogEventRegister("SPBulkResidual", id, &log->bulkResidual));
  PetscCall(PetscLogEventRegister("SPBulkJacobian", id, &log->bulkJacobian));
  PetscCall(PetscLogEventRegister("SPContactSearch", id, &log->contactSearch));
  PetscCall(PetscLogEventRegister("SPContactAssem", id, &log->contactAssembly));
  PetscCall(PetscLogEventRegister("SPShiftUpdate", id, &log->shiftUpdate));
  PetscCall(PetscLogEventRegister("SPMatCreate", id, &log->matCreate));
  PetscCall(PetscLogEventRegister("SPNearNullSpace", id, &log->nearNullSpace));
  PetscCall(PetscLogEventRegister("SPFastSetUp", id, &log->fastSetUp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One line on stdout per converged load step (silenced by -quiet): step k/N (N the number of
   steps the run needs at the current increment: -load_steps until a cut-back, then more, fewer
   again as the increment grows back), load factor, Newton and linear iterations of the step
   (its0/lits0: the solver's totals before it), active points and max penetration of the last
   Newton iterate, wall time since start. */
PetscErrorCode SPLogProgress(SPApp app, PetscInt step, PetscInt total, PetscReal load, PetscInt its0, PetscInt lits0)
{
  SPContactStats st = {0};
  PetscInt       its, lits;
  PetscBool      on;
  PetscLogDouble t;

  PetscFunctionBeginUser;
  if (app->progress.quiet) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPSolverGetCounts(app->solver, &its, &lits, NULL));
  PetscCall(SPContactIsActive(app->contact, &on));
  if (on) PetscCall(SPContactGetIterationStats(app->contact, &st));
  PetscCall(PetscTime(&t));
  PetscCall(PetscPrintf(app->comm, "step %" PetscInt_FMT "/%" PetscInt_FMT " load %.6f newton %" PetscInt_FMT " linear %" PetscInt_FMT " active %" PetscInt_FMT " max_penetration %.3e wall %.2fs\n", step, total, (double)load, its - its0, lits - lits0, st.activePoints, (double)st.maxPenetration, (double)(t - app->progress.t0)));
  app->progress.last = t;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Within a load step, at the end of Newton iteration it >= 1: one line (indented, so not a step
   line) once -progress_interval seconds have passed since the last progress line, or every
   iteration with 0; the augmentation (aug >= 0: methods that update after a solve, whose Newton
   count restarts with each), the Newton residual against its target, the active points and the max
   penetration of the iterate, the wall time since the start. Rank 0's clock decides (only rank 0
   prints; nothing here is collective). */
PetscErrorCode SPProgressIteration(SPProgress *p, MPI_Comm comm, PetscInt step, PetscInt aug, PetscInt it, PetscReal fnorm, PetscReal target, PetscInt active, PetscReal maxPen)
{
  PetscLogDouble t;
  char           augs[48] = "";

  PetscFunctionBeginUser;
  if (p->quiet || it == 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscTime(&t));
  if (t - p->last < p->interval) PetscFunctionReturn(PETSC_SUCCESS);
  if (aug >= 0) PetscCall(PetscSNPrintf(augs, sizeof(augs), " augmentation %" PetscInt_FMT, aug));
  PetscCall(PetscPrintf(comm, "  step %" PetscInt_FMT "%s newton %" PetscInt_FMT " residual %.3e target %.3e active %" PetscInt_FMT " max_penetration %.3e wall %.2fs\n", step, augs, it, (double)fnorm, (double)target, active, (double)maxPen, (double)(t - p->t0)));
  p->last = t;
  PetscFunctionReturn(PETSC_SUCCESS);
}
