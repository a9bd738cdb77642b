/* Contact pairs (deformable-deformable contact: 2D node-to-segment, 3D node-to-facet on linear
   triangles and bilinear quadrilaterals): pair options, the master facet table, its exchange
   between ranks at every evaluation, and the closest-point search. One code path for 2D and 3D;
   the geometry kernels are kernels/contact-pair.h (segments, dispatch) and kernels/contact-facet.h
   (triangles: closed-form projection; quads: Newton projection with a Gauss-Newton fallback).

   Exchange: every rank owns the master facets of its part. At every evaluation the ranks share
   their slave bounding boxes (deformed, inflated by twice the largest slave/master facet edge),
   and each rank sends its owned master facets (deformed coordinates, global dofs, contact-point
   numbers) to the ranks whose box they meet (MPI_Alltoallv). -contact_pair_exchange_all sends to
   every rank (the whole-surface gather, for comparison). The cost is printed in the summary
   (contact_exchange_time, contact_exchange_facets_per_rank). The free sides of the master
   surfaces come from a one-time gather of the whole table at set-up.

   Projection rule (documented in the README). A facet's sides are its end vertices (2D) or its
   edges (3D, side s joins vertices s and s+1). Among the master facets of the point's pairs, the
   one whose CLAMPED closest point is nearest wins (2D: parameter clamped to [0,1]; 3D: the
   projection itself if it lies inside the facet, else the nearest point of its boundary edges).
   On a tie (within 1e-10 relative: a shared vertex or edge) the facet whose unclamped projection
   lies inside it, or less far outside (excess: max over sides of how far the projection lies
   beyond the side, in parameter units: segment [0,1], triangle barycentric, quad [-1,1]/2), wins,
   then the facet with the lexicographically smaller reference centroid (independent of the
   partition). The gap and normal come from the winning facet at its UNCLAMPED projection (an
   extended facet), which keeps g continuous across flat junctions and makes the dead zone at a
   convex edge or corner belong to one facet. A projection beyond a free side of the master surface
   (a vertex/edge of one master facet only, within the pair) by more than SP_PAIR_END_TOL (in the
   same parameter units) is off the surface: the point has no contact element. A quad facet whose
   projection fails (see kernels/contact-facet.h) is not a candidate.

   Hysteresis at a vertex or edge. Near a master vertex a penetrated slave point projects inside
   both facets that share it, with gaps of either sign, and the nearest one can change from one
   Newton iterate to the next; each change moves the point back: a 2-cycle that cut-backs repeat
   (F2's rigid-edge set-up on halved contact meshes, load 0.925). So within a load step the facet
   of the last Newton iterate (keepFacet) stays the point's facet while its unclamped projection
   lies within SP_PAIR_END_TOL of it (the extended facet, as for the gap) and its distance is
   within SP_PAIR_KEEP_RTOL h of the nearest. Both are node-to-segment gaps of the point; they
   differ by the kink at the vertex times the distance to it. A kept facet's distance is the
   clamped one, the distance to the vertex for a point beyond it, so a point that oscillates a
   little more than 1e-4 h about the vertex still switches: F2's rigid edge without friction
   (-contact_friction_mu 0 -bc_2_value 0) stalled at load 0.145 in a 2-cycle of a point 1.2e-4 h
   either side of a vertex (its facet switching every Newton iterate, the whole contact's gaps
   +-1.7e-9 with it), 7 cut-backs and exit 2. So once a point's kept facet has gone back to the one
   before it SP_PAIR_RETURNS times in a step, its band widens to the end tolerance (1e-2 h): that
   run converges with no cut-back. The band stays narrow for every other point: a point sliding
   over vertices never goes back, and widening it for all points cost F2 at alpha 1000 28 more
   Newton iterations (75 -> 103). */
#include <spcontact-impl.h>

#define SP_PAIR_END_TOL 1e-2
#define SP_PAIR_KEEP_RTOL 1e-4 /* the kept facet's distance may exceed the nearest by this x h */
#define SP_PAIR_KEEP_WIDE 1e-2 /* ... and by this x h after SP_PAIR_RETURNS returns in the step */
#define SP_PAIR_RETURNS   2


