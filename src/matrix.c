/* The system matrix: creation and preallocation. For a first-order layout (every dof on a vertex,
   P1/Q1) the sparsity is vertex adjacency through cells, built here directly: each rank lists the
   neighbours of its local vertices, ghost vertices send their lists to the owner (PetscSFGather),
   and the owner counts the unconstrained dofs of the union, split into diagonal/off-diagonal
   blocks. The pattern is then fixed by inserting a zero row per owned dof with the union as its
   columns (DMCreateMatrix inserts zero cell blocks, rows of other ranks included), so the result
   is the same matrix (same nonzeros, block size, local-to-global map, DM) at a fraction of the
   cost. Contact-pair couplings are added later by contact-pattern.c. Every other
   layout (P2/Q2, several fields) goes through DMCreateMatrix. */
#include <spcontact-impl.h>

/* Global index of component i of vertex v, as DMPlexGetClosureIndices gives it: constrained
   components negative, the others numbered consecutively from the (owner's) global offset */
PetscErrorCode SPVertexGlobalIndices(PetscSection ls, PetscSection gs, PetscInt v, PetscInt dim, PetscInt idx[])
{
  PetscInt        goff, ncon, k = 0, j = 0;
  const PetscInt *cind = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscSectionGetOffset(gs, v, &goff));
  if (goff < 0) goff = -(goff + 1);
  PetscCall(PetscSectionGetConstraintDof(ls, v, &ncon));
  if (ncon) PetscCall(PetscSectionGetConstraintIndices(ls, v, &cind));
  for (PetscInt i = 0; i < dim; ++i) {
    if (j < ncon && cind[j] == i) idx[i] = -(goff + i + 1), ++j;
    else idx[i] = goff + k++;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Vertex adjacency of the local mesh. A vertex is coded as 4 g + n: g the global offset of its
   dofs (the owner's), n its number of unconstrained dofs (<= 3), so a neighbour list carries the
   owner's column indices g .. g + n - 1, and sorted codes give sorted columns. */
typedef struct {
  PetscInt    vStart, vEnd, cStart, cEnd, dim;
  PetscInt   *cellOff, *cellVert; /* CSR: local vertices of each cell */
  PetscInt   *vOff, *vCell;       /* CSR: cells of each vertex */
  PetscInt64 *code;               /* code of each local vertex */
  PetscInt    maxNbr;             /* bound on the neighbour list length (with repeats) */
} Graph;

static PetscErrorCode GraphCreate(DM dm, Graph *g)
{
  PetscSection ls, gs;
  PetscInt     nv, nc, verts[64], n, *cnt, *bound;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &g->dim));
  PetscCall(DMGetLocalSection(dm, &ls));
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &g->vStart, &g->vEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &g->cStart, &g->cEnd));
  nv = g->vEnd - g->vStart;
  nc = g->cEnd - g->cStart;
  /* vertex codes */
  PetscCall(PetscMalloc1(nv, &g->code));
  for (PetscInt v = 0; v < nv; ++v) {
    PetscInt dof, cdof, goff;
    PetscCall(PetscSectionGetDof(ls, g->vStart + v, &dof));
    PetscCall(PetscSectionGetConstraintDof(ls, g->vStart + v, &cdof));
    PetscCall(PetscSectionGetOffset(gs, g->vStart + v, &goff));
    if (goff < 0) goff = -(goff + 1);
    g->code[v] = 4 * (PetscInt64)goff + (dof - cdof);
  }
  /* cells -> vertices */
  PetscCall(PetscMalloc1(nc + 1, &g->cellOff));
  g->cellOff[0] = 0;
  for (PetscInt c = 0; c < nc; ++c) {
    PetscCall(SPMeshPointVertices(dm, g->cStart + c, g->vStart, g->vEnd, &n, verts, 64));
    g->cellOff[c + 1] = g->cellOff[c] + n;
  }
  PetscCall(PetscMalloc1(g->cellOff[nc], &g->cellVert));
  for (PetscInt c = 0; c < nc; ++c) {
    PetscCall(SPMeshPointVertices(dm, g->cStart + c, g->vStart, g->vEnd, &n, verts, 64));
    for (PetscInt k = 0; k < n; ++k) g->cellVert[g->cellOff[c] + k] = verts[k] - g->vStart;
  }
  /* vertices -> cells */
  PetscCall(PetscCalloc1(nv + 1, &g->vOff));
  PetscCall(PetscCalloc2(nv, &cnt, nv, &bound));
  for (PetscInt c = 0; c < nc; ++c)
    for (PetscInt k = g->cellOff[c]; k < g->cellOff[c + 1]; ++k) {
      g->vOff[g->cellVert[k] + 1]++;
      bound[g->cellVert[k]] += g->cellOff[c + 1] - g->cellOff[c];
    }
  g->maxNbr = 0;
  for (PetscInt v = 0; v < nv; ++v) g->maxNbr = PetscMax(g->maxNbr, bound[v]);
  for (PetscInt v = 0; v < nv; ++v) g->vOff[v + 1] += g->vOff[v];
  PetscCall(PetscMalloc1(g->vOff[nv], &g->vCell));
  for (PetscInt c = 0; c < nc; ++c)
    for (PetscInt k = g->cellOff[c]; k < g->cellOff[c + 1]; ++k) {
      const PetscInt v = g->cellVert[k];
      g->vCell[g->vOff[v] + cnt[v]++] = c;
    }
  PetscCall(PetscFree2(cnt, bound));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode GraphDestroy(Graph *g)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(g->code));
  PetscCall(PetscFree(g->cellOff));
  PetscCall(PetscFree(g->cellVert));
  PetscCall(PetscFree(g->vOff));
  PetscCall(PetscFree(g->vCell));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Sort buf[0..*n) and drop repeats */
