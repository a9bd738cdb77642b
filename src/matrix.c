/* The system matrix: creation and preallocation. For a first-order layout (every dof on a vertex,
   P1/Q1) the sparsity is vertex adjacency through cells, built here directly: each rank lists the
   neighbours of its local vertices, ghost vertices send their lists to the owner (PetscSFGather),
   and the owner counts the unconstrained dofs of the union, split into diagonal/off-diagonal
   blocks. The pattern is then fixed by inserting zero cell blocks, as DMCreateMatrix does, so the
   result is the same matrix (same nonzeros, block size, local-to-global map, DM) at a fraction of
   the cost. Contact-pair couplings are added later by contact-pattern.c. Every other
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

/* Vertex adjacency of the local mesh. A vertex is coded as 4 g + n: g its global vertex number,
   n its number of unconstrained dofs (<= 3), so a neighbour list carries what the owner counts. */
typedef struct {
  PetscInt    vStart, vEnd, cStart, cEnd, dim;
  PetscInt   *cellOff, *cellVert; /* CSR: local vertices of each cell */
  PetscInt   *vOff, *vCell;       /* CSR: cells of each vertex */
  PetscInt64 *code;               /* code of each local vertex */
  PetscInt    maxNbr;             /* bound on the neighbour list length (with repeats) */
} Graph;

