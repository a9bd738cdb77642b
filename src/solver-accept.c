/* A linear solve that stopped short of its tolerance: GMRES at its iteration limit (-ksp_max_it),
   or a breakdown at a restart (the residual of the Arnoldi recursion drifted from the true one, as
   with friction at alpha ~ 1000). If its true residual |b - A x| is at most -solver_linear_accept
   x |b|, x is a usable inexact Newton step (a forcing term of that size still reduces |F|), so the
   solve counts as converged (KSP_CONVERGED_ITS) instead of failing the Newton solve into a
   recovery or a cut-back. The next Newton iteration solves again from the new iterate. */
#include <spcontact-impl.h>
#include <petsc/private/kspimpl.h> /* ksp->reason: PETSc 3.18 has no setter */

static PetscErrorCode AcceptShortSolve(KSP ksp, Vec b, Vec x, void *ctx)
{
  SPSolver           s = (SPSolver)ctx;
  KSPConvergedReason kr;
  Mat                A;
  Vec                r;
  PetscReal          rn, bn;

  PetscFunctionBeginUser;
  PetscCall(KSPGetConvergedReason(ksp, &kr));
  if (s->acceptRtol <= 0.0 || (kr != KSP_DIVERGED_ITS && kr != KSP_DIVERGED_BREAKDOWN)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(KSPGetOperators(ksp, &A, NULL));
  PetscCall(VecDuplicate(b, &r));
  PetscCall(MatMult(A, x, r));
  PetscCall(VecAYPX(r, -1.0, b));
  PetscCall(VecNorm(r, NORM_2, &rn));
  PetscCall(VecNorm(b, NORM_2, &bn));
  PetscCall(VecDestroy(&r));
  if (!(rn <= s->acceptRtol * bn)) { /* NaN fails too */
    PetscCall(PetscInfo(ksp, "linear solve stopped (%s) at true relative residual %g > -solver_linear_accept %g: not accepted\n", KSPConvergedReasons[kr], (double)(rn / bn), (double)s->acceptRtol));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  ksp->reason = KSP_CONVERGED_ITS;
  s->accepted++;
  PetscCall(PetscInfo(ksp, "linear solve stopped (%s) at true relative residual %g <= -solver_linear_accept %g: accepted as an inexact Newton step\n", KSPConvergedReasons[kr], (double)(rn / bn), (double)s->acceptRtol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPSolverSetUpAccept(SPSolver s)
{
  KSP ksp;

  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPSetPostSolve(ksp, AcceptShortSolve, s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Linear solves accepted short of their tolerance, over the run (summary key linear_solves_accepted) */
PetscErrorCode SPSolverGetAccepted(SPSolver s, PetscInt *accepted)
{
  PetscFunctionBeginUser;
  *accepted = s->accepted;
  PetscFunctionReturn(PETSC_SUCCESS);
}
