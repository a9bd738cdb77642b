/* Anderson acceleration of the in-Newton shift update (-contact_shift_accel anderson).

   On a settled active set the plain update s <- s + g(s) is a fixed-point iteration of the affine
   map G(s) = s + g(s) over the active points' shifts; it contracts only by about k/(k + eps) per
   update (method.md section 2). Anderson's method (Walker and Ni, type II, mixing 1) keeps the last
   m differences dS_j = s_{j+1} - s_j, dF_j = g_{j+1} - g_j and takes
       gamma = argmin || g_k - dF gamma ||_2,   s_{k+1} = s_k + g_k - (dS + dF) gamma,
   which on an affine map is GMRES on the shifts. The vector is distributed: every inner product is
   one MPI_Allreduce, and the small least-squares problem is solved redundantly on every rank from
   the reduced Gram matrix, so the step is the same on any number of ranks up to round-off.

   Safeguards: the history is reset when the set of points changes (the map is another one), and
   when the gap residual ||g|| grew since the last step (the step did not pay off: start again from
   the current iterate with the plain update); a column whose part orthogonal to the newer columns
   is below SP_ACCEL_DROP of its norm is dropped with every older one (ill-conditioning); with no
   column left the plain update stands. The caller clips s <= 0 afterwards. */
#include <spcontact-impl.h>

const char *const SPShiftAccelTypes[] = {"none", "anderson", "schur", "SPShiftAccelType", "SP_ACCEL_", NULL};

#define SP_ACCEL_DROP 1e-5 /* least sine of the angle between a column and the newer ones */

struct _n_SPShiftAccel {
  MPI_Comm   comm;
  PetscInt   n, m;       /* local points, depth (columns kept) */
  PetscInt   k, head;    /* columns stored; ring position of the newest */
  PetscBool  have;       /* sPrev, gPrev hold the previous record */
  PetscReal *sPrev, *gPrev, *dS, *dF; /* n, n, m n, m n */
  PetscBool *inPrev;     /* the points of the previous record */
  PetscReal  fPrev;      /* ||g||_2^2 of the previous record (global) */
  PetscReal *G, *b, *L, *gamma; /* m x m Gram matrix, m right-hand side, Cholesky factor, solution */
  PetscInt   steps;      /* accelerated updates taken */
};

PetscErrorCode SPShiftAccelCreate(MPI_Comm comm, PetscInt n, PetscInt m, SPShiftAccel *accel)
{
  SPShiftAccel a;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&a));
  a->comm = comm;
  a->n    = n;
  a->m    = m;
  PetscCall(PetscCalloc5(n + 1, &a->sPrev, n + 1, &a->gPrev, m * n + 1, &a->dS, m * n + 1, &a->dF, n + 1, &a->inPrev));
  PetscCall(PetscCalloc4(m * m, &a->G, m + m * m, &a->b, m * m, &a->L, m, &a->gamma));
  *accel = a;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPShiftAccelDestroy(SPShiftAccel *accel)
{
  PetscFunctionBeginUser;
  if (!*accel) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree5((*accel)->sPrev, (*accel)->gPrev, (*accel)->dS, (*accel)->dF, (*accel)->inPrev));
  PetscCall(PetscFree4((*accel)->G, (*accel)->b, (*accel)->L, (*accel)->gamma));
  PetscCall(PetscFree(*accel));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Forget the history (a new solve, a cut-back, a change of the active set) */