/* The vertices of cell c, by walking cones down to depth 0 (cheaper than a transitive closure) */
static PetscErrorCode CellVertices(DM dm, PetscInt c, PetscInt vStart, PetscInt vEnd, PetscInt *n, PetscInt verts[], PetscInt maxn)
{
  PetscInt stack[256], top = 0;

  PetscFunctionBeginUser;
  *n           = 0;
  stack[top++] = c;
  while (top) {
    const PetscInt  p = stack[--top];
    const PetscInt *cone;
    PetscInt        nc;
    if (p >= vStart && p < vEnd) {
      PetscBool seen = PETSC_FALSE;
      for (PetscInt k = 0; k < *n && !seen; ++k) seen = verts[k] == p ? PETSC_TRUE : PETSC_FALSE;
      if (!seen) {
        PetscCheck(*n < maxn, PETSC_COMM_SELF, PETSC_ERR_SUP, "cell %" PetscInt_FMT " has more than %" PetscInt_FMT " vertices", c, maxn);
        verts[(*n)++] = p;
      }
      continue;
    }
    PetscCall(DMPlexGetConeSize(dm, p, &nc));
    PetscCall(DMPlexGetCone(dm, p, &cone));
    PetscCheck(top + nc <= 256, PETSC_COMM_SELF, PETSC_ERR_SUP, "cone walk of cell %" PetscInt_FMT " too deep", c);
    for (PetscInt k = 0; k < nc; ++k) stack[top++] = cone[k];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode GraphCreate(DM dm, Graph *g)
{
  PetscSection    ls;
  IS              vnum;
  const PetscInt *gv;
  PetscInt        nv, nc, verts[64], n, *cnt, *bound;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &g->dim));
  PetscCall(DMGetLocalSection(dm, &ls));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &g->vStart, &g->vEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &g->cStart, &g->cEnd));
  nv = g->vEnd - g->vStart;
  nc = g->cEnd - g->cStart;
  /* vertex codes */
  PetscCall(PetscMalloc1(nv, &g->code));
  PetscCall(DMPlexGetVertexNumbering(dm, &vnum));
  PetscCall(ISGetIndices(vnum, &gv));
  for (PetscInt v = 0; v < nv; ++v) {
    PetscInt dof, cdof, num = gv[v] < 0 ? -(gv[v] + 1) : gv[v];
    PetscCall(PetscSectionGetDof(ls, g->vStart + v, &dof));
    PetscCall(PetscSectionGetConstraintDof(ls, g->vStart + v, &cdof));
    g->code[v] = 4 * (PetscInt64)num + (dof - cdof);
  }
  PetscCall(ISRestoreIndices(vnum, &gv));
  /* cells -> vertices */
  PetscCall(PetscMalloc1(nc + 1, &g->cellOff));
  g->cellOff[0] = 0;
  for (PetscInt c = 0; c < nc; ++c) {
    PetscCall(CellVertices(dm, g->cStart + c, g->vStart, g->vEnd, &n, verts, 64));
    g->cellOff[c + 1] = g->cellOff[c] + n;
  }
  PetscCall(PetscMalloc1(g->cellOff[nc], &g->cellVert));
  for (PetscInt c = 0; c < nc; ++c) {
    PetscCall(CellVertices(dm, g->cStart + c, g->vStart, g->vEnd, &n, verts, 64));
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
  PetscCall(PetscSortInt64(m, buf));
  *n = 0;
  for (PetscInt k = 0; k < m; ++k)
    if (!*n || buf[k] != buf[*n - 1]) buf[(*n)++] = buf[k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Ghost vertices send their neighbour lists to the owner: an SF with one leaf per ghost vertex
   (data: count, then the codes, padded to width W) gathered onto the owner's vertex points.
   On return, recv holds deg[p] lists of width W for each local point p (rootOff[p] onwards). */
static PetscErrorCode GatherGhostLists(DM dm, const Graph *g, PetscInt *W, const PetscInt **deg, PetscInt **rootOff, PetscInt64 **recv, PetscSF *vsf)
{
  MPI_Comm           comm = PetscObjectComm((PetscObject)dm);
  PetscSF            sf;
  const PetscInt    *ilocal;
  const PetscSFNode *iremote;
  PetscSFNode       *rem;
  PetscInt           nroots, nleaves, ng = 0, pStart, pEnd, w, total = 0, *buf;
  PetscInt64        *send, *nb;
  MPI_Datatype       unit;

  PetscFunctionBeginUser;
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, &nroots, &nleaves, &ilocal, &iremote));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
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
  w = 0;
  for (PetscInt i = 0; i < ng; ++i) {
    PetscInt n;
    PetscCall(Neighbours(g, buf[i], g->maxNbr + 1, nb, &n));
    w = PetscMax(w, n);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &w, 1, MPIU_INT, MPI_MAX, comm));
  *W = w + 1;
  PetscCall(PetscCalloc1(ng * *W + 1, &send));
  for (PetscInt i = 0; i < ng; ++i) {
    PetscInt n;
    PetscCall(Neighbours(g, buf[i], g->maxNbr + 1, nb, &n));
    send[i * *W] = n;
    for (PetscInt k = 0; k < n; ++k) send[i * *W + 1 + k] = nb[k];
  }
  PetscCall(PetscFree(nb));
  PetscCall(PetscFree(buf));
  PetscCall(PetscSFCreate(comm, vsf));
  PetscCall(PetscSFSetGraph(*vsf, pEnd - pStart, ng, NULL, PETSC_OWN_POINTER, rem, PETSC_OWN_POINTER));
  PetscCall(PetscSFComputeDegreeBegin(*vsf, deg));
  PetscCall(PetscSFComputeDegreeEnd(*vsf, deg));
  PetscCall(PetscMalloc1(pEnd - pStart + 1, rootOff));
  for (PetscInt p = 0; p < pEnd - pStart; ++p) (*rootOff)[p] = total, total += (*deg)[p];
  (*rootOff)[pEnd - pStart] = total;
  PetscCall(PetscMalloc1(total * *W + 1, recv));
  PetscCallMPI(MPI_Type_contiguous((PetscMPIInt)*W, MPIU_INT64, &unit));
  PetscCallMPI(MPI_Type_commit(&unit));
  PetscCall(PetscSFGatherBegin(*vsf, unit, send, *recv));
  PetscCall(PetscSFGatherEnd(*vsf, unit, send, *recv));
  PetscCallMPI(MPI_Type_free(&unit));
  PetscCall(PetscFree(send));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rows per owned vertex: diagonal/off-diagonal nonzeros of each unconstrained dof row */