static void SortUnique(PetscInt64 buf[], PetscInt *n)
{
  PetscInt m = 0;

  (void)PetscSortInt64(*n, buf);
  for (PetscInt k = 0; k < *n; ++k)
    if (!m || buf[k] != buf[m - 1]) buf[m++] = buf[k];
  *n = m;
}

/* Sorted unique codes of the neighbours of local vertex v (itself included); buf holds cap */
static PetscErrorCode Neighbours(const Graph *g, PetscInt v, PetscInt cap, PetscInt64 buf[], PetscInt *n)
{
  PetscInt m = 0;

  PetscFunctionBeginUser;
  for (PetscInt k = g->vOff[v]; k < g->vOff[v + 1]; ++k) {
    const PetscInt c = g->vCell[k];
    for (PetscInt j = g->cellOff[c]; j < g->cellOff[c + 1]; ++j) {
      PetscCheck(m < cap, PETSC_COMM_SELF, PETSC_ERR_PLIB, "neighbour buffer too small");
      buf[m++] = g->code[g->cellVert[j]];
    }
  }
  SortUnique(buf, &m);
  *n = m;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The rows of the owned vertices: their own neighbour lists and those their ghost copies on other
   ranks send (an SF with one leaf per ghost vertex, data: count, then the codes, padded to width
   W, gathered onto the owner's vertex points: deg[p] lists for local point p from rootOff[p]) */
typedef struct {
  PetscSF         vsf;
  const PetscInt *deg; /* belongs to vsf */
  PetscInt       *rootOff, W, pStart, cap;
  PetscInt64     *recv, *nb; /* nb: one merged list, cap long */
} Rows;

static PetscErrorCode RowsCreate(DM dm, const Graph *g, Rows *r)
{
  MPI_Comm           comm = PetscObjectComm((PetscObject)dm);
  PetscSF            sf;
  const PetscInt    *ilocal;
  const PetscSFNode *iremote;
  PetscSFNode       *rem;
  PetscInt           nroots, nleaves, ng = 0, pEnd, w = 0, total = 0, *buf;
  PetscInt64        *send, *nb;
  MPI_Datatype       unit;

  PetscFunctionBeginUser;
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, &nroots, &nleaves, &ilocal, &iremote));
  PetscCall(DMPlexGetChart(dm, &r->pStart, &pEnd));
  if (nleaves < 0) nleaves = 0;
  PetscCall(PetscMalloc1(nleaves, &rem));
  PetscCall(PetscMalloc1(nleaves, &buf));
  for (PetscInt l = 0; l < nleaves; ++l) {
    const PetscInt p = ilocal ? ilocal[l] : l;
    if (p < g->vStart || p >= g->vEnd) continue;
    rem[ng]   = iremote[l];
    buf[ng++] = p - g->vStart;
  }
  /* width: the longest ghost list anywhere */
  PetscCall(PetscMalloc1(g->maxNbr + 1, &nb));
  for (PetscInt i = 0; i < ng; ++i) {
    PetscInt n;
    PetscCall(Neighbours(g, buf[i], g->maxNbr + 1, nb, &n));
    w = PetscMax(w, n);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &w, 1, MPIU_INT, MPI_MAX, comm));
  r->W = w + 1;
  PetscCall(PetscCalloc1(ng * r->W + 1, &send));
  for (PetscInt i = 0; i < ng; ++i) {
    PetscInt n;
    PetscCall(Neighbours(g, buf[i], g->maxNbr + 1, nb, &n));
    send[i * r->W] = n;
    for (PetscInt k = 0; k < n; ++k) send[i * r->W + 1 + k] = nb[k];
  }
  PetscCall(PetscFree(nb));
  PetscCall(PetscFree(buf));
  PetscCall(PetscSFCreate(comm, &r->vsf));
  PetscCall(PetscSFSetGraph(r->vsf, pEnd - r->pStart, ng, NULL, PETSC_OWN_POINTER, rem, PETSC_OWN_POINTER));
  PetscCall(PetscSFComputeDegreeBegin(r->vsf, &r->deg));
  PetscCall(PetscSFComputeDegreeEnd(r->vsf, &r->deg));
  PetscCall(PetscMalloc1(pEnd - r->pStart + 1, &r->rootOff));
  for (PetscInt p = 0; p < pEnd - r->pStart; ++p) r->rootOff[p] = total, total += r->deg[p];
  r->rootOff[pEnd - r->pStart] = total;
  PetscCall(PetscMalloc1(total * r->W + 1, &r->recv));
  PetscCallMPI(MPI_Type_contiguous((PetscMPIInt)r->W, MPIU_INT64, &unit));
  PetscCallMPI(MPI_Type_commit(&unit));
  PetscCall(PetscSFGatherBegin(r->vsf, unit, send, r->recv));
  PetscCall(PetscSFGatherEnd(r->vsf, unit, send, r->recv));
  PetscCallMPI(MPI_Type_free(&unit));
  PetscCall(PetscFree(send));
  r->cap = g->maxNbr + 1;
  for (PetscInt v = g->vStart; v < g->vEnd; ++v) r->cap = PetscMax(r->cap, g->maxNbr + 1 + r->deg[v - r->pStart] * r->W);
  PetscCall(PetscMalloc1(r->cap, &r->nb));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode RowsDestroy(Rows *r)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(r->nb));
  PetscCall(PetscFree(r->rootOff));
  PetscCall(PetscFree(r->recv));
  PetscCall(PetscSFDestroy(&r->vsf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The sorted unique codes of the columns of the rows of local vertex v (a mesh point), in r->nb */
static PetscErrorCode RowNeighbours(const Graph *g, Rows *r, PetscInt v, PetscInt *n)
{
  const PetscInt p = v - r->pStart;

  PetscFunctionBeginUser;
  PetscCall(Neighbours(g, v - g->vStart, r->cap, r->nb, n));
  if (!r->deg[p]) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt k = r->rootOff[p]; k < r->rootOff[p + 1]; ++k)
    for (PetscInt j = 0; j < r->recv[k * r->W]; ++j) r->nb[(*n)++] = r->recv[k * r->W + 1 + j];
  SortUnique(r->nb, n);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rows per owned vertex: diagonal/off-diagonal nonzeros of each unconstrained dof row */
static PetscErrorCode CountNonzeros(DM dm, const Graph *g, Rows *r, PetscInt rStart, PetscInt nrows, PetscInt dnnz[], PetscInt onnz[])
{
  PetscSection gs;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(dm, &gs));
  for (PetscInt v = g->vStart; v < g->vEnd; ++v) {
    PetscInt goff, n, d = 0, o = 0, rows = (PetscInt)(g->code[v - g->vStart] % 4);
    PetscCall(PetscSectionGetOffset(gs, v, &goff));
    if (goff < 0 || !rows) continue;
    PetscCall(RowNeighbours(g, r, v, &n));
    for (PetscInt k = 0; k < n; ++k) {
      const PetscInt64 col = r->nb[k] / 4;
      if (col >= rStart && col < (PetscInt64)rStart + nrows) d += (PetscInt)(r->nb[k] % 4);
      else o += (PetscInt)(r->nb[k] % 4);
    }
    for (PetscInt i = 0; i < rows; ++i) {
      PetscCheck(goff - rStart + i >= 0 && goff - rStart + i < nrows, PETSC_COMM_SELF, PETSC_ERR_PLIB, "row outside the local range");
      dnnz[goff - rStart + i] = d;
      onnz[goff - rStart + i] = o;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Fix the pattern: the zero rows of each owned vertex, in ascending column order, so nothing
   travels between ranks and every row fills from its start */
static PetscErrorCode FillPattern(DM dm, const Graph *g, Rows *r, Mat J)
{
  PetscSection gs;
  PetscInt    *cols, rowIdx[3];
  PetscScalar *zero;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(PetscMalloc1(3 * r->cap, &cols));
  PetscCall(PetscCalloc1(3 * 3 * r->cap, &zero));
  for (PetscInt v = g->vStart; v < g->vEnd; ++v) {
    PetscInt goff, n, m = 0, rows = (PetscInt)(g->code[v - g->vStart] % 4);
    PetscCall(PetscSectionGetOffset(gs, v, &goff));
    if (goff < 0 || !rows) continue;
    PetscCall(RowNeighbours(g, r, v, &n));
    for (PetscInt k = 0; k < n; ++k)
      for (PetscInt i = 0; i < (PetscInt)(r->nb[k] % 4); ++i) cols[m++] = (PetscInt)(r->nb[k] / 4) + i;
    for (PetscInt i = 0; i < rows; ++i) rowIdx[i] = goff + i;
    PetscCall(MatSetValues(J, rows, rowIdx, m, cols, zero, INSERT_VALUES));
  }
  PetscCall(PetscFree(zero));
  PetscCall(PetscFree(cols));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* First-order layout: one field, dofs on vertices only, dim per vertex, an AIJ matrix type */
static PetscErrorCode VertexLayout(DM dm, PetscBool *ok)
{
  PetscSection ls;
  PetscInt     pStart, pEnd, vStart, vEnd, dim, nf;
  MatType      mtype;
  PetscBool    aij, seq, mpi;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMGetLocalSection(dm, &ls));
  PetscCall(PetscSectionGetNumFields(ls, &nf));
  PetscCall(PetscSectionGetChart(ls, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMGetMatType(dm, &mtype));
  PetscCall(PetscStrcmp(mtype, MATAIJ, &aij));
  PetscCall(PetscStrcmp(mtype, MATSEQAIJ, &seq));
  PetscCall(PetscStrcmp(mtype, MATMPIAIJ, &mpi));
  *ok = (aij || seq || mpi) && nf <= 1 && dim <= 3 ? PETSC_TRUE : PETSC_FALSE;
  for (PetscInt p = pStart; p < pEnd && *ok; ++p) {
    PetscInt dof;
    PetscCall(PetscSectionGetDof(ls, p, &dof));
    if ((p >= vStart && p < vEnd) ? dof != dim : dof != 0) *ok = PETSC_FALSE;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, ok, 1, MPIU_BOOL, MPI_LAND, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Block size as DMCreateMatrix chooses it: dim unless some vertex anywhere is partially
   constrained (fully constrained vertices have no rows and do not break the blocks) */
static PetscErrorCode BlockSize(DM dm, const Graph *g, PetscInt *bs)
{
  PetscInt any = 0;

  PetscFunctionBeginUser;
  for (PetscInt v = 0; v < g->vEnd - g->vStart; ++v)
    if (g->code[v] % 4 != g->dim && g->code[v] % 4 != 0) any = 1;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)dm)));
  *bs = any ? 1 : g->dim;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CreateVertexMatrix(DM dm, Mat *J)
{
  MPI_Comm               comm = PetscObjectComm((PetscObject)dm);
  Graph                  g;
  Rows                   r;
  PetscSection           gs;
  PetscInt               nrows, rStart, bs = 1, *dnnz, *onnz;
  MatType                mtype;
  ISLocalToGlobalMapping ltog;

  PetscFunctionBeginUser;
  PetscCall(GraphCreate(dm, &g));
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(PetscSectionGetConstrainedStorageSize(gs, &nrows));
  PetscCallMPI(MPI_Scan(&nrows, &rStart, 1, MPIU_INT, MPI_SUM, comm));
  rStart -= nrows;
  PetscCall(PetscCalloc2(nrows, &dnnz, nrows, &onnz));
  PetscCall(RowsCreate(dm, &g, &r));
  PetscCall(CountNonzeros(dm, &g, &r, rStart, nrows, dnnz, onnz));
  PetscCall(BlockSize(dm, &g, &bs));
  if (bs > 1)
    for (PetscInt i = 0; i < nrows / bs; ++i) dnnz[i] = dnnz[i * bs] / bs, onnz[i] = onnz[i * bs] / bs;
  PetscCall(DMGetMatType(dm, &mtype));
  PetscCall(MatCreate(comm, J));
  PetscCall(MatSetSizes(*J, nrows, nrows, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetType(*J, mtype));
  PetscCall(MatSetBlockSize(*J, bs));
  PetscCall(MatSetFromOptions(*J));
  PetscCall(MatXAIJSetPreallocation(*J, bs, dnnz, onnz, NULL, NULL));
  PetscCall(PetscFree2(dnnz, onnz));
  PetscCall(DMGetLocalToGlobalMapping(dm, &ltog));
  PetscCall(MatSetLocalToGlobalMapping(*J, ltog, ltog));
  PetscCall(MatSetDM(*J, dm));
  PetscCall(MatSetOption(*J, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  PetscCall(FillPattern(dm, &g, &r, *J));
  PetscCall(RowsDestroy(&r));
  PetscCall(GraphDestroy(&g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The system matrix of dm, assembled with zeros on its full pattern. fast: vertex-adjacency
   preallocation when the layout is first order (otherwise, or with fast false, DMCreateMatrix). */
PetscErrorCode SPMatrixCreate(DM dm, PetscBool fast, Mat *J)
{
  PetscBool ok = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (fast) PetscCall(VertexLayout(dm, &ok));
  if (ok) PetscCall(CreateVertexMatrix(dm, J));
  else PetscCall(DMCreateMatrix(dm, J));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rigid-body modes on a first-order layout, as DMPlexCreateRigidBody builds them (translations,
   then rotations with its sign convention, constrained dofs left out, orthonormalised in the same
   order), from the vertex coordinates directly instead of a projection */
static PetscErrorCode VertexRigidBody(DM dm, MatNullSpace *sp)
{
  const PetscInt     eps[3][3][3] = {{{0, 0, 0}, {0, 0, 1}, {0, -1, 0}}, {{0, 0, -1}, {0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {-1, 0, 0}, {0, 0, 0}}};
  MPI_Comm           comm         = PetscObjectComm((PetscObject)dm);
  PetscSection       ls, gs, cs;
  Vec                mode[6], coords;
  const PetscScalar *x;
  PetscScalar       *a[6];
  PetscInt           dim, m, vStart, vEnd, rStart, n;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  m = dim * (dim + 1) / 2;
  PetscCall(DMGetLocalSection(dm, &ls));
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  for (PetscInt d = 0; d < m; ++d) {
    PetscCall(DMCreateGlobalVector(dm, &mode[d]));
    PetscCall(VecGetArray(mode[d], &a[d]));
  }
  PetscCall(VecGetOwnershipRange(mode[0], &rStart, NULL));
  PetscCall(VecGetLocalSize(mode[0], &n));
  PetscCall(VecGetArrayRead(coords, &x));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt goff, coff, idx[3];
    PetscCall(PetscSectionGetOffset(gs, v, &goff));
    if (goff < 0) continue; /* owned elsewhere */
    PetscCall(PetscSectionGetOffset(cs, v, &coff));
    PetscCall(SPVertexGlobalIndices(ls, gs, v, dim, idx));
    for (PetscInt d = 0; d < m; ++d) {
      const PetscInt k = dim > 2 ? d - dim : d;
      PetscScalar    val[3] = {0, 0, 0};
      if (d < dim) val[d] = 1.0;
      else
        for (PetscInt i = 0; i < dim; ++i)
          for (PetscInt j = 0; j < dim; ++j) val[j] += eps[i][j][k] * x[coff + i];
      for (PetscInt j = 0; j < dim; ++j)
        if (idx[j] >= 0) a[d][idx[j] - rStart] = val[j];
    }
  }
  PetscCall(VecRestoreArrayRead(coords, &x));
  for (PetscInt d = 0; d < m; ++d) PetscCall(VecRestoreArray(mode[d], &a[d]));
  for (PetscInt i = 0; i < m; ++i) {
    PetscScalar dots[6];
    PetscCall(VecNormalize(mode[i], NULL));
    PetscCall(VecMDot(mode[i], m - i - 1, mode + i + 1, dots + i + 1));
    for (PetscInt j = i + 1; j < m; ++j) PetscCall(VecAXPY(mode[j], -dots[j], mode[i]));
  }
  PetscCall(MatNullSpaceCreate(comm, PETSC_FALSE, m, mode, sp));
  for (PetscInt d = 0; d < m; ++d) PetscCall(VecDestroy(&mode[d]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The rigid-body modes as GAMG's near-null space of J: built from the vertex coordinates on a
   first-order layout (fast), by DMPlexCreateRigidBody otherwise */
PetscErrorCode SPMatrixSetRigidBodyModes(DM dm, PetscBool fast, Mat J)
{
  MatNullSpace nsp;
  PetscBool    ok = PETSC_FALSE;
  PetscInt     dim;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  if (fast && dim > 1) PetscCall(VertexLayout(dm, &ok));
  if (ok) PetscCall(VertexRigidBody(dm, &nsp));
  else PetscCall(DMPlexCreateRigidBody(dm, 0, &nsp)); /* on the dof layout: constrained dofs excluded */
  PetscCall(MatSetNearNullSpace(J, nsp));
  PetscCall(MatNullSpaceDestroy(&nsp));
  PetscFunctionReturn(PETSC_SUCCESS);
}
