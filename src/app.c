/* The application: owns every module object; create, set up, run, summarise, destroy. */
#include <spcontact-impl.h>
#include <version.h>

PetscErrorCode SPAppCreate(MPI_Comm comm, SPApp *app)
{
  SPApp a;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&a));
  a->comm        = comm;
  a->loadSteps   = 1;
  a->loadBefore  = -1.0; /* no converged step before the first */
  a->maxCutbacks = 20;
  a->debugErrorRank = -1;
  a->minIncrement = 1e-4;
  a->growAfter    = 4;
  a->progress.interval = 10.0;
  PetscCall(PetscTime(&a->progress.t0));
  a->progress.last = a->progress.t0;
  PetscCall(SPLogRegister(&a->log));
  *app = a;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode RunLine(SPApp);

static PetscErrorCode LoadingSetFromOptions(SPApp a)
{
  PetscBool floorSet;

  PetscFunctionBeginUser;
  PetscOptionsBegin(a->comm, NULL, "Loading options", "spcontact");
  PetscCall(PetscOptionsInt("-load_steps", "Number of load steps (load factor k/N scales loads, Dirichlet values, obstacle motion)", "SPAppSetUp", a->loadSteps, &a->loadSteps, NULL));
  PetscCall(PetscOptionsString("-restart", "Resume a load-stepped run from the last converged step stored in this .h5 (or .h5.part) file of an interrupted or failed run (same mesh and options, any rank count)", "SPAppSetUp", a->restartFile, a->restartFile, sizeof(a->restartFile), NULL));
  PetscCall(PetscOptionsInt("-debug_interrupt_after_step", "Testing: rank 0 raises SIGTERM after this converged load step (0: never)", "SPAppSetUp", a->signals.debugStep, &a->signals.debugStep, NULL));
  PetscCall(PetscOptionsInt("-debug_error_on_rank", "Testing: this rank alone raises a one-line error before the first load step, as an internal error would (-1: never)", "SPAppSetUp", a->debugErrorRank, &a->debugErrorRank, NULL));
  PetscCall(PetscOptionsInt("-load_max_cutbacks", "Budget of the run: total times a failing load increment may be halved before the run stops", "SPAppSetUp", a->maxCutbacks, &a->maxCutbacks, NULL));
  PetscCall(PetscOptionsInt("-load_grow_after", "After a cut-back, double the increment (up to 1/load_steps) after this many converged steps in a row (0: never)", "SPAppSetUp", a->growAfter, &a->growAfter, NULL));
  PetscCall(PetscOptionsReal("-load_min_increment", "Floor of the cut-back: the run stops rather than halve the load-factor increment below this", "SPAppSetUp", a->minIncrement, &a->minIncrement, &floorSet));
  PetscCall(PetscOptionsReal("-max_wall_time", "Seconds: no new load step starts after this wall time; the run stops keeping its converged steps (status stopped, exit 3; -restart its .h5.part to go on; 0: no limit)", "SPAppSetUp", a->maxWallTime, &a->maxWallTime, NULL));
  PetscCall(PetscOptionsBool("-quiet", "No progress lines on stdout: neither the run line nor the lines per load step and per -progress_interval (the summary is still printed)", "SPAppSetUp", a->progress.quiet, &a->progress.quiet, NULL));
  PetscCall(PetscOptionsReal("-progress_interval", "Seconds: within a load step, a progress line per Newton iteration at most this often (0: every Newton iteration)", "SPAppSetUp", a->progress.interval, &a->progress.interval, NULL));
  PetscOptionsEnd();
  PetscCheck(a->minIncrement > 0.0 && a->minIncrement <= 1.0, a->comm, PETSC_ERR_USER_INPUT, "-load_min_increment %.6g: must be in (0, 1] (a load-factor increment)", (double)a->minIncrement);
  PetscCheck(!floorSet || a->minIncrement < 1.0 / a->loadSteps || a->loadSteps < 1, a->comm, PETSC_ERR_USER_INPUT, "-load_min_increment %.6g: not below the load step 1/%" PetscInt_FMT " (no cut-back could happen); give a smaller floor, or -load_max_cutbacks 0 for none", (double)a->minIncrement, a->loadSteps);
  PetscCheck(a->signals.debugStep >= 0, a->comm, PETSC_ERR_USER_INPUT, "-debug_interrupt_after_step %" PetscInt_FMT ": must be >= 0 (0: never)", a->signals.debugStep);
  PetscCheck(a->progress.interval >= 0.0 && !PetscIsInfOrNanReal(a->progress.interval), a->comm, PETSC_ERR_USER_INPUT, "-progress_interval %.6g: must be a number of seconds >= 0 (0: a line every Newton iteration; -quiet: none)", (double)a->progress.interval);
  PetscCheck(a->maxWallTime >= 0.0, a->comm, PETSC_ERR_USER_INPUT, "-max_wall_time %.6g: must be >= 0 seconds (0: no limit)", (double)a->maxWallTime);
  PetscCheck(a->loadSteps >= 1, a->comm, PETSC_ERR_USER_INPUT, "-load_steps %" PetscInt_FMT ": need at least one load step", a->loadSteps);
  PetscCheck(a->growAfter >= 0, a->comm, PETSC_ERR_USER_INPUT, "-load_grow_after %" PetscInt_FMT ": must be >= 0 (0: the increment never grows back)", a->growAfter);
  PetscCheck(a->maxCutbacks >= 0, a->comm, PETSC_ERR_USER_INPUT, "-load_max_cutbacks %" PetscInt_FMT ": must be >= 0", a->maxCutbacks);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Options that each make sense but not together */
static PetscErrorCode CheckCombination(SPApp a)
{
  PetscBool contact, help;

  PetscFunctionBeginUser;
  PetscCall(SPContactIsActive(a->contact, &contact));
  PetscCheck(!(contact && a->problem->mmsAmp != 0.0), a->comm, PETSC_ERR_USER_INPUT, "-material_mms: the manufactured solution is a contact-free verification (its exact solution ignores contact); drop -material_mms or the contact options");
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (!help) PetscCall(SPBCCheckBodies(a->dm, a->contact)); /* each body (or group linked by pairs) held on its own */
  if (!help) PetscCall(SPBCCheckAbsorbed(a->dm, a->problem)); /* a load on held dofs only */
  if (!help) PetscCall(SPBCCheckBalance(a->dm, a->problem, a->contact)); /* -help alone sets up a box with no condition */
  if (!help) PetscCall(SPBCCheckBodiesInPairs(a->dm, a->contact)); /* each body in a pair, the others held still */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The global cells and vertices (a->cells, a->vertices), each counted once at its owner; once, at
   the set-up, for the run line and the summary. Collective. */
static PetscErrorCode MeshCounts(SPApp a)
{
  PetscInt        cStart, cEnd, vStart, vEnd, n[2], N[2], nleaves;
  PetscSF         sf;
  const PetscInt *leaves;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(a->dm, 0, &cStart, &cEnd));
  PetscCall(DMPlexGetDepthStratum(a->dm, 0, &vStart, &vEnd));
  PetscCall(DMGetPointSF(a->dm, &sf));
  PetscCall(PetscSFGetGraph(sf, NULL, &nleaves, &leaves, NULL));
  n[0] = cEnd - cStart;
  n[1] = vEnd - vStart;
  for (PetscInt l = 0; l < (nleaves > 0 ? nleaves : 0); ++l) {
    const PetscInt p = leaves ? leaves[l] : l;
    if (p >= vStart && p < vEnd) n[1]--; /* count each vertex once, at its owner */
    if (p >= cStart && p < cEnd) n[0]--;
  }
  PetscCallMPI(MPI_Allreduce(n, N, 2, MPIU_INT, MPI_SUM, a->comm));
  a->cells    = N[0];
  a->vertices = N[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPAppSetUp(SPApp a)
{
  PetscBool help;

  PetscFunctionBeginUser;
  PetscCall(SPOptionsCheckNamedValues(a->comm));
  PetscCall(LoadingSetFromOptions(a));
  PetscCall(PetscLogStagePush(a->log.mesh));
  PetscCall(SPMeshCreate(a->comm, &a->dm));
  PetscCall(MeshCounts(a));
  PetscCall(PetscLogStagePop());
  PetscCall(PetscLogStagePush(a->log.setup));
  PetscCall(SPProblemCreate(a->dm, &a->problem));
  PetscCall(SPProblemSetFromOptions(a->problem));
  PetscCall(SPContactCreate(a->dm, a->problem, a->log.contactSearch, &a->contact));
  PetscCall(SPContactSetFromOptions(a->contact));
  PetscCall(SPOutputCreate(a->dm, &a->output));
  PetscCall(SPOutputSetFromOptions(a->output));
  PetscCall(SPProblemSetUp(a->problem));
  PetscCall(SPContactSetUp(a->contact));
  PetscCall(CheckCombination(a));
  PetscCall(SPSolverCreate(a->dm, a->problem, a->contact, &a->log, &a->solver));
  PetscCall(SPSolverSetFromOptions(a->solver));
  SPSolverSetProgress(a->solver, &a->progress);
  PetscCall(SPOptionsCheckValues(a->comm)); /* every option of the set-up read: none lost its value */
  PetscCall(DMCreateGlobalVector(a->dm, &a->u));
  PetscCall(PetscObjectSetName((PetscObject)a->u, "displacement"));
  PetscCall(VecSet(a->u, 0.0));
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (!help) PetscCall(SPRestartLoad(a)); /* before the output files (re)open */
  if (!help) PetscCall(SPOutputOpen(a->output)); /* -help lists the options and writes no file */
  if (!help) PetscCall(RunLine(a));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The run's status for the h5 and the summary */
static const char *RunStatus(SPApp a)
{
  if (a->interrupted) return "interrupted";
  if (a->wallStopped) return "stopped";
  return a->converged ? "complete" : "failed";
}

/* The process's exit code for that status (README, Running): a batch script tells a planned stop
   (-max_wall_time, a signal), which a restart continues, from a step that did not converge */
static int ExitCode(SPApp a)
{
  if (a->interrupted) return 128 + a->interrupted;
  if (a->wallStopped) return 3;
  return a->converged ? 0 : 2;
}

PetscErrorCode SPAppRun(SPApp a, int *code)
{
  PetscBool on;

  PetscFunctionBeginUser;
  PetscCall(SPSignalsInstall(&a->signals));
  PetscCall(PetscLogStagePush(a->log.solve));
  PetscCall(SPLoadingRun(a));
  PetscCall(PetscLogStagePop());
  PetscCall(PetscLogStagePush(a->log.output));
  PetscCall(SPContactIsActive(a->contact, &on));
  if (on) {
    char file[PETSC_MAX_PATH_LEN + 32];
    PetscCall(SPOutputGetPointsFile(a->output, file, sizeof(file)));
    PetscCall(SPOutputWriteBegin(a->output, file, PETSC_FALSE));
    PetscCall(SPOutputWriteEnd(a->output, SPContactWritePoints(a->contact, a->u, file)));
  }
  PetscCall(SPOutputClose(a->output, a->contact, RunStatus(a), a->stepsDone, a->loadReached));
  PetscCall(PetscLogStagePop());
  PetscCall(SPSignalsRestore(&a->signals));
  *code = ExitCode(a);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One line on stdout before the first load step (not with -quiet): what this run is */
static PetscErrorCode RunLine(SPApp a)
{
  PetscInt    dofs, dim;
  PetscMPIInt size;
  char        contact[256], linear[256];

  PetscFunctionBeginUser;
  if (a->progress.quiet) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Comm_size(a->comm, &size));
  PetscCall(DMGetDimension(a->dm, &dim));
  PetscCall(VecGetSize(a->u, &dofs));
  PetscCall(SPContactDescribe(a->contact, contact, sizeof(contact)));
  PetscCall(SPSolverDescribeLinear(a->solver, linear, sizeof(linear)));
  PetscCall(PetscPrintf(a->comm, "run: %" PetscInt_FMT "D, %" PetscInt_FMT " dofs, %" PetscInt_FMT " cells, %d rank%s; %" PetscInt_FMT " load step%s; %s; linear solver %s\n", dim, dofs, a->cells, size, size == 1 ? "" : "s", a->loadSteps, a->loadSteps == 1 ? "" : "s", contact, linear));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MeshSummary(SPApp a, PetscViewer v)
{
  PetscInt    dofs, dim, degree;
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(a->comm, &size));
  PetscCall(DMGetDimension(a->dm, &dim));
  PetscCall(VecGetSize(a->u, &dofs));
  PetscCall(SPProblemGetDegree(a->problem, &degree));
  PetscCall(PetscViewerASCIIPrintf(v, "ranks %d\ndim %" PetscInt_FMT "\ncells %" PetscInt_FMT "\nvertices %" PetscInt_FMT "\ndofs %" PetscInt_FMT "\nfe_degree %" PetscInt_FMT "\n", size, dim, a->cells, a->vertices, dofs, degree));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Peak resident memory of this process in MiB (Linux VmHWM; -1 where /proc is not available) */
static PetscReal PeakMemoryMiB(void)
{
  FILE     *fp = fopen("/proc/self/status", "r");
  char      line[256];
  PetscReal kb = -1024.0;

  if (!fp) return -1.0;
  while (fgets(line, sizeof(line), fp))
    if (!strncmp(line, "VmHWM:", 6)) kb = atof(line + 6);
  fclose(fp);
  return kb / 1024.0;
}

/* The summary block: one `key value` per line, the same keys every run (contact_* only with contact). */
PetscErrorCode SPAppSummary(SPApp a)
{
  PetscViewer    v = PETSC_VIEWER_STDOUT_(a->comm);
  PetscInt       newton, linear, functions, reuses, refined, refinedLinear, accepted, directStep;
  PetscReal      umax, err;
  PetscBool      hasErr, on;
  PetscLogDouble t1;
  const char    *prefix, *bulk, *ksp, *pc;

  PetscFunctionBeginUser;
  PetscCall(SPSolverGetCounts(a->solver, &newton, &linear, &functions));
  PetscCall(VecNorm(a->u, NORM_INFINITY, &umax));
  PetscCall(SPProblemComputeError(a->problem, a->u, &hasErr, &err));
  PetscCall(SPOutputGetPrefix(a->output, &prefix));
  PetscCall(PetscTime(&t1));
  PetscCall(PetscViewerASCIIPrintf(v, "=== spcontact summary ===\n"));
  PetscCall(PetscViewerASCIIPrintf(v, "spcontact_version %s\n", SP_VERSION));
  PetscCall(MeshSummary(a, v));
  PetscCall(PetscViewerASCIIPrintf(v, "status %s\n", RunStatus(a)));
  PetscCall(PetscViewerASCIIPrintf(v, "converged %s\nload_steps %" PetscInt_FMT "\ncutbacks %" PetscInt_FMT "\nload_factor %g\n", a->converged ? "yes" : "no", a->stepsDone, a->cutbacks, (double)a->loadReached));
  PetscCall(PetscViewerASCIIPrintf(v, "newton_iterations %" PetscInt_FMT "\nlinear_iterations %" PetscInt_FMT "\nfunction_evaluations %" PetscInt_FMT "\n", newton, linear, functions));
  PetscCall(SPSolverGetJacobianReuses(a->solver, &reuses));
  PetscCall(PetscViewerASCIIPrintf(v, "jacobian_reuses %" PetscInt_FMT "\n", reuses));
  PetscCall(SPSolverGetPCKeeps(a->solver, &reuses));
  PetscCall(PetscViewerASCIIPrintf(v, "preconditioner_kept %" PetscInt_FMT "\n", reuses));
  PetscCall(SPSolverGetRefinements(a->solver, &refined, &refinedLinear));
  PetscCall(PetscViewerASCIIPrintf(v, "refined_steps %" PetscInt_FMT "\nrefinement_linear_iterations %" PetscInt_FMT "\n", refined, refinedLinear));
  PetscCall(SPSolverGetAccepted(a->solver, &accepted));
  PetscCall(PetscViewerASCIIPrintf(v, "linear_solves_accepted %" PetscInt_FMT "\n", accepted));
  PetscCall(PetscViewerASCIIPrintf(v, "krylov_reorthogonalised %s\n", SPSolverReorthogonalises(a->solver) ? "yes" : "no"));
  PetscCall(SPSolverGetDirectStep(a->solver, &directStep));
  PetscCall(PetscViewerASCIIPrintf(v, "direct_solver_from_step %" PetscInt_FMT "\n", directStep));
  PetscCall(SPSolverGetLinearSolver(a->solver, &ksp, &pc));
  PetscCall(PetscViewerASCIIPrintf(v, "linear_solver %s/%s\n", ksp ? ksp : "none", pc ? pc : "none"));
  PetscCall(SPSolverGetBulkOperator(a->solver, &bulk));
  PetscCall(PetscViewerASCIIPrintf(v, "bulk_operator %s\n", bulk));
  PetscCall(PetscViewerASCIIPrintf(v, "displacement_max %.10e\n", (double)umax));
  if (hasErr) PetscCall(PetscViewerASCIIPrintf(v, "l2_error %.10e\n", (double)err)); /* -material_mms only */
  PetscCall(SPContactIsActive(a->contact, &on));
  if (on && !a->converged && !a->interrupted) PetscCall(SPContactEvaluateFinal(a->contact, a->u));
  if (on) PetscCall(SPContactView(a->contact, v));
  {
    PetscReal mem = PeakMemoryMiB(), memMax;
    PetscCallMPI(MPI_Allreduce(&mem, &memMax, 1, MPIU_REAL, MPI_MAX, a->comm));
    PetscCall(PetscViewerASCIIPrintf(v, "memory_peak_rank_mib %.1f\n", (double)memMax));
  }
  PetscCall(PetscViewerASCIIPrintf(v, "output_prefix %s\n", prefix));
  PetscCall(PetscViewerASCIIPrintf(v, "wall_time %.3f\n", (double)(t1 - a->progress.t0)));
  PetscCall(PetscViewerASCIIPrintf(v, "=== end summary ===\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPAppDestroy(SPApp *app)
{
  SPApp a = *app;

  PetscFunctionBeginUser;
  if (!a) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPSignalsRestore(&a->signals));
  PetscCall(VecDestroy(&a->u));
  PetscCall(SPSolverDestroy(&a->solver));
  PetscCall(SPOutputDestroy(&a->output));
  PetscCall(SPContactDestroy(&a->contact));
  if (a->problem) PetscCall(SPProblemDestroy(&a->problem));
  PetscCall(DMDestroy(&a->dm));
  PetscCall(PetscFree(*app));
  PetscFunctionReturn(PETSC_SUCCESS);
}
