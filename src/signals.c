/* SIGTERM and SIGINT: the handler only records which signal came; the load-step loop asks at its
   safe point (after a converged step is written) with SPSignalsPending, collectively, so every
   rank stops after the same step. A second signal of the same kind while the first is pending
   restores the default action and re-raises it: the run ends at once (its files keep .part
   names). The recorded signal number is the code's only file-scope variable: a handler can
   leave it nowhere else. mpiexec forwards SIGTERM and SIGINT to the ranks. */
#include <spcontact-impl.h>
#include <signal.h>

static volatile sig_atomic_t caught = 0;

static void Handler(int sig)
{
  if (caught == sig) { /* asked twice: stop now */
    signal(sig, SIG_DFL);
    raise(sig);
    return;
  }
  caught = sig;
}

/* Replaces the handlers of SIGTERM and SIGINT (PETSc's included) until SPSignalsRestore */
PetscErrorCode SPSignalsInstall(SPSignals *s)
{
  PetscFunctionBeginUser;
  caught     = 0;
  s->oldTerm = signal(SIGTERM, Handler);
  s->oldInt  = signal(SIGINT, Handler);
  PetscCheck(s->oldTerm != SIG_ERR && s->oldInt != SIG_ERR, PETSC_COMM_SELF, PETSC_ERR_SYS, "cannot install the SIGTERM/SIGINT handlers");
  s->installed = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPSignalsRestore(SPSignals *s)
{
  PetscFunctionBeginUser;
  if (!s->installed) PetscFunctionReturn(PETSC_SUCCESS);
  (void)signal(SIGTERM, s->oldTerm);
  (void)signal(SIGINT, s->oldInt);
  s->installed = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After converged load step `step`: the signal any rank caught (0: none), the same on every rank.
   -debug_interrupt_after_step k makes rank 0 raise SIGTERM itself after step k (tests). */
PetscErrorCode SPSignalsPending(MPI_Comm comm, SPSignals *s, PetscInt step, int *sig)
{
  PetscMPIInt rank;
  int         mine;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0 && s->debugStep > 0 && step == s->debugStep) PetscCheck(!raise(SIGTERM), PETSC_COMM_SELF, PETSC_ERR_SYS, "raise(SIGTERM) failed");
  mine = (int)caught;
  PetscCallMPI(MPI_Allreduce(&mine, sig, 1, MPI_INT, MPI_MAX, comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}
