/* The size of the mesh to be made, checked before PETSc makes it: the box's options (a count of
   faces or corner coordinates that does not match the dimension stopped PETSc with an error wall,
   a zero or negative face count deep in the cell geometry; one face count in 2D silently gave a
   4 x 2 box) and the uniform refinements (-dm_refine 20 on an 8 x 8 box asked for 7e13 cells and
   ran until the memory was gone: PETSc refines the serial mesh on rank 0 before it is
   distributed). The scale -dm_plex_scale too: a unit change is a factor > 0 (0 or nan were
   refused as flat cells, -1 as inverted cells in 3D, which named the vertex order or the box
   extents, not the option; in 2D -1 turned the mesh half a turn). */
#include <spcontact-impl.h>
#include <unistd.h>

/* A lower bound of the memory a run needs per displacement dof (B4 takes about 3.6 KiB) */
#define SP_MIN_BYTES_PER_DOF 1024.0

/* -dm_plex_box_faces/_lower/_upper of a box of dimension dim; *cells: its number of cells */
static PetscErrorCode CheckBox(MPI_Comm comm, PetscInt dim, PetscBool simplex, PetscReal *cells)
{
  const char *const corner[] = {"-dm_plex_box_lower", "-dm_plex_box_upper"};
  PetscInt          faces[4], n = 4;
  PetscReal         x[4];
  PetscBool         set;

  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < dim; ++d) faces[d] = dim == 1 ? 1 : 4 - dim; /* PETSc's defaults */
  PetscCall(PetscOptionsGetIntArray(NULL, NULL, "-dm_plex_box_faces", faces, &n, &set));
  PetscCheck(!set || n == dim, comm, PETSC_ERR_USER_INPUT, "-dm_plex_box_faces: give %" PetscInt_FMT " face counts for this %" PetscInt_FMT "D box (got %" PetscInt_FMT "), or set -dm_plex_dim", dim, dim, n);
  *cells = simplex ? (dim == 3 ? 6.0 : 2.0) : 1.0;
  for (PetscInt d = 0; d < dim; ++d) {
    PetscCheck(faces[d] >= 1, comm, PETSC_ERR_USER_INPUT, "-dm_plex_box_faces: %" PetscInt_FMT " faces along direction %" PetscInt_FMT "; give at least 1 along each", faces[d], d);
    *cells *= (PetscReal)faces[d];
  }
  for (PetscInt k = 0; k < 2; ++k) {
    n = 4;
    PetscCall(PetscOptionsGetRealArray(NULL, NULL, corner[k], x, &n, &set));
    PetscCheck(!set || n == dim, comm, PETSC_ERR_USER_INPUT, "%s: give %" PetscInt_FMT " coordinates for this %" PetscInt_FMT "D box (got %" PetscInt_FMT "), or set -dm_plex_dim", corner[k], dim, dim, n);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The physical memory of the nodes the job runs on, in bytes (each node counted once) */
static PetscErrorCode JobMemory(MPI_Comm comm, PetscReal *bytes)
{
  MPI_Comm    node;
  PetscMPIInt rank;
  double      mine = 0.0, all;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node));
  PetscCallMPI(MPI_Comm_rank(node, &rank));
  if (!rank) mine = (double)sysconf(_SC_PHYS_PAGES) * (double)sysconf(_SC_PAGE_SIZE);
  PetscCallMPI(MPI_Comm_free(&node));
  PetscCallMPI(MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, comm));
  *bytes = all;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The uniform refinements (-dm_refine, -dm_refine_pre) of a mesh of cells0 cells: each one
   multiplies the cells by 2^dim. Refused where the refined mesh's points (about 2^dim per cell)
   would overflow PETSc's indices, or where its dofs (dim per vertex; a vertex per quadrilateral or
   hexahedron, per 2 triangles, per 6 tetrahedra) could not fit in the job's memory. */
