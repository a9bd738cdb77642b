/* METIS 5 k-way partition of the cell dual graph, handed to PETSc's shell partitioner.
   The mesh is serial (rank 0 holds every cell) when this runs; other ranks pass empty graphs. */
#include <spcontact-impl.h>
#include <metis.h>

static PetscErrorCode MetisPartition(MPI_Comm comm, PetscInt nv, const PetscInt off[], const PetscInt adj[], PetscInt nparts, PetscInt part[])
{
  idx_t  nvtxs = (idx_t)nv, ncon = 1, np = (idx_t)nparts, objval, options[METIS_NOPTIONS];
  idx_t *xadj, *adjncy, *where;
  int    status;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc3(nv + 1, &xadj, PetscMax(off[nv], 1), &adjncy, nv, &where));
  for (PetscInt i = 0; i <= nv; ++i) xadj[i] = (idx_t)off[i];
  for (PetscInt i = 0; i < off[nv]; ++i) adjncy[i] = (idx_t)adj[i];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_SEED]      = 42; /* reproducible partitions */
  status = METIS_PartGraphKway(&nvtxs, &ncon, xadj, adjncy, NULL, NULL, NULL, &np, NULL, NULL, options, &objval, where);
  PetscCheck(status == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS_PartGraphKway failed with status %d", status);
  for (PetscInt i = 0; i < nv; ++i) part[i] = (PetscInt)where[i];
  PetscCall(PetscFree3(xadj, adjncy, where));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPPartitionerSetMetis(DM dm)
{
  MPI_Comm         comm = PetscObjectComm((PetscObject)dm);
  PetscPartitioner part;
  PetscMPIInt      size;
  PetscInt         nv, *off, *adj, *where, *sizes, *points, *pos, holders = 0, nv1;
  IS               gnum;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(DMPlexCreatePartitionerGraph(dm, 0, &nv, &off, &adj, &gnum));
  nv1 = nv > 0 ? 1 : 0;
  PetscCallMPI(MPI_Allreduce(&nv1, &holders, 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&nv, &nv1, 1, MPIU_INT, MPI_MAX, comm));
  PetscCheck(nv1 >= size, comm, PETSC_ERR_USER_INPUT, "the mesh has %" PetscInt_FMT " cells, fewer than the %d ranks; refine it or use fewer ranks", nv1, (int)size);
  PetscCheck(holders <= 1, comm, PETSC_ERR_SUP, "METIS partitioning expects a serial mesh; use -mesh_partitioner ptscotch for a mesh that is already distributed");
  PetscCall(PetscCalloc4(nv, &where, size, &sizes, nv, &points, size + 1, &pos));
  if (nv > 0) PetscCall(MetisPartition(PETSC_COMM_SELF, nv, off, adj, size, where));
  for (PetscInt i = 0; i < nv; ++i) sizes[where[i]]++;
  for (PetscMPIInt r = 0; r < size; ++r) pos[r + 1] = pos[r] + sizes[r];
  for (PetscInt i = 0; i < nv; ++i) points[pos[where[i]]++] = i;
  PetscCall(DMPlexGetPartitioner(dm, &part));
  PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERSHELL));
  PetscCall(PetscPartitionerShellSetPartition(part, size, sizes, points));
  PetscCall(PetscFree4(where, sizes, points, pos));
  PetscCall(PetscFree(off));
  PetscCall(PetscFree(adj));
  PetscCall(ISDestroy(&gnum));
  PetscFunctionReturn(PETSC_SUCCESS);
}