static PetscErrorCode PairSetFromOptions(MPI_Comm comm, PetscInt k, PetscReal mu, SPPair *p, PetscBool *found)
{
  char      prefix[48];
  PetscBool hasS, hasM, hasL;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "contact_pair_%" PetscInt_FMT "_", k));
  PetscCall(PetscMemzero(p, sizeof(*p)));
  PetscCall(PetscStrcpy(p->label, "Face Sets"));
  p->nslave = p->nmaster = SP_MAX_VALUES;
  p->mu = mu;
  PetscOptionsBegin(comm, prefix, "Contact pair (deformable-deformable, node-to-segment in 2D, node-to-facet in 3D)", "spcontact");
  PetscCall(PetscOptionsString("-label", "Mesh label of the pair's two surfaces", "SPContactPairsSetFromOptions", p->label, p->label, sizeof(p->label), &hasL));
  PetscCall(PetscOptionsIntArray("-slave_values", "Label values of the slave surface (its vertices are contact points)", "SPContactPairsSetFromOptions", p->slave, &p->nslave, &hasS));
  PetscCall(PetscOptionsIntArray("-master_values", "Label values of the master surface (its facets are projected on)", "SPContactPairsSetFromOptions", p->master, &p->nmaster, &hasM));
  PetscCall(PetscOptionsReal("-mu", "Coulomb friction coefficient of the pair (default -contact_friction_mu)", "SPContactPairsSetFromOptions", p->mu, &p->mu, NULL));
  PetscOptionsEnd();
  PetscCall(SPOptionsCheckLength(comm, prefix, "-slave_values", SP_MAX_VALUES));
  PetscCall(SPOptionsCheckLength(comm, prefix, "-master_values", SP_MAX_VALUES));
  PetscCall(SPContactCheckMu(comm, prefix, p->mu));
  if (!hasS) p->nslave = 0;
  if (!hasM) p->nmaster = 0;
  *found = hasS || hasM || hasL ? PETSC_TRUE : PETSC_FALSE;
  if (!*found) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(p->nslave > 0, comm, PETSC_ERR_USER_INPUT, "contact pair %" PetscInt_FMT ": no slave surface, add -%sslave_values <label values>", k, prefix);
  PetscCheck(p->nmaster > 0, comm, PETSC_ERR_USER_INPUT, "contact pair %" PetscInt_FMT ": no master surface, add -%smaster_values <label values>", k, prefix);
  for (PetscInt a = 0; a < p->nslave; ++a)
    for (PetscInt b = 0; b < p->nmaster; ++b) PetscCheck(p->slave[a] != p->master[b], comm, PETSC_ERR_USER_INPUT, "contact pair %" PetscInt_FMT ": label value %" PetscInt_FMT " is both slave and master (self-contact is not supported)", k, p->slave[a]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactPairsSetFromOptions(SPContact c)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)c->dm);
  PetscBool found = PETSC_TRUE;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Contact pairs", "spcontact");
  PetscCall(PetscOptionsBool("-contact_pair_exchange_all", "Contact pairs: send every master facet to every rank at each evaluation (default: only to ranks whose slave bounding box, inflated by 2 x the largest facet, they meet)", "SPContactPairsSetFromOptions", c->exchangeAll, &c->exchangeAll, NULL));
  PetscOptionsEnd();
  for (c->nuser = 0; c->nuser < SP_MAX_PAIRS; ++c->nuser) {
    PetscCall(PairSetFromOptions(comm, c->nuser, c->mu, &c->pair[c->nuser], &found));
    if (!found) break;
  }
  PetscCall(SPOptionsCheckNoGap(comm, "-contact_pair_", c->nuser, SP_MAX_PAIRS, "contact pairs", "contact pair", "slave_values"));
  c->npair = c->nuser;
  PetscCheck(c->nuser > 0 || !c->twoPass, comm, PETSC_ERR_USER_INPUT, "-contact_two_pass needs a contact pair (-contact_pair_0_slave_values, -contact_pair_0_master_values)");
  if (c->twoPass)
    for (PetscInt k = 0; k < c->nuser; ++k) {
      SPPair *m = &c->pair[c->npair++];
      *m        = c->pair[k];
      m->nslave = c->pair[k].nmaster;
      m->nmaster = c->pair[k].nslave;
      PetscCall(PetscArraycpy(m->slave, c->pair[k].master, m->nslave));
      PetscCall(PetscArraycpy(m->master, c->pair[k].slave, m->nmaster));
      m->mirror = PETSC_TRUE;
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Swap the vertex order of facet f if its normal does not point away from the supporting cell */
static PetscErrorCode OrientFacet(DM dm, PetscInt f, PetscInt dim, PetscInt nv, PetscInt vert[], PetscReal X[])
{
  const PetscInt *supp;
  PetscInt        ns, cnv, cvert[8];
  PetscReal       cx[8 * 3], xc[3] = {0, 0, 0}, xf[3] = {0, 0, 0}, n[3];

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetSupportSize(dm, f, &ns));
  PetscCall(DMPlexGetSupport(dm, f, &supp));
  PetscCheck(ns == 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "contact pairs: master facet %" PetscInt_FMT " is not on the boundary (%" PetscInt_FMT " cells)", f, ns);
  {
    PetscInt *cl = NULL, ncl, vStart, vEnd;
    PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
    PetscCall(DMPlexGetTransitiveClosure(dm, supp[0], PETSC_TRUE, &ncl, &cl));
    cnv = 0;
    for (PetscInt p = 0; p < 2 * ncl; p += 2)
      if (cl[p] >= vStart && cl[p] < vEnd && cnv < 8) cvert[cnv++] = cl[p];
    PetscCall(DMPlexRestoreTransitiveClosure(dm, supp[0], PETSC_TRUE, &ncl, &cl));
  }
  for (PetscInt a = 0; a < cnv; ++a) {
    PetscInt nv1, v1[4];
    PetscCall(SPContactFacetVertices(dm, cvert[a], &nv1, v1, &cx[a * dim]));
    for (PetscInt k = 0; k < dim; ++k) xc[k] += cx[a * dim + k] / cnv;
  }
  for (PetscInt a = 0; a < nv; ++a)
    for (PetscInt k = 0; k < dim; ++k) xf[k] += X[a * dim + k] / nv;
  for (PetscInt k = 0; k < dim; ++k) xc[k] -= xf[k];
  SPPairCentreNormal(dim, nv, X, n);
  if (SPDot(dim, xc, n) > 0.0) { /* the cell centroid lies on the normal side: reverse */
    for (PetscInt a = 0; a < nv / 2; ++a) {
      const PetscInt b = nv - 1 - a, tv = vert[a];
      vert[a] = vert[b], vert[b] = tv;
      for (PetscInt k = 0; k < dim; ++k) {
        const PetscReal t = X[a * dim + k];
        X[a * dim + k] = X[b * dim + k], X[b * dim + k] = t;
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Static data of this rank's owned master facets */
static PetscErrorCode OwnedFacets(SPContact c, PetscInt *nown, SPMasterFacet **own, PetscInt **ownVert)
{
  const PetscInt  dim = c->dim;
  PetscSF         sf;
  PetscInt        nleaves, pStart, pEnd, cap = 0, n = 0;
  const PetscInt *leaves;
  PetscBool      *ghost;
  PetscSection    ls, gs, gsC;
  IS              numIS;
  const PetscInt *num, *serial;
  SPMasterFacet  *tab = NULL;
  PetscInt       *tv  = NULL;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(c->dm, &pStart, &pEnd));
  PetscCall(PetscCalloc1(pEnd - pStart, &ghost));
  PetscCall(DMGetPointSF(c->dm, &sf));
  PetscCall(PetscSFGetGraph(sf, NULL, &nleaves, &leaves, NULL));
  for (PetscInt l = 0; l < (nleaves > 0 ? nleaves : 0); ++l) ghost[(leaves ? leaves[l] : l) - pStart] = PETSC_TRUE;
  PetscCall(DMGetLocalSection(c->dm, &ls));
  PetscCall(DMGetGlobalSection(c->dm, &gs));
  PetscCall(DMGetGlobalSection(c->dmC, &gsC));
  PetscCall(DMPlexCreatePointNumbering(c->dm, &numIS));
  PetscCall(ISGetIndices(numIS, &num));
  PetscCall(SPMeshGetSerialNumbers(c->dm, &serial));
  for (PetscInt k = 0; k < c->npair; ++k) {
    const SPPair *p = &c->pair[k];
    PetscInt      nf, *facets;
    PetscCall(SPMeshGetLabelFacets(c->dm, p->label, p->nmaster, p->master, &nf, &facets));
    if (n + nf > cap) {
      SPMasterFacet *t;
      PetscInt      *v;
      cap = 2 * (n + nf);
      PetscCall(PetscCalloc1(cap, &t));
      PetscCall(PetscCalloc1(cap * SP_FACET_MAXV, &v));
      if (n) PetscCall(PetscArraycpy(t, tab, n));
      if (n) PetscCall(PetscArraycpy(v, tv, n * SP_FACET_MAXV));
      PetscCall(PetscFree(tab));
      PetscCall(PetscFree(tv));
      tab = t;
      tv  = v;
    }
    for (PetscInt j = 0; j < nf; ++j) {
      SPMasterFacet *m = &tab[n];
      PetscInt       vert[SP_FACET_MAXV];
      if (ghost[facets[j] - pStart]) continue;
      PetscCall(PetscMemzero(m, sizeof(*m)));
      m->pair = k;
      m->sid  = serial[facets[j] - pStart];
      PetscCall(SPContactFacetVertices(c->dm, facets[j], &m->nv, vert, m->X));
      PetscCall(OrientFacet(c->dm, facets[j], dim, m->nv, vert, m->X));
      for (PetscInt a = 0; a < m->nv; ++a) {
        PetscInt *idx = NULL, nidx, dof, off;
        m->vid[a] = num[vert[a] - pStart] >= 0 ? num[vert[a] - pStart] : -(num[vert[a] - pStart] + 1);
        PetscCall(DMPlexGetClosureIndices(c->dm, ls, gs, vert[a], PETSC_TRUE, &nidx, &idx, NULL, NULL));
        for (PetscInt d = 0; d < dim; ++d) m->dof[a * dim + d] = idx[d];
        PetscCall(DMPlexRestoreClosureIndices(c->dm, ls, gs, vert[a], PETSC_TRUE, &nidx, &idx, NULL, NULL));
        PetscCall(PetscSectionGetDof(gsC, vert[a], &dof));
        PetscCall(PetscSectionGetOffset(gsC, vert[a], &off));
        m->cp[a] = dof > 0 ? off : (dof < -1 ? -(off + 1) : -1); /* global section: ghosts store -(x+1) */
        tv[n * SP_FACET_MAXV + a] = vert[a];
        for (PetscInt d = 0; d < dim; ++d) m->x[a * dim + d] = m->X[a * dim + d], m->u[a * dim + d] = 0.0;
      }
      n++;
    }
    PetscCall(PetscFree(facets));
  }
  PetscCall(ISRestoreIndices(numIS, &num));
  PetscCall(ISDestroy(&numIS));
  PetscCall(PetscFree(ghost));
  *nown    = n;
  *own     = tab;
  *ownVert = tv;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Key of side s of facet m: 2D the vertex s, 3D the edge (s, s+1) (unordered), with the pair */
static PetscInt64 SideKey(const SPMasterFacet *m, PetscInt dim, PetscInt s, PetscInt64 nvg)
{
  const PetscInt64 v0 = m->vid[s], v1 = dim == 2 ? v0 : m->vid[(s + 1) % m->nv];
  return (PetscMin(v0, v1) * nvg + PetscMax(v0, v1)) * (2 * SP_MAX_PAIRS) + m->pair;
}

/* Free sides: sides (2D: end vertices, 3D: edges) of one master facet only, within the same pair */
static PetscErrorCode MarkFreeSides(SPContact c)
{
  PetscInt64 *key, nvg = 1;
  PetscInt    nk = 0;

  PetscFunctionBeginUser;
  for (PetscInt f = 0; f < c->nmf; ++f)
    for (PetscInt a = 0; a < c->mf[f].nv; ++a) nvg = PetscMax(nvg, (PetscInt64)c->mf[f].vid[a] + 1);
  PetscCheck(nvg < ((PetscInt64)1 << 29), PETSC_COMM_SELF, PETSC_ERR_SUP, "contact pairs: too many mesh points for the free-side keys");
  PetscCall(PetscMalloc1(c->nmf * SP_FACET_MAXV + 1, &key));
  for (PetscInt f = 0; f < c->nmf; ++f)
    for (PetscInt a = 0; a < c->mf[f].nv; ++a) key[nk++] = SideKey(&c->mf[f], c->dim, a, nvg);
  PetscCall(PetscSortInt64(nk, key));
  for (PetscInt f = 0; f < c->nmf; ++f)
    for (PetscInt a = 0; a < c->mf[f].nv; ++a) {
      const PetscInt64 k = SideKey(&c->mf[f], c->dim, a, nvg);
      PetscInt         lo = 0, hi = nk, cnt = 0;
      while (lo < hi) { /* first index with key >= k */
        const PetscInt mid = (lo + hi) / 2;
        if (key[mid] < k) lo = mid + 1;
        else hi = mid;
      }
      while (lo + cnt < nk && key[lo + cnt] == k) cnt++;
      c->mf[f].freeSide[a] = cnt == 1 ? PETSC_TRUE : PETSC_FALSE;
    }
  PetscCall(PetscFree(key));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The slave and master surfaces of pair k share no vertex: a shared vertex would face a master
   facet that contains it (self-contact, not supported), and the solve would fail for no reason
   the user could see */
static PetscErrorCode CheckDisjoint(SPContact c, PetscInt k)
{
  const SPPair *p = &c->pair[k];
  DMLabel       s, m;
  PetscInt      vStart, vEnd, shared = 0, sharedAll;

  PetscFunctionBeginUser;
  PetscCall(SPMeshCreateCompletedLabel(c->dm, p->label, p->nslave, p->slave, "spcontact_check_slave", &s));
  PetscCall(SPMeshCreateCompletedLabel(c->dm, p->label, p->nmaster, p->master, "spcontact_check_master", &m));
  PetscCall(DMPlexGetDepthStratum(c->dm, 0, &vStart, &vEnd));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt a, b;
    PetscCall(DMLabelGetValue(s, v, &a));
    if (a != 1) continue;
    PetscCall(DMLabelGetValue(m, v, &b));
    if (b == 1) shared++;
  }
  PetscCall(DMRemoveLabel(c->dm, "spcontact_check_slave", NULL));
  PetscCall(DMRemoveLabel(c->dm, "spcontact_check_master", NULL));
  PetscCallMPI(MPI_Allreduce(&shared, &sharedAll, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  PetscCheck(sharedAll == 0, PetscObjectComm((PetscObject)c->dm), PETSC_ERR_USER_INPUT, "contact pair %" PetscInt_FMT ": its slave and master surfaces (-contact_pair_%" PetscInt_FMT "_slave_values, _master_values) share vertices; self-contact is not supported: give the pair the surfaces of two separate bodies", k, k);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Every pair's label and values exist and are not empty, and its two surfaces are disjoint */
PetscErrorCode SPContactPairsCheckLabels(SPContact c)
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < c->nuser; ++k) {
    char opt[64];
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-contact_pair_%" PetscInt_FMT "_slave_values", k));
    PetscCall(SPMeshCheckLabel(c->dm, c->pair[k].label, c->pair[k].nslave, c->pair[k].slave, opt));
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-contact_pair_%" PetscInt_FMT "_master_values", k));
    PetscCall(SPMeshCheckLabel(c->dm, c->pair[k].label, c->pair[k].nmaster, c->pair[k].master, opt));
    PetscCall(CheckDisjoint(c, k));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Global facet numbers, free ends (from a one-time gather of the whole table) and the margin */
static PetscErrorCode SetUpStatic(SPContact c)
{
  MPI_Comm       comm = PetscObjectComm((PetscObject)c->dm);
  PetscMPIInt    size, rank, mine = (PetscMPIInt)c->nmfOwned, *cnt, *dsp, *cb, *db;
  PetscReal      hmax = 0.0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMalloc4(size, &cnt, size + 1, &dsp, size, &cb, size, &db));
  PetscCallMPI(MPI_Allgather(&mine, 1, MPI_INT, cnt, 1, MPI_INT, comm));
  dsp[0] = 0;
  for (PetscMPIInt r = 0; r < size; ++r) dsp[r + 1] = dsp[r] + cnt[r];
  c->nmfAll  = dsp[size];
  c->mfStart = dsp[rank];
  PetscCheck(c->nmfAll > 0, comm, PETSC_ERR_USER_INPUT, "contact pairs: the master surfaces have no facets");
  for (PetscInt j = 0; j < c->nmfOwned; ++j) c->own[j].gid = c->mfStart + j;
  c->nmf = c->mfCap = c->nmfAll;
  PetscCall(PetscCalloc1(c->mfCap, &c->mf));
  for (PetscMPIInt r = 0; r < size; ++r) cb[r] = cnt[r] * (PetscMPIInt)sizeof(SPMasterFacet), db[r] = dsp[r] * (PetscMPIInt)sizeof(SPMasterFacet);
  PetscCallMPI(MPI_Allgatherv(c->own, mine * (PetscMPIInt)sizeof(SPMasterFacet), MPI_BYTE, c->mf, cb, db, MPI_BYTE, comm));
  PetscCall(MarkFreeSides(c));
  for (PetscInt j = 0; j < c->nmfOwned; ++j) c->own[j] = c->mf[c->mfStart + j];
  PetscCall(PetscMalloc1(c->nmfAll, &c->mfKey));
  for (PetscInt g = 0; g < c->nmfAll; ++g) c->mfKey[g] = c->mf[g].sid * 2 * SP_MAX_PAIRS + c->mf[g].pair;
  for (PetscInt f = 0; f < c->nmf; ++f) {
    const SPMasterFacet *m = &c->mf[f];
    for (PetscInt a = 0; a < m->nv; ++a) {
      const PetscInt b = (a + 1) % m->nv;
      PetscReal      t[3];
      for (PetscInt k = 0; k < c->dim; ++k) t[k] = m->X[b * c->dim + k] - m->X[a * c->dim + k];
      hmax = PetscMax(hmax, SPNorm(c->dim, t));
    }
  }
  for (PetscInt i = 0; i < c->n; ++i) hmax = PetscMax(hmax, c->pt[i].h);
  PetscCallMPI(MPI_Allreduce(&hmax, &c->margin, 1, MPIU_REAL, MPI_MAX, comm));
  c->margin *= 2.0;
  PetscCall(PetscFree4(cnt, dsp, cb, db));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One warning per pair whose slave surface is more than 100x stiffer than its master: the soft
   master's facets sag between the stiff slave's nodes (node-to-segment checks slave nodes only),
   and eps sized for the stiff side over-stiffens the soft one (QA helper 28: B2's bodies with E
   1e6 on the slave and 1 on the master, 20 cut-backs in 100 s; swapped, 8 Newton iterations).
   Collective. */
static PetscErrorCode WarnStiffSlave(SPContact c)
{
  PetscReal E[2 * SP_MAX_PAIRS], all[2 * SP_MAX_PAIRS];

  PetscFunctionBeginUser;
  if (c->twoPass) PetscFunctionReturn(PETSC_SUCCESS); /* each surface is a slave anyway */
  for (PetscInt k = 0; k < c->npair; ++k) E[2 * k] = 0.0, E[2 * k + 1] = -PETSC_MAX_REAL; /* max slave E, -(min master E) */
  for (PetscInt i = 0; i < c->n; ++i)
    for (PetscInt k = 0; k < c->npair; ++k) {
      PetscReal Ev;
      if (!(c->pt[i].pairMask & ((PetscInt)1 << k))) continue;
      PetscCall(SPProblemGetVertexYoung(c->problem, c->pt[i].vertex, &Ev));
      E[2 * k] = PetscMax(E[2 * k], Ev);
    }
  for (PetscInt j = 0; j < c->nmfOwned; ++j)
    for (PetscInt a = 0; a < c->own[j].nv; ++a) {
      PetscReal Ev;
      PetscCall(SPProblemGetVertexYoung(c->problem, c->mfVert[j * SP_FACET_MAXV + a], &Ev));
      E[2 * c->own[j].pair + 1] = PetscMax(E[2 * c->own[j].pair + 1], -Ev);
    }
  PetscCallMPI(MPI_Allreduce(E, all, (PetscMPIInt)(2 * c->npair), MPIU_REAL, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  for (PetscInt k = 0; k < c->npair; ++k)
    if (all[2 * k + 1] > -PETSC_MAX_REAL && all[2 * k] > 100.0 * -all[2 * k + 1])
      PetscCall(PetscFPrintf(PetscObjectComm((PetscObject)c->dm), PETSC_STDERR, "spcontact: warning: contact pair %" PetscInt_FMT ": its slave surface is %.3g times stiffer than its master (E %.6g against %.6g): the soft master sags between the stiff slave's nodes and the solve can cut back to its floor; swap -contact_pair_%" PetscInt_FMT "_slave_values and -contact_pair_%" PetscInt_FMT "_master_values (the slave on the softer body)\n", k, (double)(all[2 * k] / -all[2 * k + 1]), (double)all[2 * k], (double)-all[2 * k + 1], k, k));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* With alpha (not an absolute penalty), a pair's slave points take eps = alpha E / h with E the
   larger of their own material's and the stiffest material on the pair's master surface: the two
   sides of a contact then get the same scale (with two passes both passes contract alike; with the
   slave's own E alone the mirrored pass on a 10x softer body contracted 10x slower). One material:
   no change. */
static PetscErrorCode PairPenalties(SPContact c)
{
  PetscReal Em[2 * SP_MAX_PAIRS] = {0}, Eall[2 * SP_MAX_PAIRS];

  PetscFunctionBeginUser;
  PetscCall(WarnStiffSlave(c));
  if (c->penalty > 0.0) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt j = 0; j < c->nmfOwned; ++j)
    for (PetscInt a = 0; a < c->own[j].nv; ++a) {
      PetscReal E;
      PetscCall(SPProblemGetVertexYoung(c->problem, c->mfVert[j * SP_FACET_MAXV + a], &E));
      Em[c->own[j].pair] = PetscMax(Em[c->own[j].pair], E);
    }
  PetscCallMPI(MPI_Allreduce(Em, Eall, (PetscMPIInt)c->npair, MPIU_REAL, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  for (PetscInt i = 0; i < c->n; ++i) {
    SPContactPoint *pt = &c->pt[i];
    PetscReal       E  = pt->eps * pt->h / c->alpha;
    for (PetscInt k = 0; k < c->npair; ++k)
      if (pt->pairMask & ((PetscInt)1 << k)) E = PetscMax(E, Eall[k]);
    pt->eps = c->alpha * E / pt->h;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactPairsSetUp(SPContact c)
{
  PetscFunctionBeginUser;
  if (!c->npair) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(OwnedFacets(c, &c->nmfOwned, &c->own, &c->mfVert));
  PetscCall(SetUpStatic(c));
  PetscCall(PairPenalties(c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* This rank's slave bounding box (deformed), inflated by the margin; empty: lo > hi */
static void SlaveBox(SPContact c, PetscReal box[])
{
  const PetscInt dim = c->dim;
  for (PetscInt d = 0; d < dim; ++d) box[d] = PETSC_MAX_REAL, box[dim + d] = -PETSC_MAX_REAL;
  for (PetscInt i = 0; i < c->n; ++i) {
    if (!c->pt[i].pairMask) continue;
    for (PetscInt d = 0; d < dim; ++d) {
      box[d]       = PetscMin(box[d], c->pt[i].geo.x[d] - c->margin);
      box[dim + d] = PetscMax(box[dim + d], c->pt[i].geo.x[d] + c->margin);
    }
  }
}

static PetscBool FacetMeets(const SPMasterFacet *m, PetscInt dim, const PetscReal box[])
{
  for (PetscInt d = 0; d < dim; ++d) {
    PetscReal lo = PETSC_MAX_REAL, hi = -PETSC_MAX_REAL;
    for (PetscInt a = 0; a < m->nv; ++a) lo = PetscMin(lo, m->x[a * dim + d]), hi = PetscMax(hi, m->x[a * dim + d]);
    if (hi < box[d] || lo > box[dim + d]) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

/* Deformed master geometry at the local displacement u: each rank sends its owned master facets to
   every rank whose slave bounding box (inflated by the margin) they meet, or to every rank with
   -contact_pair_exchange all. Needs the points' deformed positions (geo.x) of the current state. Collective. */
PetscErrorCode SPContactPairsExchange(SPContact c, const PetscScalar u[])
{
  MPI_Comm       comm = PetscObjectComm((PetscObject)c->dm);
  const PetscInt dim  = c->dim, sz = (PetscInt)sizeof(SPMasterFacet);
  PetscMPIInt    size, *scnt, *sdsp, *rcnt, *rdsp;
  PetscReal      box[6], *boxes;
  PetscSection   ls;
  SPMasterFacet *send;
  PetscInt       nsend = 0, nrecv = 0;
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(&t0));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(DMGetLocalSection(c->dm, &ls));
  for (PetscInt j = 0; j < c->nmfOwned; ++j) {
    SPMasterFacet *m = &c->own[j];
    for (PetscInt a = 0; a < m->nv; ++a) {
      PetscInt off;
      PetscCall(PetscSectionGetOffset(ls, c->mfVert[j * SP_FACET_MAXV + a], &off));
      for (PetscInt d = 0; d < dim; ++d) m->u[a * dim + d] = PetscRealPart(u[off + d]), m->x[a * dim + d] = m->X[a * dim + d] + m->u[a * dim + d];
    }
  }
  SlaveBox(c, box);
  PetscCall(PetscMalloc5(size * 2 * dim, &boxes, size, &scnt, size + 1, &sdsp, size, &rcnt, size + 1, &rdsp));
  PetscCallMPI(MPI_Allgather(box, (PetscMPIInt)(2 * dim), MPIU_REAL, boxes, (PetscMPIInt)(2 * dim), MPIU_REAL, comm));
  for (PetscMPIInt r = 0; r < size; ++r) {
    scnt[r] = 0;
    for (PetscInt j = 0; j < c->nmfOwned; ++j)
      if (c->exchangeAll || FacetMeets(&c->own[j], dim, &boxes[r * 2 * dim])) scnt[r]++;
    nsend += scnt[r];
  }
  PetscCall(PetscMalloc1(nsend + 1, &send));
  sdsp[0] = 0;
  for (PetscMPIInt r = 0; r < size; ++r) {
    PetscInt k = sdsp[r];
    for (PetscInt j = 0; j < c->nmfOwned; ++j)
      if (c->exchangeAll || FacetMeets(&c->own[j], dim, &boxes[r * 2 * dim])) send[k++] = c->own[j];
    sdsp[r + 1] = (PetscMPIInt)k;
  }
  PetscCallMPI(MPI_Alltoall(scnt, 1, MPI_INT, rcnt, 1, MPI_INT, comm));
  rdsp[0] = 0;
  for (PetscMPIInt r = 0; r < size; ++r) rdsp[r + 1] = rdsp[r] + rcnt[r];
  nrecv = rdsp[size];
  if (nrecv > c->mfCap) {
    PetscCall(PetscFree(c->mf));
    c->mfCap = nrecv;
    PetscCall(PetscMalloc1(c->mfCap, &c->mf));
  }
  for (PetscMPIInt r = 0; r < size; ++r) scnt[r] *= (PetscMPIInt)sz, sdsp[r] *= (PetscMPIInt)sz, rcnt[r] *= (PetscMPIInt)sz, rdsp[r] *= (PetscMPIInt)sz;
  PetscCallMPI(MPI_Alltoallv(send, scnt, sdsp, MPI_BYTE, c->mf, rcnt, rdsp, MPI_BYTE, comm));
  c->nmf = nrecv;
  PetscCall(PetscFree(send));
  PetscCall(PetscFree5(boxes, scnt, sdsp, rcnt, rdsp));
  PetscCall(PetscTime(&t1));
  c->exchangeTime += t1 - t0;
  c->exchanges++;
  c->received += nrecv;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Is candidate (d, excess, facet f) better than the current best (db, eb, fb)? */
static PetscBool Better(const SPContact c, PetscReal d, PetscReal e, PetscInt f, PetscReal db, PetscReal eb, PetscInt fb)
{
  const PetscReal tol = 1e-10 * (1.0 + db);
  if (fb < 0 || d < db - tol) return PETSC_TRUE;
  if (d > db + tol) return PETSC_FALSE;
  if (e < eb - 1e-12) return PETSC_TRUE;
  if (e > eb + 1e-12) return PETSC_FALSE;
  for (PetscInt k = 0; k < c->dim; ++k) { /* reference vertex sums (centroids), lexicographic */
    PetscReal mf = 0.0, mb = 0.0;
    for (PetscInt a = 0; a < c->mf[f].nv; ++a) mf += c->mf[f].X[a * c->dim + k];
    for (PetscInt a = 0; a < c->mf[fb].nv; ++a) mb += c->mf[fb].X[a * c->dim + k];
    if (c->mf[f].nv == c->mf[fb].nv && mf != mb) return mf < mb ? PETSC_TRUE : PETSC_FALSE;
    if (c->mf[f].nv != c->mf[fb].nv && mf / c->mf[f].nv != mb / c->mf[fb].nv) return mf / c->mf[f].nv < mb / c->mf[fb].nv ? PETSC_TRUE : PETSC_FALSE;
  }
  return PETSC_FALSE;
}

/* Lower bound of the distance from x to facet m (its deformed bounding box) */
static PetscReal BoxDistance(const SPMasterFacet *m, PetscInt dim, const PetscReal x[])
{
  PetscReal d2 = 0.0;
  for (PetscInt k = 0; k < dim; ++k) {
    PetscReal lo = PETSC_MAX_REAL, hi = -PETSC_MAX_REAL, e;
    for (PetscInt a = 0; a < m->nv; ++a) lo = PetscMin(lo, m->x[a * dim + k]), hi = PetscMax(hi, m->x[a * dim + k]);
    e = x[k] < lo ? lo - x[k] : (x[k] > hi ? x[k] - hi : 0.0);
    d2 += e * e;
  }
  return PetscSqrtReal(d2);
}

/* At a Newton boundary: each point's facet at the evaluated iterate becomes the facet it keeps near
   a vertex (the hysteresis at the top) */
void SPContactPairsKeepFacets(SPContact c)
{
  for (PetscInt i = 0; i < c->n; ++i) {
    SPContactPoint *pt  = &c->pt[i];
    const PetscInt  gid = pt->geo.elem >= 0 ? c->mf[pt->geo.elem].gid : -1;
    if (gid == pt->keepFacet) continue;
    if (gid >= 0 && gid == pt->lastFacet) pt->facetReturns++;
    pt->lastFacet = pt->keepFacet;
    pt->keepFacet = gid;
  }
}

/* A new load step, or a cut-back: no facet kept */
void SPContactPairsForgetFacets(SPContactPoint *pt)
{
  pt->keepFacet = pt->lastFacet = -1;
  pt->facetReturns = 0;
}

/* Closest-point projection of point i (deformed position geo.x) onto the master facets of its
   pairs: facet (or SP_ELEM_NONE), parameter, gap and normal (see the rule at the top) */
PetscErrorCode SPContactPairsProject(SPContact c, PetscInt i, PetscInt *facet, PetscReal *xi, PetscReal *g, PetscReal n[])
{
  const PetscReal *x = c->pt[i].geo.x;
  PetscInt         best = -1, kept = -1;
  PetscReal        db = 0.0, eb = 0.0, xb[2] = {0.0, 0.0}, dk = 0.0, xk[2] = {0.0, 0.0};

  PetscFunctionBeginUser;
  *facet = SP_ELEM_NONE;
  for (PetscInt f = 0; f < c->nmf; ++f) {
    const SPMasterFacet *m = &c->mf[f];
    PetscReal            t[2], d, e;
    PetscBool            keep = m->gid == c->pt[i].keepFacet ? PETSC_TRUE : PETSC_FALSE;
    if (!(c->pt[i].pairMask & ((PetscInt)1 << m->pair))) continue;
    if (!keep && best >= 0 && BoxDistance(m, c->dim, x) > db + 1e-9 * (1.0 + db)) continue; /* cannot win (Better's tolerance is 1e-10) */
    if (!SPPairCandidate(c->dim, m->nv, m->x, x, t, &d, &e)) continue;
    if (keep && e <= SP_PAIR_END_TOL) kept = f, dk = d, xk[0] = t[0], xk[1] = t[1];
    if (Better(c, d, e, f, db, eb, best)) best = f, db = d, eb = e, xb[0] = t[0], xb[1] = t[1];
  }
  if (best < 0) PetscFunctionReturn(PETSC_SUCCESS);
  if (kept >= 0 && kept != best && dk <= db + (c->pt[i].facetReturns >= SP_PAIR_RETURNS ? SP_PAIR_KEEP_WIDE : SP_PAIR_KEEP_RTOL) * c->pt[i].h) best = kept, xb[0] = xk[0], xb[1] = xk[1];
  for (PetscInt s = 0; s < c->mf[best].nv; ++s)
    if (c->mf[best].freeSide[s] && SPPairBeyond(c->dim, c->mf[best].nv, xb, s) > SP_PAIR_END_TOL) PetscFunctionReturn(PETSC_SUCCESS);
  {
    PetscReal N[3 * (1 + SP_FACET_MAXV)];
    SPPairGap(c->dim, c->mf[best].nv, c->mf[best].x, x, xb, g, n, N, NULL);
  }
  xi[0]  = xb[0];
  xi[1]  = xb[1];
  *facet = best;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactPairsDestroy(SPContact c)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(c->mf));
  PetscCall(PetscFree(c->mfKey));
  PetscCall(PetscFree(c->own));
  PetscCall(PetscFree(c->mfVert));
  PetscFunctionReturn(PETSC_SUCCESS);
}
