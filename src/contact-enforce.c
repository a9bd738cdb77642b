/* Contact enforcement: the contact terms of the residual and Jacobian, and the nodal forces.
   Every element evaluates the method's normal law at its point's gap and shift; what differs
   between methods (when the shift moves) lives in src/methods/ and contact-update.c. */
#include <spcontact-impl.h>

/* -contact_chatter_flips N (3 by default, 0 = off; shifted and alm): point i, closed at the last
   bookkeeping after it changed between open and closed N times in this Newton solve, stays closed
   while the tension this puts on it, eps (g + s), is below -contact_chatter_tension times the
   largest pressure of the last iterate. The converged state has |g| within the gap tolerance at
   every closed point, so the hold leaves no tension there; penalty, which has no such test, never
   holds. With it, friction runs get the step-cap recovery too (SPContactTightenStepCap). Why: a
   contact-edge point whose exact pressure is about 0 can cycle. Closed, the Newton step puts it at
   g + s ~ 0, which the step's nonlinear remainder opens a little; open, the next step takes the
   contact elsewhere deep. F2 at alpha 1000 (a shear step near load 0.95, the point at x =
   -0.1012): opened to g + s = +7e-10 (a tension of 2e-3 p0 if held), then 2.2e-5 deep (h = 0.005),
   |F| 1e-5 and 3e-2 in turn until the step was cut back. Most holds are in the first Newton
   iterations of a step, where whole rows of points plunge in, bounce out a little and in again.
   Newton iterations, off -> 3, 1 rank, alpha 1000: F2 163 (2 cut-backs) -> 75 (alm 191 -> 126), B6
   41 -> 19 (alm 43 -> 20), dissimilar B6 37 -> 16, slide2d 268 -> 96, slide3d 100 (1 cut-back) ->
   15; every input at alpha 10 unchanged but F3 (72 -> 71), at 100 the same or fewer; two-pass B6
   at 1000 loses (47 -> 56, alm 51 -> 58). N = 2 held F1c's (friction_slide3d) rear edge, whose
   points open for real under a small tension: 70 and 55 Newton iterations at alpha 10 and 100 ->
   324 and 393; with 3 F1c holds no point. A fixed opening (g + s below a fraction of h) instead of
   the tension: F2 needed 3e-7 h or more, and 1e-6 h let F1c at alpha 1000 take 450 Newton
   iterations instead of 49. Off by default with -contact_two_pass (contact.c): on the curved
   two-pass pairs it held points that open, shifted at alpha 10 and 100 (Neo-Hookean B6 at 10:
   326 Newton iterations -> 47; the dissimilar Neo-Hookean pair at 10 did not finish in 240 s ->
   41), while it saves about 2.5 times the iterations there at 1000 (README, "Chatter hold"). */
PetscBool SPContactChatterHolds(SPContact c)
{
  return c->chatterFlips > 0 && c->method->timing != SP_UPDATE_NONE ? PETSC_TRUE : PETSC_FALSE;
}

PetscBool SPContactChatterHeld(SPContact c, PetscInt i)
{
  const SPContactPoint *pt = &c->pt[i];
  if (!SPContactChatterHolds(c) || pt->st.flipsN < c->chatterFlips || !pt->st.active || pt->st.holdOff) return PETSC_FALSE;
  return pt->eps * (pt->geo.gap + pt->st.sN) < c->chatterTension * c->peakIterate ? PETSC_TRUE : PETSC_FALSE;
}

/* Pressure p and stiffness k = -dp/dg of point i: the method's law at the last evaluated gap */
void SPContactPointTraction(SPContact c, PetscInt i, PetscReal *p, PetscReal *k)
{
  const SPContactPoint *pt = &c->pt[i];
  if ((c->holding && pt->st.held) || SPContactChatterHeld(c, i)) c->method->law->closed(pt->geo.gap, pt->st.sN, pt->eps, p, k); /* held after a shift update (contact-update.c HoldBranches), or a chattering point */
  else c->method->law->traction(pt->geo.gap, pt->st.sN, pt->eps, p, k);
}

/* A point is active (carries stiffness) where the law's stiffness is positive */
PetscBool SPContactPointActive(SPContact c, PetscInt i)
{
  PetscReal p, k;
  SPContactPointTraction(c, i, &p, &k);
  return k > 0.0 ? PETSC_TRUE : PETSC_FALSE;
}


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

/* locF += contact forces at the global state X. Every element adds into the global vector Fc with
   global indices (a master facet may live on another rank); Fc then comes back as an owned-only
   local vector. */
PetscErrorCode SPContactAddResidual(SPContact c, Vec X, Vec locF)
{
  Vec L;

  PetscFunctionBeginUser;
  PetscCall(SPContactEvaluate(c, X));
  PetscCall(VecZeroEntries(c->Fc));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt    nd, dofs[SP_ELEM_MAXD];
    PetscReal   A, p, k, N[SP_ELEM_MAXD], r[SP_ELEM_MAXD];
    PetscScalar rs[SP_ELEM_MAXD];
    PetscCall(SPContactPointElement(c, i, &nd, dofs, &A, N, NULL));
    if (!nd) continue;
    SPContactPointTraction(c, i, &p, &k);
    SPContactElement(nd, A, p, k, N, NULL, r, NULL);
    for (PetscInt j = 0; j < nd; ++j) rs[j] = r[j];
    PetscCall(VecSetValues(c->Fc, nd, dofs, rs, ADD_VALUES)); /* negative (constrained) skipped */
  }
  PetscCall(SPFrictionAddResidual(c));
  PetscCall(VecAssemblyBegin(c->Fc));
  PetscCall(VecAssemblyEnd(c->Fc));
  PetscCall(DMGetLocalVector(c->dm, &L));
  PetscCall(GlobalToOwnedLocal(c->dm, c->Fc, L));
  PetscCall(VecAXPY(locF, 1.0, L));
  PetscCall(DMRestoreLocalVector(c->dm, &L));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* J += contact tangent (shifts frozen) at X: each element's block with global indices (rows may
   be owned by another rank; the pattern holds them, see contact-pattern.c) */
