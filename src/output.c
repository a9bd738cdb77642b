/* Output: one HDF5 file per run (mesh once, then per load step the vertex fields displacement
   and, with contact, contact_pressure, gap, shift, active; with friction (any obstacle or pair
   with mu > 0) also tangential_traction and slip (vectors) and status (0 open, 1 stick, 2 slip, 3 closed without friction,
   -1 on vertices that are not contact points)), an XDMF file beside it for ParaView,
   and the CSV Newton history. Files are written as *.part and renamed only when the run completes,
   so a failed or interrupted run never leaves a file that looks complete; the h5's root attribute
   status says complete / failed / interrupted. */
#include <spcontact-impl.h>
#include <petscviewerhdf5.h>
#include <errno.h>
#include <string.h>

static const char *const ContactFields[] = {"contact_pressure", "gap", "shift", "active"};
static const char *const FrictionFields[] = {"tangential_traction", "slip", "status"};

PetscErrorCode SPOutputCreate(DM dm, SPOutput *out)
{
  SPOutput o;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&o));
  o->dm      = dm;
  o->enabled = PETSC_TRUE;
  PetscCall(PetscStrcpy(o->dir, "output"));
  PetscCall(PetscStrcpy(o->name, "spcontact"));
  *out = o;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPOutputSetFromOptions(SPOutput o)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(PetscObjectComm((PetscObject)o->dm), NULL, "Output options", "spcontact");
  PetscCall(PetscOptionsString("-output_dir", "Directory for the .h5, .xmf and .csv files (created if missing)", "SPOutputSetFromOptions", o->dir, o->dir, sizeof(o->dir), NULL));
  PetscCall(PetscOptionsString("-output_name", "Base name of the output files (sub/name: in the subdirectory sub of -output_dir, created if missing)", "SPOutputSetFromOptions", o->name, o->name, sizeof(o->name), NULL));
  PetscCall(PetscOptionsBool("-output_fields", "Write the HDF5/XDMF fields (the CSV history is always written)", "SPOutputSetFromOptions", o->enabled, &o->enabled, NULL));
  PetscOptionsEnd();
  PetscCall(PetscSNPrintf(o->prefix, sizeof(o->prefix), "%s/%s", o->dir, o->name));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A clone of the mesh with nc dofs on every vertex (one field), for vertex output */
