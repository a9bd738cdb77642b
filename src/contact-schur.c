/* -contact_shift_accel schur: the shift update that zeroes the linearised gaps of the next step.
   With a settled active set the Newton step from shifts s + d changes the gap of active point i by
   -(M d)_i - (B J^-1 R)_i, where J is the step's Jacobian, B the gap rows (B du: the gap changes)
   and M = B J^-1 D with D the shift's forces (column i: A_i eps_i N_i, the residual's derivative
   in s_i). The plain rule takes d = g (M = I, the rigid-point limit); this one solves M d = g by
   GMRES, each product one back-substitution with the factorization the Newton step used, and so
   removes the contraction k/(k + eps) of the plain update (doc/performance.md: its spectrum lies
   in [1 - rho, 1], GMRES needs a handful of products). It needs a factorization: with an iterative
   linear solver every product would be a whole Krylov solve, and the update stays the plain one.
   The Newton step's residual term is dropped: at the boundary the new iterate W = X - J^-1 F(X)
   has R(W) = 0 up to the nonlinear remainder, which the next Newton step removes. */
#include <spcontact-impl.h>

typedef struct {
  SPContact   c;
  PetscInt    nrow, ndof;  /* rows (points the rule updated), their dofs (with repeats) */
  PetscInt   *row, *off;   /* per row: point index, offset into dof/N */
  PetscInt   *dof;         /* global dofs (constrained ones dropped) */
  PetscReal  *N, *D;       /* N = dg/du per dof; D = A eps per row */
  PetscBool  *in;          /* per point: a row */
  Vec         F, Z, zloc;  /* global force and solution, gathered solution values */
  VecScatter  gather;
} SchurCtx;

static PetscErrorCode Rows(SchurCtx *x)
{
  SPContact c = x->c;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(c->n + 1, &x->in));
  for (PetscInt i = 0; i < c->n; ++i) x->in[i] = c->accIn[i] && SPContactPointActive(c, i);
  for (PetscInt i = 0; i < c->n; ++i) x->nrow += x->in[i];
  PetscCall(PetscMalloc4(x->nrow + 1, &x->row, x->nrow + 1, &x->off, x->nrow * SP_ELEM_MAXD + 1, &x->dof, x->nrow * SP_ELEM_MAXD + 1, &x->N));
  PetscCall(PetscMalloc1(x->nrow + 1, &x->D));
  x->nrow = 0;
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt  nd, dofs[SP_ELEM_MAXD];
    PetscReal A, N[SP_ELEM_MAXD];
    if (!x->in[i]) continue;
    PetscCall(SPContactPointElement(c, i, &nd, dofs, &A, N, NULL));
    x->row[x->nrow] = i, x->off[x->nrow] = x->ndof, x->D[x->nrow] = A * c->pt[i].eps;
    for (PetscInt k = 0; k < nd; ++k)
      if (dofs[k] >= 0 && N[k] != 0.0) x->dof[x->ndof] = dofs[k], x->N[x->ndof++] = N[k];
    if (x->ndof == x->off[x->nrow]) x->in[i] = PETSC_FALSE; /* no free dof moves its gap: not a row (M would be singular) */
    else x->nrow++;
  }
  x->off[x->nrow] = x->ndof;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the gathering of the rows' dofs of a global vector (master facets may live on other ranks) */