PetscErrorCode SPShiftAccelReset(SPShiftAccel a)
{
  PetscFunctionBeginUser;
  if (!a) PetscFunctionReturn(PETSC_SUCCESS);
  a->k = a->head = 0;
  a->have        = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPShiftAccelGetSteps(SPShiftAccel a, PetscInt *steps)
{
  PetscFunctionBeginUser;
  *steps = a ? a->steps : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Ring slot of the j-th newest column (j = 0: newest) */
static inline PetscInt Slot(SPShiftAccel a, PetscInt j)
{
  return (a->head - j + a->m) % a->m;
}

/* Whether the set of points differs from the previous record (collective) and ||g||^2 */
static PetscErrorCode Compare(SPShiftAccel a, const PetscBool in[], const PetscReal g[], PetscBool *changed, PetscReal *f2)
{
  PetscReal loc[2] = {0.0, 0.0}, all[2];

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < a->n; ++i) {
    if (a->have && in[i] != a->inPrev[i]) loc[0] = 1.0;
    if (in[i]) loc[1] += g[i] * g[i];
  }
  PetscCallMPI(MPI_Allreduce(loc, all, 2, MPIU_REAL, MPI_SUM, a->comm));
  *changed = all[0] > 0.0 ? PETSC_TRUE : PETSC_FALSE;
  *f2      = all[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Store the differences to the previous record as the newest column, then the record itself */
static void Push(SPShiftAccel a, const PetscBool in[], const PetscReal s[], const PetscReal g[], PetscReal f2)
{
  if (a->have) {
    PetscReal *dS, *dF;
    a->head = a->k ? (a->head + 1) % a->m : 0;
    a->k    = PetscMin(a->k + 1, a->m);
    dS      = &a->dS[a->head * a->n];
    dF      = &a->dF[a->head * a->n];
    for (PetscInt i = 0; i < a->n; ++i) {
      dS[i] = in[i] ? s[i] - a->sPrev[i] : 0.0;
      dF[i] = in[i] ? g[i] - a->gPrev[i] : 0.0;
    }
  }
  for (PetscInt i = 0; i < a->n; ++i) a->sPrev[i] = s[i], a->gPrev[i] = g[i], a->inPrev[i] = in[i];
  a->fPrev = f2;
  a->have  = PETSC_TRUE;
}

/* Gram matrix G_jl = dF_j . dF_l and b_j = dF_j . g over the points (columns newest first): one
   reduction */
static PetscErrorCode Gram(SPShiftAccel a, const PetscBool in[], const PetscReal g[])
{
  const PetscInt k = a->k;
  PetscReal     *loc = a->b + a->m; /* scratch: k + k k values */

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < k + k * k; ++j) loc[j] = 0.0;
  for (PetscInt j = 0; j < k; ++j) {
    const PetscReal *fj = &a->dF[Slot(a, j) * a->n];
    for (PetscInt i = 0; i < a->n; ++i)
      if (in[i]) loc[j] += fj[i] * g[i];
    for (PetscInt l = 0; l <= j; ++l) {
      const PetscReal *fl = &a->dF[Slot(a, l) * a->n];
      PetscReal        sum = 0.0;
      for (PetscInt i = 0; i < a->n; ++i)
        if (in[i]) sum += fj[i] * fl[i];
      loc[k + j * k + l] = sum;
    }
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, loc, (int)(k + k * k), MPIU_REAL, MPI_SUM, a->comm));
  for (PetscInt j = 0; j < k; ++j) {
    a->b[j] = loc[j];
    for (PetscInt l = 0; l <= j; ++l) a->G[j * a->m + l] = a->G[l * a->m + j] = loc[k + j * k + l];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Cholesky of the Gram matrix, newest column first; a column nearly in the span of the newer ones
   ends the factor there (it and every older column are dropped). Returns the columns kept. */
static PetscInt Factor(SPShiftAccel a)
{
  const PetscInt m = a->m;
  for (PetscInt j = 0; j < a->k; ++j) {
    PetscReal d = a->G[j * m + j];
    for (PetscInt l = 0; l < j; ++l) {
      PetscReal v = a->G[j * m + l];
      for (PetscInt q = 0; q < l; ++q) v -= a->L[j * m + q] * a->L[l * m + q];
      a->L[j * m + l] = v / a->L[l * m + l];
      d -= PetscSqr(a->L[j * m + l]);
    }
    if (!(d > PetscSqr(SP_ACCEL_DROP) * a->G[j * m + j]) || !PetscIsNormalReal(d)) return j;
    a->L[j * m + j] = PetscSqrtReal(d);
  }
  return a->k;
}

/* gamma from L L^T gamma = b over the first k columns */
static void Solve(SPShiftAccel a, PetscInt k)
{
  const PetscInt m = a->m;
  for (PetscInt j = 0; j < k; ++j) {
    PetscReal v = a->b[j];
    for (PetscInt l = 0; l < j; ++l) v -= a->L[j * m + l] * a->gamma[l];
    a->gamma[j] = v / a->L[j * m + j];
  }
  for (PetscInt j = k - 1; j >= 0; --j) {
    PetscReal v = a->gamma[j];
    for (PetscInt l = j + 1; l < k; ++l) v -= a->L[l * m + j] * a->gamma[l];
    a->gamma[j] = v / a->L[j * m + j];
  }
}

/* One update of the points with in[i]: their shifts s and gaps g at the new iterate; snew holds the
   plain update on entry and the accelerated one on return (*used), before the clip s <= 0 (the
   caller's). Collective. */
PetscErrorCode SPShiftAccelUpdate(SPShiftAccel a, const PetscBool in[], const PetscReal s[], const PetscReal g[], PetscReal snew[], PetscBool *used)
{
  PetscBool changed;
  PetscReal f2;
  PetscInt  k;

  PetscFunctionBeginUser;
  *used = PETSC_FALSE;
  PetscCall(Compare(a, in, g, &changed, &f2));
  if (changed || (a->have && f2 > a->fPrev)) {
    PetscCall(PetscInfo(NULL, "shift acceleration: history reset (%s)\n", changed ? "new set of points" : "the gap residual grew"));
    PetscCall(SPShiftAccelReset(a));
  }
  Push(a, in, s, g, f2);
  if (!a->k) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(Gram(a, in, g));
  k = Factor(a);
  if (k < a->k) PetscCall(PetscInfo(NULL, "shift acceleration: %" PetscInt_FMT " of %" PetscInt_FMT " columns kept (ill-conditioned)\n", k, a->k));
  a->k = k; /* the dropped columns are the oldest: the ring keeps the newest k */
  if (!k) PetscFunctionReturn(PETSC_SUCCESS);
  Solve(a, k);
  for (PetscInt j = 0; j < k; ++j)
    if (PetscIsInfOrNanReal(a->gamma[j])) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < a->n; ++i) {
    PetscReal v = s[i] + g[i];
    if (!in[i]) continue;
    for (PetscInt j = 0; j < k; ++j) v -= a->gamma[j] * (a->dS[Slot(a, j) * a->n + i] + a->dF[Slot(a, j) * a->n + i]);
    snew[i] = v;
  }
  a->steps++;
  *used = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}
