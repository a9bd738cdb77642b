/* Contact-surface grid: <prefix>-surface.xmf (ParaView's default Xdmf3 reader; .part until a
   complete run renames it with the .h5) holds the slave
   facets (the obstacle slave boundary -contact_values and every user pair's slave surface) as a
   grid over the volume's /geometry/vertices, with per load step the vertex fields
   contact_pressure, gap (NaN where none exists), shift, active and, with friction,
   tangential_traction, slip, status. The facet connectivity (global vertex numbers, the order of
   /geometry/vertices) is gathered on rank 0 and written inline. */
#include <spcontact-impl.h>

/* The closure vertices of the labelled facets, as global vertex numbers, appended to conn */
static PetscErrorCode AddFacets(DM dm, const char label[], PetscInt nv, const PetscInt values[], PetscInt *n, PetscInt **conn, PetscInt *corners)
{
  PetscInt        nf, *facets, vStart, vEnd, *cl = NULL, ncl;
  IS              vnum;
  const PetscInt *g;

  PetscFunctionBeginUser;
  PetscCall(SPMeshGetLabelFacets(dm, label, nv, values, &nf, &facets));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMPlexGetVertexNumbering(dm, &vnum));
  PetscCall(ISGetIndices(vnum, &g));
  PetscCall(PetscRealloc(sizeof(PetscInt) * (*n + 4 * nf + 1), conn));
  for (PetscInt f = 0; f < nf; ++f) {
    PetscInt k = 0;
    PetscCall(DMPlexGetTransitiveClosure(dm, facets[f], PETSC_TRUE, &ncl, &cl));
    for (PetscInt p = 0; p < 2 * ncl && k < 4; p += 2)
      if (cl[p] >= vStart && cl[p] < vEnd) {
        const PetscInt gv = g[cl[p] - vStart];
        (*conn)[*n + k++] = gv >= 0 ? gv : -(gv + 1);
      }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, facets[f], PETSC_TRUE, &ncl, &cl));
    *corners = k;
    *n += k;
  }
  PetscCall(ISRestoreIndices(vnum, &g));
  PetscCall(PetscFree(facets));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* All slave facets on rank 0: conn (nfacet x corners), NULL elsewhere */
static PetscErrorCode GatherFacets(SPContact c, DM dm, PetscInt *nfacet, PetscInt *corners, PetscInt **all)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)dm);
  PetscInt    n = 0, k = 0, *conn = NULL, cmax;
  PetscMPIInt size, rank, cnt, *counts = NULL, *displs = NULL, total = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(1, &conn));
  if (c->nob > 0) PetscCall(AddFacets(dm, c->label, c->nvalues, c->values, &n, &conn, &k));
  for (PetscInt p = 0; p < c->nuser; ++p) PetscCall(AddFacets(dm, c->pair[p].label, c->pair[p].nslave, c->pair[p].slave, &n, &conn, &k));
  PetscCallMPI(MPI_Allreduce(&k, &cmax, 1, MPIU_INT, MPI_MAX, comm));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMPIIntCast(n, &cnt));
  if (!rank) PetscCall(PetscMalloc2(size, &counts, size, &displs));
  PetscCallMPI(MPI_Gather(&cnt, 1, MPI_INT, counts, 1, MPI_INT, 0, comm));
  for (PetscMPIInt r = 0; !rank && r < size; ++r) displs[r] = total, total += counts[r];
  *all = NULL;
  if (!rank) PetscCall(PetscMalloc1(total + 1, all));
  PetscCallMPI(MPI_Gatherv(conn, cnt, MPIU_INT, *all, counts, displs, MPIU_INT, 0, comm));
  if (!rank) PetscCall(PetscFree2(counts, displs));
  PetscCall(PetscFree(conn));
  *corners = cmax;
  *nfacet  = cmax > 0 ? total / cmax : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void Field(FILE *fp, const char h5[], const char name[], PetscInt nc, PetscInt step, PetscInt nsteps, PetscInt nv)
{
  if (nc == 1)
    fprintf(fp, "        <Attribute Name=\"%s\" AttributeType=\"Scalar\" Center=\"Node\">\n          <DataItem DataType=\"Float\" Precision=\"8\" Dimensions=\"%d\" Format=\"HDF\">%s:/vertex_fields/%s_Field_0|%d 0:1 1:1 %d:%d %d</DataItem>\n        </Attribute>\n", name, (int)nv, h5, name, (int)step, (int)nv, (int)nsteps, (int)nv);
  else
    fprintf(fp, "        <Attribute Name=\"%s\" AttributeType=\"Vector\" Center=\"Node\">\n          <DataItem DataType=\"Float\" Precision=\"8\" Dimensions=\"%d %d\" Format=\"HDF\">%s:/vertex_fields/%s_Field_0|%d 0 0:1 1 1:1 %d %d:%d %d %d</DataItem>\n        </Attribute>\n", name, (int)nv, (int)nc, h5, name, (int)step, (int)nv, (int)nc, (int)nsteps, (int)nv, (int)nc);
}

