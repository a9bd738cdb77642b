/* Partition-independent vectors for restart files. Items (mesh points with displacement dofs,
   contact points) are named by their point numbers in the serial mesh (SPMeshGetSerialNumbers);
   an item's position in the file is the count of items, over all ranks, with smaller serial
   numbers, so a file written on any rank count is read on any other. Each item holds bs reals. */
#include <spcontact-impl.h>

/* pos[i] = number of items of all ranks named below sid[i] (names unique over the ranks); *N the
   items' total. A distributed mark vector over the serial numbers: O(points / ranks) memory. */
static PetscErrorCode Positions(MPI_Comm comm, PetscInt n, const PetscInt sid[], PetscInt pos[], PetscInt *N)
{
  Vec          marks, mine;
  VecScatter   sc;
  IS           from;
  PetscInt     smax = -1, nser, lo, hi, cnt = 0, off = 0;
  PetscScalar *a;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < n; ++i) smax = PetscMax(smax, sid[i]);
  PetscCallMPI(MPI_Allreduce(&smax, &nser, 1, MPIU_INT, MPI_MAX, comm));
  nser += 1;
  PetscCall(VecCreateMPI(comm, PETSC_DECIDE, PetscMax(nser, 1), &marks));
  PetscCall(VecSet(marks, 0.0));
  for (PetscInt i = 0; i < n; ++i) PetscCall(VecSetValue(marks, sid[i], 1.0, INSERT_VALUES));
  PetscCall(VecAssemblyBegin(marks));
  PetscCall(VecAssemblyEnd(marks));
  PetscCall(VecGetOwnershipRange(marks, &lo, &hi));
  PetscCall(VecGetArray(marks, &a));
  for (PetscInt k = 0; k < hi - lo; ++k) cnt += PetscRealPart(a[k]) != 0.0;
  PetscCallMPI(MPI_Exscan(&cnt, &off, 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&cnt, N, 1, MPIU_INT, MPI_SUM, comm));
  {
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(comm, &rank));
    if (!rank) off = 0; /* MPI_Exscan leaves rank 0's result undefined */
  }
  for (PetscInt k = 0; k < hi - lo; ++k) a[k] = PetscRealPart(a[k]) != 0.0 ? (PetscScalar)(off++) : -1.0;
  PetscCall(VecRestoreArray(marks, &a));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, n, &mine));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, sid, PETSC_COPY_VALUES, &from));
  PetscCall(VecScatterCreate(marks, from, mine, NULL, &sc));
  PetscCall(VecScatterBegin(sc, marks, mine, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, marks, mine, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArray(mine, &a));
  for (PetscInt i = 0; i < n; ++i) pos[i] = (PetscInt)PetscRealPart(a[i]);
  PetscCall(VecRestoreArray(mine, &a));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(ISDestroy(&from));
  PetscCall(VecDestroy(&mine));
  PetscCall(VecDestroy(&marks));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPNaturalCreate(MPI_Comm comm, PetscInt n, const PetscInt sid[], PetscInt bs, SPNatural *nat)
{
  PetscFunctionBeginUser;
  nat->comm = comm;
  nat->n    = n;
  nat->bs   = bs;
  PetscCall(PetscMalloc1(n + 1, &nat->idx));
  PetscCall(Positions(comm, n, sid, nat->idx, &nat->N));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The file's vector: N items of bs reals, in the viewer's current group and timestep */
static PetscErrorCode FileVec(SPNatural *nat, const char name[], Vec *v)
{
  PetscFunctionBeginUser;
  PetscCall(VecCreate(nat->comm, v));
  PetscCall(VecSetSizes(*v, PETSC_DECIDE, nat->N * nat->bs));
  PetscCall(VecSetBlockSize(*v, nat->bs));
  PetscCall(VecSetType(*v, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)*v, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* vals: n items of bs reals, this rank's */
PetscErrorCode SPNaturalWrite(SPNatural *nat, PetscViewer h5, const char name[], const PetscReal vals[])
{
  Vec v;

  PetscFunctionBeginUser;
  PetscCall(FileVec(nat, name, &v));
  for (PetscInt i = 0; i < nat->n; ++i)
    for (PetscInt j = 0; j < nat->bs; ++j) PetscCall(VecSetValue(v, nat->idx[i] * nat->bs + j, vals[i * nat->bs + j], INSERT_VALUES));
  PetscCall(VecAssemblyBegin(v));
  PetscCall(VecAssemblyEnd(v));
  PetscCall(VecView(v, h5));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPNaturalRead(SPNatural *nat, PetscViewer h5, const char name[], PetscReal vals[])
{
  Vec          v, mine;
  VecScatter   sc;
  IS           from;
  PetscInt    *idx;
  PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(FileVec(nat, name, &v));
  PetscCall(VecLoad(v, h5));
  PetscCall(PetscMalloc1(nat->n * nat->bs + 1, &idx));
  for (PetscInt i = 0; i < nat->n; ++i)
    for (PetscInt j = 0; j < nat->bs; ++j) idx[i * nat->bs + j] = nat->idx[i] * nat->bs + j;
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, nat->n * nat->bs, idx, PETSC_OWN_POINTER, &from));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, nat->n * nat->bs, &mine));
  PetscCall(VecScatterCreate(v, from, mine, NULL, &sc));
  PetscCall(VecScatterBegin(sc, v, mine, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, v, mine, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArray(mine, &a));
  for (PetscInt k = 0; k < nat->n * nat->bs; ++k) vals[k] = PetscRealPart(a[k]);
  PetscCall(VecRestoreArray(mine, &a));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(ISDestroy(&from));
  PetscCall(VecDestroy(&mine));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPNaturalDestroy(SPNatural *nat)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(nat->idx));
  PetscFunctionReturn(PETSC_SUCCESS);
}
