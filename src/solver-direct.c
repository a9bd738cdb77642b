/* 2D runs factor their Jacobian with a sparse direct solver: small ones from the start, larger
   ones once the iterative solve struggles.
   A 2D factorization is cheap (nested dissection: fill n log n). With an optimized BLAS under
   MUMPS (OpenBLAS, which scripts/setup-deps.sh installs) it beats CG/GMRES + GAMG at every 2D
   size measured, 1e4 to 6e5 dofs, because the Jacobian is reused across shift updates and a
   factorization makes every Newton step exact (1 rank): B2 (9690 dofs) 0.29 -> 0.23 s, B2 refined
   twice (1.5e5 dofs) 21.8 -> 8.9 s, F2 (Cattaneo-Mindlin, friction, 1.8e4 dofs) 21.9 -> 7.6 s, B6
   (two discs) 1.77 -> 1.35 s (doc/performance.md, "2D: a factorization from the start"). So a 2D run
   with at most -solver_direct_dofs displacement dofs factors from its first solve. A larger one
   starts iterative, and once one linear solve takes more than -solver_direct_switch iterations,
   or fails, the rest of the run factors: at high alpha the penalty entries make the system
   ill-conditioned, and on two bodies GAMG's aggregates cannot follow them (F2 at alpha 1000 took
   about 160 s of GMRES with up to 2000 iterations per solve, B6 at alpha 1000 10141 CG
   iterations for 39 Newton iterations). MUMPS: Cholesky (LDL^T) where the Jacobian is symmetric
   (frictionless small strain), half the work (B2 as a process 0.33 -> 0.28 s); LU with friction
   or finite strain (PETSc's own LU on one process without MUMPS, for the switch only). Not from
   the start in 3D, where a factorization costs more than the iterations it saves (B3, 15887 dofs:
   4.7 s against 2.5 s with OpenBLAS, 20 s with the reference BLAS; F3, friction, 28062 dofs, alpha
   10: 203 s against 68 s, the same 71 Newton iterations), but a 3D run with GMRES (friction,
   finite strain) of at most -solver_direct_dofs_3d dofs switches once a solve takes more than
   -solver_direct_switch_3d (500) iterations or fails: F3 at alpha 1000, where GMRES + GAMG took up
   to 2000 iterations per solve (95 Newton iterations, 3 cut-backs, 35 minutes), converges with LU
   in 56 and none (about 2 minutes). Not when the user chose the solver
   (-ksp_type or -pc_type); -solver_direct_switch 0 keeps every solve iterative. The
   factorization is reused with the Jacobian (Jacobian reuse). A restart resumes with the solver
   of the interrupted run (the switch's step is in the restart data). */
#include <spcontact-impl.h>

/* Cholesky (LDL^T, MUMPS) where the Jacobian is symmetric at every iterate (frictionless small
   strain: MAT_SYMMETRY_ETERNAL, set in SPSolverSetUp), half the work of LU; else, or with
   -solver_direct_cholesky false, LU */
static PetscBool UseCholesky(SPSolver s)
{
  PetscBool set, sym, mumps;

  if (!s->directChol) return PETSC_FALSE;
  if (MatIsSymmetricKnown(s->J, &set, &sym) || !set || !sym) return PETSC_FALSE;
  if (MatGetFactorAvailable(s->J, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &mumps)) return PETSC_FALSE;
  return mumps;
}

/* The solver from here on: preonly + Cholesky or LU (MUMPS; LU: PETSc's own on one process
   without MUMPS) */
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
  PetscCall(PCSetType(pc, UseCholesky(s) ? PCCHOLESKY : PCLU));
  PetscCall(PCFactorSetMatSolverType(pc, mumps ? MATSOLVERMUMPS : MATSOLVERPETSC));
  /* MUMPS's working space: its estimate plus 50 % (MUMPS: 20 %). With 20 % the LDL^T of B2 on 3
     ranks stopped short of it (INFOG(1) = -9, INFO(2) = 1) and every cut-back failed alike */
  if (mumps) PetscCall(SPOptionsSetDefault("-mat_mumps_icntl_14", "50"));
  s->directAllowed = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* "LU" or "Cholesky", for the messages */
static const char *FactorName(SPSolver s)
{
  return UseCholesky(s) ? "Cholesky" : "LU";
}

/* The option that sets this run's switch threshold */
static const char *SwitchOption(SPSolver s)
{
  PetscInt dim = 2;

  (void)DMGetDimension(s->dm, &dim);
  return dim == 3 ? "-solver_direct_switch_3d" : "-solver_direct_switch";
}

