/* Fast bulk operator: element-level isotropic elasticity on first-order cells (P1/Q1, any cell
   type, 2D and 3D through dim). A nonlinear law (finite strain) goes through its pointwise stress
   and tangent (SPMaterialLaw.stress/tangent): r_e = sum_q w detJ G^T P(F_q), K_e = sum_q w detJ
   G^T A(F_q) G, F_q = I + sum_a u_a G_a. For the linear law: Per cell K_e = sum_q w detJ B^T D B with the structure written
   out (kernels/elastic.h) and the cell's own Lame constants (the problem's per-cell material
   parameters, so region materials are honoured), inserted with the closure indices that PETSc's own assembly uses, so the
   matrix is the generic PetscFE one to round-off: constrained (Dirichlet) dofs carry negative
   indices and MatSetValues drops them; the global system has no rows for them at all.
   The residual is r_e = K_e u_e (exact for a linear material) plus PETSc's boundary residual for the
   Neumann conditions. Everything else (other degrees, manufactured solutions, laws without the
   fast operator (SPMaterialLaw.fastOperator), mixed cell types) stays on the PetscFE path. */
#include <spcontact-impl.h>
#include <kernels/elastic.h>

/* The scalar reference gradients of the vector FE, when its basis is "scalar basis x unit vector"
   ordered node-major (b = a * dim + c, as the closure dofs). Otherwise *ok = false. */