static PetscErrorCode Gather(SchurCtx *x)
{
  IS from;

  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(x->c->dm, &x->F));
  PetscCall(VecDuplicate(x->F, &x->Z));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, x->ndof, &x->zloc));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, x->ndof, x->dof, PETSC_USE_POINTER, &from));
  PetscCall(VecScatterCreate(x->F, from, x->zloc, NULL, &x->gather));
  PetscCall(ISDestroy(&from));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* y = M x on the rows, y = x elsewhere (the other points' d = 0) */
static PetscErrorCode Mult(Mat M, Vec X, Vec Y)
{
  SchurCtx          *x;
  const PetscScalar *xa, *z;
  PetscScalar       *ya;
  PetscBool          ok;

  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(M, &x));
  PetscCall(VecZeroEntries(x->F));
  PetscCall(VecGetArrayRead(X, &xa));
  for (PetscInt r = 0; r < x->nrow; ++r)
    for (PetscInt k = x->off[r]; k < x->off[r + 1]; ++k) PetscCall(VecSetValue(x->F, x->dof[k], x->D[r] * x->N[k] * xa[x->row[r]], ADD_VALUES));
  PetscCall(VecAssemblyBegin(x->F));
  PetscCall(VecAssemblyEnd(x->F));
  PetscCall(x->c->jsolve(x->c->jctx, x->F, x->Z, &ok));
  PetscCheck(ok, PetscObjectComm((PetscObject)M), PETSC_ERR_NOT_CONVERGED, "the back-substitution of the shift update failed");
  x->c->schurSolves++;
  PetscCall(VecScatterBegin(x->gather, x->Z, x->zloc, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(x->gather, x->Z, x->zloc, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(x->zloc, &z));
  PetscCall(VecGetArray(Y, &ya));
  for (PetscInt i = 0; i < x->c->n; ++i) ya[i] = xa[i];
  for (PetscInt r = 0; r < x->nrow; ++r) {
    PetscReal dg = 0.0;
    for (PetscInt k = x->off[r]; k < x->off[r + 1]; ++k) dg += x->N[k] * PetscRealPart(z[k]);
    ya[x->row[r]] = dg;
  }
  PetscCall(VecRestoreArray(Y, &ya));
  PetscCall(VecRestoreArrayRead(x->zloc, &z));
  PetscCall(VecRestoreArrayRead(X, &xa));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Destroy(SchurCtx *x)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(x->in));
  PetscCall(PetscFree4(x->row, x->off, x->dof, x->N));
  PetscCall(PetscFree(x->D));
  PetscCall(VecDestroy(&x->F));
  PetscCall(VecDestroy(&x->Z));
  PetscCall(VecDestroy(&x->zloc));
  PetscCall(VecScatterDestroy(&x->gather));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Solve M d = g over the rows with GMRES to 0.1 of the gap tolerance; *ok: it converged */
static PetscErrorCode SolveShift(SchurCtx *x, Vec d, PetscInt *its, PetscBool *ok)
{
  KSPConvergedReason reason;
  SPContact   c    = x->c;
  MPI_Comm    comm = PetscObjectComm((PetscObject)c->dm);
  Mat         M;
  KSP         ksp;
  PC          pc;
  Vec         b;
  PetscScalar *ba;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(d, &b));
  PetscCall(VecGetArray(b, &ba));
  for (PetscInt i = 0; i < c->n; ++i) ba[i] = x->in[i] ? c->pt[i].geo.gap : 0.0;
  PetscCall(VecRestoreArray(b, &ba));
  PetscCall(MatCreateShell(comm, c->n, c->n, PETSC_DETERMINE, PETSC_DETERMINE, x, &M));
  PetscCall(MatShellSetOperation(M, MATOP_MULT, (void (*)(void))Mult));
  PetscCall(KSPCreate(comm, &ksp));
  PetscCall(KSPSetOperators(ksp, M, M));
  PetscCall(KSPSetType(ksp, KSPGMRES));
  PetscCall(KSPGMRESSetRestart(ksp, SP_SCHUR_MAX_IT));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCNONE));
  PetscCall(KSPSetTolerances(ksp, 1e-14, 0.1 * c->gapTol, PETSC_DEFAULT, SP_SCHUR_MAX_IT));
  PetscCall(KSPSolve(ksp, b, d));
  PetscCall(KSPGetIterationNumber(ksp, its));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  *ok = reason > 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(KSPDestroy(&ksp));
  PetscCall(MatDestroy(&M));
  PetscCall(VecDestroy(&b));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Without a factorization the plain update stays; said once */
static PetscErrorCode CanSolve(SPContact c, PetscBool *ok)
{
  PetscFunctionBeginUser;
  *ok = PETSC_FALSE;
  if (c->jsolve) PetscCall(c->jsolve(c->jctx, NULL, NULL, ok));
  if (!*ok && !c->schurSaid) PetscCall(PetscPrintf(PetscObjectComm((PetscObject)c->dm), "shift update: -contact_shift_accel schur back-substitutes with a factorization (-pc_type lu or cholesky); this linear solver has none, so the update is the plain one\n"));
  if (!*ok) c->schurSaid = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After the plain rule at a boundary (or an augmentation): the shifts of the points it updated
   (c->accIn, from c->accS) replaced by s + d, clipped to s <= 0. *maxDs: the largest change.
   Nothing changes without a factorization to back-substitute with, or where GMRES did not reach
   its tolerance in SP_SCHUR_MAX_IT products (the plain update then stands). */
PetscErrorCode SPContactSchurUpdate(SPContact c, PetscReal *maxDs)
{
  SchurCtx           x = {0};
  PetscBool          ok;
  Vec                d;
  const PetscScalar *da;
  PetscInt           its, nall;

  PetscFunctionBeginUser;
  PetscCall(CanSolve(c, &ok));
  if (!ok) PetscFunctionReturn(PETSC_SUCCESS);
  x.c = c;
  PetscCall(Rows(&x));
  PetscCallMPI(MPI_Allreduce(&x.nrow, &nall, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  if (nall) {
    PetscCall(Gather(&x));
    PetscCall(VecCreateMPI(PetscObjectComm((PetscObject)c->dm), c->n, PETSC_DETERMINE, &d));
    PetscCall(SolveShift(&x, d, &its, &ok));
    PetscCall(VecGetArrayRead(d, &da));
    if (ok) *maxDs = 0.0;
    for (PetscInt i = 0; i < c->n && ok; ++i) {
      if (x.in[i]) c->pt[i].st.sN = PetscMin(0.0, c->accS[i] + PetscRealPart(da[i]));
      *maxDs = PetscMax(*maxDs, PetscAbsReal(c->pt[i].st.sN - c->accS[i]));
    }
    PetscCall(VecRestoreArrayRead(d, &da));
    PetscCall(VecDestroy(&d));
    c->schurSteps += ok;
    PetscCall(PetscInfo(c->dm, "shift update by the contact Schur complement: %" PetscInt_FMT " points, %" PetscInt_FMT " back-substitutions%s\n", nall, its, ok ? "" : ", not converged: the plain update"));
  }
  PetscCall(Destroy(&x));
  PetscFunctionReturn(PETSC_SUCCESS);
}
