/* XDMF index of the HDF5 file, written by rank 0 after the HDF5 file is complete: a temporal
   collection of grids sharing /geometry/vertices and /viz/topology/cells, with the vertex fields
   of each step read as slabs of /vertex_fields/<name>_Field_0 (PETSc's layout); one file for
   ParaView's default Xdmf3 reader, one for its legacy XDMF reader. */
#include <spcontact-impl.h>

static const char *TopologyType(PetscInt dim, PetscInt corners)
{
  if (dim == 2) return corners == 3 ? "Triangle" : "Quadrilateral";
  return corners == 4 ? "Tetrahedron" : "Hexahedron";
}

static PetscErrorCode MeshCounts(DM dm, PetscInt *nv, PetscInt *nc, PetscInt *corners)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscInt cStart, cEnd, vStart, vEnd, k = 0, *cl = NULL, ncl, loc[2], all[2];
  IS       cellIS, vertIS;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  if (cEnd > cStart) {
    PetscCall(DMPlexGetTransitiveClosure(dm, cStart, PETSC_TRUE, &ncl, &cl));
    for (PetscInt p = 0; p < 2 * ncl; p += 2) k += (cl[p] >= vStart && cl[p] < vEnd);
    PetscCall(DMPlexRestoreTransitiveClosure(dm, cStart, PETSC_TRUE, &ncl, &cl));
  }
  PetscCallMPI(MPI_Allreduce(&k, corners, 1, MPIU_INT, MPI_MAX, comm));
  PetscCall(DMPlexGetCellNumbering(dm, &cellIS));
  PetscCall(DMPlexGetVertexNumbering(dm, &vertIS));
  loc[0] = loc[1] = 0;
  { /* owned entries are >= 0 in the numberings */
    const PetscInt *idx;
    PetscInt        n;
    PetscCall(ISGetLocalSize(cellIS, &n));
    PetscCall(ISGetIndices(cellIS, &idx));
    for (PetscInt i = 0; i < n; ++i) loc[0] += idx[i] >= 0;
    PetscCall(ISRestoreIndices(cellIS, &idx));
    PetscCall(ISGetLocalSize(vertIS, &n));
    PetscCall(ISGetIndices(vertIS, &idx));
    for (PetscInt i = 0; i < n; ++i) loc[1] += idx[i] >= 0;
    PetscCall(ISRestoreIndices(vertIS, &idx));
  }
  PetscCallMPI(MPI_Allreduce(loc, all, 2, MPIU_INT, MPI_SUM, comm));
  *nc = all[0];
  *nv = all[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One vertex field of one step: the step's slab of the (nsteps, nv[, nc]) dataset. Xdmf3 (ParaView's
   default reader) selects it with the "path|start:stride:count:dims" syntax of its HDF5 controller
   and rejects HyperSlab items ("unrecognized array type"); the legacy reader needs a HyperSlab. */
static void Attribute(FILE *fp, const char h5[], const char name[], PetscInt nc, PetscInt step, PetscInt nsteps, PetscInt nv, PetscBool legacy)
{
  char one[64], zero[16], dims[96];

  snprintf(one, sizeof(one), nc == 1 ? "%d" : "%d %d", (int)nv, (int)nc); /* one step's shape */
  snprintf(zero, sizeof(zero), nc == 1 ? "0" : "0 0");
  snprintf(dims, sizeof(dims), "%d %s", (int)nsteps, one);
  fprintf(fp, "        <Attribute Name=\"%s\" AttributeType=\"%s\" Center=\"Node\">\n", name, nc == 1 ? "Scalar" : "Vector");
  if (legacy) {
    fprintf(fp, "          <DataItem ItemType=\"HyperSlab\" Dimensions=\"1 %s\" Type=\"HyperSlab\">\n", one);
    fprintf(fp, "            <DataItem Dimensions=\"3 %d\" Format=\"XML\">%d %s %s 1 1 %s</DataItem>\n", nc == 1 ? 2 : 3, (int)step, zero, nc == 1 ? "1" : "1 1", one);
    fprintf(fp, "            <DataItem DataType=\"Float\" Precision=\"8\" Dimensions=\"%s\" Format=\"HDF\">%s:/vertex_fields/%s_Field_0</DataItem>\n", dims, h5, name);
    fprintf(fp, "          </DataItem>\n");
  } else {
    fprintf(fp, "          <DataItem DataType=\"Float\" Precision=\"8\" Dimensions=\"%s\" Format=\"HDF\">%s:/vertex_fields/%s_Field_0|%d %s:1 %s:1 %s:%s</DataItem>\n", one, h5, name, (int)step, zero, nc == 1 ? "1" : "1 1", one, dims);
  }
  fprintf(fp, "        </Attribute>\n");
}

/* Rank 0: one XDMF file, the XML header (v2: XDMF 2.0 with its DOCTYPE, as both volume files have
   it; else 3.0, the surface file's) and a temporal
   collection with one uniform grid per output step; grid() writes a step's topology, geometry and
   fields. The surface file (output-surface.c) is written by it too. */
