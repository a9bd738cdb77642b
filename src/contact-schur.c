/* -contact_shift_accel schur: the shift update that zeroes the linearised gaps of the next step.
   With a settled active set the Newton step from shifts s + d changes the gap of an updated point
   by -(M d) - (R J^-1 F), where J is the step's Jacobian, R the gap rows (R du: the gap changes)
   and M = R J^-1 C with C the shift's forces (column of a normal shift: A eps N, plus
   A eps mu B_T^T m at a slipping point, whose Coulomb traction mu p m follows p; column of a stuck
   point's tangential shift: A eps_T B_T^T e_a, its row B_T e_a, its "gap" Dg_T + c_T). The plain
   rule takes d = gap (M = I, the rigid-point limit); this one solves M d = gap by GMRES, each
   product one back-substitution with the factorization the Newton step used, and so removes the
   contraction k/(k + eps) of the plain update (doc/performance.md: its spectrum lies in
   [1 - rho, 1], GMRES needs a handful of products). It needs a factorization: with an iterative
   linear solver every product would be a whole Krylov solve, and the update stays the plain one.
   The Newton step's residual term is dropped: at the boundary the new iterate W = X - J^-1 F(X)
   has F(W) = 0 up to the nonlinear remainder, which the next Newton step removes.
   A slipping point's tangential shifts are rows too: the rule s_T <- -mu p m / eps_T, m = y/|y|,
   y = -eps_T (Dg_T + s_T), p = p(g, s_N), follows p and in 3D turns s_T towards the slip by a
   fraction kappa = mu p/|y| < 1 of the way only, so near the stick zone's edge (kappa -> 1) F3's
   directions converged by ~0.15 per Newton iteration. Its derivatives give the rows: u-part
   (mu k/eps_T) m N + kappa P B_T (P = I - m m^T), on the point's own shifts I - kappa P (tangential)
   and -(mu k/eps_T) m (normal); columns A eps_T kappa B_T^T P e_a (in 2D P = 0: no force). */
#include <spcontact-impl.h>

typedef struct {
  PetscBool normal;    /* a normal shift, else a tangential one */
  PetscInt  slot, off; /* slot in the shift vector, offset into dof/R/C */
  PetscReal b;         /* the rule's change (its "gap") */
  PetscReal coef[3];   /* M's terms on the point's own shifts (normal, tangential): slipping points */
} SchurRow;

typedef struct {
  SPContact  c;
  PetscInt   slots;       /* per point in the shift vector: the normal shift, then dim - 1 tangential */
  PetscBool  tangential;  /* the stuck and slipping points' tangential shifts are rows */
  PetscInt   nrow, ndof;  /* rows (updated shifts), their dofs (with repeats) */
  SchurRow  *row;         /* nrow + 1 (the last: the end offset) */
  PetscInt  *dof;         /* global dofs (constrained ones dropped) */
  PetscReal *R, *C;       /* row (gap change per dof), column (force per unit shift) */
  Vec        F, Z, zloc;  /* global force and solution, gathered solution values */
  VecScatter gather;
  PetscBool  failed;      /* a back-substitution failed: the plain update stands */
} SchurCtx;