static PetscErrorCode CheckRefinement(MPI_Comm comm, PetscInt dim, PetscBool simplex, PetscReal cells0)
{
  const char *const name[] = {"-dm_refine", "-dm_refine_pre"};
  PetscInt          r[2] = {0, 0};
  PetscReal         cells, dofs, need, have = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < 2; ++k) {
    PetscCall(PetscOptionsGetInt(NULL, NULL, name[k], &r[k], NULL));
    PetscCheck(r[k] >= 0, comm, PETSC_ERR_USER_INPUT, "%s %" PetscInt_FMT ": the number of uniform refinements must be 0 or more", name[k], r[k]);
  }
  if (!r[0] && !r[1]) PetscFunctionReturn(PETSC_SUCCESS);
  cells = cells0 * PetscPowReal(2.0, (PetscReal)(dim * (r[0] + r[1])));
  PetscCheck(cells * PetscPowReal(2.0, (PetscReal)dim) < (PetscReal)PETSC_MAX_INT, comm, PETSC_ERR_USER_INPUT, "%s %" PetscInt_FMT ": the refined mesh would have about %.3g cells, beyond the %d-bit indices of this PETSc build (%.3g mesh points); give fewer refinements", r[0] ? name[0] : name[1], r[0] ? r[0] : r[1], (double)cells, (int)(8 * sizeof(PetscInt)), (double)PETSC_MAX_INT);
  dofs = dim * cells / (simplex ? (dim == 3 ? 6.0 : 2.0) : 1.0);
  need = SP_MIN_BYTES_PER_DOF * dofs;
  PetscCall(JobMemory(comm, &have));
  PetscCheck(have <= 0.0 || need <= have, comm, PETSC_ERR_USER_INPUT, "%s %" PetscInt_FMT ": the refined mesh would have about %.3g cells and %.3g dofs, which need at least %.3g GiB (1 KiB per dof) against the %.3g GiB of memory of this job's nodes; give fewer refinements or more nodes", r[0] ? name[0] : name[1], r[0] ? r[0] : r[1], (double)cells, (double)dofs, (double)(need / 1073741824.0), (double)(have / 1073741824.0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Before DMSetFromOptions, after the dimension's check: dm is the mesh read from a file, or NULL for PETSc's box */
/* -dm_plex_scale L: PETSc multiplies the coordinates by L (README: a change of units) */
static PetscErrorCode CheckScale(MPI_Comm comm)
{
  PetscReal L = 1.0;
  PetscBool set;
  char      given[64] = "";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-dm_plex_scale", given, sizeof(given), NULL)); /* as given, for the line */
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-dm_plex_scale", &L, &set));
  PetscCheck(!set || (L > 0.0 && !PetscIsInfOrNanReal(L)), comm, PETSC_ERR_USER_INPUT, "-dm_plex_scale %s: must be a finite factor > 0 (it multiplies the mesh coordinates, a change of units: scale E, the loads and the Dirichlet values with it)", given);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPMeshCheckSize(MPI_Comm comm, DM dm)
{
  PetscInt  dim = 2, cStart = 0, cEnd = 0;
  PetscBool simplex = PETSC_FALSE;
  PetscReal cells;

  PetscFunctionBeginUser;
  PetscCall(CheckScale(comm));
  if (dm) {
    PetscCall(DMGetDimension(dm, &dim));
    PetscCall(SPMeshIsSimplex(dm, &simplex));
    PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
    cells = (PetscReal)(cEnd - cStart);
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &cells, 1, MPIU_REAL, MPIU_SUM, comm));
  } else {
    PetscCall(PetscOptionsGetInt(NULL, NULL, "-dm_plex_dim", &dim, NULL));
    PetscCall(PetscOptionsGetBool(NULL, NULL, "-dm_plex_simplex", &simplex, NULL)); /* -dm_plex_dim: 2 or 3 (mesh.c) */
    PetscCall(CheckBox(comm, dim, simplex, &cells));
  }
  PetscCall(CheckRefinement(comm, dim, simplex, cells));
  PetscFunctionReturn(PETSC_SUCCESS);
}
