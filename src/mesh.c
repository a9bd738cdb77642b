/* Mesh: read gmsh (or build a PETSc box mesh), partition (METIS by default), distribute. */
#include <ctype.h>
#include <spcontact-impl.h>
#include <kernels/tensor.h>
#include <sys/stat.h>

/* The range of the node coordinates of an ASCII gmsh file at its $Nodes section (r: min x, y, z,
   then max x, y, z); false if the section cannot be read (binary files: not looked at). PETSc's
   reader keeps dim coordinates of a 2D mesh and drops z, so a 2D mesh drawn out of the x-y plane
   is read projected on it. The scan stops once z spans more than 1e-3 of the extent so far: the
   mesh is then 3D or plainly out of the plane, and a 3D mesh is not read through twice. */
static PetscBool NodeRange(FILE *fp, int major, double r[6])
{
  char line[256];
  long nb = 1, nn;

  for (int d = 0; d < 3; ++d) r[d] = PETSC_MAX_REAL, r[3 + d] = -PETSC_MAX_REAL;
  while (fgets(line, sizeof(line), fp) && strncmp(line, "$Nodes", 6)) {}
  if (feof(fp)) return PETSC_FALSE;
  if (major == 4 && fscanf(fp, "%ld %*d %*d %*d", &nb) != 1) return PETSC_FALSE;
  for (long b = 0; b < nb; ++b) {
    int dim = 0, param = 0;
    if (major == 4 && fscanf(fp, "%d %*d %d %ld", &dim, &param, &nn) != 3) return PETSC_FALSE;
    if (major != 4 && fscanf(fp, "%ld", &nn) != 1) return PETSC_FALSE;
    for (long k = 0; major == 4 && k < nn; ++k)
      if (fscanf(fp, "%*d") != 0) return PETSC_FALSE;
    for (long k = 0; k < nn; ++k) {
      double x[3];
      if (major != 4 && fscanf(fp, "%*d") != 0) return PETSC_FALSE;
      if (fscanf(fp, "%lf %lf %lf", &x[0], &x[1], &x[2]) != 3) return PETSC_FALSE;
      for (int u = 0; param && u < dim; ++u)
        if (fscanf(fp, "%*f") != 0) return PETSC_FALSE;
      for (int d = 0; d < 3; ++d) r[d] = PetscMin(r[d], x[d]), r[3 + d] = PetscMax(r[3 + d], x[d]);
      if (r[5] - r[2] > 1e-3 * PetscMax(r[3] - r[0], r[4] - r[1])) return PETSC_TRUE;
    }
  }
  return PETSC_TRUE;
}

/* Whether a gmsh element type is first order (types 1-7 and 15) */
static PetscBool FirstOrder(int type)
{
  return (type >= 1 && type <= 7) || type == 15 ? PETSC_TRUE : PETSC_FALSE;
}

/* The last element type of an ASCII gmsh file above first order (tri6, quad9, tet10, ...; gmsh
   writes the cells last), 0 if none or not known. PETSc's reader makes such a mesh's coordinates
   a higher-order field, and the facet geometry failed on it with "Edge has 0 coordinates != 4";
   spcontact reads the corner nodes instead (CornerNodesOnly). */
static int HighOrderType(FILE *fp, int major)
{
  char line[4096];
  long nb, n;
  int  type, high = 0;

  rewind(fp);
  while (fgets(line, sizeof(line), fp) && strncmp(line, "$Elements", 9)) {}
  if (feof(fp) || !fgets(line, sizeof(line), fp) || sscanf(line, "%ld", &nb) != 1) return 0;
  if (major != 4) { /* 2.2: one element per line, its type second */
    while (fgets(line, sizeof(line), fp) && strncmp(line, "$EndElements", 12))
      if (sscanf(line, "%*d %d", &type) == 1 && !FirstOrder(type)) high = type;
    return high;
  }
  for (long b = 0; b < nb; ++b) { /* 4.x: blocks of one type each */
    if (!fgets(line, sizeof(line), fp) || sscanf(line, "%*d %*d %d %ld", &type, &n) != 2) return high;
    if (!FirstOrder(type)) high = type;
    for (long k = 0; k < n; ++k)
      if (!fgets(line, sizeof(line), fp)) return high;
  }
  return high;
}

/* A gmsh file must exist and start with $MeshFormat; checked on rank 0 before PETSc's reader
   runs, so a bad file is a clear, collective error instead of a parse failure deep inside.
   range: its nodes' coordinate range (NodeRange; min > max if not known); *high: its last element
   type above first order (HighOrderType; 0: none) */