PetscErrorCode SPXdmfWriteCollection(SPOutput o, const char xmf[], PetscBool v2, const char name[], const char stepName[], void (*grid)(FILE *, PetscInt, void *), void *ctx)
{
  FILE *fp;

  PetscFunctionBeginUser;
  fp = fopen(xmf, "w");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write %s", xmf);
  fprintf(fp, "<?xml version=\"1.0\" ?>\n%s<Xdmf Version=\"%s\">\n  <Domain>\n", v2 ? "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n" : "", v2 ? "2.0" : "3.0");
  fprintf(fp, "    <Grid Name=\"%s\" GridType=\"Collection\" CollectionType=\"Temporal\">\n", name);
  for (PetscInt k = 0; k < o->nsteps; ++k) {
    fprintf(fp, "      <Grid Name=\"%s_%d\" GridType=\"Uniform\">\n        <Time Value=\"%.10g\"/>\n", stepName, (int)k, (double)o->times[k]);
    grid(fp, k, ctx);
    fprintf(fp, "      </Grid>\n");
  }
  fprintf(fp, "    </Grid>\n  </Domain>\n</Xdmf>\n");
  PetscCall(SPOutputCheckStream(fp, xmf, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

const char *const SPOutputContactFields[4]  = {"contact_pressure", "gap", "shift", "active"};
const char *const SPOutputFrictionFields[3] = {"tangential_traction", "slip", "status"}; /* vector, vector, scalar */

typedef struct {
  SPOutput    o;
  const char *h5;
  PetscInt    dim, nv, nc, corners;
  PetscBool   legacy;
} VolumeGrid;

static void VolumeStep(FILE *fp, PetscInt k, void *ctx)
{
  const VolumeGrid *g = (const VolumeGrid *)ctx;
  const SPOutput    o = g->o;

  fprintf(fp, "        <Topology TopologyType=\"%s\" NumberOfElements=\"%d\">\n", TopologyType(g->dim, g->corners), (int)g->nc);
  fprintf(fp, "          <DataItem Format=\"HDF\" DataType=\"Int\" Dimensions=\"%d %d\">%s:/viz/topology/cells</DataItem>\n        </Topology>\n", (int)g->nc, (int)g->corners, g->h5);
  fprintf(fp, "        <Geometry GeometryType=\"%s\">\n", g->dim == 2 ? "XY" : "XYZ");
  fprintf(fp, "          <DataItem Format=\"HDF\" DataType=\"Float\" Precision=\"8\" Dimensions=\"%d %d\">%s:/geometry/vertices</DataItem>\n        </Geometry>\n", (int)g->nv, (int)g->dim, g->h5);
  Attribute(fp, g->h5, "displacement", g->dim, k, o->nsteps, g->nv, g->legacy);
  if (o->contactFields)
    for (PetscInt f = 0; f < 4; ++f) Attribute(fp, g->h5, SPOutputContactFields[f], 1, k, o->nsteps, g->nv, g->legacy);
  if (o->frictionFields)
    for (PetscInt f = 0; f < 3; ++f) Attribute(fp, g->h5, SPOutputFrictionFields[f], f < 2 ? g->dim : 1, k, o->nsteps, g->nv, g->legacy);
}

/* <prefix>.xmf for ParaView's default (Xdmf3) reader and <prefix>-xdmf2.xmf for the legacy "XDMF
   Reader", written as .part files that point at the .h5 (complete run: renamed with it) or the
   .h5.part (failed or interrupted run: they stay .part); no file at all when no step converged (an
   XDMF without grids crashes ParaView). */
PetscErrorCode SPOutputWriteXdmf(SPOutput o, PetscBool complete)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)o->dm);
  PetscMPIInt rank;
  PetscInt    nv = 0, nc = 0, corners = 0, dim;
  char        h5[PETSC_MAX_PATH_LEN + 8], xmf[PETSC_MAX_PATH_LEN + 16];

  PetscFunctionBeginUser;
  PetscCall(MeshCounts(o->dm, &nv, &nc, &corners));
  PetscCall(DMGetDimension(o->dm, &dim));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPOutputH5Reference(o, complete, h5, sizeof(h5)));
  for (PetscInt legacy = 0; legacy < 2; ++legacy) {
    VolumeGrid g = {o, h5, dim, nv, nc, corners, legacy ? PETSC_TRUE : PETSC_FALSE};
    PetscCall(PetscSNPrintf(xmf, sizeof(xmf), legacy ? "%s-xdmf2.xmf.part" : "%s.xmf.part", o->prefix));
    PetscCall(PetscStrncpy(o->guard.file, xmf, sizeof(o->guard.file))); /* the file a failure names */
    if (o->nsteps) PetscCall(SPXdmfWriteCollection(o, xmf, PETSC_TRUE, "spcontact", "step", VolumeStep, &g));
    else (void)remove(xmf); /* a stale file of an earlier run must not pose as this run's */
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
