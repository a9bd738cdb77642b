static const char help[] = "spcontact: parallel FEM contact mechanics with the shifted penalty method.\n"
                           "Run `spcontact -help` for every option; the README documents them.\n";

#include <spcontact.h>

/* User-input errors print one line on rank 0 (no PETSc traceback); everything else keeps
   PETSc's full traceback. Set SPCONTACT_TRACEBACK=1 to see the traceback for input errors. */
static PetscErrorCode ErrorHandler(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  PetscMPIInt rank = 0;
  if (p != PETSC_ERROR_INITIAL) return n;
  if ((n == PETSC_ERR_USER_INPUT || n == PETSC_ERR_USER || n == PETSC_ERR_ARG_OUTOFRANGE || n == PETSC_ERR_ARG_WRONG) && !getenv("SPCONTACT_TRACEBACK")) {
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    if (rank == 0) fprintf(stderr, "spcontact: error: %s\n", mess ? mess : "(no message)");
    return n;
  }
  return PetscTraceBackErrorHandler(comm, line, fun, file, n, p, mess, ctx);
}

static PetscErrorCode Run(PetscBool *converged, int *interrupted)
{
  SPApp     app = NULL;
  PetscBool help;

  PetscFunctionBeginUser;
  PetscCall(SPAppCreate(PETSC_COMM_WORLD, &app));
  PetscCall(SPAppSetUp(app));
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (help) { /* -help lists the options of every module (set up above) and stops */
    *converged = PETSC_TRUE;
    PetscCall(SPAppDestroy(&app));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(SPAppRun(app, converged, interrupted));
  PetscCall(SPAppSummary(app));
  PetscCall(SPAppDestroy(&app));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscErrorCode ierr;
  PetscBool      converged = PETSC_FALSE;
  int            interrupted = 0; /* the signal that stopped the run */

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscPushErrorHandler(ErrorHandler, NULL));
  ierr = Run(&converged, &interrupted);
  if (ierr == PETSC_ERR_USER_INPUT || ierr == PETSC_ERR_USER || ierr == PETSC_ERR_ARG_OUTOFRANGE || ierr == PETSC_ERR_ARG_WRONG) {
    (void)PetscFinalize();
    return 1; /* bad input: one line on stderr */
  }
  if (ierr) PETSCABORT(PETSC_COMM_WORLD, ierr);
  if (interrupted) { /* SPLoadingRun printed how to restart */
    PetscCall(PetscFinalize());
    return 128 + interrupted;
  }
  if (!converged) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "spcontact: the solve did not converge; results above are for the last converged load step only\n"));
  PetscCall(PetscFinalize());
  return converged ? 0 : 2;
}