static PetscErrorCode CheckMeshFile(MPI_Comm comm, const char file[], double range[6], int *high)
{
  PetscMPIInt rank;
  int         status = 0, type = 1; /* 0 ok, 1 missing, 2 not gmsh, 3 unsupported version, 4 a directory; type 0: ASCII */
  char        version[32] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  for (int d = 0; d < 3; ++d) range[d] = 1.0, range[3 + d] = 0.0;
  *high = 0;
  if (rank == 0) {
    FILE       *fp = fopen(file, "r");
    char        line[64] = "";
    struct stat st;
    if (!fp) status = 1;
    else if (!stat(file, &st) && S_ISDIR(st.st_mode)) status = 4, fclose(fp); /* fopen opens a directory */
    else {
      if (!fgets(line, sizeof(line), fp) || strncmp(line, "$MeshFormat", 11)) status = 2;
      else if (!fgets(line, sizeof(line), fp) || sscanf(line, "%31s %d", version, &type) < 1) status = 2;
      else if (strncmp(version, "2.2", 3) && strncmp(version, "4", 1)) status = 3; /* PETSc 3.18 reads 2.2 and 4.x */
      if (!status && type == 0 && !NodeRange(fp, version[0] == '4' ? 4 : 2, range))
        for (int d = 0; d < 3; ++d) range[d] = 1.0, range[3 + d] = 0.0;
      if (!status && type == 0) *high = HighOrderType(fp, version[0] == '4' ? 4 : 2);
      fclose(fp);
    }
  }
  PetscCallMPI(MPI_Bcast(&status, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(version, sizeof(version), MPI_CHAR, 0, comm));
  PetscCallMPI(MPI_Bcast(range, 6, MPI_DOUBLE, 0, comm));
  PetscCallMPI(MPI_Bcast(high, 1, MPI_INT, 0, comm));
  PetscCheck(status != 1, comm, PETSC_ERR_USER_INPUT, "-mesh_file %s: cannot open the file (check the path; run `make meshes` to build input/*.geo into build/mesh/)", file);
  PetscCheck(status != 4, comm, PETSC_ERR_USER_INPUT, "-mesh_file %s: a directory, not a mesh file; give the .msh file's path", file);
  { /* a geometry for the mesh, not the mesh (input/<case>.geo next to build/mesh/<case>.msh) */
    size_t n = strlen(file);
    PetscCheck(status != 2 || n < 4 || strcmp(file + n - 4, ".geo"), comm, PETSC_ERR_USER_INPUT, "-mesh_file %s: a gmsh geometry, not a mesh: mesh it first (gmsh -2 %s -format msh22 -o F.msh, or make meshes, which builds input/<case>.geo into build/mesh/<case>.msh)", file, file);
  }
  PetscCheck(status != 2, comm, PETSC_ERR_USER_INPUT, "-mesh_file %s: not a gmsh mesh (no $MeshFormat header); give a .msh written by gmsh", file);
  PetscCheck(status != 3, comm, PETSC_ERR_USER_INPUT, "-mesh_file %s: gmsh format %s is not supported; write format 4.1 or 2.2 (gmsh -format msh41, or File > Export), or convert it with scripts/convert-mesh", file, version);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A 2D mesh must lie in a plane z = const: PETSc keeps its x, y and drops z, so a mesh drawn in
   the x-z plane became flat cells and a tilted one was solved projected, without a word */
static PetscErrorCode CheckPlanar(DM dm, const char file[], const double r[6])
{
  PetscInt dim;
  double   extent = 0.0;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  if (dim != 2 || r[0] > r[3]) PetscFunctionReturn(PETSC_SUCCESS);
  for (int d = 0; d < 3; ++d) extent = PetscMax(extent, r[3 + d] - r[d]);
  PetscCheck(r[5] - r[2] <= 1e-10 * extent, PetscObjectComm((PetscObject)dm), PETSC_ERR_USER_INPUT, "-mesh_file %s: a 2D mesh whose nodes leave the plane z = const (z from %g to %g): spcontact's 2D is plane strain in x and y, and the reader would drop z; draw the 2D geometry in the x-y plane, or give a 3D mesh", file, r[2], r[5]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Read with PETSc's errors returned, not printed: bad = 1 if the reader failed */
static PetscErrorCode TryRead(MPI_Comm comm, const char file[], PetscBool interpolate, DM *dm, int *bad)
{
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = DMPlexCreateFromFile(comm, file, "spcontact", interpolate, dm);
  PetscCall(PetscPopErrorHandler());
  *bad = ierr ? 1 : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A higher-order gmsh type's name for the warning */
static const char *TypeName(int type)
{
  switch (type) {
  case 8: return "gmsh type 8, 3-node lines";
  case 9: return "gmsh type 9, 6-node triangles";
  case 10: return "gmsh type 10, 9-node quadrangles";
  case 11: return "gmsh type 11, 10-node tetrahedra";
  case 12: return "gmsh type 12, 27-node hexahedra";
  case 16: return "gmsh type 16, 8-node quadrangles";
  case 17: return "gmsh type 17, 20-node hexahedra";
  default: return "a gmsh type above first order";
  }
}

/* Higher-order gmsh elements are read by their corner nodes, as first-order cells: spcontact's
   geometry (facet normals and areas, contact points, the fast operator) is first order, and
   PETSc's higher-order coordinate field stopped the facet geometry with a PETSc message */
static PetscErrorCode CornerNodesOnly(MPI_Comm comm, const char file[], int high, PetscBool hi)
{
  PetscFunctionBeginUser;
  PetscCheck(!hi, comm, PETSC_ERR_USER_INPUT, "-dm_plex_gmsh_highorder true: spcontact's geometry is first order (P1/Q1 cells; contact points at vertices); leave the option out, and a second-order mesh is read by its corner nodes");
  PetscCall(SPOptionsSetDefault("-dm_plex_gmsh_highorder", "false"));
  if (high) PetscCall(PetscFPrintf(comm, PETSC_STDERR, "spcontact: warning: -mesh_file %s holds higher-order elements (%s): read by their corner nodes as first-order cells, so curved edges become straight and the other nodes are not used; mesh with Mesh.ElementOrder = 1 to silence this, and refine for the geometry\n", file, TypeName(high)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadMesh(MPI_Comm comm, const char file[], PetscBool highOrder, DM *dm)
{
  PetscMPIInt size, rank;
  int         bad = 0, high;
  double      range[6];

  PetscFunctionBeginUser;
  PetscCall(CheckMeshFile(comm, file, range, &high));
  PetscCall(CornerNodesOnly(comm, file, high, highOrder));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (size == 1) { /* one process: nobody can be left waiting, so one read (B2: 17 ms saved) */
    PetscCall(TryRead(comm, file, PETSC_TRUE, dm, &bad));
    PetscCheck(!bad, comm, PETSC_ERR_USER_INPUT, "-mesh_file %s: the gmsh reader failed; is the file complete?", file);
    PetscCall(CheckPlanar(*dm, file, range));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  /* Parse once on rank 0 alone: a truncated file then fails on rank 0 only and is reported to all,
     instead of leaving the other ranks waiting in the reader's broadcast. */
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    DM probe = NULL;
    PetscCall(TryRead(PETSC_COMM_SELF, file, PETSC_FALSE, &probe, &bad));
    PetscCall(DMDestroy(&probe));
  }
  PetscCallMPI(MPI_Bcast(&bad, 1, MPI_INT, 0, comm));
  PetscCheck(!bad, comm, PETSC_ERR_USER_INPUT, "-mesh_file %s: the gmsh reader failed; is the file complete?", file);
  PetscCall(DMPlexCreateFromFile(comm, file, "spcontact", PETSC_TRUE, dm));
  PetscCall(CheckPlanar(*dm, file, range));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KeepSerialNumbers(DM, PetscSF);

static PetscErrorCode Distribute(DM *dm, const char partitioner[])
{
  PetscPartitioner part;
  PetscSF          sfMig = NULL;
  DM               dist = NULL;
  PetscMPIInt      size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)*dm), &size));
  PetscCheck(!strcmp(partitioner, "metis") || !strcmp(partitioner, "ptscotch") || !strcmp(partitioner, "simple"), PetscObjectComm((PetscObject)*dm), PETSC_ERR_USER_INPUT, "-mesh_partitioner %s: unknown partitioner (use metis, ptscotch or simple)", partitioner);
  if (size == 1) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(DMPlexGetPartitioner(*dm, &part));
  if (!strcmp(partitioner, "metis")) PetscCall(SPPartitionerSetMetis(*dm));
  else {
    PetscErrorCode ierr;
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = PetscPartitionerSetType(part, partitioner);
    PetscCall(PetscPopErrorHandler());
    PetscCheck(!ierr, PetscObjectComm((PetscObject)*dm), PETSC_ERR_USER_INPUT, "-mesh_partitioner %s: unknown or unavailable partitioner (use metis, ptscotch or simple)", partitioner);
  }
  PetscCall(DMPlexDistribute(*dm, 0, &sfMig, &dist));
  if (dist) {
    PetscCall(KeepSerialNumbers(dist, sfMig));
    PetscCall(DMDestroy(dm));
    *dm = dist;
  }
  PetscCall(PetscSFDestroy(&sfMig));
  PetscFunctionReturn(PETSC_SUCCESS);
}

#define SERIAL_KEY "spcontact_serial_points"

/* Every local point's number in the serial mesh (rank 0 held every point before the distribution:
   the migration SF's roots), composed on the distributed mesh. These numbers do not depend on the
   rank count: restart files key their data by them. */
static PetscErrorCode KeepSerialNumbers(DM dist, PetscSF sfMig)
{
  PetscInt           pStart, pEnd, nleaves, *sid;
  const PetscInt    *ilocal;
  const PetscSFNode *iremote;
  IS                 is;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dist, &pStart, &pEnd));
  PetscCall(PetscSFGetGraph(sfMig, NULL, &nleaves, &ilocal, &iremote));
  PetscCheck(nleaves == pEnd - pStart, PETSC_COMM_SELF, PETSC_ERR_PLIB, "migration SF: %" PetscInt_FMT " leaves for %" PetscInt_FMT " points", nleaves, pEnd - pStart);
  PetscCall(PetscMalloc1(pEnd - pStart, &sid));
  for (PetscInt l = 0; l < nleaves; ++l) {
    PetscCheck(iremote[l].rank == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "the serial mesh was not on rank 0");
    sid[(ilocal ? ilocal[l] : l) - pStart] = iremote[l].index;
  }
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, pEnd - pStart, sid, PETSC_OWN_POINTER, &is));
  PetscCall(PetscObjectCompose((PetscObject)dist, SERIAL_KEY, (PetscObject)is));
  PetscCall(ISDestroy(&is));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The serial point numbers of the chart's points (identity on a mesh that was not distributed) */
PetscErrorCode SPMeshGetSerialNumbers(DM dm, const PetscInt **sid)
{
  IS is = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectQuery((PetscObject)dm, SERIAL_KEY, (PetscObject *)&is));
  if (!is) {
    PetscInt pStart, pEnd;
    PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
    PetscCall(ISCreateStride(PETSC_COMM_SELF, pEnd - pStart, pStart, 1, &is));
    PetscCall(ISToGeneral(is));
    PetscCall(PetscObjectCompose((PetscObject)dm, SERIAL_KEY, (PetscObject)is));
    PetscCall(ISDestroy(&is));
    PetscCall(PetscObjectQuery((PetscObject)dm, SERIAL_KEY, (PetscObject *)&is));
  }
  PetscCall(ISGetIndices(is, sid)); /* a general IS lends its own array, which lives with the DM */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the mesh's cells are simplices, the same answer on every rank: PETSc's DMPlexIsSimplex
   looks at this rank's first cell and says "tensor" on a rank with none, so a rank left without
   cells built a Q1 field beside the others' P1 and the ranks' PETSc objects no longer matched
   (a two-cell mesh on two ranks hung in the restart writer's first exchange) */
PetscErrorCode SPMeshIsSimplex(DM dm, PetscBool *simplex)
{
  PetscInt cStart, cEnd;
  int      mine = 0, any;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  if (cEnd > cStart) {
    PetscBool s;
    PetscCall(DMPlexIsSimplex(dm, &s));
    mine = s ? 1 : 0;
  }
  PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, PetscObjectComm((PetscObject)dm)));
  *simplex = any ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* detJ of a dim x dim Jacobian J_ik = dx_i/dxi_k and its scale-free shape detJ / prod_k |J e_k|
   (1 for a square, 0 for a flat cell) */
static void JacobianShape(PetscInt dim, const PetscReal J[], PetscReal *detJ, PetscReal *shape)
{
  PetscReal cols = 1.0;

  for (PetscInt k = 0; k < dim; ++k) {
    PetscReal n2 = 0.0;
    for (PetscInt i = 0; i < dim; ++i) n2 += PetscSqr(J[i * dim + k]);
    cols *= PetscSqrtReal(n2);
  }
  *detJ  = SPDeterminant(dim, J);
  *shape = cols > 0.0 ? *detJ / cols : 0.0;
}

/* Where a cell of type ct is checked: tensor cells at their 2^dim Gauss points, simplices (affine)
   at the reference centroid */
static PetscErrorCode CheckPoints(PetscInt dim, DMPolytopeType ct, PetscQuadrature *q)
{
  PetscReal *x, *w;

  PetscFunctionBeginUser;
  if (ct == DM_POLYTOPE_QUADRILATERAL || ct == DM_POLYTOPE_HEXAHEDRON) {
    PetscCall(PetscDTGaussTensorQuadrature(dim, 1, 2, -1.0, 1.0, q));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscMalloc1(dim, &x));
  PetscCall(PetscMalloc1(1, &w));
  for (PetscInt d = 0; d < dim; ++d) x[d] = -1.0 + 2.0 / (dim + 1);
  w[0] = 1.0;
  PetscCall(PetscQuadratureCreate(PETSC_COMM_SELF, q));
  PetscCall(PetscQuadratureSetData(*q, dim, 1, 1, x, w));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The coordinate field's tabulation at q, once for all cells, when the coordinates are a PetscFE
   of dimension dim on cells of one type (NULL otherwise: the caller asks PETSc per cell, which
   tabulates per cell and cost 20 s of setup at 1e6 dofs) */
static PetscErrorCode CoordinateTabulation(DM dm, PetscQuadrature q, PetscTabulation *T)
{
  DM             cdm;
  PetscObject    disc = NULL;
  PetscClassId   id = 0;
  PetscInt       dim, cdim, np, cStart, cEnd, mixed = 0;
  DMPolytopeType ct0, ct;
  const PetscReal *pts;

  PetscFunctionBeginUser;
  *T = NULL;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMGetCoordinateDim(dm, &cdim));
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetNumFields(cdm, &np));
  if (np == 1) PetscCall(DMGetField(cdm, 0, NULL, &disc));
  if (disc) PetscCall(PetscObjectGetClassId(disc, &id));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  if (cEnd > cStart) PetscCall(DMPlexGetCellType(dm, cStart, &ct0));
  for (PetscInt c = cStart + 1; c < cEnd && !mixed; ++c) {
    PetscCall(DMPlexGetCellType(dm, c, &ct));
    mixed = ct != ct0;
  }
  if (id != PETSCFE_CLASSID || cdim != dim || mixed || cEnd <= cStart) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscQuadratureGetData(q, NULL, NULL, &np, &pts, NULL));
  PetscCall(PetscFECreateTabulation((PetscFE)disc, 1, np, pts, 1, T));
  if ((*T)->Nc != dim || (*T)->cdim != dim) PetscCall(PetscTabulationDestroy(T));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The reference-to-cell Jacobians J[p dim^2 + i dim + k] = dX_i/dxi_k and their determinants at the
   points of q (at most 8) of cell c: from the coordinate tabulation T (J_ik = sum_b x_b dphi_b,i/dxi_k
   over the cell's closure coordinates) or, T NULL, from PETSc */
PetscErrorCode SPMeshCellJacobians(DM dm, Vec coords, PetscTabulation T, PetscQuadrature q, PetscInt c, PetscReal J[], PetscReal detJ[])
{
  DM           cdm;
  PetscInt     dim, np, n;
  PetscReal    v0[3 * 8], invJ[9 * 8];
  PetscScalar *x = NULL;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(PetscQuadratureGetData(q, NULL, NULL, &np, NULL, NULL));
  PetscCheck(np <= 8, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%" PetscInt_FMT " points: at most 8", np);
  if (!T) {
    PetscCall(DMPlexComputeCellGeometryFEM(dm, c, q, v0, J, invJ, detJ));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMPlexVecGetClosure(cdm, NULL, coords, c, &n, &x));
  PetscCheck(n == T->Nb, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cell %" PetscInt_FMT ": %" PetscInt_FMT " closure coordinates for %" PetscInt_FMT " basis functions", c, n, T->Nb);
  for (PetscInt p = 0; p < np; ++p) {
    for (PetscInt i = 0; i < dim; ++i)
      for (PetscInt k = 0; k < dim; ++k) {
        PetscReal v = 0.0;
        for (PetscInt b = 0; b < n; ++b) v += PetscRealPart(x[b]) * T->T[1][((p * n + b) * dim + i) * dim + k]; /* Nc = cdim = dim */
        J[p * dim * dim + i * dim + k] = v;
      }
    detJ[p] = SPDeterminant(dim, &J[p * dim * dim]);
  }
  PetscCall(DMPlexVecRestoreClosure(cdm, NULL, coords, c, &n, &x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* detJ and shape (JacobianShape) at the check points of cell c */
static PetscErrorCode CellJacobians(DM dm, Vec coords, PetscTabulation T, PetscQuadrature q, PetscInt c, PetscReal detJ[], PetscReal shape[])
{
  PetscInt  dim, np;
  PetscReal J[9 * 8], d;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(PetscQuadratureGetData(q, NULL, NULL, &np, NULL, NULL));
  PetscCall(SPMeshCellJacobians(dm, coords, T, q, c, J, detJ));
  for (PetscInt p = 0; p < np; ++p) JacobianShape(dim, &J[p * dim * dim], &d, &shape[p]); /* detJ: PETSc's own without T */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The coordinate field's tabulation at q (CoordinateTabulation), kept only if its Jacobians agree
   with PETSc's on the first 8 cells (closure permutations, layouts); NULL: ask PETSc per cell
   (SPMeshCellJacobians). Not collective: coordinates set up (DMGetCoordinatesLocalSetUp). */
PetscErrorCode SPMeshCoordinateTabulation(DM dm, PetscQuadrature q, PetscTabulation *T)
{
  Vec       coords;
  PetscReal d0[8], d1[8], s[8];
  PetscInt  np, cStart, cEnd;

  PetscFunctionBeginUser;
  PetscCall(CoordinateTabulation(dm, q, T));
  if (!*T) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscCall(PetscQuadratureGetData(q, NULL, NULL, &np, NULL, NULL));
  for (PetscInt c = cStart; c < PetscMin(cEnd, cStart + 8) && *T; ++c) {
    PetscCall(CellJacobians(dm, coords, *T, q, c, d0, s));
    PetscCall(CellJacobians(dm, coords, NULL, q, c, d1, s));
    for (PetscInt k = 0; k < np && *T; ++k)
      if (PetscAbsReal(d0[k] - d1[k]) > 1e-10 * PetscAbsReal(d1[k])) PetscCall(PetscTabulationDestroy(T));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Every cell must have a positive Jacobian determinant at its check points (tensor cells: 2^dim
   Gauss points; simplices: affine) and not be flat: shape (JacobianShape) above 1e-8, a
   scale-free bound. One line otherwise. */
static PetscErrorCode CheckCells(DM dm)
{
  PetscQuadrature q = NULL;
  PetscTabulation T = NULL;
  Vec             coords;
  PetscInt        dim, cStart, cEnd, np, bad = -1, kind = 0, badAll[2];
  PetscReal       detJ[8], shape[8];
  DMPolytopeType  ct = DM_POLYTOPE_UNKNOWN;

  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinatesLocalSetUp(dm)); /* collective, before the per-cell geometry */
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  if (cEnd > cStart) PetscCall(DMPlexGetCellType(dm, cStart, &ct));
  PetscCall(CheckPoints(dim, ct, &q));
  PetscCall(SPMeshCoordinateTabulation(dm, q, &T));
  PetscCall(PetscQuadratureGetData(q, NULL, NULL, &np, NULL, NULL));
  for (PetscInt c = cStart; c < cEnd && bad < 0; ++c) {
    PetscCall(CellJacobians(dm, coords, T, q, c, detJ, shape));
    for (PetscInt k = 0; k < np && bad < 0; ++k) {
      if (detJ[k] < 0.0) bad = c, kind = 1;
      else if (!(shape[k] > 1e-8)) bad = c, kind = 2;
    }
  }
  if (T) PetscCall(PetscTabulationDestroy(&T));
  PetscCall(PetscQuadratureDestroy(&q));
  badAll[0] = bad >= 0 ? 1 : 0, badAll[1] = kind;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, badAll, 2, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)dm)));
  PetscCheck(badAll[1] != 1, PetscObjectComm((PetscObject)dm), PETSC_ERR_USER_INPUT, "the mesh has inverted cells (negative Jacobian determinant): reorder their vertices (gmsh: Mesh > Reverse), or check -dm_plex_box_lower/upper");
  PetscCheck(badAll[1] != 2, PetscObjectComm((PetscObject)dm), PETSC_ERR_USER_INPUT, "the mesh has degenerate (flat) cells (detJ / edge lengths below 1e-8): fix the mesh or the box extents");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* spcontact solves 2D (plane strain) and 3D problems: a 1D box (-dm_plex_dim 1) ran a 1D problem
   to exit 0, a gmsh mesh of lines only was refused as flat cells, and -dm_plex_dim 4 gave PETSc's
   "Dimension 4 should be in [1, 3]". The box's option is looked at before PETSc reads it; dm: the
   mesh read (NULL: a box, not yet built) */
static PetscErrorCode CheckDimension(MPI_Comm comm, const char file[], DM dm)
{
  PetscInt  dim = 2;
  PetscBool set = PETSC_TRUE;

  PetscFunctionBeginUser;
  if (dm) PetscCall(DMGetDimension(dm, &dim));
  else PetscCall(PetscOptionsGetInt(NULL, NULL, "-dm_plex_dim", &dim, &set));
  if (!set) PetscFunctionReturn(PETSC_SUCCESS);
  if (file[0]) PetscCheck(dim == 2 || dim == 3, comm, PETSC_ERR_USER_INPUT, "-mesh_file %s: a %" PetscInt_FMT "D mesh: spcontact solves 2D (plane strain) and 3D problems; mesh the geometry's surfaces (gmsh -2) or volumes (gmsh -3)", file, dim);
  PetscCheck(dim == 2 || dim == 3, comm, PETSC_ERR_USER_INPUT, "-dm_plex_dim %" PetscInt_FMT ": spcontact solves 2D (plane strain) and 3D problems; give 2 or 3", dim);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The vertices of mesh point c (a cell or a facet), by walking cones down to depth 0: cheaper than
   a transitive closure, which asks every point's cell type (the matrix graph; bc-bodies.c) */
PetscErrorCode SPMeshPointVertices(DM dm, PetscInt c, PetscInt vStart, PetscInt vEnd, PetscInt *n, PetscInt verts[], PetscInt maxn)
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
        PetscCheck(*n < maxn, PETSC_COMM_SELF, PETSC_ERR_SUP, "mesh point %" PetscInt_FMT " has more than %" PetscInt_FMT " vertices", c, maxn);
        verts[(*n)++] = p;
      }
      continue;
    }
    PetscCall(DMPlexGetConeSize(dm, p, &nc));
    PetscCall(DMPlexGetCone(dm, p, &cone));
    PetscCheck(top + nc <= 256, PETSC_COMM_SELF, PETSC_ERR_SUP, "cone walk of mesh point %" PetscInt_FMT " too deep", c);
    for (PetscInt k = 0; k < nc; ++k) stack[top++] = cone[k];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* PETSc's -dm_plex_filename names the mesh as -mesh_file does and is read the same way, through
   the file checks (DMSetFromOptions read it behind them: a truncated file ended in PETSc's error
   wall, and the box's default -dm_plex_simplex 0 met a triangle mesh) */
static PetscErrorCode MeshFileAlias(MPI_Comm comm, char file[], size_t len)
{
  char      alias[PETSC_MAX_PATH_LEN];
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-dm_plex_filename", alias, sizeof(alias), &set));
  if (!set) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(!file[0] || !strcmp(file, alias), comm, PETSC_ERR_USER_INPUT, "-mesh_file %s and -dm_plex_filename %s name two meshes; give one of them (-mesh_file)", file, alias);
  PetscCall(PetscStrncpy(file, alias, len));
  PetscCall(PetscOptionsClearValue(NULL, "-dm_plex_filename"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPMeshCreate(MPI_Comm comm, DM *dm)
{
  char      file[PETSC_MAX_PATH_LEN] = "", partitioner[64] = "metis";
  PetscBool highOrder = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Mesh options", "spcontact");
  PetscCall(PetscOptionsString("-mesh_file", "gmsh .msh file (PETSc's -dm_plex_filename is taken as this); without it a PETSc box mesh is built from -dm_plex_box_* options", "SPMeshCreate", file, file, sizeof(file), NULL));
  PetscCall(PetscOptionsString("-mesh_partitioner", "Partitioner: metis (METIS 5 k-way, default), ptscotch, simple", "SPMeshCreate", partitioner, partitioner, sizeof(partitioner), NULL));
  PetscCall(PetscOptionsBool("-dm_plex_gmsh_highorder", "PETSc's higher-order gmsh coordinates: refused if true (spcontact's geometry is first order; a higher-order mesh is read by its corner nodes, with a warning)", "SPMeshCreate", highOrder, &highOrder, NULL));
  PetscOptionsEnd();
  PetscCall(MeshFileAlias(comm, file, sizeof(file)));
  for (char *c = partitioner; *c; ++c) *c = (char)tolower((unsigned char)*c); /* any case, as PETSc's lists */
  if (file[0]) {
    PetscCall(ReadMesh(comm, file, highOrder, dm));
    PetscCall(CheckDimension(comm, file, *dm));
    PetscCall(SPMeshCheckSize(comm, *dm));
  } else {
    /* Debian's PETSc has no simplex generator: default the box to tensor cells (Q1) */
    PetscCall(SPOptionsSetDefault("-dm_plex_simplex", "0"));
    PetscCall(CheckDimension(comm, file, NULL));
    PetscCall(SPMeshCheckSize(comm, NULL));
    PetscCall(DMCreate(comm, dm));
    PetscCall(DMSetType(*dm, DMPLEX));
  }
  /* PETSc's options (box sizes, -dm_refine, ...) act on the serial mesh; we distribute ourselves */
  PetscCall(DMPlexDistributeSetDefault(*dm, PETSC_FALSE));
  PetscCall(DMSetFromOptions(*dm));
  PetscCall(Distribute(dm, partitioner));
  PetscCall(CheckCells(*dm));
  PetscCall(PetscObjectSetName((PetscObject)*dm, "mesh"));
  PetscCall(DMViewFromOptions(*dm, NULL, "-dm_view"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A label named by the user must exist and hold points for every requested value (globally). */
PetscErrorCode SPMeshCheckLabel(DM dm, const char name[], PetscInt nv, const PetscInt values[], const char option[])
{
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  DMLabel  label;
  PetscInt has, hasAll;

  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(dm, name, &label));
  has = label ? 1 : 0;
  PetscCallMPI(MPI_Allreduce(&has, &hasAll, 1, MPIU_INT, MPI_MAX, comm));
  PetscCheck(hasAll, comm, PETSC_ERR_USER_INPUT, "%s: the mesh has no label \"%s\" (gmsh physical groups are \"Face Sets\"/\"Cell Sets\"; box meshes have \"Face Sets\" and \"marker\")", option, name);
  PetscCheck(nv > 0, comm, PETSC_ERR_USER_INPUT, "%s: no label values given for label \"%s\"", option, name);
  for (PetscInt i = 0; i < nv; ++i) {
    PetscInt n = 0, nAll;
    if (label) PetscCall(DMLabelGetStratumSize(label, values[i], &n));
    PetscCallMPI(MPI_Allreduce(&n, &nAll, 1, MPIU_INT, MPI_SUM, comm));
    PetscCheck(nAll > 0, comm, PETSC_ERR_USER_INPUT, "%s: label \"%s\" has no points with value %" PetscInt_FMT " (check the gmsh physical group numbers)", option, name, values[i]);
    for (PetscInt j = 0; j < i; ++j) /* a repeated value would count its faces twice: a load applied twice */
      PetscCheck(values[j] != values[i], comm, PETSC_ERR_USER_INPUT, "%s: value %" PetscInt_FMT " is given twice (its faces would carry the condition twice); give each value once", option, values[i]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A new label `name` (value 1) marking the given strata of `src` and their closure; completion
   runs on the distributed mesh and PETSc propagates it across ranks, so every copy of a shared
   vertex agrees (essential conditions and contact points need that). */
PetscErrorCode SPMeshCreateCompletedLabel(DM dm, const char src[], PetscInt nv, const PetscInt values[], const char name[], DMLabel *out)
{
  DMLabel label;

  PetscFunctionBeginUser;
  PetscCall(DMCreateLabel(dm, name));
  PetscCall(DMGetLabel(dm, name, out));
  PetscCall(DMGetLabel(dm, src, &label));
  for (PetscInt v = 0; v < nv; ++v) {
    IS              is;
    const PetscInt *pts;
    PetscInt        n = 0;
    PetscCall(DMLabelGetStratumIS(label, values[v], &is));
    if (!is) continue;
    PetscCall(ISGetLocalSize(is, &n));
    PetscCall(ISGetIndices(is, &pts));
    for (PetscInt p = 0; p < n; ++p) PetscCall(DMLabelSetValue(*out, pts[p], 1));
    PetscCall(ISRestoreIndices(is, &pts));
    PetscCall(ISDestroy(&is));
  }
  PetscCall(DMPlexLabelComplete(dm, *out));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Outward unit normal, centroid and measure of a boundary facet (outward: away from its cell) */
PetscErrorCode SPMeshFacetGeometry(DM dm, PetscInt dim, PetscInt f, PetscReal n[3], PetscReal x[3], PetscReal *area)
{
  const PetscInt *supp;
  PetscReal       xc[3] = {0, 0, 0}, vol, len = 0.0, side = 0.0;

  PetscFunctionBeginUser;
  PetscCall(DMPlexComputeCellGeometryFVM(dm, f, area, x, n));
  PetscCall(DMPlexGetSupport(dm, f, &supp));
  PetscCall(DMPlexComputeCellGeometryFVM(dm, supp[0], &vol, xc, NULL));
  for (PetscInt d = 0; d < dim; ++d) len += n[d] * n[d], side += n[d] * (x[d] - xc[d]);
  len = PetscSqrtReal(len) * (side < 0.0 ? -1.0 : 1.0);
  for (PetscInt d = 0; d < dim; ++d) n[d] /= len;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The facets (height-1 points) of the given strata of label `name`, local to this rank; free with PetscFree */
PetscErrorCode SPMeshGetLabelFacets(DM dm, const char name[], PetscInt nv, const PetscInt values[], PetscInt *n, PetscInt **facets)
{
  DMLabel  label;
  PetscInt fStart, fEnd, total = 0;

  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(dm, name, &label));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &fStart, &fEnd));
  for (PetscInt v = 0; v < nv; ++v) {
    PetscInt size = 0;
    if (label) PetscCall(DMLabelGetStratumSize(label, values[v], &size));
    total += size;
  }
  PetscCall(PetscMalloc1(total + 1, facets));
  *n = 0;
  for (PetscInt v = 0; v < nv && label; ++v) {
    IS              is;
    const PetscInt *pts;
    PetscInt        size = 0;
    PetscCall(DMLabelGetStratumIS(label, values[v], &is));
    if (!is) continue;
    PetscCall(ISGetLocalSize(is, &size));
    PetscCall(ISGetIndices(is, &pts));
    for (PetscInt k = 0; k < size; ++k)
      if (pts[k] >= fStart && pts[k] < fEnd) (*facets)[(*n)++] = pts[k];
    PetscCall(ISRestoreIndices(is, &pts));
    PetscCall(ISDestroy(&is));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
