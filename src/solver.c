/* Solver: SNES Newton whose FormFunction/FormJacobian wrap PETSc's DMPlex FEM routines and add
   the contact terms. The shift update hook is a line-search post-check on the accepted iterate
   (it flags the iterate as changed, so SNES recomputes the residual and its norm for the new
   shift); a contact-aware test wraps SNESConvergedDefault (solver-converged.c). */
#include <spcontact-impl.h>

/* Bulk residual (and Neumann terms), added into the local vector locF: the fast element operator
   when it applies, PETSc's FEM residual otherwise */
static PetscErrorCode BulkResidual(SPSolver s, Vec locX, Vec locF)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(s->log->bulkResidual, 0, 0, 0, 0));
  if (s->fast) PetscCall(SPFastElasticAddResidual(s->fast, locX, locF));
  else PetscCall(DMPlexSNESComputeResidualFEM(s->dm, locX, locF, NULL));
  PetscCall(PetscLogEventEnd(s->log->bulkResidual, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode BulkJacobian(SPSolver s, Vec locX, Mat P)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(s->log->bulkJacobian, 0, 0, 0, 0));
  PetscCall(MatZeroEntries(P));
  if (s->fast) PetscCall(SPFastElasticAddJacobian(s->fast, locX, P));
  else PetscCall(DMPlexSNESComputeJacobianFEM(s->dm, locX, P, P, NULL));
  PetscCall(PetscLogEventEnd(s->log->bulkJacobian, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The matrix against DMCreateMatrix's (nonzeros, allocation, block size) and its rigid-body modes
   against DMPlexCreateRigidBody's (max norm of the differences) */
static PetscErrorCode CheckMatrix(SPSolver s)
{
  Mat          R;
  MatInfo      a, b;
  PetscInt     bsA, bsB, nA, nB;
  MatNullSpace spA, spB;
  const Vec   *vA, *vB;
  PetscReal    diff = 0.0;

  PetscFunctionBeginUser;
  PetscCall(MatGetNearNullSpace(s->J, &spA));
  PetscCall(DMPlexCreateRigidBody(s->dm, 0, &spB));
  PetscCall(MatNullSpaceGetVecs(spA, NULL, &nA, &vA));
  PetscCall(MatNullSpaceGetVecs(spB, NULL, &nB, &vB));
  for (PetscInt k = 0; k < PetscMin(nA, nB); ++k) {
    Vec       d;
    PetscReal nd;
    PetscCall(VecDuplicate(vA[k], &d));
    PetscCall(VecWAXPY(d, -1.0, vA[k], vB[k]));
    PetscCall(VecNorm(d, NORM_INFINITY, &nd));
    PetscCall(VecDestroy(&d));
    diff = PetscMax(diff, nd);
  }
  if (nA != nB) diff = PETSC_MAX_REAL;
  PetscCall(MatNullSpaceDestroy(&spB));
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)s->dm), "rigid_body_check modes %" PetscInt_FMT " max_difference %.3e\n", nA, (double)diff));
  PetscCall(DMCreateMatrix(s->dm, &R));
  PetscCall(MatGetInfo(s->J, MAT_GLOBAL_SUM, &a));
  PetscCall(MatGetInfo(R, MAT_GLOBAL_SUM, &b));
  PetscCall(MatGetBlockSize(s->J, &bsA));
  PetscCall(MatGetBlockSize(R, &bsB));
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)s->dm), "matrix_check nonzeros %.0f allocated %.0f block_size %" PetscInt_FMT " dmcreatematrix_nonzeros %.0f block_size %" PetscInt_FMT "\n", a.nz_used, a.nz_allocated, bsA, b.nz_used, bsB));
  PetscCall(MatDestroy(&R));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -solver_check_fast: residual and Jacobian of both bulk operators at one random state (Dirichlet
   values and loads of the current load factor); prints |r_fast - r|/|r| and ||K_fast - K||_F/||K||_F */
static PetscErrorCode CheckFast(SPSolver s)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)s->dm);
  Vec         X, locX, locF, F[2];
  Mat         A[2];
  PetscRandom rnd;
  PetscReal   nr, dr, nK, dK;

  PetscFunctionBeginUser;
  PetscCall(CheckMatrix(s));
  if (!s->fast) {
    PetscCall(PetscPrintf(comm, "fast_check not_applicable (generic bulk operator)\n"));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(DMGetGlobalVector(s->dm, &X));
  PetscCall(PetscRandomCreate(comm, &rnd));
  PetscCall(VecSetRandom(X, rnd));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecScale(X, 1e-3));
  PetscCall(SPProblemGetLocalState(s->problem, X, &locX));
  PetscCall(DMGetLocalVector(s->dm, &locF));
  for (PetscInt k = 0; k < 2; ++k) {
    PetscCall(VecDuplicate(s->r, &F[k]));
    PetscCall(VecZeroEntries(locF));
    if (k) PetscCall(SPFastElasticAddResidual(s->fast, locX, locF));
    else PetscCall(DMPlexSNESComputeResidualFEM(s->dm, locX, locF, NULL));
    PetscCall(VecZeroEntries(F[k]));
    PetscCall(DMLocalToGlobal(s->dm, locF, ADD_VALUES, F[k]));
    PetscCall(MatDuplicate(s->J, MAT_DO_NOT_COPY_VALUES, &A[k]));
    PetscCall(MatZeroEntries(A[k]));
    if (k) PetscCall(SPFastElasticAddJacobian(s->fast, locX, A[k]));
    else PetscCall(DMPlexSNESComputeJacobianFEM(s->dm, locX, A[k], A[k], NULL));
  }
  PetscCall(VecNorm(F[0], NORM_2, &nr));
  PetscCall(VecAXPY(F[1], -1.0, F[0]));
  PetscCall(VecNorm(F[1], NORM_2, &dr));
  PetscCall(MatNorm(A[0], NORM_FROBENIUS, &nK));
  PetscCall(MatAXPY(A[1], -1.0, A[0], SAME_NONZERO_PATTERN));
  PetscCall(MatNorm(A[1], NORM_FROBENIUS, &dK));
  PetscCall(PetscPrintf(comm, "fast_check residual_rel_diff %.3e jacobian_rel_diff %.3e\n", (double)(dr / nr), (double)(dK / nK)));
  for (PetscInt k = 0; k < 2; ++k) {
    PetscCall(VecDestroy(&F[k]));
    PetscCall(MatDestroy(&A[k]));
  }
  PetscCall(DMRestoreLocalVector(s->dm, &locF));
  PetscCall(SPProblemRestoreLocalState(s->problem, &locX));
  PetscCall(DMRestoreGlobalVector(s->dm, &X));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Linear material: K once, into J (J = K + C, solver-stiffness.c); r0 = r(u_free = 0) once per
   load factor (loads, Dirichlet lifting). Again after the contact pattern of J grew (J zeroed). */