/* The linear solver for the run line (app.c): ksp/pc, and when a run factors */
PetscErrorCode SPSolverDescribeLinear(SPSolver s, char *buf, size_t len)
{
  const char *ksp, *pc;

  PetscFunctionBeginUser;
  PetscCall(SPSolverGetLinearSolver(s, &ksp, &pc));
  ksp = ksp ? ksp : "none";
  pc  = pc ? pc : "none";
  if (s->directStart) PetscCall(PetscSNPrintf(buf, len, "%s/%s (MUMPS %s from the first solve: 2D with at most -solver_direct_dofs %" PetscInt_FMT " dofs)", ksp, pc, FactorName(s), s->directDofs));
  else if (s->directAllowed) PetscCall(PetscSNPrintf(buf, len, "%s/%s (a sparse direct solver once a solve takes more than %s %" PetscInt_FMT " iterations)", ksp, pc, SwitchOption(s), s->switchIts));
  else PetscCall(PetscSNPrintf(buf, len, "%s/%s", ksp, pc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After SNESSetFromOptions: whether this run factors from the start (2D, at most directDofs dofs,
   MUMPS), or may switch later (2D, a factorization available; 3D GMRES runs up to directDofs3,
   MUMPS); neither with the user's solver or a switch threshold 0 */
PetscErrorCode SPSolverSetUpDirect(SPSolver s)
{
  PetscInt    dim, N;
  PetscBool   kspSet, pcSet, mumps;
  PetscMPIInt size;

  PetscFunctionBeginUser;
  s->directAllowed = s->directStart = PETSC_FALSE;
  PetscCall(DMGetDimension(s->dm, &dim));
  PetscCall(PetscOptionsHasName(NULL, NULL, "-ksp_type", &kspSet));
  PetscCall(PetscOptionsHasName(NULL, NULL, "-pc_type", &pcSet));
  if (kspSet || pcSet) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MatGetFactorAvailable(s->J, MATSOLVERMUMPS, MAT_FACTOR_LU, &mumps));
  PetscCall(MatGetSize(s->J, &N, NULL));
  if (dim == 3) { /* the switch only, GMRES runs, up to directDofs3 */
    KSP       ksp;
    PetscBool gmres;
    PetscCall(SNESGetKSP(s->snes, &ksp));
    PetscCall(PetscObjectTypeCompare((PetscObject)ksp, KSPGMRES, &gmres));
    s->switchIts     = s->directIts3;
    s->directAllowed = gmres && mumps && s->directIts3 > 0 && N <= s->directDofs3 ? PETSC_TRUE : PETSC_FALSE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  s->switchIts = s->directIts;
  if (s->directIts <= 0 || dim != 2) PetscFunctionReturn(PETSC_SUCCESS);
  if (mumps && N <= s->directDofs) {
    PetscCall(SetDirect(s));
    s->directStart = PETSC_TRUE;
    s->directStep  = 1;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)s->dm), &size));
  if (!mumps && size > 1) PetscFunctionReturn(PETSC_SUCCESS);
  s->directAllowed = PETSC_TRUE;
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
  PetscInt dim;
  PetscCall(DMGetDimension(s->dm, &dim));
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)s->dm), "linear solver: %s %s (%" PetscInt_FMT "D): from here on a sparse direct solver (%s); %s 0 keeps the iterative one\n", ktype, why, dim, FactorName(s), SwitchOption(s)));
  PetscCall(SetDirect(s));
  s->directStep = s->step;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A restart of a run that had switched in load step `step` (0: it had not): the same solver
   again, unless this run may not switch (-solver_direct_switch 0, the user's -ksp_type/-pc_type) */
PetscErrorCode SPSolverResumeDirect(SPSolver s, PetscInt step)
{
  PetscFunctionBeginUser;
  if (s->directStart) PetscFunctionReturn(PETSC_SUCCESS); /* direct from the start again (directStep 1) */
  s->directStep = 0;
  if (step <= 0 || !s->directAllowed) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)s->dm), "linear solver: the sparse direct solver (%s) of the interrupted run, from its load step %" PetscInt_FMT "; %s 0 keeps the iterative one\n", FactorName(s), step, SwitchOption(s)));
  PetscCall(SetDirect(s));
  s->directStep = step;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* At a Newton iteration boundary: the last linear solve took lits iterations */
PetscErrorCode SPSolverDirectCheck(SPSolver s, PetscInt lits)
{
  char why[128];

  PetscFunctionBeginUser;
  if (!s->directAllowed || lits <= s->switchIts) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(why, sizeof(why), "took %" PetscInt_FMT " iterations in one solve (%s %" PetscInt_FMT ")", lits, SwitchOption(s), s->switchIts));
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