/* Element of point i: dofs, area, N = dg/du and (friction, anchored) B_T = dDg_T/du; *nd = 0: none */
static PetscErrorCode Element(SPContact c, PetscInt i, PetscInt *nd, PetscInt dofs[], PetscReal *A, PetscReal N[], PetscReal BT[], PetscBool *tangent)
{
  PetscFunctionBeginUser;
  *tangent = PETSC_FALSE;
  if (c->friction) PetscCall(SPFrictionElementDofs(c, i, nd, dofs, N, BT, A));
  if (c->friction && *nd) *tangent = PETSC_TRUE;
  else PetscCall(SPContactPointElement(c, i, nd, dofs, A, N, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One row: R and C over the element's free dofs; dropped when no free dof moves its gap */
static void AddRow(SchurCtx *x, SchurRow row, PetscInt nd, const PetscInt dofs[], const PetscReal R[], const PetscReal C[])
{
  const PetscInt start = x->ndof;
  for (PetscInt k = 0; k < nd; ++k)
    if (dofs[k] >= 0 && (R[k] != 0.0 || C[k] != 0.0)) x->dof[x->ndof] = dofs[k], x->R[x->ndof] = R[k], x->C[x->ndof++] = C[k];
  if (x->ndof == start) return;
  row.off          = start;
  x->row[x->nrow++] = row;
}

/* The tangential rows of point i slipping at the rule's state (old shifts in accTS, accS): none
   where its status is frozen by chatter or kept stuck by the branch hold, or at the cone */
static void SlipRows(SchurCtx *x, PetscInt i, PetscInt nd, const PetscInt dofs[], PetscReal A, const PetscReal N[], const PetscReal BT[])
{
  SPContact             c  = x->c;
  const SPContactPoint *pt = &c->pt[i];
  const PetscInt        nt = c->dim - 1;
  const PetscReal      *s  = &c->accTS[2 * i];
  PetscReal             p, k, y[2] = {0, 0}, ny, m[2], kappa, f, R[SP_FRIC_MAXD], C[SP_FRIC_MAXD];

  if (pt->st.flips > c->maxFlips || (c->holding && pt->st.held && pt->st.heldStick)) return;
  SPContactPointTraction(c, i, &p, &k);
  if (c->accIn[i]) p += k * (pt->st.sN - c->accS[i]); /* at the old normal shift */
  for (PetscInt a = 0; a < nt; ++a) y[a] = -pt->epsT * (pt->geo.dgT[a] + s[a]);
  ny = SPNorm(nt, y);
  if (p <= 0.0 || ny <= pt->geo.mu * p) return;
  kappa = pt->geo.mu * p / ny;
  f     = pt->geo.mu * k / pt->epsT;
  for (PetscInt a = 0; a < nt; ++a) m[a] = y[a] / ny;
  for (PetscInt a = 0; a < nt; ++a) {
    SchurRow row = {PETSC_FALSE, i * x->slots + 1 + a, 0, -pt->geo.mu * p / pt->epsT * m[a] - s[a], {-f * m[a], 0, 0}};
    for (PetscInt b = 0; b < nt; ++b) row.coef[1 + b] = (a == b) - kappa * ((a == b) - m[a] * m[b]);
    for (PetscInt q = 0; q < nd; ++q) {
      PetscReal PB = 0.0;
      for (PetscInt b = 0; b < nt; ++b) PB += ((a == b) - m[a] * m[b]) * BT[b * nd + q];
      R[q] = f * m[a] * N[q] + kappa * PB;
      C[q] = A * pt->epsT * kappa * PB;
    }
    AddRow(x, row, nd, dofs, R, C);
  }
}

/* The rows of point i: its normal shift if the rule updated it (normal), its tangential ones if
   it is stuck or slips and the rule updated them (tangential) */
static PetscErrorCode PointRows(SchurCtx *x, PetscInt i, PetscBool normal, PetscBool tangential)
{
  SPContact       c  = x->c;
  const PetscInt  nt = c->dim - 1;
  PetscInt        nd, dofs[SP_FRIC_MAXD];
  PetscReal       A, N[SP_FRIC_MAXD], BT[2 * SP_FRIC_MAXD], C[SP_FRIC_MAXD], y[2], t[2], nt2;
  PetscBool       tangent, stick = PETSC_TRUE;
  const PetscBool rowN = normal && c->accIn[i] && SPContactPointActive(c, i) ? PETSC_TRUE : PETSC_FALSE;
  const PetscBool rowS = tangential && c->accTSlip[i] ? PETSC_TRUE : PETSC_FALSE;
  PetscBool       rowT = PETSC_FALSE;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < nt && tangential; ++a) rowT = rowT || c->accTIn[2 * i + a];
  if (!rowN && !rowT && !rowS) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(Element(c, i, &nd, dofs, &A, N, BT, &tangent));
  if (!nd) PetscFunctionReturn(PETSC_SUCCESS);
  if (tangent) SPFrictionTraction(c, i, y, t, &stick);
  nt2 = tangent ? SPNorm(nt, t) : 0.0;
  if (rowN) {
    for (PetscInt k = 0; k < nd; ++k) {
      C[k] = A * c->pt[i].eps * N[k];
      for (PetscInt a = 0; a < nt && !stick && nt2 > 0.0; ++a) C[k] += A * c->pt[i].eps * c->pt[i].geo.mu * BT[a * nd + k] * t[a] / nt2;
    }
    AddRow(x, (SchurRow){PETSC_TRUE, i * x->slots, 0, c->pt[i].geo.gap, {0, 0, 0}}, nd, dofs, N, C);
  }
  for (PetscInt a = 0; a < nt && tangent && rowT; ++a) {
    if (!c->accTIn[2 * i + a]) continue;
    for (PetscInt k = 0; k < nd; ++k) C[k] = A * c->pt[i].epsT * BT[a * nd + k];
    AddRow(x, (SchurRow){PETSC_FALSE, i * x->slots + 1 + a, 0, c->accTG[2 * i + a], {0, 0, 0}}, nd, dofs, &BT[a * nd], C);
  }
  if (rowS && tangent && !stick) SlipRows(x, i, nd, dofs, A, N, BT);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Rows(SchurCtx *x, PetscBool normal, PetscBool tangential)
{
  const PetscInt n = x->c->n * x->slots;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n + 1, &x->row));
  PetscCall(PetscMalloc3(n * SP_FRIC_MAXD + 1, &x->dof, n * SP_FRIC_MAXD + 1, &x->R, n * SP_FRIC_MAXD + 1, &x->C));
  for (PetscInt i = 0; i < x->c->n; ++i) PetscCall(PointRows(x, i, normal, tangential));
  x->row[x->nrow].off = x->ndof;
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
    for (PetscInt k = x->row[r].off; k < x->row[r + 1].off; ++k) PetscCall(VecSetValue(x->F, x->dof[k], x->C[k] * xa[x->row[r].slot], ADD_VALUES));
  PetscCall(VecAssemblyBegin(x->F));
  PetscCall(VecAssemblyEnd(x->F));
  PetscCall(x->c->jsolve(x->c->jctx, x->F, x->Z, &ok));
  if (!ok) { /* collective: every rank's KSP failed alike */
    x->failed = PETSC_TRUE;
    PetscCall(VecZeroEntries(x->Z));
  }
  x->c->schurSolves++;
  PetscCall(VecScatterBegin(x->gather, x->Z, x->zloc, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(x->gather, x->Z, x->zloc, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(x->zloc, &z));
  PetscCall(VecGetArray(Y, &ya));
  for (PetscInt i = 0; i < x->c->n * x->slots; ++i) ya[i] = xa[i];
  for (PetscInt r = 0; r < x->nrow; ++r) {
    const PetscInt base = x->row[r].slot - x->row[r].slot % x->slots;
    PetscReal      dg   = 0.0;
    for (PetscInt q = 0; q < x->slots; ++q) dg += x->row[r].coef[q] * PetscRealPart(xa[base + q]);
    for (PetscInt k = x->row[r].off; k < x->row[r + 1].off; ++k) dg += x->R[k] * PetscRealPart(z[k]);
    ya[x->row[r].slot] = dg;
  }
  PetscCall(VecRestoreArray(Y, &ya));
  PetscCall(VecRestoreArrayRead(x->zloc, &z));
  PetscCall(VecRestoreArrayRead(X, &xa));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Destroy(SchurCtx *x)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(x->row));
  PetscCall(PetscFree3(x->dof, x->R, x->C));
  PetscCall(VecDestroy(&x->F));
  PetscCall(VecDestroy(&x->Z));
  PetscCall(VecDestroy(&x->zloc));
  PetscCall(VecScatterDestroy(&x->gather));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Solve M d = gap over the rows with GMRES to 0.1 of the gap tolerance; *ok: it converged */
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
  PetscCall(VecZeroEntries(b));
  PetscCall(VecGetArray(b, &ba));
  for (PetscInt r = 0; r < x->nrow; ++r) ba[x->row[r].slot] = x->row[r].b;
  PetscCall(VecRestoreArray(b, &ba));
  PetscCall(MatCreateShell(comm, c->n * x->slots, c->n * x->slots, PETSC_DETERMINE, PETSC_DETERMINE, x, &M));
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
  *ok = reason > 0 && !x->failed ? PETSC_TRUE : PETSC_FALSE;
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
  if (!*ok && !c->schurSaid) PetscCall(PetscPrintf(PetscObjectComm((PetscObject)c->dm), "shift update: -contact_shift_accel schur back-substitutes with a factorization (for example -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps); while the linear solver has none, the update is the plain one\n"));
  if (!*ok) c->schurSaid = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The new shifts from d: normal s_N = min(0, s + d), tangential s_T = s + d, then the cone's clip. *maxDs (this rank's) and *dsT (collective) grow to the largest changes. */
static PetscErrorCode Apply(SchurCtx *x, Vec d, PetscReal *maxDs, PetscReal *dsT)
{
  SPContact          c  = x->c;
  const PetscInt     nt = c->dim - 1;
  const PetscScalar *da;
  PetscReal          dT = 0.0, all;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(d, &da));
  for (PetscInt r = 0; r < x->nrow; ++r) {
    const PetscInt  i = x->row[r].slot / x->slots, a = x->row[r].slot % x->slots - 1;
    const PetscReal v = PetscRealPart(da[x->row[r].slot]);
    if (x->row[r].normal) c->pt[i].st.sN = PetscMin(0.0, c->accS[i] + v);
    else c->pt[i].st.sT[a] = c->accTS[2 * i + a] + v;
  }
  PetscCall(VecRestoreArrayRead(d, &da));
  for (PetscInt r = 0; r < x->nrow; ++r) {
    const PetscInt  i     = x->row[r].slot / x->slots;
    const PetscBool moved = x->tangential && (c->accTIn[2 * i] || c->accTIn[2 * i + 1] || !x->row[r].normal);
    PetscReal       ds[2] = {0, 0};
    if (c->friction) SPFrictionClipShift(c, i);
    *maxDs = PetscMax(*maxDs, PetscAbsReal(c->pt[i].st.sN - c->accS[i]));
    for (PetscInt a = 0; a < nt && moved; ++a) ds[a] = c->pt[i].st.sT[a] - c->accTS[2 * i + a];
    dT = PetscMax(dT, SPNorm(nt, ds));
  }
  PetscCallMPI(MPI_Allreduce(&dT, &all, 1, MPIU_REAL, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  *dsT = PetscMax(*dsT, all);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After the plain rules at a boundary (or an augmentation): the normal shifts the rule updated
   (normal: c->accIn, from c->accS) and the stuck points' tangential ones (tangential: c->accTIn,
   from c->accTS) replaced by the Schur update. Nothing changes without a factorization to
   back-substitute with, or where GMRES did not reach its tolerance in SP_SCHUR_MAX_IT products
   (the plain update then stands). Collective. */
PetscErrorCode SPContactSchurUpdate(SPContact c, PetscBool normal, PetscBool tangential, PetscReal *maxDs, PetscReal *dsT)
{
  SchurCtx  x = {0};
  PetscBool ok;
  Vec       d;
  PetscInt  its, nall;

  PetscFunctionBeginUser;
  if (c->params.accel != SP_ACCEL_SCHUR || (!normal && !tangential)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(CanSolve(c, &ok));
  if (!ok) PetscFunctionReturn(PETSC_SUCCESS);
  x.c     = c;
  x.slots      = c->dim;
  x.tangential = tangential && c->friction ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(Rows(&x, normal, x.tangential));
  PetscCallMPI(MPI_Allreduce(&x.nrow, &nall, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  if (nall) {
    PetscCall(Gather(&x));
    PetscCall(VecCreateMPI(PetscObjectComm((PetscObject)c->dm), c->n * x.slots, PETSC_DETERMINE, &d));
    PetscCall(SolveShift(&x, d, &its, &ok));
    if (!its) ok = PETSC_FALSE; /* the gaps are below GMRES's tolerance already: the plain rule's shifts stand (d = 0 would undo them) */
    if (ok) PetscCall(Apply(&x, d, maxDs, dsT));
    PetscCall(VecDestroy(&d));
    c->schurSteps += ok;
    PetscCall(PetscInfo(c->dm, "shift update by the contact Schur complement: %" PetscInt_FMT " shifts, %" PetscInt_FMT " back-substitutions%s\n", nall, its, ok ? "" : ", not converged: the plain update"));
  }
  PetscCall(Destroy(&x));
  PetscFunctionReturn(PETSC_SUCCESS);
}