static PetscErrorCode CountNonzeros(DM dm, const Graph *g, PetscInt rStart, PetscInt nrows, PetscInt dnnz[], PetscInt onnz[])
{
  MPI_Comm        comm = PetscObjectComm((PetscObject)dm);
  PetscSection    gs;
  PetscSF         vsf;
  const PetscInt *deg;
  PetscInt       *rootOff, W = 1, nOwned = 0, vlo, cap, pStart;
  PetscInt64     *recv, *nb, lo, hi;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(DMPlexGetChart(dm, &pStart, NULL));
  PetscCall(GatherGhostLists(dm, g, &W, &deg, &rootOff, &recv, &vsf));
  /* owned global vertex numbers are [vlo, vlo + nOwned) */
  for (PetscInt v = g->vStart; v < g->vEnd; ++v) {
    PetscInt goff;
    PetscCall(PetscSectionGetOffset(gs, v, &goff));
    if (goff >= 0) nOwned++;
  }
  PetscCallMPI(MPI_Scan(&nOwned, &vlo, 1, MPIU_INT, MPI_SUM, comm));
  vlo -= nOwned;
  lo = vlo, hi = (PetscInt64)vlo + nOwned;
  cap = g->maxNbr + 1;
  for (PetscInt v = g->vStart; v < g->vEnd; ++v) cap = PetscMax(cap, g->maxNbr + 1 + (deg[v - pStart]) * W);
  PetscCall(PetscMalloc1(cap, &nb));
  for (PetscInt v = g->vStart; v < g->vEnd; ++v) {
    PetscInt goff, n, d = 0, o = 0, rows = (PetscInt)(g->code[v - g->vStart] % 4);
    PetscCall(PetscSectionGetOffset(gs, v, &goff));
    if (goff < 0 || !rows) continue;
    PetscCall(Neighbours(g, v - g->vStart, cap, nb, &n));
    if (deg[v - pStart]) { /* merge the lists of the ghost copies */
      for (PetscInt k = rootOff[v - pStart]; k < rootOff[v - pStart + 1]; ++k)
        for (PetscInt j = 0; j < recv[k * W]; ++j) nb[n++] = recv[k * W + 1 + j];
      PetscCall(PetscSortInt64(n, nb));
      {
        PetscInt m = 0;
        for (PetscInt k = 0; k < n; ++k)
          if (!m || nb[k] != nb[m - 1]) nb[m++] = nb[k];
        n = m;
      }
    }
    for (PetscInt k = 0; k < n; ++k) {
      const PetscInt64 gv = nb[k] / 4;
      if (gv >= lo && gv < hi) d += (PetscInt)(nb[k] % 4);
      else o += (PetscInt)(nb[k] % 4);
    }
    for (PetscInt r = 0; r < rows; ++r) {
      PetscCheck(goff - rStart + r >= 0 && goff - rStart + r < nrows, PETSC_COMM_SELF, PETSC_ERR_PLIB, "row outside the local range");
      dnnz[goff - rStart + r] = d;
      onnz[goff - rStart + r] = o;
    }
  }
  PetscCall(PetscFree(nb));
  PetscCall(PetscFree(rootOff));
  PetscCall(PetscFree(recv));
  PetscCall(PetscSFDestroy(&vsf)); /* deg belongs to the SF */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Fix the pattern: a zero block per cell, with global indices (constrained < 0) */
static PetscErrorCode FillPattern(DM dm, const Graph *g, Mat J)
{
  PetscSection ls, gs;
  PetscInt     dim = g->dim, idx[64 * 3], n;
  PetscScalar *zero;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm, &ls));
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(PetscCalloc1(64 * 3 * 64 * 3, &zero));
  for (PetscInt c = 0; c < g->cEnd - g->cStart; ++c) {
    n = g->cellOff[c + 1] - g->cellOff[c];
    for (PetscInt k = 0; k < n; ++k) PetscCall(SPVertexGlobalIndices(ls, gs, g->vStart + g->cellVert[g->cellOff[c] + k], dim, &idx[k * dim]));
    PetscCall(MatSetValues(J, n * dim, idx, n * dim, idx, zero, INSERT_VALUES));
  }
  PetscCall(PetscFree(zero));
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
  PetscCall(CountNonzeros(dm, &g, rStart, nrows, dnnz, onnz));
  PetscCall(BlockSize(dm, &g, &bs));
  if (bs > 1)
    for (PetscInt r = 0; r < nrows / bs; ++r) dnnz[r] = dnnz[r * bs] / bs, onnz[r] = onnz[r * bs] / bs;
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
  PetscCall(FillPattern(dm, &g, *J));
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