static PetscErrorCode VertexDM(DM dm, PetscInt nc, DM *dmV)
{
  PetscSection s;
  PetscInt     pStart, pEnd, vStart, vEnd;

  PetscFunctionBeginUser;
  PetscCall(DMClone(dm, dmV));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)dm), &s));
  PetscCall(PetscSectionSetNumFields(s, 1));
  PetscCall(PetscSectionSetFieldComponents(s, 0, nc));
  PetscCall(PetscSectionSetChart(s, pStart, pEnd));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscCall(PetscSectionSetDof(s, v, nc));
    PetscCall(PetscSectionSetFieldDof(s, v, 0, nc));
  }
  PetscCall(PetscSectionSetUp(s));
  PetscCall(DMSetLocalSection(*dmV, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The CSV history's header (rank 0 writes it) */
static PetscErrorCode OpenHistory(SPOutput o, const char file[])
{
  MPI_Comm comm = PetscObjectComm((PetscObject)o->dm);

  PetscFunctionBeginUser;
  PetscCall(PetscFOpen(comm, file, "w", &o->csv));
  PetscCall(PetscFPrintf(comm, o->csv, "step,augmentation,iteration,residual_norm,active_points,max_penetration,max_shift_change,linear_iterations,stick_points,slip_points,max_stick_creep\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The h5 file with the mesh */
static PetscErrorCode OpenFields(SPOutput o, const char file[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5Open(PetscObjectComm((PetscObject)o->dm), file, FILE_MODE_WRITE, &o->h5));
  PetscCall(PetscViewerPushFormat(o->h5, PETSC_VIEWER_HDF5_XDMF));
  PetscCall(DMView(o->dm, o->h5));
  PetscCall(PetscViewerHDF5PushTimestepping(o->h5));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPOutputOpen(SPOutput o)
{
  char     file[PETSC_MAX_PATH_LEN + 16];
  PetscInt dim;

  PetscFunctionBeginUser;
  PetscCall(SPOutputCheckFiles(o));
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s.csv.part", o->prefix));
  PetscCall(SPOutputWriteBegin(o, file, PETSC_FALSE));
  PetscCall(SPOutputWriteEnd(o, OpenHistory(o, file)));
  if (!o->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(DMGetDimension(o->dm, &dim));
  PetscCall(VertexDM(o->dm, dim, &o->dmV));
  PetscCall(VertexDM(o->dm, 1, &o->dmS));
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s.h5.part", o->prefix));
  PetscCall(SPOutputWriteBegin(o, file, PETSC_TRUE));
  PetscCall(SPOutputWriteEnd(o, OpenFields(o, file)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPOutputGetHistoryFile(SPOutput o, FILE **fp)
{
  PetscFunctionBeginUser;
  *fp = o->csv;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Vertex values of the displacement (any Lagrange degree: the vertex dofs), with Dirichlet values */
static PetscErrorCode VertexDisplacement(SPOutput o, SPProblem problem, Vec u, Vec uV)
{
  DM                 dm = o->dm;
  PetscSection       ls, gsV;
  PetscInt           vStart, vEnd, dim, rstart;
  Vec                locX;
  const PetscScalar *x;
  PetscScalar       *y;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMGetLocalSection(dm, &ls));
  PetscCall(DMGetGlobalSection(o->dmV, &gsV));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(VecGetOwnershipRange(uV, &rstart, NULL));
  PetscCall(SPProblemGetLocalState(problem, u, &locX));
  PetscCall(VecGetArrayRead(locX, &x));
  PetscCall(VecGetArray(uV, &y));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt goff, off;
    PetscCall(PetscSectionGetOffset(gsV, v, &goff));
    if (goff < 0) continue;
    PetscCall(PetscSectionGetOffset(ls, v, &off));
    for (PetscInt d = 0; d < dim; ++d) y[goff - rstart + d] = x[off + d];
  }
  PetscCall(VecRestoreArray(uV, &y));
  PetscCall(VecRestoreArrayRead(locX, &x));
  PetscCall(SPProblemRestoreLocalState(problem, &locX));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteFields(SPOutput o, SPProblem problem, Vec u, SPContact contact)
{
  Vec       uV, f[4];
  PetscBool on;
  PetscReal load;

  PetscFunctionBeginUser;
  PetscCall(SPProblemGetLoadFactor(problem, &load));
  PetscCall(PetscViewerHDF5SetTimestep(o->h5, o->nsteps));
  if (o->nsteps == o->maxSteps) { /* the load factors of the steps, for the XDMF: grown by doubling */
    o->maxSteps = o->maxSteps ? 2 * o->maxSteps : 64;
    PetscCall(PetscRealloc(o->maxSteps * sizeof(PetscReal), &o->times));
  }
  o->times[o->nsteps++] = load;
  PetscCall(DMGetGlobalVector(o->dmV, &uV));
  PetscCall(PetscObjectSetName((PetscObject)uV, "displacement"));
  PetscCall(VertexDisplacement(o, problem, u, uV));
  PetscCall(VecView(uV, o->h5));
  PetscCall(DMRestoreGlobalVector(o->dmV, &uV));
  PetscCall(SPContactIsActive(contact, &on));
  if (!on) PetscFunctionReturn(PETSC_SUCCESS);
  o->contactFields = PETSC_TRUE;
  for (PetscInt k = 0; k < 4; ++k) {
    PetscCall(DMGetGlobalVector(o->dmS, &f[k]));
    PetscCall(PetscObjectSetName((PetscObject)f[k], ContactFields[k]));
  }
  PetscCall(SPContactGetFields(contact, u, f[0], f[1], f[2], f[3]));
  for (PetscInt k = 0; k < 4; ++k) {
    PetscCall(VecView(f[k], o->h5));
    PetscCall(DMRestoreGlobalVector(o->dmS, &f[k]));
  }
  PetscCall(SPContactHasFriction(contact, &on));
  if (!on) PetscFunctionReturn(PETSC_SUCCESS);
  o->frictionFields = PETSC_TRUE;
  PetscCall(DMGetGlobalVector(o->dmV, &f[0]));
  PetscCall(DMGetGlobalVector(o->dmV, &f[1]));
  PetscCall(DMGetGlobalVector(o->dmS, &f[2]));
  for (PetscInt k = 0; k < 3; ++k) PetscCall(PetscObjectSetName((PetscObject)f[k], FrictionFields[k]));
  PetscCall(SPContactGetFrictionFields(contact, u, f[0], f[1], f[2]));
  for (PetscInt k = 0; k < 3; ++k) PetscCall(VecView(f[k], o->h5));
  PetscCall(DMRestoreGlobalVector(o->dmV, &f[0]));
  PetscCall(DMRestoreGlobalVector(o->dmV, &f[1]));
  PetscCall(DMRestoreGlobalVector(o->dmS, &f[2]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* rank 0: the step's lines of the CSV history reached the file */
static PetscErrorCode FlushHistory(SPOutput o, PetscBool close)
{
  PetscMPIInt rank;
  FILE       *fp = o->csv;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)o->dm), &rank));
  if (close) o->csv = NULL; /* closed below, whatever happens */
  if (!rank && fp) PetscCall(SPOutputCheckStream(fp, o->guard.file, close));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A converged step: its fields in the h5 (with -output_fields), its history lines flushed */
PetscErrorCode SPOutputWriteStep(SPOutput o, SPProblem problem, Vec u, SPContact contact)
{
  char file[PETSC_MAX_PATH_LEN + 16];

  PetscFunctionBeginUser;
  PetscCall(SPOutputRemoveEarlierResults(o));
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s.csv.part", o->prefix));
  PetscCall(SPOutputWriteBegin(o, file, PETSC_FALSE));
  PetscCall(SPOutputWriteEnd(o, FlushHistory(o, PETSC_FALSE)));
  if (!o->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s.h5.part", o->prefix));
  PetscCall(SPOutputWriteBegin(o, file, PETSC_TRUE));
  PetscCall(SPOutputWriteEnd(o, WriteFields(o, problem, u, contact)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPOutputGetPrefix(SPOutput o, const char **prefix)
{
  PetscFunctionBeginUser;
  *prefix = o->prefix;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPOutputDestroy(SPOutput *out)
{
  SPOutput o = *out;

  PetscFunctionBeginUser;
  if (!o) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscViewerDestroy(&o->h5));
  PetscCall(DMDestroy(&o->dmV));
  PetscCall(DMDestroy(&o->dmS));
  PetscCall(PetscFree(o->times));
  PetscCall(PetscFree(*out));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPOutputGetPointsFile(SPOutput o, char file[], size_t len)
{
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(file, len, "%s_contact.csv.part", o->prefix));
  o->pointsFile = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rank 0: every *.part file of the run to its final name, or none: a failed rename undoes the
   ones before it. *failed: the index of the failing file + 1 (0: all renamed), errno in *err. */
static PetscErrorCode RenameAll(SPOutput o, const char *const files[], PetscInt n, PetscInt *failed, int *err)
{
  char from[PETSC_MAX_PATH_LEN + 32], to[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBeginUser;
  *failed = 0;
  for (PetscInt k = 0; k < n && !*failed; ++k) {
    PetscCall(PetscSNPrintf(from, sizeof(from), "%s%s.part", o->prefix, files[k]));
    PetscCall(PetscSNPrintf(to, sizeof(to), "%s%s", o->prefix, files[k]));
    if (rename(from, to)) *failed = k + 1, *err = errno;
  }
  for (PetscInt k = *failed - 2; k >= 0; --k) { /* undo */
    PetscCall(PetscSNPrintf(from, sizeof(from), "%s%s.part", o->prefix, files[k]));
    PetscCall(PetscSNPrintf(to, sizeof(to), "%s%s", o->prefix, files[k]));
    (void)rename(to, from);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The run's status (complete / failed / interrupted), last converged step and load factor as
   attributes of the h5 root group */
static PetscErrorCode WriteStatus(SPOutput o, const char status[], PetscInt step, PetscReal load)
{
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5WriteAttribute(o->h5, "/", "status", PETSC_STRING, status));
  PetscCall(PetscViewerHDF5WriteAttribute(o->h5, "/", "last_step", PETSC_INT, &step));
  PetscCall(PetscViewerHDF5WriteAttribute(o->h5, "/", "last_load_factor", PETSC_REAL, &load));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The h5's status attributes, then the file closed */
static PetscErrorCode CloseFields(SPOutput o, const char status[], PetscInt step, PetscReal load)
{
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5PopTimestepping(o->h5));
  PetscCall(WriteStatus(o, status, step, load));
  PetscCall(PetscViewerPopFormat(o->h5));
  PetscCall(PetscViewerDestroy(&o->h5));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Finish the files: the status attribute, the XDMF (volume for both readers, contact surface);
   only a complete run renames its *.part files (h5, xmf, csv history, contact-points csv) to their
   final names, all or none. A failed or
   interrupted run keeps the .part names; its h5 holds every converged step (readable). */
PetscErrorCode SPOutputClose(SPOutput o, SPContact contact, const char status[], PetscInt step, PetscReal load)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)o->dm);
  PetscMPIInt rank;
  PetscBool   complete, surface = PETSC_FALSE;
  const char *files[6];
  PetscInt    n = 0, failed = 0;
  int         err = 0;
  char        file[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBeginUser;
  PetscCall(PetscStrcmp(status, "complete", &complete));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s.csv.part", o->prefix));
  PetscCall(SPOutputWriteBegin(o, file, PETSC_FALSE));
  PetscCall(SPOutputWriteEnd(o, FlushHistory(o, PETSC_TRUE)));
  if (o->h5) {
    PetscCall(PetscSNPrintf(file, sizeof(file), "%s.h5.part", o->prefix));
    PetscCall(SPOutputWriteBegin(o, file, PETSC_TRUE));
    PetscCall(SPOutputWriteEnd(o, CloseFields(o, status, step, load)));
  }
  if (o->enabled) {
    PetscCall(PetscSNPrintf(file, sizeof(file), "%s.xmf.part", o->prefix));
    PetscCall(SPOutputWriteBegin(o, file, PETSC_FALSE));
    PetscCall(SPOutputWriteEnd(o, SPOutputWriteXdmf(o, complete)));
    PetscCall(PetscSNPrintf(file, sizeof(file), "%s-surface.xmf.part", o->prefix));
    PetscCall(SPOutputWriteBegin(o, file, PETSC_FALSE));
    PetscCall(SPOutputWriteEnd(o, SPOutputWriteSurfaceXdmf(o, contact, complete, &surface)));
  }
  if (!complete) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPOutputRemoveEarlierResults(o)); /* done at the first step; a run always has one */
  files[n++] = ".csv";
  if (o->pointsFile) files[n++] = "_contact.csv";
  if (o->enabled) files[n++] = ".xmf", files[n++] = "-xdmf2.xmf";
  if (surface) files[n++] = "-surface.xmf";
  if (o->enabled) files[n++] = ".h5";
  if (rank == 0) PetscCall(RenameAll(o, files, n, &failed, &err));
  PetscCallMPI(MPI_Bcast(&failed, 1, MPIU_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCheck(!failed, comm, PETSC_ERR_USER_INPUT, "cannot rename %s%s.part to %s%s (%s); the complete results stay under their .part names", o->prefix, files[failed - 1], o->prefix, files[failed - 1], strerror(err));
  PetscFunctionReturn(PETSC_SUCCESS);
}