PetscErrorCode SPContactAddJacobian(SPContact c, Vec X, Mat J)
{
  PetscFunctionBeginUser;
  PetscCall(SPContactEvaluate(c, X));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt    nd, dofs[SP_ELEM_MAXD];
    PetscReal   A, p, k, N[SP_ELEM_MAXD], H[SP_ELEM_MAXD * SP_ELEM_MAXD], K[SP_ELEM_MAXD * SP_ELEM_MAXD];
    PetscScalar Ks[SP_ELEM_MAXD * SP_ELEM_MAXD];
    SPContactPointTraction(c, i, &p, &k);
    if (k <= 0.0) continue;
    PetscCall(SPContactPointElement(c, i, &nd, dofs, &A, N, H));
    if (!nd) continue;
    SPContactElement(nd, A, p, k, N, H, NULL, K);
    for (PetscInt j = 0; j < nd * nd; ++j) Ks[j] = K[j];
    PetscCall(MatSetValues(J, nd, dofs, nd, dofs, Ks, ADD_VALUES)); /* constrained dofs are negative: skipped */
  }
  PetscCall(SPFrictionAddJacobian(c, J));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Nodal contact forces at the contact points (slave part of its own element plus the parts it
   receives as a master vertex, e.g. in the other pass of -contact_two_pass) and the recovered
   pressure p_i = f_i . n_i / A_i and tangential traction (f_i - (f_i . n_i) n_i) / A_i (with two
   passes the split between the passes is not unique; the total is). Against an obstacle or in
   one pass p_i is the law's pressure and the tangential traction the return map's.
   The master force is the reaction on the master bodies of the user's pairs: the master part of
   the user pairs' elements plus, with two passes, the slave part of the mirrored pairs' elements
   (whose slaves lie on those master bodies). Uses the last evaluated state; collective. */
PetscErrorCode SPContactRecoverForces(SPContact c)
{
  const PetscInt     dim = c->dim;
  PetscInt           remote = 0;
  PetscReal          fm[3] = {0, 0, 0};
  const PetscScalar *f;

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(c->fvec));
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscInt e = c->pt[i].geo.elem;
    PetscInt       nd, dofs[SP_ELEM_MAXD], idx[SP_ELEM_MAXD];
    PetscReal      A, p, k, N[SP_ELEM_MAXD], r[SP_ELEM_MAXD];
    PetscScalar    fs[SP_ELEM_MAXD];
    PetscBool      mirror;
    PetscCall(SPContactPointElement(c, i, &nd, dofs, &A, N, NULL));
    if (!nd) continue;
    SPContactPointTraction(c, i, &p, &k);
    SPContactElement(nd, A, p, k, N, NULL, r, NULL);
    mirror = e >= 0 && c->pair[c->mf[e].pair].mirror ? PETSC_TRUE : PETSC_FALSE;
    for (PetscInt j = 0; j < nd; ++j) {
      const PetscInt a = j / dim, cp = a == 0 ? c->rstart + i : c->mf[e].cp[a - 1];
      idx[j] = cp >= 0 ? cp * dim + j % dim : -1;
      fs[j]  = -r[j]; /* force on the body = -residual */
      if (e >= 0 && (a > 0) != mirror) fm[j % dim] -= r[j];
    }
    if (e >= 0 && (c->mf[e].gid < c->mfStart || c->mf[e].gid >= c->mfStart + c->nmfOwned)) remote++;
    PetscCall(VecSetValues(c->fvec, nd, idx, fs, ADD_VALUES));
  }
  PetscCall(SPFrictionForces(c, c->fvec, fm));
  PetscCall(VecAssemblyBegin(c->fvec));
  PetscCall(VecAssemblyEnd(c->fvec));
  PetscCallMPI(MPI_Allreduce(fm, c->stats.forceMaster, 3, MPIU_REAL, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  PetscCallMPI(MPI_Allreduce(&remote, &c->stats.remoteElements, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  PetscCall(VecGetArrayRead(c->fvec, &f));
  for (PetscInt i = 0; i < c->n; ++i) {
    SPContactPoint *pt = &c->pt[i];
    PetscReal       y[2];
    const PetscReal *n = SPContactPointNormal(c, i);
    for (PetscInt d = 0; d < dim; ++d) pt->f[d] = PetscRealPart(f[i * dim + d]);
    pt->press = pt->area > 0.0 ? SPDot(dim, pt->f, n) / pt->area : 0.0;
    for (PetscInt d = 0; d < dim; ++d) pt->ft[d] = pt->area > 0.0 ? pt->f[d] / pt->area - pt->press * n[d] : 0.0;
    SPFrictionTraction(c, i, y, pt->t, &pt->stick);
  }
  PetscCall(VecRestoreArrayRead(c->fvec, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}