static PetscErrorCode ScalarGradients(SPFastElastic f, PetscFE fe, PetscBool *ok)
{
  PetscTabulation T;
  PetscInt        Nb, Nc, dim = f->dim;

  PetscFunctionBeginUser;
  PetscCall(PetscFEGetCellTabulation(fe, 1, &T));
  Nb = T->Nb;
  Nc = T->Nc;
  *ok = (Nc == dim && Nb % dim == 0 && T->cdim == dim && T->Np == f->nq) ? PETSC_TRUE : PETSC_FALSE;
  if (!*ok) PetscFunctionReturn(PETSC_SUCCESS);
  f->nb = Nb / dim;
  PetscCall(PetscMalloc1(f->nq * f->nb * dim, &f->dN));
  for (PetscInt q = 0; q < f->nq; ++q)
    for (PetscInt b = 0; b < Nb; ++b)
      for (PetscInt c = 0; c < Nc; ++c)
        for (PetscInt k = 0; k < dim; ++k) {
          const PetscReal v = T->T[1][((q * Nb + b) * Nc + c) * dim + k];
          const PetscInt  a = b / dim;
          if (c == b % dim) {
            if (b % dim == 0) f->dN[(q * f->nb + a) * dim + k] = v;
            else if (PetscAbsReal(v - f->dN[(q * f->nb + a) * dim + k]) > 1e-12) *ok = PETSC_FALSE;
          } else if (PetscAbsReal(v) > 1e-12) *ok = PETSC_FALSE;
        }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Per cell: the vertices in closure order (the FE basis order), their global and local dof
   indices, and their coordinates. Built from one transitive closure per cell; the indices are
   checked against DMPlexGetClosureIndices on the first cells (closure permutations, layouts). */
static PetscErrorCode CacheCells(SPFastElastic f, PetscBool *ok)
{
  PetscSection       ls, gs, cs;
  Vec                coords;
  const PetscScalar *x;
  PetscInt           nc = f->cEnd - f->cStart, vStart, vEnd, dim = f->dim;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(f->dm, &ls));
  PetscCall(DMGetGlobalSection(f->dm, &gs));
  PetscCall(DMGetCoordinateSection(f->dm, &cs));
  PetscCall(DMGetCoordinatesLocal(f->dm, &coords));
  PetscCall(DMPlexGetDepthStratum(f->dm, 0, &vStart, &vEnd));
  PetscCall(PetscMalloc3(nc * f->nidx, &f->gidx, nc * f->nidx, &f->lidx, nc * f->nidx, &f->xc));
  PetscCall(VecGetArrayRead(coords, &x));
  for (PetscInt c = 0; c < nc && *ok; ++c) {
    PetscInt *pts = NULL, npts, a = 0;
    PetscCall(DMPlexGetTransitiveClosure(f->dm, f->cStart + c, PETSC_TRUE, &npts, &pts));
    for (PetscInt p = 0; p < npts && *ok; ++p) {
      const PetscInt v = pts[2 * p];
      PetscInt       off, coff, dof, cdof;
      if (v < vStart || v >= vEnd) continue;
      PetscCall(PetscSectionGetDof(ls, v, &dof));
      PetscCall(PetscSectionGetDof(cs, v, &cdof));
      PetscCall(PetscSectionGetOffset(cs, v, &coff));
      if (a >= f->nb || dof != dim || cdof != dim) {
        *ok = PETSC_FALSE;
        break;
      }
      PetscCall(PetscSectionGetOffset(ls, v, &off));
      PetscCall(SPVertexGlobalIndices(ls, gs, v, dim, &f->gidx[c * f->nidx + a * dim]));
      for (PetscInt i = 0; i < dim; ++i) {
        f->lidx[c * f->nidx + a * dim + i] = off + i;
        f->xc[c * f->nidx + a * dim + i]   = PetscRealPart(x[coff + i]);
      }
      a++;
    }
    PetscCall(DMPlexRestoreTransitiveClosure(f->dm, f->cStart + c, PETSC_TRUE, &npts, &pts));
    if (a != f->nb) *ok = PETSC_FALSE;
  }
  PetscCall(VecRestoreArrayRead(coords, &x));
  for (PetscInt c = 0; c < PetscMin(nc, 8) && *ok; ++c) {
    PetscInt *idx = NULL, n;
    PetscCall(DMPlexGetClosureIndices(f->dm, ls, gs, f->cStart + c, PETSC_TRUE, &n, &idx, NULL, NULL));
    for (PetscInt k = 0; k < n && *ok; ++k)
      if (n != f->nidx || (idx[k] != f->gidx[c * f->nidx + k] && (idx[k] >= 0 || f->gidx[c * f->nidx + k] >= 0))) *ok = PETSC_FALSE;
    PetscCall(DMPlexRestoreClosureIndices(f->dm, ls, gs, f->cStart + c, PETSC_TRUE, &n, &idx, NULL, NULL));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One cell type on this rank: the FE tabulation describes every cell */
static PetscErrorCode SingleCellType(DM dm, PetscInt cStart, PetscInt cEnd, PetscBool *ok)
{
  DMPolytopeType ct0, ct;

  PetscFunctionBeginUser;
  *ok = PETSC_TRUE;
  if (cEnd <= cStart) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(DMPlexGetCellType(dm, cStart, &ct0));
  for (PetscInt c = cStart + 1; c < cEnd && *ok; ++c) {
    PetscCall(DMPlexGetCellType(dm, c, &ct));
    if (ct != ct0) *ok = PETSC_FALSE;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* detJ and the inverse of a dim x dim matrix (dim = 1, 2, 3) */
static void Invert(PetscInt dim, const PetscReal J[], PetscReal invJ[], PetscReal *detJ)
{
  if (dim == 1) {
    *detJ   = J[0];
    invJ[0] = 1.0 / J[0];
  } else if (dim == 2) {
    *detJ   = J[0] * J[3] - J[1] * J[2];
    invJ[0] = J[3] / *detJ, invJ[1] = -J[1] / *detJ, invJ[2] = -J[2] / *detJ, invJ[3] = J[0] / *detJ;
  } else {
    invJ[0] = J[4] * J[8] - J[5] * J[7], invJ[1] = J[2] * J[7] - J[1] * J[8], invJ[2] = J[1] * J[5] - J[2] * J[4];
    invJ[3] = J[5] * J[6] - J[3] * J[8], invJ[4] = J[0] * J[8] - J[2] * J[6], invJ[5] = J[2] * J[3] - J[0] * J[5];
    invJ[6] = J[3] * J[7] - J[4] * J[6], invJ[7] = J[1] * J[6] - J[0] * J[7], invJ[8] = J[0] * J[4] - J[1] * J[3];
    *detJ = J[0] * invJ[0] + J[1] * invJ[3] + J[2] * invJ[6];
    for (PetscInt k = 0; k < 9; ++k) invJ[k] /= *detJ;
  }
}

/* Physical gradients G and weights w detJ at the quadrature points of a cell with node coordinates
   xc (closure order): the isoparametric map x = sum_a x_a N_a, J_ik = sum_a x_a,i dN_a/dxi_k
   (exact for straight-sided P1/Q1 cells, i.e. PETSc's affine/multilinear geometry). */
static void CellGradients(SPFastElastic f, const PetscScalar xc[], PetscReal G[], PetscReal wdetJ[])
{
  const PetscInt dim = f->dim, nb = f->nb;
  PetscReal      J[9], invJ[9], detJ;

  for (PetscInt q = 0; q < f->nq; ++q) {
    const PetscReal *dNq = &f->dN[q * nb * dim];
    for (PetscInt k = 0; k < dim * dim; ++k) J[k] = 0.0;
    for (PetscInt a = 0; a < nb; ++a)
      for (PetscInt i = 0; i < dim; ++i)
        for (PetscInt k = 0; k < dim; ++k) J[i * dim + k] += PetscRealPart(xc[a * dim + i]) * dNq[a * dim + k];
    Invert(dim, J, invJ, &detJ);
    wdetJ[q] = f->w[q] * detJ; /* PETSc integrates with detJ itself */
    for (PetscInt a = 0; a < nb; ++a)
      for (PetscInt d = 0; d < dim; ++d) {
        PetscReal g = 0.0;
        for (PetscInt e = 0; e < dim; ++e) g += dNq[a * dim + e] * invJ[e * dim + d];
        G[(q * nb + a) * dim + d] = g;
      }
  }
}

/* K_e of local cell c (0-based), with its own Lame constants */
static void CellStiffness(SPFastElastic f, PetscInt c, PetscReal G[], PetscReal wdetJ[], PetscScalar K[])
{
  CellGradients(f, &f->xc[c * f->nidx], G, wdetJ);
  SPElasticElementStiffness(f->dim, f->nb, f->nq, G, wdetJ, f->lame[c * SP_LAW_NPARAM + SP_A_LAMBDA], f->lame[c * SP_LAW_NPARAM + SP_A_MU], K);
}

/* K += w G_a,J A_iJkL G_b,L for the node pairs b >= a, contracted in two passes (H_a,ikL =
   A_iJkL G_a,J, then H G_b): a sixth of the multiplications of the direct four-index sum over
   all pairs at 8 nodes in 3D. MirrorTangent fills b < a: the laws are hyperelastic (A_iJkL =
   A_kLiJ, A the second derivative of an energy), so K is symmetric */
static inline void AddTangent(const PetscInt dim, const PetscInt nb, const PetscReal Gq[], PetscReal w, const PetscScalar A[], PetscScalar K[])
{
  const PetscInt n = nb * dim;

  for (PetscInt a = 0; a < nb; ++a) {
    PetscReal wGa[3];
    for (PetscInt J = 0; J < dim; ++J) wGa[J] = w * Gq[a * dim + J];
    for (PetscInt i = 0; i < dim; ++i) {
      PetscScalar H[9] = {0}; /* H[k * dim + L] for this (a, i) */
      for (PetscInt k = 0; k < dim; ++k)
        for (PetscInt J = 0; J < dim; ++J)
          for (PetscInt L = 0; L < dim; ++L) H[k * dim + L] += wGa[J] * A[((i * dim + k) * dim + J) * dim + L];
      for (PetscInt b = a; b < nb; ++b)
        for (PetscInt k = 0; k < dim; ++k) {
          PetscScalar v = 0.0;
          for (PetscInt L = 0; L < dim; ++L) v += H[k * dim + L] * Gq[b * dim + L];
          K[(a * dim + i) * n + b * dim + k] += v;
        }
    }
  }
}

static void MirrorTangent(PetscInt dim, PetscInt nb, PetscScalar K[])
{
  const PetscInt n = nb * dim;

  for (PetscInt a = 0; a < nb; ++a)
    for (PetscInt b = a + 1; b < nb; ++b)
      for (PetscInt i = 0; i < dim; ++i)
        for (PetscInt k = 0; k < dim; ++k) K[(b * dim + k) * n + a * dim + i] = K[(a * dim + i) * n + b * dim + k];
}

/* A nonlinear law at local cell c with nodal displacements u (closure order): the residual r and,
   if K != NULL, the tangent K of the cell (w->work sized for one quadrature point) */
static void CellNonlinear(SPFastElastic f, PetscInt c, const PetscScalar u[], PetscReal G[], PetscReal wdetJ[], PetscScalar r[], PetscScalar K[])
{
  const PetscInt   dim = f->dim, nb = f->nb, n = f->nidx;
  const PetscReal *param = &f->lame[c * SP_LAW_NPARAM];
  PetscScalar      ux[9], P[9], A[81];

  CellGradients(f, &f->xc[c * n], G, wdetJ);
  for (PetscInt i = 0; i < n; ++i) r[i] = 0.0;
  if (K) for (PetscInt i = 0; i < n * n; ++i) K[i] = 0.0;
  for (PetscInt q = 0; q < f->nq; ++q) {
    const PetscReal *Gq = &G[q * nb * dim];
    for (PetscInt k = 0; k < dim * dim; ++k) ux[k] = 0.0;
    for (PetscInt a = 0; a < nb; ++a)
      for (PetscInt i = 0; i < dim; ++i)
        for (PetscInt J = 0; J < dim; ++J) ux[i * dim + J] += u[a * dim + i] * Gq[a * dim + J];
    f->law->stress(dim, param, ux, P);
    for (PetscInt a = 0; a < nb; ++a)
      for (PetscInt i = 0; i < dim; ++i)
        for (PetscInt J = 0; J < dim; ++J) r[a * dim + i] += wdetJ[q] * P[i * dim + J] * Gq[a * dim + J];
    if (!K) continue;
    f->law->tangent(dim, param, ux, A);
    /* Q1 hexes and P1 tets with constant trip counts (the compiler unrolls the loops) */
    if (dim == 3 && nb == 8) AddTangent(3, 8, Gq, wdetJ[q], A, K);
    else if (dim == 3 && nb == 4) AddTangent(3, 4, Gq, wdetJ[q], A, K);
    else AddTangent(dim, nb, Gq, wdetJ[q], A, K);
  }
  if (K) MirrorTangent(dim, nb, K);
}

/* The geometry above agrees with PETSc's on the first cells; otherwise the fast path does not apply */
static PetscErrorCode CheckGeometry(SPFastElastic f, PetscBool *ok)
{
  const PetscInt nq = f->nq, dim = f->dim;
  PetscReal     *v0, *J, *invJ, *detJ, *G, *wdetJ;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc6(nq * dim, &v0, nq * dim * dim, &J, nq * dim * dim, &invJ, nq, &detJ, nq * f->nb * dim, &G, nq, &wdetJ));
  for (PetscInt c = 0; c < PetscMin(f->cEnd - f->cStart, 8) && *ok; ++c) {
    PetscCall(DMPlexComputeCellGeometryFEM(f->dm, f->cStart + c, f->quad, v0, J, invJ, detJ));
    CellGradients(f, &f->xc[c * f->nidx], G, wdetJ);
    for (PetscInt q = 0; q < nq && *ok; ++q)
      if (PetscAbsReal(wdetJ[q] - f->w[q] * detJ[q]) > 1e-10 * PetscAbsReal(f->w[q] * detJ[q])) *ok = PETSC_FALSE;
  }
  PetscCall(PetscFree6(v0, J, invJ, detJ, G, wdetJ));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPFastElasticCreate(DM dm, SPProblem p, SPFastElastic *fast)
{
  SPFastElastic f;
  PetscDS       ds;
  PetscFE       fe;
  PetscInt      nf;
  PetscBool     ok, okAll, localized;

  PetscFunctionBeginUser;
  *fast = NULL;
  PetscCall(DMGetDS(dm, &ds));
  PetscCall(PetscDSGetNumFields(ds, &nf));
  ok = p->fastOperator && p->degree == 1 && p->mmsAmp == 0.0 && nf == 1 ? PETSC_TRUE : PETSC_FALSE;
  PetscCallMPI(MPI_Allreduce(&ok, &okAll, 1, MPIU_BOOL, MPI_LAND, PetscObjectComm((PetscObject)dm)));
  if (!okAll) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscNew(&f));
  f->dm = dm;
  PetscCall(DMGetDimension(dm, &f->dim));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &f->cStart, &f->cEnd));
  PetscCheck(f->cStart == p->cStart && f->cEnd == p->cEnd, PETSC_COMM_SELF, PETSC_ERR_PLIB, "fast operator and problem see different cells");
  f->lame = p->cellParam; /* lambda, mu per cell (SP_A_LAMBDA, SP_A_MU) */
  f->law  = p->mat[0].law;  /* every cell's (checked in problem.c) */
  PetscCall(PetscDSGetDiscretization(ds, 0, (PetscObject *)&fe));
  PetscCall(PetscFEGetQuadrature(fe, &f->quad));
  PetscCall(PetscQuadratureGetData(f->quad, NULL, NULL, &f->nq, NULL, &f->w));
  PetscCall(SingleCellType(dm, f->cStart, f->cEnd, &ok));
  if (ok) PetscCall(ScalarGradients(f, fe, &ok));
  f->nidx = f->nb * f->dim;
  if (ok) PetscCall(DMGetCoordinatesLocalized(dm, &localized));
  if (ok && localized) ok = PETSC_FALSE; /* periodic meshes: cell coordinates, not handled here */
  if (ok) PetscCall(CacheCells(f, &ok));
  if (ok) PetscCall(CheckGeometry(f, &ok));
  PetscCallMPI(MPI_Allreduce(&ok, &okAll, 1, MPIU_BOOL, MPI_LAND, PetscObjectComm((PetscObject)dm)));
  if (okAll) *fast = f;
  else PetscCall(SPFastElasticDestroy(&f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Work space of one cell */
typedef struct {
  PetscReal   *G, *wdetJ;
  PetscScalar *K, *u, *r;
} Work;

static PetscErrorCode WorkGet(SPFastElastic f, Work *w)
{
  const PetscInt nq = f->nq, dim = f->dim, n = f->nidx;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc5(nq * f->nb * dim, &w->G, nq, &w->wdetJ, n * n, &w->K, n, &w->u, n, &w->r));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WorkRestore(Work *w)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree5(w->G, w->wdetJ, w->K, w->u, w->r));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The natural boundaries (Neumann and pressure terms) of the DS, exactly as PETSc adds them: into
   P their Jacobians (follower pressure: its load stiffness), or into locF their residuals per
   value (the other one NULL) */
static PetscErrorCode AddBoundary(SPFastElastic f, Vec locX, Mat P, Vec locF)
{
  PetscDS  ds;
  PetscInt nbd;

  PetscFunctionBeginUser;
  PetscCall(DMGetDS(f->dm, &ds));
  PetscCall(PetscDSGetNumBoundary(ds, &nbd));
  for (PetscInt b = 0; b < nbd; ++b) {
    PetscWeakForm           wf;
    DMBoundaryConditionType type;
    DMLabel                 label;
    const PetscInt         *values;
    PetscInt                nv, field;
    PetscBool               has = PETSC_FALSE;
    PetscCall(PetscDSGetBoundary(ds, b, &wf, &type, NULL, &label, &nv, &values, &field, NULL, NULL, NULL, NULL, NULL));
    if (type & DM_BC_ESSENTIAL) continue;
    if (P) PetscCall(PetscWeakFormHasBdJacobian(wf, &has));
    if (has) PetscCall(DMPlexComputeBdJacobianSingle(f->dm, PETSC_MIN_REAL, wf, label, nv, values, field, locX, NULL, 0.0, P, P));
    for (PetscInt v = 0; v < nv && locF; ++v) {
      PetscFormKey key = {label, values[v], field, 0};
      PetscCall(DMPlexComputeBdResidualSingle(f->dm, PETSC_MIN_REAL, wf, key, locX, NULL, locF));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* P += K (the bulk stiffness at locX; the linear law ignores locX) and the boundary Jacobians,
   then final assembly */
PetscErrorCode SPFastElasticAddJacobian(SPFastElastic f, Vec locX, Mat P)
{
  Work               w;
  const PetscScalar *x;

  PetscFunctionBeginUser;
  PetscCall(WorkGet(f, &w));
  PetscCall(VecGetArrayRead(locX, &x));
  for (PetscInt c = f->cStart; c < f->cEnd; ++c) {
    const PetscInt *idx = &f->gidx[(c - f->cStart) * f->nidx], *lidx = &f->lidx[(c - f->cStart) * f->nidx];
    if (f->law->linear) CellStiffness(f, c - f->cStart, w.G, w.wdetJ, w.K);
    else {
      for (PetscInt k = 0; k < f->nidx; ++k) w.u[k] = x[lidx[k]];
      CellNonlinear(f, c - f->cStart, w.u, w.G, w.wdetJ, w.r, w.K);
    }
    PetscCall(MatSetValues(P, f->nidx, idx, f->nidx, idx, w.K, ADD_VALUES)); /* negative (constrained) indices are skipped */
  }
  PetscCall(VecRestoreArrayRead(locX, &x));
  PetscCall(WorkRestore(&w));
  PetscCall(AddBoundary(f, locX, P, NULL));
  PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* locF += r(locX): r_e = K_e u_e per cell for the linear law, the law's stress integrated otherwise
   (u_e holds the Dirichlet values), plus the Neumann terms */
PetscErrorCode SPFastElasticAddResidual(SPFastElastic f, Vec locX, Vec locF)
{
  Work               w;
  const PetscScalar *x;
  PetscScalar       *y;
  const PetscInt     n = f->nidx;

  PetscFunctionBeginUser;
  PetscCall(WorkGet(f, &w));
  PetscCall(VecGetArrayRead(locX, &x));
  PetscCall(VecGetArray(locF, &y));
  for (PetscInt c = f->cStart; c < f->cEnd; ++c) {
    const PetscInt *idx = &f->lidx[(c - f->cStart) * n];
    for (PetscInt k = 0; k < n; ++k) w.u[k] = x[idx[k]];
    if (f->law->linear) {
      CellStiffness(f, c - f->cStart, w.G, w.wdetJ, w.K);
      for (PetscInt i = 0; i < n; ++i) {
        w.r[i] = 0.0;
        for (PetscInt k = 0; k < n; ++k) w.r[i] += w.K[i * n + k] * w.u[k];
      }
    } else CellNonlinear(f, c - f->cStart, w.u, w.G, w.wdetJ, w.r, NULL);
    for (PetscInt i = 0; i < n; ++i) y[idx[i]] += w.r[i];
  }
  PetscCall(VecRestoreArray(locF, &y));
  PetscCall(VecRestoreArrayRead(locX, &x));
  PetscCall(WorkRestore(&w));
  PetscCall(AddBoundary(f, locX, NULL, locF));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPFastElasticDestroy(SPFastElastic *fast)
{
  PetscFunctionBeginUser;
  if (!*fast) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree((*fast)->dN));
  PetscCall(PetscFree3((*fast)->gidx, (*fast)->lidx, (*fast)->xc));
  PetscCall(PetscFree(*fast));
  PetscFunctionReturn(PETSC_SUCCESS);
}