typedef struct {
  SPOutput        o;
  const char     *h5;
  PetscInt        dim, nv, nf, corners;
  const PetscInt *conn;
} SurfaceGrid;

/* One step of the surface grid: nf facets (connectivity conn, inline) over /geometry/vertices */
static void SurfaceStep(FILE *fp, PetscInt k, void *ctx)
{
  const SurfaceGrid *g = (const SurfaceGrid *)ctx;

  if (g->dim == 2) fprintf(fp, "        <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"%d\">\n", (int)g->nf);
  else fprintf(fp, "        <Topology TopologyType=\"%s\" NumberOfElements=\"%d\">\n", g->corners == 3 ? "Triangle" : "Quadrilateral", (int)g->nf);
  fprintf(fp, "          <DataItem Format=\"XML\" DataType=\"Int\" Dimensions=\"%d %d\">\n", (int)g->nf, (int)g->corners);
  for (PetscInt f = 0; f < g->nf; ++f) {
    for (PetscInt j = 0; j < g->corners; ++j) fprintf(fp, "%s%d", j ? " " : "            ", (int)g->conn[f * g->corners + j]);
    fprintf(fp, "\n");
  }
  fprintf(fp, "          </DataItem>\n        </Topology>\n");
  fprintf(fp, "        <Geometry GeometryType=\"%s\">\n          <DataItem Format=\"HDF\" DataType=\"Float\" Precision=\"8\" Dimensions=\"%d %d\">%s:/geometry/vertices</DataItem>\n        </Geometry>\n", g->dim == 2 ? "XY" : "XYZ", (int)g->nv, (int)g->dim, g->h5);
  for (PetscInt f = 0; f < 4; ++f) Field(fp, g->h5, SPOutputContactFields[f], 1, k, g->o->nsteps, g->nv);
  if (g->o->frictionFields)
    for (PetscInt f = 0; f < 3; ++f) Field(fp, g->h5, SPOutputFrictionFields[f], f < 2 ? g->dim : 1, k, g->o->nsteps, g->nv);
}

/* Collective. A failed write on rank 0 is returned there (for SPOutputWriteEnd) after the
   broadcast the other ranks wait in. */
PetscErrorCode SPOutputWriteSurfaceXdmf(SPOutput o, SPContact c, PetscBool complete, PetscBool *written)
{
  PetscInt       nf = 0, corners = 0, dim, nv, *conn = NULL;
  Vec            one;
  PetscMPIInt    rank;
  PetscErrorCode ierr = PETSC_SUCCESS;
  char           h5[PETSC_MAX_PATH_LEN + 8], xmf[PETSC_MAX_PATH_LEN + 16];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)o->dm), &rank));
  PetscCall(PetscSNPrintf(xmf, sizeof(xmf), "%s-surface.xmf.part", o->prefix));
  *written = PETSC_FALSE;
  if (!o->contactFields || !o->nsteps || !c || !c->enabled) {
    if (!rank) (void)remove(xmf);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(DMGetDimension(o->dm, &dim));
  PetscCall(DMGetGlobalVector(o->dmS, &one));
  PetscCall(VecGetSize(one, &nv)); /* one value per vertex: the rows of /geometry/vertices */
  PetscCall(DMRestoreGlobalVector(o->dmS, &one));
  PetscCall(GatherFacets(c, o->dm, &nf, &corners, &conn));
  if (!rank && nf > 0) {
    const SurfaceGrid g = {o, h5, dim, nv, nf, corners, conn};
    PetscCall(SPOutputH5Reference(o, complete, h5, sizeof(h5)));
    ierr = SPXdmfWriteCollection(o, xmf, PETSC_FALSE, "contact_surface", "surface_step", SurfaceStep, (void *)&g);
  }
  *written = nf > 0 && !ierr ? PETSC_TRUE : PETSC_FALSE;
  PetscCallMPI(MPI_Bcast(written, 1, MPIU_BOOL, 0, PetscObjectComm((PetscObject)o->dm)));
  PetscCall(PetscFree(conn));
  PetscFunctionReturn(ierr);
}