static PetscErrorCode BulkStiffness(SPSolver s)
{
  Vec zero, locX;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(s->dm, &zero));
  PetscCall(VecZeroEntries(zero));
  PetscCall(SPProblemGetLocalState(s->problem, zero, &locX));
  PetscCall(BulkJacobian(s, locX, s->J));
  PetscCall(SPProblemRestoreLocalState(s->problem, &locX));
  PetscCall(DMRestoreGlobalVector(s->dm, &zero));
  PetscCall(SPStiffnessSetUp(&s->stiff, s->J, s->contact));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode LinearParts(SPSolver s)
{
  PetscReal load;
  Vec       zero, locX, locF;

  PetscFunctionBeginUser;
  PetscCall(SPProblemGetLoadFactor(s->problem, &load));
  if (!s->stiff) {
    PetscCall(BulkStiffness(s));
    PetscCall(VecDuplicate(s->r, &s->r0));
    s->r0Load = PETSC_MAX_REAL;
  }
  if (s->r0Load != load) {
    PetscCall(DMGetGlobalVector(s->dm, &zero));
    PetscCall(VecZeroEntries(zero));
    PetscCall(SPProblemGetLocalState(s->problem, zero, &locX));
    PetscCall(DMGetLocalVector(s->dm, &locF));
    PetscCall(VecZeroEntries(locF));
    PetscCall(BulkResidual(s, locX, locF));
    PetscCall(VecZeroEntries(s->r0));
    PetscCall(DMLocalToGlobal(s->dm, locF, ADD_VALUES, s->r0));
    PetscCall(DMRestoreLocalVector(s->dm, &locF));
    PetscCall(SPProblemRestoreLocalState(s->problem, &locX));
    PetscCall(DMRestoreGlobalVector(s->dm, &zero));
    s->r0Load = load;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FormFunction(SNES snes, Vec X, Vec F, void *ctx)
{
  SPSolver  s = (SPSolver)ctx;
  Vec       locX, locF;
  PetscBool on;

  PetscFunctionBeginUser;
  PetscCall(SPContactIsActive(s->contact, &on));
  PetscCall(SPProblemGetLocalState(s->problem, X, &locX));
  PetscCall(DMGetLocalVector(s->dm, &locF));
  PetscCall(VecZeroEntries(locF));
  if (!s->reuse) PetscCall(BulkResidual(s, locX, locF));
  if (on) {
    PetscCall(PetscLogEventBegin(s->log->contactAssembly, 0, 0, 0, 0));
    PetscCall(SPContactAddResidual(s->contact, X, locF));
    PetscCall(PetscLogEventEnd(s->log->contactAssembly, 0, 0, 0, 0));
  }
  PetscCall(VecZeroEntries(F));
  PetscCall(DMLocalToGlobal(s->dm, locF, ADD_VALUES, F));
  if (s->reuse) { /* F += r0 + K X */
    PetscCall(LinearParts(s));
    PetscCall(PetscLogEventBegin(s->log->bulkResidual, 0, 0, 0, 0));
    PetscCall(SPStiffnessMultAdd(s->stiff, s->J, X, F));
    PetscCall(VecAXPY(F, 1.0, s->r0));
    PetscCall(PetscLogEventEnd(s->log->bulkResidual, 0, 0, 0, 0));
  }
  PetscCall(DMRestoreLocalVector(s->dm, &locF));
  PetscCall(SPProblemRestoreLocalState(s->problem, &locX));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Jacobian reuse: with a linear bulk, the Jacobian of an iterate whose active set is the one of
   the last assembly differs from it only through the contact geometry (normals, projections, the
   pressure in the curvature term), a change of the order of the displacement increment over the
   curvature radius. Keeping the assembled matrix then keeps the preconditioner too (PCSetUp
   skips an unchanged operator), at the price of a chord step on that small change; at most
   jacReuseMax reuses in a row (-solver_jacobian_reuse), without limit where that change is zero
   (rigid planes, no friction: SPContactTangentFixed). */
static PetscBool ReuseJacobian(SPSolver s)
{
  PetscInt version;

  if (!s->reuse || !s->jacValid || !s->jacReuseMax) return PETSC_FALSE;
  if (s->jacReused >= s->jacReuseMax && !SPContactTangentFixed(s->contact)) return PETSC_FALSE;
  if (SPContactGetActiveVersion(s->contact, &version)) return PETSC_FALSE;
  return version == s->jacVersion ? PETSC_TRUE : PETSC_FALSE;
}

static PetscErrorCode FormJacobian(SNES snes, Vec X, Mat J, Mat P, void *ctx)
{
  SPSolver  s = (SPSolver)ctx;
  Vec       locX;
  PetscBool on;

  PetscFunctionBeginUser;
  if (ReuseJacobian(s)) {
    s->jacReused++;
    s->jacReuses++;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  s->jacReused = 0;
  s->jacValid  = PETSC_TRUE;
  PetscCall(SPContactGetActiveVersion(s->contact, &s->jacVersion));
  PetscCall(SPProblemGetLocalState(s->problem, X, &locX));
  PetscCall(SPContactIsActive(s->contact, &on));
  if (s->reuse) { /* J = K + C: the rows contact touched go back to K, then the new contact part */
    PetscObjectState nz0, nz1;
    PetscCall(LinearParts(s));
    PetscCall(MatGetNonzeroState(P, &nz0));
    PetscCall(SPContactSetUpJacobian(s->contact, X, P)); /* contact-pair couplings in the pattern of P */
    PetscCall(MatGetNonzeroState(P, &nz1));
    if (nz1 != nz0) PetscCall(BulkStiffness(s)); /* P grew and was zeroed */
    PetscCall(PetscLogEventBegin(s->log->contactAssembly, 0, 0, 0, 0));
    PetscCall(SPStiffnessAssemble(s->stiff, P, on ? s->contact : NULL, X));
    PetscCall(PetscLogEventEnd(s->log->contactAssembly, 0, 0, 0, 0));
  } else {
    PetscCall(SPContactSetUpJacobian(s->contact, X, P));
    PetscCall(BulkJacobian(s, locX, P));
    if (on) {
      PetscCall(PetscLogEventBegin(s->log->contactAssembly, 0, 0, 0, 0));
      PetscCall(SPContactAddJacobian(s->contact, X, P));
      PetscCall(PetscLogEventEnd(s->log->contactAssembly, 0, 0, 0, 0));
    }
  }
  PetscCall(SPSolverPCLagJacobian(s));
  if (J != P) {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscCall(SPProblemRestoreLocalState(s->problem, &locX));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A step solved loosely while the shift update it might feed needs s->refineRtol (LinearTolerance):
   if the shifts move at W, the linear solve continues from Y, with the same operator and right-hand
   side F(X), to that tolerance, and W = X - Y. Where they do not (the active set moved at W) the
   looser step was all the next iterate needed. Its iterations count as linear iterations. */
static PetscErrorCode RefineStep(SPSolver s, Vec X, Vec Y, Vec W, PetscBool *refined)
{
  PetscBool feeds, direct, guess;
  KSP       ksp;
  Vec       F;
  PetscInt  lits = 0;

  PetscFunctionBeginUser;
  *refined = PETSC_FALSE;
  if (s->refineRtol <= 0.0 || s->refineRtol >= s->rtol) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPSolverIsDirect(s, &direct));
  if (direct) PetscFunctionReturn(PETSC_SUCCESS); /* a direct solve: the step is exact already */
  PetscCall(SPContactStepFeedsUpdate(s->contact, W, &feeds));
  if (!feeds) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SNESGetFunction(s->snes, &F, NULL, NULL)); /* F(X): the line search evaluates F(W) after this hook */
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPGetInitialGuessNonzero(ksp, &guess));
  PetscCall(KSPSetInitialGuessNonzero(ksp, PETSC_TRUE));
  /* with a nonzero initial guess PETSc's test is relative to the right-hand side, as the first solve's */
  PetscCall(KSPSetTolerances(ksp, s->refineRtol, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(KSPSolve(ksp, F, Y));
  PetscCall(KSPSetInitialGuessNonzero(ksp, guess));
  PetscCall(KSPGetIterationNumber(ksp, &lits));
  s->refineLinear += lits, s->refineStep += lits;
  s->refinedSteps++, s->refinedLinear += lits;
  PetscCall(VecWAXPY(W, -1.0, Y, X));
  PetscCall(PetscInfo(s->snes, "step refined to linear rtol %g for the shift update it feeds: %" PetscInt_FMT " more linear iterations\n", (double)s->refineRtol, lits));
  *refined = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* x = J^-1 b with the factorization of the last Newton step (-contact_shift_accel schur; any
   Krylov method around it converges in one iteration); NULL vectors ask whether the
   preconditioner is one (*ok) */
static PetscErrorCode SolveJacobian(void *ctx, Vec b, Vec x, PetscBool *ok)
{
  SPSolver           s = (SPSolver)ctx;
  KSP                ksp;
  PC                 pc;
  KSPConvergedReason reason;

  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)pc, ok, PCLU, PCCHOLESKY, ""));
  if (!*ok || !b) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(KSPSolve(ksp, b, x));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  *ok = reason > 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The Newton-iteration boundary: W is the accepted new iterate. */
static PetscErrorCode ShiftHook(SNESLineSearch ls, Vec X, Vec Y, Vec W, PetscBool *changedY, PetscBool *changedW, void *ctx)
{
  SPSolver  s = (SPSolver)ctx;
  PetscBool limited, shifted, refined = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(SPSolverPCLagSolved(s)); /* before RefineStep continues the solve */
  PetscCall(PetscLogEventBegin(s->log->shiftUpdate, 0, 0, 0, 0));
  PetscCall(SPContactLimitStep(s->contact, X, Y, W, &limited));
  PetscCall(PetscLogEventEnd(s->log->shiftUpdate, 0, 0, 0, 0));
  if (!limited) PetscCall(RefineStep(s, X, Y, W, &refined)); /* its KSPSolve logs as a linear solve */
  *changedY = refined;
  PetscCall(PetscLogEventBegin(s->log->shiftUpdate, 0, 0, 0, 0));
  PetscCall(SPContactNewtonUpdate(s->contact, W, &shifted));
  *changedW = limited || shifted || refined ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(PetscLogEventEnd(s->log->shiftUpdate, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPSolverCreate(DM dm, SPProblem problem, SPContact contact, SPLog *log, SPSolver *solver)
{
  SPSolver     s;
  KSP          ksp;
  PC           pc;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&s));
  s->dm      = dm;
  s->problem = problem;
  s->contact = contact;
  s->log     = log;
  PetscCall(DMCreateGlobalVector(dm, &s->r));
  PetscCall(SNESCreate(PetscObjectComm((PetscObject)dm), &s->snes));
  PetscCall(SNESSetDM(s->snes, dm));
  PetscCall(SNESSetFunction(s->snes, s->r, FormFunction, s));
  PetscCall(SNESSetConvergenceTest(s->snes, SPSolverConverged, s, NULL));
  /* no absolute atol: it is atolRel x the run's largest initial residual (SPSolverConverged) */
  PetscCall(SNESSetTolerances(s->snes, 0.0, 1e-9, PETSC_DEFAULT, 50, PETSC_DEFAULT));
  s->atolRel  = 1e-10;
  s->stallIts = 15;
  s->jacReuseMax = 5;
  s->acceptRtol  = 1e-3;
  s->directIts   = 100;
  s->directDofs  = 1000000;
  s->directIts3  = 500;
  s->directDofs3 = 100000;
  s->directChol  = PETSC_TRUE;
  s->pcLag       = 0.25;
  s->rtolMax     = 1e-3;
  s->rtolSearch  = 1e-2;
  s->rtolLater   = 0.1;
  s->settledFactor = 1e-3;
  s->measured      = PETSC_TRUE;
  s->inexactInner  = PETSC_TRUE;
  s->refine        = PETSC_TRUE;
  /* a load-controlled body touching at one point legitimately raises |F| at first */
  PetscCall(SNESSetDivergenceTolerance(s->snes, -1.0));
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED));
  PetscCall(KSPSetTolerances(ksp, 1e-10, 1e-30, PETSC_DEFAULT, 2000));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCGAMG));
  /* Unsmoothed aggregation: smoothed prolongators built from contact Jacobians with large penalty
     entries made CG stop with DIVERGED_INDEFINITE_PC (B2 at alpha >= 100, or on 2 ranks);
     unsmoothed aggregation costs more CG iterations and never broke down in our runs. */
  PetscCall(PCGAMGSetNSmooths(pc, 0));
  /* Stop coarsening at about 1000 equations (PETSc: 50) and solve that level directly (GAMG
     gathers it on one rank): B2 333 -> 197 CG iterations, F2 19439 -> 15461, B4 32^3 on 2 ranks
     203 -> 180, the same Newton iterations; -pc_gamg_coarse_eq_limit overrides it */
  PetscCall(PCGAMGSetCoarseEqLim(pc, 1000));
  /* With PETSc's safety factor 1.1 the Chebyshev smoother's eigenvalue estimate is too low on
     contact Jacobians and CG stops with DIVERGED_INDEFINITE_PC */
  PetscCall(SPOptionsSetDefault("-mg_levels_ksp_chebyshev_esteig", "0,0.05,0,1.5"));
  /* Between Newton iterations only the contact blocks change: keep GAMG's aggregation and
     prolongator, recompute the Galerkin coarse operators (same iterations on B4, PC setup ~2.5x
     cheaper; -pc_gamg_reuse_interpolation false rebuilds everything) */
  PetscCall(SPOptionsSetDefault("-pc_gamg_reuse_interpolation", "true"));
  *solver = s;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The system matrix (contact-pair couplings join its pattern in SPContactSetUpJacobian) and its near-null space */
static PetscErrorCode SetUpMatrix(SPSolver s, PetscBool prealloc, PetscBool shareGraph)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(s->log->matCreate, 0, 0, 0, 0));
  PetscCall(SPMatrixCreate(s->dm, prealloc, &s->J));
  if (shareGraph) PetscCall(SPMatrixShareGraph(s->J));
  PetscCall(PetscLogEventEnd(s->log->matCreate, 0, 0, 0, 0));
  PetscCall(PetscLogEventBegin(s->log->nearNullSpace, 0, 0, 0, 0));
  PetscCall(SPMatrixSetRigidBodyModes(s->dm, prealloc, s->J));
  PetscCall(PetscLogEventEnd(s->log->nearNullSpace, 0, 0, 0, 0));
  PetscCall(SNESSetJacobian(s->snes, s->J, s->J, FormJacobian, s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* PETSc's Newton and Krylov limits as read from the options: the inexact Newton's range starts at
   -ksp_rtol, and limits no solve could meet are refused before the solve (PETSc's option readers
   take a negative tolerance) */
static PetscErrorCode ReadLimits(SPSolver s)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)s->dm);
  KSP       ksp;
  PetscReal atol, rtol, stol, katol;
  PetscInt  maxit, kmaxit;

  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPGetTolerances(ksp, &s->rtolMin, &katol, NULL, &kmaxit));
  s->rtolMax = PetscMax(s->rtolMax, s->rtolMin);
  PetscCall(SNESGetTolerances(s->snes, &atol, &rtol, &stol, &maxit, NULL));
  PetscCheck(maxit >= 1, comm, PETSC_ERR_USER_INPUT, "-snes_max_it %" PetscInt_FMT ": a load step needs at least 1 Newton iteration", maxit);
  PetscCheck(kmaxit >= 1, comm, PETSC_ERR_USER_INPUT, "-ksp_max_it %" PetscInt_FMT ": a linear solve needs at least 1 iteration", kmaxit);
  PetscCheck(rtol >= 0.0 && rtol < 1.0, comm, PETSC_ERR_USER_INPUT, "-snes_rtol %.6g: give a relative tolerance in [0, 1)", (double)rtol);
  PetscCheck(atol >= 0.0 && !PetscIsInfOrNanReal(atol), comm, PETSC_ERR_USER_INPUT, "-snes_atol %.6g: give an absolute tolerance >= 0", (double)atol);
  PetscCheck(stol >= 0.0 && stol < 1.0, comm, PETSC_ERR_USER_INPUT, "-snes_stol %.6g: give a step tolerance in [0, 1)", (double)stol);
  PetscCheck(s->rtolMin >= 0.0 && s->rtolMin < 1.0, comm, PETSC_ERR_USER_INPUT, "-ksp_rtol %.6g: give a relative tolerance in [0, 1)", (double)s->rtolMin);
  PetscCheck(katol >= 0.0 && !PetscIsInfOrNanReal(katol), comm, PETSC_ERR_USER_INPUT, "-ksp_atol %.6g: give an absolute tolerance >= 0", (double)katol);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* GAMG's graph without the system matrix's zero entries (-pc_gamg_threshold 0; PETSc's -1 keeps
   them as edges) with contact pairs or friction. A pair's slave rows keep the couplings of every
   master facet they have met (contact-pattern.c), zero while inactive: kept, they are graph edges
   between the two bodies. Same Newton iterations, GMRES / CG iterations (1 rank, alpha 10): F2
   12897 -> 5363, F5 12922 -> 5445, F3 (2 ranks) 6691 -> 3571, B6 863 -> 400; F3 at alpha 1000
   solves its first system (238 GMRES iterations, 2000 and stopped before). Without pairs or
   friction nothing changes (B2, B4) and the graph stays the matrix itself (matrix-graph.c). */
