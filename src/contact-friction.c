/* Coulomb friction with a tangential shift (../shared/docs/friction.md). Per point, in a load step:
   the tangential relative displacement Dg_T against the anchor committed at the last converged
   step (linear in u: committed normal and tangent basis), the trial y = -eps_T (Dg_T + s_T), the
   return map onto mu p. The tangential shift s_T follows the method's timing: frozen at
   -t_T^n/eps_T (penalty: a stuck point creeps t_T/eps_T), updated s_T <- -t_T/eps_T at every
   Newton-iteration boundary (shifted: the creep moves into the shift) or after each converged
   solve (augmented Lagrangian). The anchor, the committed traction and the accumulated slip are
   state: committed at a converged step, restored by a cut-back. */
#include <spcontact-impl.h>
#include <kernels/contact-friction.h>

PetscErrorCode SPFrictionSetFromOptions(PetscOptionItems *PetscOptionsObject, SPContact c)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsReal("-contact_friction_mu", "Coulomb friction coefficient of every obstacle and pair (0: frictionless; per obstacle/pair: -contact_obstacle_<k>_mu, -contact_pair_<k>_mu)", "SPContactSetFromOptions", c->mu, &c->mu, NULL));
  c->alphaT = c->alpha; /* the default; a given value, negative or not, is checked in contact.c */
  PetscCall(PetscOptionsReal("-contact_friction_alpha", "Tangential penalty factor: eps_T = alpha_T E / h (default: -contact_alpha)", "SPContactSetFromOptions", c->alpha, &c->alphaT, &c->alphaTGiven));
  PetscCall(PetscOptionsReal("-contact_friction_creep_rtol", "Friction, methods that update the shift: converged only when no stuck point has moved more than rtol x h since it stuck (the creep committed in earlier steps counts, and the update takes it back)", "SPContactSetFromOptions", c->creepRtol, &c->creepRtol, NULL));
  PetscCall(PetscOptionsInt("-contact_friction_max_flips", "Friction: stick/slip changes of a point in a load step after which it slips for the rest of the step (a chattering point; friction.md safeguard)", "SPContactSetFromOptions", c->maxFlips, &c->maxFlips, NULL));
  PetscCall(PetscOptionsBool("-contact_friction_stick_hold", "Friction, shifted: once every stuck point has crept at most creep_rtol h and creep_rtol h_c since it stuck, stuck points keep their tangential shifts (an update would only perturb a converged state and cost a Newton iteration)", "SPContactSetFromOptions", c->stickHold, &c->stickHold, NULL));
  PetscCall(PetscOptionsReal("-contact_friction_jump_wait", "Friction, shifted: no shift update (normal or tangential) at a Newton-iteration boundary where the stick/slip set moved and the gap error grew more than this factor since the last boundary: the penetration of a step across stick/slip branches is transient, and eps times it would be locked into the shifts (0: off; else >= 1)", "SPContactSetFromOptions", c->jumpWait, &c->jumpWait, NULL));
  PetscCall(PetscOptionsReal("-contact_friction_slip_rtol", "Friction, methods that update the shift: converged only when the tangential shifts of slipping points are a fixed point of their update (one more update would move none by more than rtol x mu p / eps_T)", "SPContactSetFromOptions", c->slipRtol, &c->slipRtol, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Per point eps_T, and whether any obstacle or pair has friction */
PetscErrorCode SPFrictionSetUp(SPContact c)
{
  PetscInt on = 0, all;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->n; ++i) c->pt[i].epsT = c->pt[i].eps * c->alphaT / c->alpha;
  for (PetscInt k = 0; k < c->nob; ++k) on |= c->obMu[k] > 0.0;
  for (PetscInt k = 0; k < c->npair; ++k) on |= c->pair[k].mu > 0.0;
  PetscCallMPI(MPI_Allreduce(&on, &all, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  c->friction = all ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Index in c->mf of the master facet with global number gid, -1 if this rank does not hold it */
static PetscInt FindFacet(SPContact c, PetscInt hint, PetscInt gid)
{
  if (hint >= 0 && c->mf[hint].gid == gid) return hint;
  for (PetscInt f = 0; f < c->nmf; ++f)
    if (c->mf[f].gid == gid) return f;
  return -1;
}

/* Shape functions of a master facet at local coordinates xi (2D: segment; 3D: tri or quad) */
static void FacetShape(PetscInt dim, PetscInt nv, const PetscReal xi[], PetscReal N[])
{
  PetscReal dN[8], ddN[4];
  if (dim == 2) N[0] = 1.0 - xi[0], N[1] = xi[0];
  else SPFacetShape(nv, xi, N, dN, ddN);
}

/* Displacement of the anchor's master material point at the current state; PETSC_FALSE if the
   anchor facet is not held by this rank */
static PetscBool AnchorDisplacement(SPContact c, PetscInt i, PetscReal um[])
{
  const SPContactPoint *pt = &c->pt[i];
  const PetscInt        dim = c->dim;
  for (PetscInt d = 0; d < 3; ++d) um[d] = 0.0;
  if (pt->st.anchor < 0) {
    const SPObstacle *ob = &c->ob[-pt->st.anchor - 1];
    for (PetscInt d = 0; d < dim; ++d) um[d] = c->evalLoad * ob->motion[d];
    return PETSC_TRUE;
  } else {
    const PetscInt f = FindFacet(c, pt->geo.elem, pt->st.anchor);
    PetscReal      N[SP_FACET_MAXV];
    if (f < 0) return PETSC_FALSE;
    FacetShape(dim, c->mf[f].nv, pt->st.anchorXi, N);
    for (PetscInt a = 0; a < c->mf[f].nv; ++a)
      for (PetscInt d = 0; d < dim; ++d) um[d] += N[a] * c->mf[f].u[a * dim + d];
    return PETSC_TRUE;
  }
}

/* Friction coefficient of point i's current element, and Dg_T at the evaluated state */
void SPFrictionKinematics(SPContact c, PetscInt i)
{
  SPContactPoint *pt  = &c->pt[i];
  const PetscInt  dim = c->dim, e = pt->geo.elem;
  PetscReal       um[3], d[3];

  pt->geo.mu     = e == SP_ELEM_OBSTACLE ? c->obMu[pt->geo.obstacle] : (e >= 0 ? c->pair[c->mf[e].pair].mu : 0.0);
  pt->geo.dgT[0] = pt->geo.dgT[1] = 0.0;
  pt->geo.anchorLost = PETSC_FALSE;
  if (pt->st.fresh) pt->geo.mu = 0.0; /* open at its anchoring: no friction until the next commit anchors it closed */
  if (!c->friction || !pt->st.anchored || pt->st.fresh) return;
  if (!AnchorDisplacement(c, i, um)) {
    pt->geo.anchorLost = PETSC_TRUE;
    return;
  }
  for (PetscInt k = 0; k < dim; ++k) d[k] = (pt->geo.u[k] - pt->st.us[k]) - (um[k] - pt->st.um[k]);
  for (PetscInt a = 0; a < dim - 1; ++a) pt->geo.dgT[a] = SPDot(dim, pt->st.T[a], d);
}

/* The friction element of point i: the normal element's dofs plus, when the anchor lies on another
   master facet, that facet's; N = dg/du padded with zeros; BT = dDg_T/du (nt x nd). nd = 0: none. */
PetscErrorCode SPFrictionElementDofs(SPContact c, PetscInt i, PetscInt *nd, PetscInt dofs[], PetscReal N[], PetscReal BT[], PetscReal *A)
{
  const SPContactPoint *pt  = &c->pt[i];
  const PetscInt        dim = c->dim, nt = dim - 1;
  PetscInt              nd0, fa = -1, off = 0;
  PetscReal             Na[SP_FACET_MAXV];

  PetscFunctionBeginUser;
  PetscCall(SPContactPointElement(c, i, &nd0, dofs, A, N, NULL));
  *nd = nd0;
  if (!nd0 || !pt->st.anchored || pt->geo.anchorLost) {
    *nd = 0;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (pt->st.anchor >= 0) {
    fa = FindFacet(c, pt->geo.elem, pt->st.anchor);
    if (fa < 0) { /* not held by this rank: anchorLost, or a fresh point (no friction; the pattern's anticipation) */
      *nd = 0;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    if (fa == pt->geo.elem) off = dim;
    else {
      off = nd0;
      for (PetscInt k = 0; k < c->mf[fa].nv * dim; ++k) dofs[nd0 + k] = c->mf[fa].dof[k];
      *nd = nd0 + c->mf[fa].nv * dim;
      for (PetscInt k = nd0; k < *nd; ++k) N[k] = 0.0;
    }
    FacetShape(dim, c->mf[fa].nv, pt->st.anchorXi, Na);
  }
  for (PetscInt a = 0; a < nt; ++a) {
    PetscReal *row = &BT[a * *nd];
    for (PetscInt k = 0; k < *nd; ++k) row[k] = 0.0;
    for (PetscInt k = 0; k < dim; ++k) row[k] = pt->st.T[a][k];
    if (fa >= 0)
      for (PetscInt b = 0; b < c->mf[fa].nv; ++b)
        for (PetscInt k = 0; k < dim; ++k) row[off + b * dim + k] = -Na[b] * pt->st.T[a][k];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether point i, stuck by the return map with trial y and cone radius r, sits on the cone's
   edge (|y| = r to SP_CONE_EDGE_RTOL) and slipped at the last converged step. At a load step's
   first iterate every point that slipped sits there (its trial is its committed traction, mu p),
   and the return map calls it stuck: its stick tangent then held it against the drive, and its
   change to slip at the next iterate cost an iteration more (F1b's steady sliding took 3 Newton
   iterations per load step, now 1). SPFrictionTraction calls it slipping: the slip tangent and
   step control, in its committed direction; its traction (t = y, on the cone) is the same. */
static PetscBool SlipsOnEdge(SPContact c, PetscInt i, const PetscReal y[], PetscReal r)
{
  return c->saved[i].status == SP_POINT_SLIP && SPNorm(c->dim - 1, y) >= (1.0 - SP_CONE_EDGE_RTOL) * r ? PETSC_TRUE : PETSC_FALSE;
}

/* Point i on its friction branch of the iterate before this boundary's shift update (the normal
   one is held by SPContactPointTraction; contact-update.c, -contact_branch_hold): stuck, t = y even
   outside the cone; slipping, t = mu p y/|y| (p: its held pressure) */
static void HoldBranch(SPContact c, PetscInt i, PetscReal p, const PetscReal y[], PetscReal t[], PetscBool *stick)
{
  const SPContactPoint *pt = &c->pt[i];
  const PetscInt        nt = c->dim - 1;
  const PetscReal       ny = SPNorm(nt, y);

  *stick = pt->st.heldStick;
  for (PetscInt a = 0; a < nt; ++a) t[a] = *stick ? y[a] : (ny > 0.0 ? pt->geo.mu * PetscMax(p, 0.0) * y[a] / ny : 0.0);
}

/* Trial y and returned traction t of point i at the evaluated state; open points carry none.
   A point on the cone's edge that slipped in the last step slips (SlipsOnEdge). A point that
   changed stick/slip more than 3 times in the step keeps its status. */
void SPFrictionTraction(SPContact c, PetscInt i, PetscReal y[], PetscReal t[], PetscBool *stick)
{
  SPContactPoint *pt = &c->pt[i];
  const PetscInt  nt = c->dim - 1;
  PetscReal       p, k;

  SPContactPointTraction(c, i, &p, &k);
  y[0] = y[1] = t[0] = t[1] = 0.0;
  *stick = PETSC_FALSE;
  if (pt->geo.mu <= 0.0 || k <= 0.0 || !pt->st.anchored || pt->geo.anchorLost) return;
  for (PetscInt a = 0; a < nt; ++a) y[a] = -pt->epsT * (pt->geo.dgT[a] + pt->st.sT[a]);
  *stick = SPCoulombReturn(nt, y, pt->geo.mu * p, t);
  if (*stick && SlipsOnEdge(c, i, y, pt->geo.mu * p)) *stick = PETSC_FALSE;
  if (pt->st.flips > c->maxFlips) { /* a chattering point slips for the rest of the step */
    const PetscReal ny = SPNorm(nt, y), r = pt->geo.mu * p, nd = SPNorm(nt, pt->st.dir);
    /* ... and keeps the direction of its last slip (a reversal is a status change too): inside
       the cone y/|y| is noise near y = 0, its sign flips from one iterate to the next, each flip
       a jump of 2 mu p in the residual and a status change, so the step never converged. y is
       put on the cone edge in that direction: the tangent and the step control see a slipping
       point. Without a slip direction yet, the return map's. */
    if (nd > 0.0) {
      *stick = PETSC_FALSE;
      for (PetscInt a = 0; a < nt; ++a) t[a] = r * pt->st.dir[a] / nd, y[a] = t[a];
    } else if (*stick) {
      *stick = PETSC_FALSE;
      for (PetscInt a = 0; a < nt; ++a) t[a] = ny > 0.0 ? r * y[a] / ny : 0.0;
    }
  }
  if (c->holding && pt->st.held && (*stick != pt->st.heldStick || p < 0.0)) HoldBranch(c, i, p, y, t, stick);
}

/* c->Fc += the friction residual of every point (before the assembly of Fc) */
PetscErrorCode SPFrictionAddResidual(SPContact c)
{
  const PetscInt nt = c->dim - 1;

  PetscFunctionBeginUser;
  if (!c->friction) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt    nd, dofs[SP_FRIC_MAXD];
    PetscReal   A, y[2], t[2], N[SP_FRIC_MAXD], BT[2 * SP_FRIC_MAXD], r[SP_FRIC_MAXD];
    PetscScalar rs[SP_FRIC_MAXD];
    PetscBool   stick;
    SPFrictionTraction(c, i, y, t, &stick);
    if (t[0] == 0.0 && t[1] == 0.0) continue;
    PetscCall(SPFrictionElementDofs(c, i, &nd, dofs, N, BT, &A));
    if (!nd) continue;
    SPFrictionElement(nd, nt, A, c->pt[i].epsT, c->pt[i].geo.mu, 0.0, 0.0, BT, N, y, t, stick, r, NULL);
    for (PetscInt j = 0; j < nd; ++j) rs[j] = r[j];
    PetscCall(VecSetValues(c->Fc, nd, dofs, rs, ADD_VALUES));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* J += the friction tangent of every point with friction (before the assembly of J) */
PetscErrorCode SPFrictionAddJacobian(SPContact c, Mat J)
{
  const PetscInt nt = c->dim - 1;

  PetscFunctionBeginUser;
  if (!c->friction) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt    nd, dofs[SP_FRIC_MAXD];
    PetscReal   A, p, k, y[2], t[2], N[SP_FRIC_MAXD], BT[2 * SP_FRIC_MAXD], K[SP_FRIC_MAXD * SP_FRIC_MAXD];
    PetscScalar Ks[SP_FRIC_MAXD * SP_FRIC_MAXD];
    PetscBool   stick, frozen;
    SPContactPointTraction(c, i, &p, &k);
    if (c->pt[i].geo.mu <= 0.0 || k <= 0.0) continue;
    SPFrictionTraction(c, i, y, t, &stick);
    PetscCall(SPFrictionElementDofs(c, i, &nd, dofs, N, BT, &A));
    if (!nd) continue;
    /* A point whose slip just reversed gets the stick (elastic) tangent for one iteration: the
       slip tangent has no tangential stiffness (none at all in 2D), so Newton would throw it back
       across the cone again; its residual stays the slip traction */
    /* A chattering point slipping in its frozen direction (SPFrictionTraction): t = mu p dir does
       not depend on the tangential motion, only the normal coupling remains */
    frozen = c->pt[i].st.flips > c->maxFlips && SPNorm(nt, c->pt[i].st.dir) > 0.0 ? PETSC_TRUE : PETSC_FALSE;
    SPFrictionElement(nd, nt, A, frozen ? 0.0 : c->pt[i].epsT, c->pt[i].geo.mu, p, k, BT, N, y, t, !frozen && (stick || c->pt[i].st.reversed), NULL, K);
    for (PetscInt j = 0; j < nd * nd; ++j) Ks[j] = K[j];
    PetscCall(MatSetValues(J, nd, dofs, nd, dofs, Ks, ADD_VALUES));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Anchor point i at the evaluated state (its current closest point) with committed traction tg
   (a dim-vector; NULL: none): displacements, s_T = -t_T/eps_T, Dg_T = 0, and the basis of the
   current geometry, or, with `keep` on a point anchored before, the basis of the converged step:
   the committed traction then has no component along the new normal, so the committed state (its
   recovered forces, the summary) stays in equilibrium; SPFrictionRefreshBasis turns it to the
   current geometry at the start of the next solve. */
static void AnchorPoint(SPContact c, PetscInt i, const PetscReal tg[], PetscBool keep)
{
  SPContactPoint *pt = &c->pt[i];
  SPPointState   *st = &pt->st;
  const PetscInt  dim = c->dim, e = pt->geo.elem;

  keep           = keep && st->anchored ? PETSC_TRUE : PETSC_FALSE;
  st->basisStale = PETSC_FALSE;
  st->anchored   = e != SP_ELEM_NONE ? PETSC_TRUE : PETSC_FALSE;
  st->fresh      = st->anchored && !SPContactPointActive(c, i) ? PETSC_TRUE : PETSC_FALSE;
  st->flips    = 0;
  st->released = PETSC_FALSE;
  st->tT[0] = st->tT[1] = st->sT[0] = st->sT[1] = 0.0;
  pt->geo.dgT[0] = pt->geo.dgT[1] = 0.0;
  pt->geo.anchorLost = PETSC_FALSE;
  if (!st->anchored) return;
  st->anchor = e == SP_ELEM_OBSTACLE ? -(pt->geo.obstacle + 1) : c->mf[e].gid;
  st->anchorXi[0] = pt->geo.xi[0], st->anchorXi[1] = pt->geo.xi[1];
  for (PetscInt d = 0; d < 3; ++d) {
    st->us[d] = d < dim ? pt->geo.u[d] : 0.0;
    if (keep) continue;
    st->n[d] = pt->geo.normal[d];
    for (PetscInt a = 0; a < 2; ++a) st->T[a][d] = pt->geo.tangent[a][d];
  }
  st->basisStale = keep;
  (void)AnchorDisplacement(c, i, st->um); /* the current element's facet: always held */
  if (tg)
    for (PetscInt a = 0; a < dim - 1; ++a) {
      st->tT[a] = SPDot(dim, tg, st->T[a]);
      st->sT[a] = -st->tT[a] / pt->epsT;
    }
}

/* Start of a solve: the basis kept at commit turns to the current geometry's; the committed
   traction and the last slip direction are expressed in it (s_T = -t_T/eps_T, Dg_T = 0 still) */
static void RefreshBasis(SPContact c, PetscInt i)
{
  SPContactPoint *pt = &c->pt[i];
  SPPointState   *st = &pt->st;
  const PetscInt  dim = c->dim, nt = dim - 1;
  PetscReal       dir[3] = {0, 0, 0};

  st->basisStale = PETSC_FALSE;
  if (pt->geo.elem == SP_ELEM_NONE) return;
  for (PetscInt a = 0; a < nt; ++a)
    for (PetscInt d = 0; d < dim; ++d) dir[d] += st->dir[a] * st->T[a][d];
  for (PetscInt d = 0; d < 3; ++d) {
    st->n[d] = pt->geo.normal[d];
    for (PetscInt a = 0; a < 2; ++a) st->T[a][d] = pt->geo.tangent[a][d];
  }
  for (PetscInt a = 0; a < nt; ++a) {
    st->tT[a]  = SPDot(dim, st->tCommit, st->T[a]);
    st->sT[a]  = -st->tT[a] / pt->epsT;
    st->dir[a] = SPDot(dim, dir, st->T[a]);
  }
}

/* Anchor the points that have no anchor yet (start of a solve), or, with `commit`, every point at a
   converged step: accumulated slip and creep, committed traction and status, new anchor. */
PetscErrorCode SPFrictionAnchor(SPContact c, PetscBool commit)
{
  const PetscInt dim = c->dim;

  PetscFunctionBeginUser;
  if (!c->friction) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) {
    SPContactPoint *pt = &c->pt[i];
    PetscReal       y[2], t[2], tg[3] = {0, 0, 0}, dg[3] = {0, 0, 0};
    PetscBool       stick;
    if (!commit) {
      if (!pt->st.anchored) AnchorPoint(c, i, NULL, PETSC_FALSE);
      else if (pt->st.basisStale) RefreshBasis(c, i);
      continue;
    }
    SPFrictionTraction(c, i, y, t, &stick);
    for (PetscInt a = 0; a < dim - 1; ++a)
      for (PetscInt d = 0; d < dim; ++d) tg[d] += t[a] * pt->st.T[a][d], dg[d] += pt->geo.dgT[a] * pt->st.T[a][d];
    for (PetscInt d = 0; d < dim; ++d) pt->st.slip[d] += dg[d];
    if (pt->st.status == SP_POINT_STICK)
      for (PetscInt d = 0; d < dim; ++d) pt->st.creep[d] += dg[d];
    else
      for (PetscInt d = 0; d < dim; ++d) pt->st.creep[d] = 0.0;
    for (PetscInt d = 0; d < dim; ++d) pt->st.tCommit[d] = tg[d];
    AnchorPoint(c, i, tg, PETSC_TRUE);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The clip eps_T |s_T| <= mu lambda of point i: the cone of the multiplier lambda_N = -eps s_N, or
   of the current pressure where that is larger (a stuck point inside the current cone keeps its
   traction; an open point with a reset shift gets none). Returns lambda. */
static PetscReal ClipToCone(SPContact c, PetscInt i)
{
  SPContactPoint *pt = &c->pt[i];
  const PetscInt  nt = c->dim - 1;
  PetscReal       p, k, lam, ns;

  SPContactPointTraction(c, i, &p, &k);
  lam = PetscMax(-pt->eps * pt->st.sN, p);
  ns  = SPNorm(nt, pt->st.sT);
  if (pt->epsT * ns > pt->geo.mu * lam)
    for (PetscInt a = 0; a < nt; ++a) pt->st.sT[a] *= lam > 0.0 ? pt->geo.mu * lam / (pt->epsT * ns) : 0.0;
  return lam;
}

/* Point i's tangential shift clipped to its cone (after a prediction) */
void SPFrictionClipShift(SPContact c, PetscInt i)
{
  (void)ClipToCone(c, i);
}

/* A slipping point's tangential shift against its update at the same state: |s_T' - s_T| in
   units of mu lambda_N / eps_T, with s_T' = -t_T/eps_T from the traction its new s_T gives (clipped
   like the update). The shift tracks the traction mu p, so a change of p in the step moves it
   although the state is already the update's fixed point: what convergence needs is that a
   further update would not move it (F1b at alpha 100: 83 -> 76 Newton iterations). A point the
   new shift turns to stick is not converged. */
static PetscReal SlipFixedPointError(SPContact c, PetscInt i, PetscReal lam)
{
  SPContactPoint *pt = &c->pt[i];
  const PetscInt  nt = c->dim - 1;
  PetscReal       y[2], t[2], s2[2] = {0, 0}, d[2] = {0, 0}, ns;
  PetscBool       stick;

  SPFrictionTraction(c, i, y, t, &stick);
  if (stick) return PETSC_MAX_REAL;
  for (PetscInt a = 0; a < nt; ++a) s2[a] = -t[a] / pt->epsT;
  ns = SPNorm(nt, s2);
  if (pt->epsT * ns > pt->geo.mu * lam)
    for (PetscInt a = 0; a < nt; ++a) s2[a] *= pt->geo.mu * lam / (pt->epsT * ns);
  for (PetscInt a = 0; a < nt; ++a) d[a] = s2[a] - pt->st.sT[a];
  return pt->epsT * SPNorm(nt, d) / (pt->geo.mu * lam);
}

/* |Delta s_T| of point i against its old shift */
static PetscReal ShiftChange(SPContact c, PetscInt i, const PetscReal old[])
{
  PetscReal d[2] = {0, 0};
  for (PetscInt a = 0; a < c->dim - 1; ++a) d[a] = old[a] - c->pt[i].st.sT[a];
  return SPNorm(c->dim - 1, d);
}

/* Point i's creep if it sticks: since it stuck (the committed creep plus this step's), a length */
static PetscReal Creep(SPContact c, PetscInt i)
{
  const SPContactPoint *pt  = &c->pt[i];
  const PetscInt        dim = c->dim;
  PetscReal             dg[3] = {0, 0, 0};

  for (PetscInt a = 0; a < dim - 1; ++a)
    for (PetscInt d = 0; d < dim; ++d) dg[d] += pt->geo.dgT[a] * pt->st.T[a][d];
  for (PetscInt d = 0; d < dim; ++d) dg[d] += pt->st.creep[d];
  return SPNorm(dim, dg);
}

/* Whether every stuck point of the evaluated state meets the creep test of the Newton convergence
   test (at most creep_rtol h since it stuck) and has crept at most creep_rtol h_c, collective:
   their tangential shifts then hold, as the normal ones do once the gaps hold */
static PetscErrorCode StickCreepHolds(SPContact c, PetscBool *holds)
{
  PetscReal r[2] = {0.0, 0.0}, all[2];

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->n; ++i) {
    const SPContactPoint *pt = &c->pt[i];
    PetscReal             y[2], t[2], creep;
    PetscBool             stick;
    if (pt->geo.mu <= 0.0 || !pt->st.active || !SPContactPointActive(c, i)) continue;
    SPFrictionTraction(c, i, y, t, &stick);
    if (!stick) continue;
    creep = Creep(c, i);
    r[0]  = PetscMax(r[0], creep / pt->h);
    r[1]  = PetscMax(r[1], creep / c->lengthScale);
  }
  PetscCallMPI(MPI_Allreduce(r, all, 2, MPIU_REAL, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  *holds = all[0] <= c->creepRtol && all[1] <= c->creepRtol ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The tangential shift update s_T <- -t_T/eps_T (stuck points: + their committed creep) of the
   points active in the previous and the current iterate (open points: s_T = 0), then the clip
   eps_T |s_T| <= mu lambda_N with lambda_N = -eps s_N (after the normal update). With
   -contact_shift_accel anderson the stuck points' updates (s_T <- s_T + Dg_T + c_T: the same affine
   fixed point as the normal one) get their own Anderson step (contact-accel.c), then the clip.
   With mayHold (the in-Newton update at a boundary where the normal shifts hold) and
   -contact_friction_stick_hold, once every stuck point's creep holds its tolerance stuck points
   keep their shifts: an update would only perturb a converged state, and the residual it raises
   took another Newton iteration. *maxDs: max |Delta s_T| (collective max). */
PetscErrorCode SPFrictionUpdate(SPContact c, PetscBool mayHold, PetscReal *maxDs)
{
  const PetscInt nt = c->dim - 1;
  PetscReal      dmax = 0.0, rmax = 0.0, all[2], loc[2];
  PetscBool      used = PETSC_FALSE, creepHolds = PETSC_FALSE;

  PetscFunctionBeginUser;
  *maxDs = 0.0;
  if (!c->friction) PetscFunctionReturn(PETSC_SUCCESS);
  if (mayHold && c->stickHold) PetscCall(StickCreepHolds(c, &creepHolds));
  for (PetscInt i = 0; i < c->n; ++i) {
    SPContactPoint *pt = &c->pt[i];
    PetscReal       y[2], t[2], old[2] = {pt->st.sT[0], pt->st.sT[1]}, lam, ds;
    PetscBool       stick = PETSC_TRUE, rule = PETSC_FALSE, activeNow = SPContactPointActive(c, i);
    if (c->accTIn) c->accTIn[2 * i] = c->accTIn[2 * i + 1] = PETSC_FALSE;
    if (c->accTSlip) c->accTSlip[i] = PETSC_FALSE;
    if (pt->geo.mu <= 0.0) continue;
    if (activeNow && pt->st.active) {
      SPFrictionTraction(c, i, y, t, &stick);
      /* a stuck point's fixed point is no slip since it stuck: s_T <- -t_T/eps_T + c_T takes its
         committed creep c_T back. With c_T left, what each converged step left (up to
         creep_rtol h) added up: the F2 rigid edge reached 6.2e-13 to 7.4e-13 > creep_rtol h_c =
         4.9e-13 over its 40 steps; taken back, at most 4.7e-13 at every step */
      if (!(stick && creepHolds))
        for (PetscInt a = 0; a < nt; ++a) pt->st.sT[a] = -t[a] / pt->epsT + (stick ? SPDot(c->dim, pt->st.creep, pt->st.T[a]) : 0.0);
      rule = stick && creepHolds ? PETSC_FALSE : PETSC_TRUE;
    } else if (!activeNow) pt->st.sT[0] = pt->st.sT[1] = 0.0;
    if (c->accTSlip && rule && !stick) { /* Schur: the old shift of a slipping point (its direction's update is a row) */
      c->accTSlip[i] = PETSC_TRUE;
      for (PetscInt a = 0; a < nt; ++a) c->accTS[2 * i + a] = old[a];
    }
    if (c->accTIn && rule && stick) { /* the accelerator's record (Anderson: the clip after its step) */
      for (PetscInt a = 0; a < nt; ++a) {
        const PetscInt k = 2 * i + a;
        c->accTIn[k] = PETSC_TRUE, c->accTS[k] = old[a], c->accTG[k] = pt->st.sT[a] - old[a], c->accTNew[k] = pt->st.sT[a];
      }
      if (c->accelT) continue;
    }
    lam  = ClipToCone(c, i);
    ds   = ShiftChange(c, i, old);
    dmax = PetscMax(dmax, ds);
    if (!stick && lam > 0.0) rmax = PetscMax(rmax, SlipFixedPointError(c, i, lam));
  }
  if (c->accelT) PetscCall(SPShiftAccelUpdate(c->accelT, c->accTIn, c->accTS, c->accTG, c->accTNew, &used));
  for (PetscInt i = 0; c->accelT && i < c->n; ++i) {
    if (!c->accTIn[2 * i]) continue;
    for (PetscInt a = 0; a < nt; ++a) c->pt[i].st.sT[a] = c->accTNew[2 * i + a];
    (void)ClipToCone(c, i);
    dmax = PetscMax(dmax, ShiftChange(c, i, &c->accTS[2 * i]));
  }
  loc[0] = dmax, loc[1] = rmax;
  PetscCallMPI(MPI_Allreduce(loc, all, 2, MPIU_REAL, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  *maxDs                        = all[0];
  c->stats.maxSlipShiftResidual = all[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether any point's friction status (stick / slip, slip direction) at the evaluated state
   differs from its last bookkept one (collective). The tangential shift, like the normal one,
   is updated only on a settled set: an update during a change overshoots. */
PetscErrorCode SPFrictionSettled(SPContact c, PetscBool *settled)
{
  PetscInt n = 0, all;

  PetscFunctionBeginUser;
  *settled = PETSC_TRUE;
  if (!c->friction) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n && !n; ++i) {
    const SPContactPoint *pt = &c->pt[i];
    PetscReal             y[2], t[2];
    PetscBool             stick;
    if (pt->geo.mu <= 0.0 || !pt->st.active || pt->st.status == SP_POINT_OPEN) continue;
    SPFrictionTraction(c, i, y, t, &stick);
    if (stick != (pt->st.status == SP_POINT_STICK)) n = 1;
    else if (!stick && SPDot(c->dim - 1, t, pt->st.dir) < 0.0) n = 1;
  }
  PetscCallMPI(MPI_Allreduce(&n, &all, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  *settled = all ? PETSC_FALSE : PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the Newton step to the evaluated iterate jumped across stick/slip branches: the stick/slip
   set moved and the gap error grew more than jumpWait times since the last boundary (not at a
   solve's first boundary, where the growth is the load increment's). Its penetration is then the
   linearisation's transient, not the penalty's: at alpha 1000 (eps = 2e5 on F2) 1e-7 of it is a
   pressure of a third of p0, and an update (s <- s + g) locked it in, moved the stick/slip set
   again and stalled (F2 at alpha 1000: 209 Newton iterations and 3 cut-backs, 164 and 2 with the
   wait). Waiting at every boundary where the set moved (no growth test) cost F1b 53 / 41 / 36 ->
   64 / 48 / 43 iterations at alpha 10 / 100 / 1000 and F3 72 -> 79; waiting at any growth, 58 / 46
   / 41 and 77. The caller counts the waits (c->jumpWaits). */
PetscErrorCode SPFrictionJumped(SPContact c, PetscReal gapError, PetscBool *jumped)
{
  PetscBool settled;

  PetscFunctionBeginUser;
  *jumped = PETSC_FALSE;
  if (!c->friction || c->jumpWait <= 0.0 || c->boundary == 0 || gapError <= c->jumpWait * c->stats.gapError) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPFrictionSettled(c, &settled));
  *jumped = settled ? PETSC_FALSE : PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A chattering point slipping in its frozen direction (t): how far its traction is from the
   return map's at the same state, relative to mu p (0 where the frozen direction is the slip's) */
static PetscReal FrozenDeviation(SPContact c, PetscInt i, const PetscReal t[])
{
  const SPContactPoint *pt = &c->pt[i];
  const PetscInt        nt = c->dim - 1;
  PetscReal             p, k, y[2] = {0, 0}, tr[2] = {0, 0}, d[2] = {0, 0};

  SPContactPointTraction(c, i, &p, &k);
  if (pt->geo.mu * p <= 0.0) return 0.0;
  for (PetscInt a = 0; a < nt; ++a) y[a] = -pt->epsT * (pt->geo.dgT[a] + pt->st.sT[a]);
  (void)SPCoulombReturn(nt, y, pt->geo.mu * p, tr);
  for (PetscInt a = 0; a < nt; ++a) d[a] = tr[a] - t[a];
  return SPNorm(nt, d) / (pt->geo.mu * p);
}

/* Status (open / stick / slip) of every point at the evaluated state, flips, and the friction
   figures of the iterate: stick and slip counts, status changes (with `compare`), max stick creep
   since the points stuck (the committed creep plus this step's) relative to h (for the
   convergence test) and absolute */
PetscErrorCode SPFrictionBookkeep(SPContact c, PetscBool compare)
{
  const PetscInt dim = c->dim;
  PetscInt       n[5] = {0, 0, 0, 0, 0}, nall[5];
  PetscReal      r[3] = {0, 0, 0}, rall[3];

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->n; ++i) {
    SPContactPoint *pt = &c->pt[i];
    SPPointStatus   st;
    PetscReal       y[2], t[2], creep;
    PetscBool       stick;
    if (!pt->st.active) st = SP_POINT_OPEN;
    else if (pt->geo.mu <= 0.0) st = SP_POINT_STICK; /* closed, frictionless */
    else {
      SPFrictionTraction(c, i, y, t, &stick);
      st = stick ? SP_POINT_STICK : SP_POINT_SLIP;
    }
    if (compare && st != pt->st.status) {
      n[2]++;
      if (st != SP_POINT_OPEN && pt->st.status != SP_POINT_OPEN) pt->st.flips++;
    }
    pt->st.reversed = PETSC_FALSE;
    pt->frozenDev   = 0.0;
    if (st == SP_POINT_SLIP) { /* a reversal of the slip direction is a status change too */
      const PetscReal nt_ = SPNorm(dim - 1, t);
      PetscReal       m[2] = {0, 0};
      for (PetscInt a = 0; a < dim - 1; ++a) m[a] = nt_ > 0.0 ? t[a] / nt_ : 0.0;
      pt->st.reversed = compare && pt->st.status == SP_POINT_SLIP && SPDot(dim - 1, m, pt->st.dir) < 0.0 ? PETSC_TRUE : PETSC_FALSE;
      if (pt->st.reversed) n[2]++;
      pt->st.dir[0] = m[0], pt->st.dir[1] = m[1];
      if (pt->st.flips > c->maxFlips) n[3]++, pt->frozenDev = FrozenDeviation(c, i, t), r[2] = PetscMax(r[2], pt->frozenDev);
    }
    pt->st.status     = st;
    pt->st.noFriction = st != SP_POINT_OPEN && pt->geo.mu <= 0.0 ? PETSC_TRUE : PETSC_FALSE;
    if (st != SP_POINT_OPEN && pt->st.fresh && c->friction) n[4]++;
    if (pt->geo.mu <= 0.0 || st == SP_POINT_OPEN) continue;
    n[st == SP_POINT_STICK ? 0 : 1]++;
    if (st != SP_POINT_STICK) continue;
    creep = Creep(c, i);
    r[0]  = PetscMax(r[0], creep / pt->h);
    r[1]  = PetscMax(r[1], creep);
  }
  PetscCallMPI(MPI_Allreduce(n, nall, 5, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  PetscCallMPI(MPI_Allreduce(r, rall, 3, MPIU_REAL, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  c->stats.frozenPoints    = nall[3];
  c->stats.frozenDeviation = rall[2];
  c->stats.stickPoints   = nall[0];
  c->stats.slipPoints    = nall[1];
  c->stats.freshPoints   = nall[4];
  c->stats.statusChanged = compare ? nall[2] : 0;
  c->stats.maxStickCreep = rall[1];
  c->creepRel            = rall[0];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The status written for point i (h5 `status`, `_contact.csv`): 0 open, 1 stick, 2 slip, 3 closed
   but carrying no friction (its obstacle's or pair's mu is 0, or it was open when the step began:
   the fresh-point rule); with no friction anywhere a closed point is 1, as before friction */
PetscInt SPFrictionOutputStatus(SPContact c, PetscInt i)
{
  const SPContactPoint *pt = &c->pt[i];

  if (pt->st.status == SP_POINT_STICK && c->friction && pt->st.noFriction) return 3;
  return (PetscInt)pt->st.status;
}

/* Collective, after the run's last converged step (its figures are the summary's): a warning if
   most closed points carried no friction because they were open when the step began (friction
   in one load step was frictionless without a word) */
PetscErrorCode SPFrictionWarnFresh(SPContact c, PetscInt step)
{
  const SPContactStats *st = &c->stats;

  PetscFunctionBeginUser;
  if (!c->enabled || !c->friction || st->freshPoints <= st->stickPoints + st->slipPoints) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFPrintf(PetscObjectComm((PetscObject)c->dm), PETSC_STDERR, "spcontact: warning: load step %" PetscInt_FMT ": %" PetscInt_FMT " of its %" PetscInt_FMT " closed contact points carried no friction, since they were open when the step began (a point's friction starts at the step after it closes: status 3 in the output); give more load steps (-load_steps), or a first step with the normal load alone (-bc_<i>_ramp), so that contact closes before the tangential load comes\n", step, st->freshPoints, st->freshPoints + st->stickPoints + st->slipPoints));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Friction part of the Newton convergence test: no status changed in the last iteration and, for
   methods that update the shift at Newton boundaries, stuck points moved at most creep_rtol h since
   they stuck and the slip points' shifts settled (after-solve updates check these in the loop) */
PetscBool SPFrictionConverged(SPContact c)
{
  if (!c->friction) return PETSC_TRUE;
  if (c->stats.statusChanged) return PETSC_FALSE;
  if (c->method->timing != SP_UPDATE_NEWTON) return PETSC_TRUE; /* none, or checked after the solve */
  return c->creepRel <= c->creepRtol && c->stats.maxSlipShiftResidual <= c->slipRtol ? PETSC_TRUE : PETSC_FALSE;
}

/* At an iterate that passes every other convergence test: a chattering point slipping in its
   frozen direction (SPFrictionTraction) whose traction is more than slip_rtol mu p from the return
   map's is no Coulomb state (a point that sticks, or slips another way, at this state), so it gets
   the return map again and the solve goes on (*released): once per point and load step. A point
   released before still off is not converged: the solve goes on to its stall test and cut-back. */
PetscErrorCode SPFrictionReleaseFrozen(SPContact c, PetscBool *released, PetscBool *off)
{
  PetscInt n[2] = {0, 0}, all[2];

  PetscFunctionBeginUser;
  *released = *off = PETSC_FALSE;
  if (!c->friction || !c->stats.frozenPoints || c->stats.frozenDeviation <= c->slipRtol) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) {
    SPContactPoint *pt = &c->pt[i];
    if (pt->frozenDev <= c->slipRtol) continue; /* SPFrictionBookkeep's, at this iterate */
    if (pt->st.released) n[1]++;
    else n[0]++, pt->st.released = PETSC_TRUE, pt->st.flips = 0;
  }
  PetscCallMPI(MPI_Allreduce(n, all, 2, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
  if (all[0]) PetscCall(PetscInfo(c->dm, "friction: %" PetscInt_FMT " chattering points released from their frozen slip direction (traction %g mu p off the return map's)\n", all[0], (double)c->stats.frozenDeviation));
  *released = all[0] ? PETSC_TRUE : PETSC_FALSE;
  *off      = all[1] ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Nodal friction forces: into f (the contact-point force vector, dim per point, global index
   cp dim + d) at the slave and master vertices that are contact points, and the master parts
   (or, for mirrored pairs, the slave parts) into fm, as SPContactRecoverForces does */
PetscErrorCode SPFrictionForces(SPContact c, Vec f, PetscReal fm[])
{
  const PetscInt dim = c->dim, nt = dim - 1;

  PetscFunctionBeginUser;
  if (!c->friction) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < c->n; ++i) {
    const SPContactPoint *pt = &c->pt[i];
    const PetscInt        e  = pt->geo.elem;
    PetscInt              nd, dofs[SP_FRIC_MAXD], idx[SP_FRIC_MAXD], nd0, fa = -1;
    PetscReal             A, y[2], t[2], N[SP_FRIC_MAXD], BT[2 * SP_FRIC_MAXD], r[SP_FRIC_MAXD];
    PetscScalar           fs[SP_FRIC_MAXD];
    PetscBool             stick, mirror;
    SPFrictionTraction(c, i, y, t, &stick);
    if (t[0] == 0.0 && t[1] == 0.0) continue;
    PetscCall(SPFrictionElementDofs(c, i, &nd, dofs, N, BT, &A));
    if (!nd) continue;
    SPFrictionElement(nd, nt, A, pt->epsT, pt->geo.mu, 0.0, 0.0, BT, N, y, t, stick, r, NULL);
    nd0    = e >= 0 ? dim * (1 + c->mf[e].nv) : dim;
    if (nd > nd0) fa = FindFacet(c, e, pt->st.anchor);
    mirror = e >= 0 && c->pair[c->mf[e].pair].mirror ? PETSC_TRUE : PETSC_FALSE;
    for (PetscInt j = 0; j < nd; ++j) {
      const PetscInt a  = j / dim;
      PetscInt       cp = c->rstart + i;
      if (a > 0) cp = j < nd0 ? c->mf[e].cp[a - 1] : c->mf[fa].cp[(j - nd0) / dim];
      idx[j] = cp >= 0 ? cp * dim + j % dim : -1;
      fs[j]  = -r[j];
      if (e >= 0 && (a > 0) != mirror) fm[j % dim] -= r[j];
    }
    PetscCall(VecSetValues(f, nd, idx, fs, ADD_VALUES));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Tangential Newton step control, the counterpart of the penetration cap of SPContactLimitStep.
   The slip tangent carries no tangential stiffness along the slip direction (none at all in 2D):
   the linearisation holds the friction force of a slipping point at mu p m, so a step that moves
   the point back against its slip (unloading it towards stick, or reversing it) is sized by the
   elasticity of the body behind the point, about 2 mu p L/E, instead of by the width 2 mu p/eps_T
   of the stick cone; it overshoots by about eps_T L/E (tens to hundreds), the point lands deep in
   reverse slip, and the next step throws it back (F1b, shifted: corners alternating between open
   and deep penetration, the rest of the base sliding back and forth over full slip). So: record the
   trial y0 of the points slipping at the start of the step (SPFrictionStepStart, state X); where
   the step would carry the trial component along the slip direction m0 = y0/|y0| (linear in u:
   Dg_T is, s_T is fixed in the step) past the far edge of the cone (a reversal the linearisation
   cannot see), scale the step so that it stops at 0, the centre of the cone: the point then sticks
   at the new iterate and gets the stick tangent, exact for it. A step that ends inside the cone is
   not cut (the stick tangent of the next iteration handles it). A point limits at most once per
   reversal (it no longer slips after the limited step). */
void SPFrictionStepStart(SPContact c)
{
  const PetscInt nt = c->dim - 1;

  for (PetscInt i = 0; i < c->n; ++i) {
    PetscReal y[2], t[2];
    PetscBool stick;
    c->slipStart[3 * i] = c->slipStart[3 * i + 1] = c->slipStart[3 * i + 2] = 0.0;
    if (!c->friction) continue;
    SPFrictionTraction(c, i, y, t, &stick);
    /* slipping points, but not a chattering point slipping in its frozen direction (y = t) */
    if (stick || (t[0] == 0.0 && t[1] == 0.0)) continue;
    if (c->pt[i].st.flips > c->maxFlips && SPNorm(nt, y) <= SPNorm(nt, t)) continue;
    for (PetscInt a = 0; a < nt; ++a) c->slipStart[3 * i + a] = y[a];
    c->slipStart[3 * i + 2] = SPNorm(nt, t);
  }
}

/* The largest step fraction (<= 1) of SPFrictionStepStart's rule at the proposed iterate (local) */
PetscReal SPFrictionStepLimit(SPContact c)
{
  const PetscInt nt = c->dim - 1;
  PetscReal      theta = 1.0;

  if (!c->friction) return theta;
  for (PetscInt i = 0; i < c->n; ++i) {
    const SPContactPoint *pt = &c->pt[i];
    const PetscReal      *y0 = &c->slipStart[3 * i], r0 = y0[2];
    const PetscReal       n0 = SPNorm(nt, y0);
    PetscReal             a0, a1 = 0.0;
    if (n0 == 0.0 || !pt->st.anchored || pt->geo.anchorLost) continue;
    a0 = n0; /* y0 . m0 */
    for (PetscInt a = 0; a < nt; ++a) a1 -= pt->epsT * (pt->geo.dgT[a] + pt->st.sT[a]) * y0[a] / n0;
    if (a1 < -r0) theta = PetscMin(theta, a0 / (a0 - a1));
  }
  return theta;
}
