/* The preconditioner (GAMG by default, any but a factorization) kept across a small change of the
   active set (-solver_pc_lag).
   With a linear bulk, frictionless and without pairs, the Jacobian is K plus the penalty blocks of
   the active points: a change of the active set changes the rows of the points that opened or
   closed, a perturbation of low rank, while a new preconditioner costs GAMG's Galerkin products
   again (with its interpolation reused, about 1.9 s of a 1e6-dof run on 2 ranks, 5 times in B4's
   6 Newton iterations). A kept preconditioner keeps the coarse levels of the Jacobian it was built
   from; the Krylov operator and the finest level (its smoother's matrix, the residual) are the
   new Jacobian, which is the same matrix object. It is kept while the points whose active state
   changed since its build are at most -solver_pc_lag times its active points (a first contact,
   1 point growing to 28 on B2, rebuilds it), and while a solve with it needs at most 1.5 times
   the linear iterations per decade of residual of the first solve after its build (else the next
   Jacobian rebuilds it). Not with a factorization (a kept factorization would make the Newton step
   a chord step), nor with friction or pairs (their tangents move at every iterate, and are solved
   by GMRES), nor when the user set -snes_lag_preconditioner. */
#include <spcontact-impl.h>

/* After SNESSetFromOptions: whether this run may keep the preconditioner */
PetscErrorCode SPSolverSetUpPCLag(SPSolver s)
{
  PetscBool friction, pairs, userLag, on;

  PetscFunctionBeginUser;
  PetscCall(SPContactIsActive(s->contact, &on));
  PetscCall(SPContactHasFriction(s->contact, &friction));
  PetscCall(SPContactHasPairs(s->contact, &pairs));
  PetscCall(PetscOptionsHasName(NULL, NULL, "-snes_lag_preconditioner", &userLag));
  s->pcLagAllowed = s->pcLag > 0.0 && on && s->reuse && !friction && !pairs && !userLag ? PETSC_TRUE : PETSC_FALSE;
  s->pcActive     = -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A new Jacobian was assembled: keep the preconditioner, or build it for this Jacobian (SNES reads
   its lag after the Jacobian callback) */
PetscErrorCode SPSolverPCLagJacobian(SPSolver s)
{
  PetscInt  active, changes;
  PetscBool keep, direct;

  PetscFunctionBeginUser;
  if (!s->pcLagAllowed) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPContactGetActiveChanges(s->contact, &active, &changes));
  PetscCall(SPSolverIsDirect(s, &direct));
  keep = !direct && s->pcActive > 0 && !s->pcSpent && (PetscReal)(changes - s->pcChanges) <= s->pcLag * (PetscReal)s->pcActive;
  PetscCall(SNESSetLagPreconditioner(s->snes, keep ? -1 : 1));
  if (keep) {
    s->pcKept = PETSC_TRUE;
    s->pcKeeps++;
    PetscCall(PetscInfo(s->snes, "preconditioner kept: %" PetscInt_FMT " active-state changes since its build with %" PetscInt_FMT " active points\n", changes - s->pcChanges, s->pcActive));
  } else {
    s->pcActive  = active;
    s->pcChanges = changes;
    s->pcFresh   = PETSC_TRUE;
    s->pcKept = s->pcSpent = PETSC_FALSE;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After a Newton step's linear solve (zero initial guess, right-hand side -F(X)): its iterations
   per decade of residual, the reference for a fresh preconditioner, the test for a kept one */
PetscErrorCode SPSolverPCLagSolved(SPSolver s)
{
  KSP       ksp;
  PetscInt  lits;
  PetscReal rnorm, fnorm, decades, rate;

  PetscFunctionBeginUser;
  if (!s->pcLagAllowed || (!s->pcFresh && !s->pcKept)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPGetIterationNumber(ksp, &lits));
  PetscCall(KSPGetResidualNorm(ksp, &rnorm));
  PetscCall(SNESGetFunctionNorm(s->snes, &fnorm));
  decades = rnorm > 0.0 && fnorm > rnorm ? PetscLog10Real(fnorm / rnorm) : 0.0;
  if (decades < 1.0) PetscFunctionReturn(PETSC_SUCCESS); /* too short a solve to measure */
  rate = (PetscReal)lits / decades;
  if (s->pcFresh) {
    s->pcRate  = rate;
    s->pcFresh = PETSC_FALSE;
  } else if (rate > 1.5 * s->pcRate) {
    s->pcSpent = PETSC_TRUE;
    PetscCall(PetscInfo(s->snes, "kept preconditioner: %g linear iterations per decade against %g when built; rebuilt with the next Jacobian\n", (double)rate, (double)s->pcRate));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