static PetscErrorCode GraphWithoutZeros(SPSolver s, PetscBool friction)
{
  PetscBool pairs;

  PetscFunctionBeginUser;
  PetscCall(SPContactHasPairs(s->contact, &pairs));
  if (pairs || friction) PetscCall(SPOptionsSetDefault("-pc_gamg_threshold", "0"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Options read for -help that this run cannot use, reported as unused (options-unread.c): the
   Jacobian reuse without a linear material, the kept preconditioner with a factorization from the
   start (the 2D default), the other dimension's switch to a factorization (QA helper 24) */
static PetscErrorCode UnreadUnused(SPSolver s)
{
  PetscInt dim;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(s->dm, &dim));
  if (!s->reuse) PetscCall(SPOptionsUnread("-solver_jacobian_reuse"));
  if (s->directStart) PetscCall(SPOptionsUnread("-solver_pc_lag"));
  PetscCall(SPOptionsUnread(dim == 3 ? "-solver_direct_switch" : "-solver_direct_switch_3d"));
  PetscCall(SPOptionsUnread(dim == 3 ? "-solver_direct_dofs" : "-solver_direct_dofs_3d"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPSolverSetFromOptions(SPSolver s)
{
  SNESLineSearch ls;
  PetscBool      on;
  PetscBool      fast = PETSC_TRUE, prealloc = PETSC_TRUE, share = PETSC_TRUE, linear, friction, testJ;

  PetscFunctionBeginUser;
  PetscCall(SPProblemIsLinear(s->problem, &s->reuse));
  PetscCall(SPContactHasFriction(s->contact, &friction));
  /* inexact Newton by default where it was designed and measured: a linear bulk without friction
     (GMRES on a finite-strain or stick/slip tangent: on demand) */
  s->inexact     = s->reuse && !friction ? PETSC_TRUE : PETSC_FALSE;
  s->targetFloor = !s->inexact;
  PetscOptionsBegin(PetscObjectComm((PetscObject)s->dm), NULL, "Solver options", "spcontact");
  PetscCall(PetscOptionsName("-snes_test_jacobian", "PETSc's Jacobian test against finite differences (see SNES options); here: no Jacobian reuse, every iterate's Jacobian is assembled and tested", "SPSolverSetFromOptions", &testJ));
  PetscCall(PetscOptionsBool("-solver_linear_reuse", "Linear material: assemble the bulk stiffness K once and use r(u) = r0(load) + K u (false: bulk residual/Jacobian every time)", "SPSolverSetFromOptions", s->reuse, &s->reuse, NULL));
  PetscCall(PetscOptionsBool("-solver_fast_bulk", "Element-level isotropic elasticity for P1/Q1 cells instead of PetscFE where it applies (false: always PetscFE)", "SPSolverSetFromOptions", fast, &fast, NULL));
  PetscCall(PetscOptionsBool("-solver_check_fast", "Verification: compare the fast and the PetscFE bulk residual/Jacobian (and the matrix pattern with DMCreateMatrix's) once, print the relative differences", "SPSolverSetFromOptions", s->checkFast, &s->checkFast, NULL));
  PetscCall(PetscOptionsReal("-solver_atol_rel", "Absolute residual tolerance relative to the largest initial residual norm of the run (the out-of-balance load); -snes_atol replaces it by an absolute one", "SPSolverSetFromOptions", s->atolRel, &s->atolRel, NULL));
  PetscCall(PetscOptionsInt("-solver_jacobian_reuse", "Linear material: keep the assembled Jacobian and its preconditioner for at most this many Newton iterations in a row while the active set does not change; without limit against rigid planes without friction, where the Jacobian is then exact (0: assemble every iteration)", "SPSolverSetFromOptions", s->jacReuseMax, &s->jacReuseMax, NULL));
  PetscCall(PetscOptionsBool("-solver_inexact", "Inexact Newton: search steps to -solver_inexact_rtol, steps that feed a shift update tighter (README Performance); default true for a linear material without friction (false: every solve to -ksp_rtol)", "SPSolverSetFromOptions", s->inexact, &s->inexact, NULL));
  PetscCall(PetscOptionsBool("-solver_target_floor", "Without the inexact Newton (the default with friction or a nonlinear material): no linear solve reduces the residual further than to 1% of the Newton residual target, at most -solver_inexact_rtol, at least -ksp_rtol (false: every solve to -ksp_rtol)", "SPSolverSetFromOptions", s->targetFloor, &s->targetFloor, NULL));
  PetscCall(PetscOptionsReal("-solver_inexact_rtol", "Inexact Newton: the loosest linear relative tolerance of a step that may feed a shift update", "SPSolverSetFromOptions", s->rtolMax, &s->rtolMax, NULL));
  PetscCall(PetscOptionsReal("-solver_inexact_rtol_search", "Inexact Newton, penalty and shifted: the loosest linear relative tolerance of a search step (from an iterate whose active set just changed; not a solve's first step), at most 0.1/(1 + alpha)", "SPSolverSetFromOptions", s->rtolSearch, &s->rtolSearch, NULL));
  PetscCall(PetscOptionsReal("-solver_inexact_rtol_search_later", "Inexact Newton, every method: the loosest linear relative tolerance of a search step after a solve's first one, at most 10/(1 + alpha)^2 and no tighter than the first search step's (so it moves only at alpha below about 100)", "SPSolverSetFromOptions", s->rtolLater, &s->rtolLater, NULL));
  PetscCall(PetscOptionsReal("-solver_inexact_settled", "Inexact Newton: factor on the loosest linear tolerance for a step from an iterate whose active set did not change (the step then feeds a shift update; with penalty, which feeds none, no further than a quarter of the residual target), and for a solve's first step with a method that updates the shifts (shifted, alm; with penalty it is a search step)", "SPSolverSetFromOptions", s->settledFactor, &s->settledFactor, NULL));
  PetscCall(PetscOptionsBool("-solver_inexact_measured", "Inexact Newton, methods that update the shifts in Newton (shifted): once a shift update on a settled active set has measured the contraction rho of the gap error, steps that feed a shift update are solved to rho^2 (at most the loosest tolerance), and Eisenstat-Walker does not tighten a step after a shift update or an active-set change (false: the rule before, -solver_inexact_settled x the loosest)", "SPSolverSetFromOptions", s->measured, &s->measured, NULL));
  PetscCall(PetscOptionsBool("-solver_inexact_refine", "Inexact Newton with the measured contraction (shifted): a step that needs the tight tolerance only because it may feed a shift update before the contraction is measured (a solve's first step, a settled step before the first measurement) is solved to the loosest tolerance and continued to the tight one only if the shifts then move (false: solved tight at once)", "SPSolverSetFromOptions", s->refine, &s->refine, NULL));
  PetscCall(PetscOptionsBool("-solver_inexact_inner", "Inexact Newton, methods that update the shifts after a converged solve (alm), frictionless: a solve counts as converged on a settled active set once |F| <= 0.1 rho |dF| (dF: the forces the next update adds, rho: the update's contraction), the last one (gap tolerance met) at the residual target; its steps are solved no tighter than that needs (false: every solve to the residual target)", "SPSolverSetFromOptions", s->inexactInner, &s->inexactInner, NULL));
  PetscCall(PetscOptionsReal("-solver_linear_accept", "A linear solve that stops short of its tolerance (its iteration limit, a GMRES breakdown) counts as converged if its true residual |b - A x| is at most this x |b| (0: never; it then fails the Newton solve)", "SPSolverSetFromOptions", s->acceptRtol, &s->acceptRtol, NULL));
  PetscCall(PetscOptionsInt("-solver_direct_switch", "2D, solver not chosen by -ksp_type/-pc_type, more dofs than -solver_direct_dofs: once a linear solve takes more than this many iterations, or fails, the rest of the run factors the Jacobian (MUMPS) (0: never a direct solver, not from the start either)", "SPSolverSetFromOptions", s->directIts, &s->directIts, NULL));
  PetscCall(PetscOptionsInt("-solver_direct_switch_3d", "3D with GMRES (friction, finite strain), at most -solver_direct_dofs_3d dofs, solver not chosen by -ksp_type/-pc_type, MUMPS available: once a linear solve takes more than this many iterations, or fails, the rest of the run factors the Jacobian (MUMPS LU) (0: never)", "SPSolverSetFromOptions", s->directIts3, &s->directIts3, NULL));
  PetscCall(PetscOptionsInt("-solver_direct_dofs_3d", "The largest 3D run (displacement dofs) that -solver_direct_switch_3d may switch to a factorization", "SPSolverSetFromOptions", s->directDofs3, &s->directDofs3, NULL));
  PetscCall(PetscOptionsInt("-solver_direct_dofs", "2D, solver not chosen by -ksp_type/-pc_type, MUMPS available: a run with at most this many displacement dofs factors its Jacobian from the start (MUMPS; README Performance) (0: iterative from the start)", "SPSolverSetFromOptions", s->directDofs, &s->directDofs, NULL));
  PetscCall(PetscOptionsBool("-solver_direct_cholesky", "The 2D factorization of a symmetric Jacobian (frictionless small strain) is Cholesky (LDL^T, half the work of LU); false: LU", "SPSolverSetFromOptions", s->directChol, &s->directChol, NULL));
  PetscCall(PetscOptionsReal("-solver_pc_lag", "Linear material, frictionless, no pairs, iterative solver: a new Jacobian keeps the preconditioner (GAMG by default, or the -pc_type given; not a factorization) while the points whose active state changed since its build are at most this fraction of its active points, and while solves with it converge at least 2/3 as fast per decade as the first one (README Performance; 0: a new preconditioner with every new Jacobian)", "SPSolverSetFromOptions", s->pcLag, &s->pcLag, NULL));
  PetscCall(PetscOptionsInt("-solver_stall_its", "Stop a Newton solve after this many iterations without a 1% decrease of the residual or the gap error (0: never)", "SPSolverSetFromOptions", s->stallIts, &s->stallIts, NULL));
  PetscCall(PetscOptionsBool("-solver_fast_prealloc", "First-order mesh: preallocate the matrix from vertex adjacency and build the rigid-body modes from vertex coordinates (false: DMCreateMatrix, DMPlexCreateRigidBody)", "SPSolverSetFromOptions", prealloc, &prealloc, NULL));
  PetscCall(PetscOptionsBool("-solver_gamg_shared_graph", "Frictionless small strain without contact pairs (a symmetric matrix, graph not filtered): GAMG aggregates on the system matrix itself instead of PETSc's copy of it (same aggregates, one matrix less at the peak; false: PETSc's copy). With pairs or friction the graph is PETSc's filtered copy (-pc_gamg_threshold 0)", "SPSolverSetFromOptions", share, &share, NULL));
  PetscOptionsEnd();
  PetscCheck(s->atolRel >= 0.0 && s->atolRel < 1.0, PetscObjectComm((PetscObject)s->dm), PETSC_ERR_USER_INPUT, "-solver_atol_rel %.6g: must be in [0, 1)", (double)s->atolRel);
  PetscCheck(s->acceptRtol >= 0.0 && s->acceptRtol < 1.0, PetscObjectComm((PetscObject)s->dm), PETSC_ERR_USER_INPUT, "-solver_linear_accept %.6g: must be in [0, 1) (0: a linear solve short of its tolerance fails the Newton solve)", (double)s->acceptRtol);
  PetscCheck(s->directDofs >= 0, PetscObjectComm((PetscObject)s->dm), PETSC_ERR_USER_INPUT, "-solver_direct_dofs %" PetscInt_FMT ": must be >= 0 (0: every 2D run starts iterative)", s->directDofs);
  PetscCheck(s->directIts >= 0, PetscObjectComm((PetscObject)s->dm), PETSC_ERR_USER_INPUT, "-solver_direct_switch %" PetscInt_FMT ": must be >= 0 (0: never a direct solver)", s->directIts);
  PetscCheck(s->directIts3 >= 0 && s->directDofs3 >= 0, PetscObjectComm((PetscObject)s->dm), PETSC_ERR_USER_INPUT, "-solver_direct_switch_3d %" PetscInt_FMT ", -solver_direct_dofs_3d %" PetscInt_FMT ": must be >= 0 (0: never)", s->directIts3, s->directDofs3);
  PetscCheck(s->pcLag >= 0.0 && s->pcLag < PETSC_INFINITY, PetscObjectComm((PetscObject)s->dm), PETSC_ERR_USER_INPUT, "-solver_pc_lag %.6g: must be >= 0 and finite (0: a new preconditioner with every new Jacobian)", (double)s->pcLag);
  PetscCheck(s->stallIts >= 0, PetscObjectComm((PetscObject)s->dm), PETSC_ERR_USER_INPUT, "-solver_stall_its %" PetscInt_FMT ": must be >= 0 (0: no stagnation test)", s->stallIts);
  PetscCheck(s->jacReuseMax >= 0, PetscObjectComm((PetscObject)s->dm), PETSC_ERR_USER_INPUT, "-solver_jacobian_reuse %" PetscInt_FMT ": must be >= 0 (0: assemble every Newton iteration)", s->jacReuseMax);
  PetscCheck(s->rtolMax > 0.0 && s->rtolMax < 1.0, PetscObjectComm((PetscObject)s->dm), PETSC_ERR_USER_INPUT, "-solver_inexact_rtol %.6g: must be in (0, 1) (1e-3 is the default; -solver_inexact false for exact solves)", (double)s->rtolMax);
  PetscCheck(s->rtolSearch > 0.0 && s->rtolSearch < 1.0, PetscObjectComm((PetscObject)s->dm), PETSC_ERR_USER_INPUT, "-solver_inexact_rtol_search %.6g: must be in (0, 1) (1e-2 is the default)", (double)s->rtolSearch);
  PetscCheck(s->rtolLater > 0.0 && s->rtolLater < 1.0, PetscObjectComm((PetscObject)s->dm), PETSC_ERR_USER_INPUT, "-solver_inexact_rtol_search_later %.6g: must be in (0, 1) (0.1 is the default)", (double)s->rtolLater);
  PetscCheck(s->settledFactor > 0.0 && s->settledFactor <= 1.0, PetscObjectComm((PetscObject)s->dm), PETSC_ERR_USER_INPUT, "-solver_inexact_settled %.6g: must be in (0, 1]", (double)s->settledFactor);
  if (testJ) s->jacReuseMax = 0; /* -snes_test_jacobian compares the assembled Jacobian at every iterate */
  PetscCall(PetscOptionsHasName(NULL, NULL, "-snes_atol", &s->userAtol));
  PetscCall(SetUpMatrix(s, prealloc, share));
  if (fast) {
    PetscCall(PetscLogEventBegin(s->log->fastSetUp, 0, 0, 0, 0));
    PetscCall(SPFastElasticCreate(s->dm, s->problem, &s->fast));
    PetscCall(PetscLogEventEnd(s->log->fastSetUp, 0, 0, 0, 0));
  }
  /* Full Newton steps: the penalty residual is piecewise linear (semismooth Newton); backtracking
     on |F| crawls there, adding one active point per iteration. */
  PetscCall(SNESGetLineSearch(s->snes, &ls));
  PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHBASIC));
  PetscCall(SPContactHasFriction(s->contact, &on));
  PetscCall(SPProblemIsLinear(s->problem, &linear));
  /* the slip tangent is non-symmetric, a finite-strain tangent under compression may be indefinite
     (CG stops with DIVERGED_INDEFINITE_*): GMRES with the same AMG (-ksp_type overrides) */
  if (on || !linear) {
    KSP ksp;
    PetscCall(SNESGetKSP(s->snes, &ksp));
    PetscCall(KSPSetType(ksp, KSPGMRES));
    PetscCall(KSPGMRESSetRestart(ksp, 100));
  } else {
    /* frictionless small strain: the Jacobian is the Hessian of an energy (bulk plus penalty with
       fixed shifts), symmetric at every iterate. Said once: GAMG then builds its graph without a
       transpose and a sum, and without a copy (src/matrix-graph.c) */
    PetscCall(MatSetOption(s->J, MAT_SYMMETRIC, PETSC_TRUE));
    PetscCall(MatSetOption(s->J, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
    /* CG here: one Chebyshev step per level and sweep (PETSc: 2). A V-cycle costs about half, CG
       takes 8 to 70 % more iterations (B4 32^3 on 2 ranks: 180 -> 199, KSPSolve 7.3 -> 4.0 s),
       every Newton count of the robustness table the same within +1. Not with GMRES: F2
       (friction) then stops with DIVERGED_LINEAR_SOLVE and cuts back */
    PetscCall(SPOptionsSetDefault("-mg_levels_ksp_max_it", "1"));
  }
  PetscCall(GraphWithoutZeros(s, on));
  PetscCall(SNESSetFromOptions(s->snes));
  PetscCall(SPSolverSetUpAccept(s));
  PetscCall(SPSolverSetUpDirect(s));
  PetscCall(SPSolverSetUpPCLag(s));
  PetscCall(UnreadUnused(s));
  PetscCall(ReadLimits(s));
  PetscCall(SPContactIsActive(s->contact, &on));
  if (on) {
    PetscCall(SNESGetLineSearch(s->snes, &ls));
    PetscCall(SNESLineSearchSetPostCheck(ls, ShiftHook, s));
    SPContactSetJacobianSolve(s->contact, SolveJacobian, s);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

void SPSolverSetProgress(SPSolver s, SPProgress *progress)
{
  s->progress = progress;
}

PetscErrorCode SPSolverSetHistory(SPSolver s, FILE *fp, PetscInt step)
{
  PetscFunctionBeginUser;
  s->history = fp;
  s->step    = step;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A failed solve's Jacobian is not reused, and a factorization is rebuilt from scratch: after a
   failed factorization PETSc 3.18's MUMPS interface skips every later numeric factorization of the
   same factor (its INFOG(1) stays negative) and then refuses the solve (INFOG(1)=-3). GAMG is not
   reset: its set-up with a reused interpolation cannot start again from PCReset. */
static PetscErrorCode ForgetFailedSolve(SPSolver s)
{
  KSP       ksp;
  PC        pc;
  PetscBool factor;

  PetscFunctionBeginUser;
  s->jacValid = PETSC_FALSE;
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)pc, &factor, PCLU, PCCHOLESKY, ""));
  if (factor) PetscCall(PCReset(pc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One Newton solve at the current load factor and contact state */
PetscErrorCode SPSolverSolve(SPSolver s, Vec u, SNESConvergedReason *reason)
{
  PetscReal load;
  PetscInt  its, lits, nf;
  PetscBool on;

  PetscFunctionBeginUser;
  if (s->checkFast) {
    PetscCall(CheckFast(s));
    s->checkFast = PETSC_FALSE;
  }
  PetscCall(SPContactIsActive(s->contact, &on));
  if (on) PetscCall(SPContactBeginSolve(s->contact, u));
  s->stalled = PETSC_FALSE;
  PetscCall(SPProblemGetLoadFactor(s->problem, &load));
  s->resolve = s->lastConverged && load == s->lastLoad ? PETSC_TRUE : PETSC_FALSE; /* a re-solve after a shift update */
  s->refineLinear = s->refineStep = 0;
  PetscCall(SNESSolve(s->snes, NULL, u));
  PetscCall(SNESGetConvergedReason(s->snes, reason));
  PetscCall(SPSolverRecordSolveGap(s, *reason));
  s->lastLoad      = load;
  s->lastConverged = *reason > 0 ? PETSC_TRUE : PETSC_FALSE;
  if (*reason < 0) PetscCall(ForgetFailedSolve(s));
  PetscCall(SNESGetIterationNumber(s->snes, &its));
  PetscCall(SNESGetLinearSolveIterations(s->snes, &lits));
  PetscCall(SNESGetNumberFunctionEvals(s->snes, &nf)); /* counted from 0 in every SNESSolve */
  s->newtonTotal += its;
  s->linearTotal += lits + s->refineLinear;
  s->funcTotal += nf;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The name of a solve's stop reason for messages: STALLED for the stagnation test */
const char *SPSolverReasonName(SPSolver s, SNESConvergedReason reason)
{
  return s->stalled ? "STALLED" : SNESConvergedReasons[reason];
}

PetscErrorCode SPSolverGetCounts(SPSolver s, PetscInt *newton, PetscInt *linear, PetscInt *functions)
{
  PetscFunctionBeginUser;
  if (newton) *newton = s->newtonTotal;
  if (linear) *linear = s->linearTotal;
  if (functions) *functions = s->funcTotal;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A GMRES breakdown (KSP_DIVERGED_BREAKDOWN: classical Gram-Schmidt lost the orthogonality of the
   Arnoldi basis, as it does with friction at alpha ~ 1000, F2 Cattaneo-Mindlin) is answered once
   per run: every Arnoldi vector is re-orthogonalised from then on (about 25 % more time per
   linear iteration at alpha 10, so not the default), and *retry asks the caller to solve the
   step again instead of cutting it back. */
PetscErrorCode SPSolverRecoverBreakdown(SPSolver s, PetscBool *retry)
{
  KSP                       ksp;
  KSPConvergedReason        kr;
  KSPGMRESCGSRefinementType type;
  PetscBool                 gmres;

  PetscFunctionBeginUser;
  *retry = PETSC_FALSE;
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPGetConvergedReason(ksp, &kr));
  PetscCall(PetscObjectTypeCompare((PetscObject)ksp, KSPGMRES, &gmres));
  if (kr != KSP_DIVERGED_BREAKDOWN || !gmres || s->reorthogonalise) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(KSPGMRESGetCGSRefinementType(ksp, &type));
  if (type == KSP_GMRES_CGS_REFINE_ALWAYS) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPSolverReorthogonalise(s));
  *retry = PETSC_TRUE;
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)ksp), "linear solve broke down (GMRES lost the orthogonality of its basis): the step again, re-orthogonalising from now on\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* GMRES re-orthogonalises every Arnoldi vector from now on (the breakdown recovery, or a restart
   of a run in which it ran); no effect on another Krylov method */
PetscErrorCode SPSolverReorthogonalise(SPSolver s)
{
  KSP ksp;

  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPGMRESSetCGSRefinementType(ksp, KSP_GMRES_CGS_REFINE_ALWAYS));
  s->reorthogonalise = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool SPSolverReorthogonalises(SPSolver s)
{
  return s->reorthogonalise;
}

/* The last solve was stopped by the stagnation test */
PetscBool SPSolverStalled(SPSolver s)
{
  return s->stalled;
}

/* Steps refined by the lazy tight rule (RefineStep) and their linear iterations, over the run */
PetscErrorCode SPSolverGetRefinements(SPSolver s, PetscInt *steps, PetscInt *linear)
{
  PetscFunctionBeginUser;
  *steps  = s->refinedSteps;
  *linear = s->refinedLinear;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Newton iterations that kept the last assembled Jacobian and its preconditioner */
PetscErrorCode SPSolverGetJacobianReuses(SPSolver s, PetscInt *reuses)
{
  PetscFunctionBeginUser;
  *reuses = s->jacReuses;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* New Jacobians that kept the preconditioner of an earlier one (solver-pclag.c) */
PetscErrorCode SPSolverGetPCKeeps(SPSolver s, PetscInt *keeps)
{
  PetscFunctionBeginUser;
  *keeps = s->pcKeeps;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPSolverGetBulkOperator(SPSolver s, const char **name)
{
  PetscFunctionBeginUser;
  *name = s->fast ? "fast" : "petscfe";
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The Krylov method and preconditioner of the last solve (summary key linear_solver: "cg/gamg",
   "gmres/gamg", "preonly/cholesky" or "preonly/lu" with the 2D factorization) */
PetscErrorCode SPSolverGetLinearSolver(SPSolver s, const char **ksp, const char **pc)
{
  KSP k;
  PC  p;

  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(s->snes, &k));
  PetscCall(KSPGetPC(k, &p));
  PetscCall(KSPGetType(k, ksp));
  PetscCall(PCGetType(p, pc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPSolverDestroy(SPSolver *solver)
{
  PetscFunctionBeginUser;
  if (!*solver) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SNESDestroy(&(*solver)->snes));
  PetscCall(MatDestroy(&(*solver)->J));
  PetscCall(SPStiffnessDestroy(&(*solver)->stiff));
  PetscCall(VecDestroy(&(*solver)->r0));
  PetscCall(VecDestroy(&(*solver)->r));
  PetscCall(SPFastElasticDestroy(&(*solver)->fast));
  PetscCall(PetscFree(*solver));
  PetscFunctionReturn(PETSC_SUCCESS);
}
