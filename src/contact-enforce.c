/* Contact enforcement: the method registry and the contact terms of the residual and Jacobian.
   Every method shares the shifted-penalty law (plain penalty keeps s = 0); methods differ only in
   when and how the shift is updated (contact-update.c). A new method is one function and one row. */
#include <spcontact-impl.h>

/* Delta s = g: the seed's update, s_new = s_k + g_k */
static PetscReal ShiftIncrement(PetscInt nh, const PetscReal hs[], const PetscReal hg[])
{
  return hs[nh - 1] + hg[nh - 1];
}

/* 2015-style shift from an overdetermined system: least-squares fit g = a + b s over the last nh
   pairs (nh >= 3), next shift where the fit predicts g = 0. Falls back to Delta s = g while fewer
   than 3 pairs exist or when the fit is ill-conditioned (shifts too close, or b >= 0). */
static PetscReal ShiftRegression(PetscInt nh, const PetscReal hs[], const PetscReal hg[])
{
  PetscReal ms = 0, mg = 0, sss = 0, ssg = 0, b, a, scale = 0;
  if (nh < 3) return ShiftIncrement(nh, hs, hg);
  for (PetscInt k = 0; k < nh; ++k) ms += hs[k] / nh, mg += hg[k] / nh, scale = PetscMax(scale, PetscAbsReal(hs[k]));
  for (PetscInt k = 0; k < nh; ++k) sss += (hs[k] - ms) * (hs[k] - ms), ssg += (hs[k] - ms) * (hg[k] - mg);
  if (sss <= PetscSqr(1e-8 * scale) * nh || sss == 0.0) return ShiftIncrement(nh, hs, hg);
  b = ssg / sss;
  a = mg - b * ms;
  if (!(b < -1e-3) || b < -1e3) return ShiftIncrement(nh, hs, hg);
  return -a / b;
}

static const SPMethodEntry SPMethodTable[] = {
  /* method                         name                  in-Newton    augments     gap test     shift rule */
  {SP_METHOD_PENALTY,            "penalty",            PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, NULL           },
  {SP_METHOD_SHIFTED,            "shifted",            PETSC_TRUE,  PETSC_FALSE, PETSC_TRUE,  ShiftIncrement },
  {SP_METHOD_SHIFTED_REGRESSION, "shifted_regression", PETSC_TRUE,  PETSC_FALSE, PETSC_TRUE,  ShiftRegression},
  {SP_METHOD_ALM,                "alm",                PETSC_FALSE, PETSC_TRUE,  PETSC_FALSE, ShiftIncrement },
};

const SPMethodEntry *SPContactMethodEntry(SPContactMethod m)
{
  return &SPMethodTable[m];
}

/* locF += contact forces of the owned points (LocalToGlobal(ADD) then counts each once) */
PetscErrorCode SPContactAddResidual(SPContact c, Vec locX, Vec locF)
{
  const PetscScalar *u, *s;
  PetscScalar       *f;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(locX, &u));
  PetscCall(VecGetArrayRead(c->shift, &s));
  PetscCall(VecGetArray(locF, &f));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt  dofs[3];
    PetscReal r[3];
    PetscCall(SPContactPointLaw(c, i, u, PetscRealPart(s[i]), r, NULL));
    PetscCall(SPContactPointDofs(c, i, dofs));
    for (PetscInt d = 0; d < c->dim; ++d) f[dofs[d]] += r[d];
  }
  PetscCall(VecRestoreArray(locF, &f));
  PetscCall(VecRestoreArrayRead(c->shift, &s));
  PetscCall(VecRestoreArrayRead(locX, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* J += contact tangent (s frozen): the vertex block of each owned point, global indices */
PetscErrorCode SPContactAddJacobian(SPContact c, Vec locX, Mat J)
{
  const PetscScalar *u, *s;
  PetscSection       ls, gs;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(c->dm, &ls));
  PetscCall(DMGetGlobalSection(c->dm, &gs));
  PetscCall(VecGetArrayRead(locX, &u));
  PetscCall(VecGetArrayRead(c->shift, &s));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt   *idx = NULL, nidx;
    PetscReal   K[9];
    PetscScalar Ks[9];
    PetscCall(SPContactPointLaw(c, i, u, PetscRealPart(s[i]), NULL, K));
    for (PetscInt k = 0; k < c->dim * c->dim; ++k) Ks[k] = K[k];
    PetscCall(DMPlexGetClosureIndices(c->dm, ls, gs, c->vertex[i], PETSC_TRUE, &nidx, &idx, NULL, NULL));
    PetscCall(MatSetValues(J, nidx, idx, nidx, idx, Ks, ADD_VALUES)); /* constrained dofs are negative: skipped */
    PetscCall(DMPlexRestoreClosureIndices(c->dm, ls, gs, c->vertex[i], PETSC_TRUE, &nidx, &idx, NULL, NULL));
  }
  PetscCall(VecRestoreArrayRead(c->shift, &s));
  PetscCall(VecRestoreArrayRead(locX, &u));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}
