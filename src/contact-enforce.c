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

#define SP_ELEM_MAXD (3 * (1 + SP_FACET_MAXV))

/* Local vector whose LocalToGlobal(ADD) gives the global vector G: G scattered to local, entries
   of points owned by other ranks zeroed (constrained dofs stay zero) */
static PetscErrorCode GlobalToOwnedLocal(DM dm, Vec G, Vec L)
{
  PetscSection ls, gs;
  PetscInt     pStart, pEnd;
  PetscScalar *l;

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(L));
  PetscCall(DMGlobalToLocal(dm, G, INSERT_VALUES, L));
  PetscCall(DMGetLocalSection(dm, &ls));
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(PetscSectionGetChart(ls, &pStart, &pEnd));
  PetscCall(VecGetArray(L, &l));
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt dof, off, goff;
    PetscCall(PetscSectionGetDof(ls, p, &dof));
    if (!dof) continue;
    PetscCall(PetscSectionGetOffset(gs, p, &goff));
    if (goff >= 0) continue;
    PetscCall(PetscSectionGetOffset(ls, p, &off));
    for (PetscInt d = 0; d < dof; ++d) l[off + d] = 0.0;
  }
  PetscCall(VecRestoreArray(L, &l));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* locF += contact forces. Every element adds into the global vector Fc with global indices (a
   master facet may live on another rank); Fc then comes back as an owned-only local vector. */
PetscErrorCode SPContactAddResidual(SPContact c, Vec locX, Vec locF)
{
  const PetscScalar *s;
  Vec                L;

  PetscFunctionBeginUser;
  PetscCall(SPContactEvaluate(c, locX));
  PetscCall(VecZeroEntries(c->Fc));
  PetscCall(VecGetArrayRead(c->shift, &s));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt    nd, dofs[SP_ELEM_MAXD];
    PetscReal   A, g, N[SP_ELEM_MAXD], r[SP_ELEM_MAXD];
    PetscScalar rs[SP_ELEM_MAXD];
    PetscCall(SPContactPointElement(c, i, &nd, dofs, &A, &g, N, NULL));
    if (!nd) continue;
    SPContactLawElement(nd, A, c->eps[i], g, PetscRealPart(s[i]), N, NULL, r, NULL);
    for (PetscInt k = 0; k < nd; ++k) rs[k] = r[k];
    PetscCall(VecSetValues(c->Fc, nd, dofs, rs, ADD_VALUES)); /* negative (constrained) skipped */
  }
  PetscCall(VecRestoreArrayRead(c->shift, &s));
  PetscCall(VecAssemblyBegin(c->Fc));
  PetscCall(VecAssemblyEnd(c->Fc));
  PetscCall(DMGetLocalVector(c->dm, &L));
  PetscCall(GlobalToOwnedLocal(c->dm, c->Fc, L));
  PetscCall(VecAXPY(locF, 1.0, L));
  PetscCall(DMRestoreLocalVector(c->dm, &L));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* J += contact tangent (s frozen): each element's block with global indices (rows may be owned
   by another rank; the pattern holds them, see contact-pattern.c) */
PetscErrorCode SPContactAddJacobian(SPContact c, Vec locX, Mat J)
{
  const PetscScalar *s;

  PetscFunctionBeginUser;
  PetscCall(SPContactEvaluate(c, locX));
  PetscCall(VecGetArrayRead(c->shift, &s));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt    nd, dofs[SP_ELEM_MAXD];
    PetscReal   A, g, N[SP_ELEM_MAXD], H[SP_ELEM_MAXD * SP_ELEM_MAXD], K[SP_ELEM_MAXD * SP_ELEM_MAXD];
    PetscScalar Ks[SP_ELEM_MAXD * SP_ELEM_MAXD];
    PetscCall(SPContactPointElement(c, i, &nd, dofs, &A, &g, N, H));
    if (!nd || !SPContactLawActive(g, PetscRealPart(s[i]))) continue;
    SPContactLawElement(nd, A, c->eps[i], g, PetscRealPart(s[i]), N, H, NULL, K);
    for (PetscInt k = 0; k < nd * nd; ++k) Ks[k] = K[k];
    PetscCall(MatSetValues(J, nd, dofs, nd, dofs, Ks, ADD_VALUES)); /* constrained dofs are negative: skipped */
  }
  PetscCall(VecRestoreArrayRead(c->shift, &s));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Nodal contact forces at the contact points (slave part of its own element plus the parts it
   receives as a master vertex, e.g. in the other pass of -contact_two_pass) and the recovered
   pressure p_i = f_i . n_i / A_i. Against an obstacle or in one pass p_i = -eps min(0, g + s).
   Uses the last evaluated state; collective. */
PetscErrorCode SPContactRecoverForces(SPContact c, const PetscScalar s[])
{
  const PetscInt     dim = c->dim;
  PetscInt           rstart, remote = 0;
  PetscReal          fm[3] = {0, 0, 0};
  const PetscScalar *f;

  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(c->shift, &rstart, NULL));
  PetscCall(VecZeroEntries(c->fvec));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt    nd, dofs[SP_ELEM_MAXD], idx[SP_ELEM_MAXD];
    PetscReal   A, g, N[SP_ELEM_MAXD], r[SP_ELEM_MAXD];
    PetscScalar fs[SP_ELEM_MAXD];
    PetscCall(SPContactPointElement(c, i, &nd, dofs, &A, &g, N, NULL));
    if (!nd) continue;
    SPContactLawElement(nd, A, c->eps[i], g, PetscRealPart(s[i]), N, NULL, r, NULL);
    for (PetscInt k = 0; k < nd; ++k) {
      const PetscInt a = k / dim, cp = a == 0 ? rstart + i : c->mf[c->facet[i]].cp[a - 1];
      idx[k] = cp >= 0 ? cp * dim + k % dim : -1;
      fs[k]  = -r[k]; /* force on the body = -residual */
      if (a > 0 && !c->pair[c->mf[c->facet[i]].pair].mirror) fm[k % dim] -= r[k];
    }
    if (c->facet[i] >= 0 && (c->mf[c->facet[i]].gid < c->mfStart || c->mf[c->facet[i]].gid >= c->mfStart + c->nmfOwned)) remote++;
    PetscCall(VecSetValues(c->fvec, nd, idx, fs, ADD_VALUES));
  }
  PetscCall(VecAssemblyBegin(c->fvec));
  PetscCall(VecAssemblyEnd(c->fvec));
  PetscCallMPI(MPI_Allreduce(fm, c->stats.forceMaster, 3, MPIU_REAL, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  PetscCallMPI(MPI_Allreduce(&remote, &c->stats.remoteElements, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  PetscCall(VecGetArrayRead(c->fvec, &f));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscReal fi[3] = {0, 0, 0};
    for (PetscInt d = 0; d < dim; ++d) fi[d] = c->fpt[i * dim + d] = PetscRealPart(f[i * dim + d]);
    c->press[i] = c->area[i] > 0.0 ? SPDot(dim, fi, &c->normal[i * dim]) / c->area[i] : 0.0;
  }
  PetscCall(VecRestoreArrayRead(c->fvec, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}
