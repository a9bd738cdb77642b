/* A 2D run whose iterative linear solves struggle goes on with a sparse direct solver.
   At high alpha the penalty entries make the system ill-conditioned, and on two bodies GAMG's
   aggregates cannot follow them: F2 (Cattaneo-Mindlin, friction) at alpha 1000 took about 160 s
   of GMRES with up to 2000 iterations per solve, B6 (two discs) at alpha 1000 10141 CG iterations
   for 39 Newton iterations. A 2D factorization is cheap (nested dissection: fill n log n), so once
   one linear solve takes more than -solver_direct_switch iterations, or fails, the rest of the run
   factors the Jacobian (LU, MUMPS; PETSc's own LU on one process without MUMPS): F2 at alpha 1000
   in 19 s, B6 in 5 s, the same Newton iterations within 2. The default 100 is about three times
   the break-even at 2e4 dofs (a factorization costs 30 to 40 Krylov iterations there): it also
   takes F2 at alpha 100 from 22.6 to 10.7 s, and leaves every run at alpha 10 iterative. Not in
   3D, where a factorization with Debian's reference BLAS costs far more than the iterations it
   saves (B3, 15887 dofs: 20 s against 2.5 s), and not when the user chose the solver (-ksp_type
   or -pc_type). The factorization is reused with the Jacobian (Jacobian reuse). A restart resumes
   with the solver of the interrupted run (the switch's step is in the restart data). */
#include <spcontact-impl.h>

/* After SNESSetFromOptions: whether this run may switch (2D, the solver not the user's, a
   factorization available) */
PetscErrorCode SPSolverSetUpDirect(SPSolver s)
{
  PetscInt    dim;
  PetscBool   kspSet, pcSet, mumps;
  PetscMPIInt size;

  PetscFunctionBeginUser;
  s->directAllowed = PETSC_FALSE;
  PetscCall(DMGetDimension(s->dm, &dim));
  PetscCall(PetscOptionsHasName(NULL, NULL, "-ksp_type", &kspSet));
  PetscCall(PetscOptionsHasName(NULL, NULL, "-pc_type", &pcSet));
  if (s->directIts <= 0 || dim != 2 || kspSet || pcSet) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MatGetFactorAvailable(s->J, MATSOLVERMUMPS, MAT_FACTOR_LU, &mumps));
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)s->dm), &size));
  if (!mumps && size > 1) PetscFunctionReturn(PETSC_SUCCESS);
  s->directAllowed = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The solver from here on: preonly + LU (MUMPS, else PETSc's own on one process) */
static PetscErrorCode SetDirect(SPSolver s)
{
  KSP       ksp;
  PC        pc;
  PetscBool mumps;

  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(MatGetFactorAvailable(s->J, MATSOLVERMUMPS, MAT_FACTOR_LU, &mumps));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCLU));
  PetscCall(PCFactorSetMatSolverType(pc, mumps ? MATSOLVERMUMPS : MATSOLVERPETSC));
  s->directAllowed = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The switch itself; why: what the last solve did, for the one-line message */
static PetscErrorCode SwitchToDirect(SPSolver s, const char *why)
{
  KSP     ksp;
  KSPType ktype;

  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPGetType(ksp, &ktype));
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)s->dm), "linear solver: %s %s (2D): from here on a sparse direct solver (LU); -solver_direct_switch 0 keeps the iterative one\n", ktype, why));
  PetscCall(SetDirect(s));
  s->directStep = s->step;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A restart of a run that had switched in load step `step` (0: it had not): the same solver
   again, unless this run may not switch (-solver_direct_switch 0, the user's -ksp_type/-pc_type) */
PetscErrorCode SPSolverResumeDirect(SPSolver s, PetscInt step)
{
  PetscFunctionBeginUser;
  s->directStep = 0;
  if (step <= 0 || !s->directAllowed) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)s->dm), "linear solver: the sparse direct solver (LU) of the interrupted run, from its load step %" PetscInt_FMT "; -solver_direct_switch 0 keeps the iterative one\n", step));
  PetscCall(SetDirect(s));
  s->directStep = step;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* At a Newton iteration boundary: the last linear solve took lits iterations */
PetscErrorCode SPSolverDirectCheck(SPSolver s, PetscInt lits)
{
  char why[128];

  PetscFunctionBeginUser;
  if (!s->directAllowed || lits <= s->directIts) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(why, sizeof(why), "took %" PetscInt_FMT " iterations in one solve (-solver_direct_switch %" PetscInt_FMT ")", lits, s->directIts));
  PetscCall(SwitchToDirect(s, why));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A Newton solve that failed in its linear solve: switch and solve the step again (*retry) */
PetscErrorCode SPSolverRecoverDirect(SPSolver s, PetscBool *retry)
{
  KSP                ksp;
  KSPConvergedReason kr;
  char               why[128];

  PetscFunctionBeginUser;
  *retry = PETSC_FALSE;
  if (!s->directAllowed) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPGetConvergedReason(ksp, &kr));
  PetscCall(PetscSNPrintf(why, sizeof(why), "failed (%s); the load step again", KSPConvergedReasons[kr]));
  PetscCall(SwitchToDirect(s, why));
  *retry = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether each Newton step is a direct solve (-ksp_type preonly: the switch's LU or the user's):
   its step is exact, and its factorization belongs to one Jacobian */
PetscErrorCode SPSolverIsDirect(SPSolver s, PetscBool *direct)
{
  KSP ksp;

  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(PetscObjectTypeCompare((PetscObject)ksp, KSPPREONLY, direct));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The load step from which the run factors its Jacobian (0: never; summary key direct_solver_from_step) */
PetscErrorCode SPSolverGetDirectStep(SPSolver s, PetscInt *step)
{
  PetscFunctionBeginUser;
  *step = s->directStep;
  PetscFunctionReturn(PETSC_SUCCESS);
}
