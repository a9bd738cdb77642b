#define _XOPEN_SOURCE 700 /* realpath */
/* Restart data: after every converged load step the h5 gets, as timestep k of the group /restart,
   everything the next step needs: the displacement (displacement: the global vector's values of
   every mesh point that has unconstrained dofs, padded to the largest count), every contact
   point's state (points: SP_POINT_NPACK reals each: shifts or multipliers, committed slip and
   friction anchors, status, ...), both in an order free of the partition (restart-natural.c:
   items by serial mesh point number), and per rank of the writing run the loop's and the
   counters' state (counters: load factor, increment, step, cut-backs, Newton/linear/function
   counts, contact counters, contact centre). Attributes of /restart name the run (format,
   dimension, dofs, contact points, ranks, method, friction, load steps) and the number of steps
   stored. A restart needs the same mesh and options (checked, one line each), on any rank count.
   -restart <file.h5> loads the last stored step before the output files are opened; the restarted
   run's file holds the steps after it (root attributes first_step, restarted_from). */
#include <spcontact-impl.h>
#include <petscviewerhdf5.h>
#include <hdf5.h>
#include <stdlib.h>
#include <sys/stat.h>

#define NCOUNT  36 /* reals per rank in /restart/counters */
#define NCOUNT9 35 /* format 9: without the Schur update's back-substitutions */
#define NCOUNT8 29 /* format 8: without the solver's reuse counters and the accelerated updates */
#define NCOUNT7 28 /* format 7: without the chatter holds */
#define NCOUNT6 27 /* format 6: without the direct solver's step */

/* A plain (DM-less) copy of the layout of n local reals with block size bs: VecView writes it raw */
static PetscErrorCode PlainVec(MPI_Comm comm, PetscInt n, PetscInt bs, const char name[], Vec *v)
{
  PetscFunctionBeginUser;
  PetscCall(VecCreate(comm, v));
  PetscCall(VecSetSizes(*v, n * bs, PETSC_DECIDE));
  PetscCall(VecSetBlockSize(*v, bs));
  PetscCall(VecSetType(*v, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)*v, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The counters record, one direction or the other */
static PetscErrorCode Counters(PetscBool pack, SPApp a, PetscReal *inc, PetscReal b[])
{
  SPSolver  s = a->solver;
  SPContact c = a->contact;
  PetscInt  accelSteps;

  PetscFunctionBeginUser;
  PetscCall(SPContactGetAccelSteps(c, &accelSteps));
  PetscReal v[NCOUNT] = {a->loadReached, *inc, (PetscReal)a->stepsDone, (PetscReal)a->cutbacks, (PetscReal)s->newtonTotal, (PetscReal)s->linearTotal, (PetscReal)s->funcTotal, (PetscReal)c->evaluations, (PetscReal)c->stepLimits, (PetscReal)c->shiftUpdates, (PetscReal)c->exchanges, (PetscReal)c->received, (PetscReal)c->rebuilds, (PetscReal)c->stats.augmentations, (PetscReal)c->centreSet, c->centre[0], c->centre[1], c->centre[2], (PetscReal)c->exchangeTime, s->fscale, (PetscReal)a->streak, (PetscReal)c->capRetries, (PetscReal)s->reorthogonalise, a->loadBefore, (PetscReal)c->havePrev, (PetscReal)c->predictions, (PetscReal)c->jumpWaits, (PetscReal)s->directStep, (PetscReal)c->chatterHolds, (PetscReal)s->jacReuses, (PetscReal)s->pcKeeps, (PetscReal)s->refinedSteps, (PetscReal)s->refinedLinear, (PetscReal)s->accepted, (PetscReal)accelSteps, (PetscReal)c->schurSolves};

  if (pack) {
    for (PetscInt k = 0; k < NCOUNT; ++k) b[k] = v[k];
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  a->loadReached = b[0], *inc = b[1], a->stepsDone = (PetscInt)b[2], a->cutbacks = (PetscInt)b[3];
  s->newtonTotal = (PetscInt)b[4], s->linearTotal = (PetscInt)b[5], s->funcTotal = (PetscInt)b[6];
  c->evaluations = (PetscInt)b[7], c->stepLimits = (PetscInt)b[8], c->shiftUpdates = (PetscInt)b[9];
  c->exchanges = (PetscInt)b[10], c->received = (PetscInt64)b[11], c->rebuilds = (PetscInt)b[12];
  c->stats.augmentations = (PetscInt)b[13], c->centreSet = b[14] != 0.0 ? PETSC_TRUE : PETSC_FALSE;
  for (PetscInt d = 0; d < 3; ++d) c->centre[d] = b[15 + d];
  c->exchangeTime = b[18];
  s->fscale       = b[19]; /* the residual tolerance's scale: the largest initial |F| of the run */
  a->streak       = (PetscInt)b[20]; /* converged steps since the last cut-back or growth */
  c->capRetries      = (PetscInt)b[21]; /* steps solved again with a tighter step cap */
  s->reorthogonalise = b[22] != 0.0 ? PETSC_TRUE : PETSC_FALSE; /* applied by LoadCounters */
  a->loadBefore      = b[23]; /* the stuck points' predictor: the converged load before loadReached */
  c->havePrev        = b[24] != 0.0 ? PETSC_TRUE : PETSC_FALSE;
  c->predictions     = (PetscInt)b[25];
  c->jumpWaits       = (PetscInt)b[26]; /* shift updates held back after a stick/slip jump */
  s->directStep      = (PetscInt)b[27]; /* the switch to LU (applied by LoadCounters; 0: none) */
  c->chatterHolds    = (PetscInt)b[28]; /* points kept closed by the chatter hold */
  s->jacReuses       = (PetscInt)b[29]; /* format 9: the summary's reuse counters */
  s->pcKeeps         = (PetscInt)b[30];
  s->refinedSteps    = (PetscInt)b[31];
  s->refinedLinear   = (PetscInt)b[32];
  s->accepted        = (PetscInt)b[33];
  c->accelStepsBefore = (PetscInt)b[34]; /* the accelerated updates before the restart */
  c->schurSolves      = (PetscInt)b[35]; /* format 10: the Schur update's back-substitutions */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The run's identity, as attributes of /restart: written with the first step, compared on restart */
#define FORMAT 10 /* 1: vectors in the partition's order (same rank count only); 2: partition-free; 3: + the growth streak; 4: + the recoveries (step-cap retries, GMRES re-orthogonalisation); 5: + the stuck points' predictor (the step before the last); 6: + the stick/slip jump waits; 7: + the direct solver's step; 8: + the chatter holds; 9: + the solver's reuse counters and the accelerated updates; 10: + the Schur update's back-substitutions (6 to 9 are read too) */

typedef struct {
  PetscInt dim, dofs, points, ranks, friction, loadSteps;
  char     method[64];
} Identity;

static PetscErrorCode GetIdentity(SPApp a, Identity *id)
{
  PetscMPIInt size;
  PetscInt    n = a->contact->enabled ? a->contact->n : 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(id, sizeof(*id)));
  PetscCallMPI(MPI_Comm_size(a->comm, &size));
  PetscCall(DMGetDimension(a->dm, &id->dim));
  PetscCall(VecGetSize(a->u, &id->dofs));
  PetscCallMPI(MPI_Allreduce(&n, &id->points, 1, MPIU_INT, MPI_SUM, a->comm));
  id->ranks     = size;
  id->friction  = a->contact->enabled && a->contact->friction;
  id->loadSteps = a->loadSteps;
  PetscCall(PetscStrncpy(id->method, a->contact->enabled ? a->contact->method->name : "none", sizeof(id->method)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const char *const IdNames[] = {"dim", "dofs", "contact_points", "ranks", "friction", "load_steps"};

static PetscErrorCode WriteIdentity(SPApp a, PetscViewer h5, const Identity *id)
{
  const PetscInt v[6] = {id->dim, id->dofs, id->points, id->ranks, id->friction, id->loadSteps};
  const PetscInt format = FORMAT;
  char          *physics, geometry[512];

  PetscFunctionBeginUser;
  PetscCall(SPRestartPhysicsOptions(a, &physics));
  PetscCall(PetscViewerHDF5WriteAttribute(h5, "/restart", "physics_options", PETSC_STRING, physics));
  PetscCall(PetscFree(physics));
  PetscCall(SPRestartMeshGeometry(a->dm, geometry, sizeof(geometry)));
  PetscCall(PetscViewerHDF5WriteAttribute(h5, "/restart", "mesh_geometry", PETSC_STRING, geometry));
  PetscCall(PetscViewerHDF5WriteAttribute(h5, "/restart", "format", PETSC_INT, &format));
  for (PetscInt k = 0; k < 6; ++k) PetscCall(PetscViewerHDF5WriteAttribute(h5, "/restart", IdNames[k], PETSC_INT, &v[k]));
  PetscCall(PetscViewerHDF5WriteAttribute(h5, "/restart", "method", PETSC_STRING, id->method));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The displacement's items: this rank's mesh points with unconstrained dofs (their global offsets
   and counts), named by serial point number; bs the largest count over the ranks */
typedef struct {
  SPNatural nat;
  PetscInt *off, *cnt;
} DofItems;

static PetscErrorCode DofItemsCreate(SPApp a, DofItems *it)
{
  PetscSection    gs;
  PetscInt        pStart, pEnd, n = 0, bs = 0, bsAll, rstart, *sid;
  const PetscInt *serial;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(a->dm, &gs));
  PetscCall(PetscSectionGetChart(gs, &pStart, &pEnd));
  PetscCall(VecGetOwnershipRange(a->u, &rstart, NULL));
  PetscCall(SPMeshGetSerialNumbers(a->dm, &serial));
  PetscCall(PetscMalloc1(pEnd - pStart + 1, &sid));
  PetscCall(PetscMalloc2(pEnd - pStart + 1, &it->off, pEnd - pStart + 1, &it->cnt));
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt dof, cdof, off;
    PetscCall(PetscSectionGetDof(gs, p, &dof));
    PetscCall(PetscSectionGetConstraintDof(gs, p, &cdof));
    PetscCall(PetscSectionGetOffset(gs, p, &off));
    if (dof <= 0 || off < 0 || dof - cdof <= 0) continue; /* no dofs, not owned, or all constrained */
    sid[n] = serial[p - pStart], it->off[n] = off - rstart, it->cnt[n] = dof - cdof;
    bs     = PetscMax(bs, dof - cdof);
    n++;
  }
  PetscCallMPI(MPI_Allreduce(&bs, &bsAll, 1, MPIU_INT, MPI_MAX, a->comm));
  PetscCall(SPNaturalCreate(a->comm, n, sid, bsAll, &it->nat));
  PetscCall(PetscFree(sid));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode DofItemsDestroy(DofItems *it)
{
  PetscFunctionBeginUser;
  PetscCall(SPNaturalDestroy(&it->nat));
  PetscCall(PetscFree2(it->off, it->cnt));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The displacement to (pack) or from the items' values (bs per item, padded with zeros) */
static PetscErrorCode DofValues(PetscBool pack, SPApp a, DofItems *it, PetscReal vals[])
{
  PetscScalar *u;
  const PetscInt bs = it->nat.bs;

  PetscFunctionBeginUser;
  PetscCall(VecGetArray(a->u, &u));
  for (PetscInt i = 0; i < it->nat.n; ++i)
    for (PetscInt j = 0; j < bs; ++j) {
      if (pack) vals[i * bs + j] = j < it->cnt[i] ? PetscRealPart(u[it->off[i] + j]) : 0.0;
      else if (j < it->cnt[i]) u[it->off[i] + j] = vals[i * bs + j];
    }
  PetscCall(VecRestoreArray(a->u, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The contact points as items: named by their vertices' serial numbers */
static PetscErrorCode PointItems(SPApp a, SPNatural *nat)
{
  SPContact       c = a->contact;
  PetscInt        n = c->enabled ? c->n : 0, *sid;
  const PetscInt *serial;

  PetscFunctionBeginUser;
  PetscCall(SPMeshGetSerialNumbers(a->dm, &serial));
  PetscCall(PetscMalloc1(n + 1, &sid));
  for (PetscInt i = 0; i < n; ++i) sid[i] = serial[c->pt[i].vertex];
  PetscCall(SPNaturalCreate(a->comm, n, sid, SP_POINT_NPACK, nat));
  PetscCall(PetscFree(sid));
  PetscFunctionReturn(PETSC_SUCCESS);
}
/* After converged step a->stepsDone was written (output timestep nsteps - 1): its restart data */
static PetscErrorCode WriteStep(SPApp a, PetscReal inc)
{
  SPOutput     o = a->output;
  SPContact    c = a->contact;
  Vec          v;
  PetscScalar *x;
  PetscReal   *vals;
  PetscInt     steps = o->nsteps;
  DofItems     dofs;
  SPNatural    pts;
  hid_t        fid;

  PetscFunctionBeginUser;
  if (!o->enabled || !o->h5) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscViewerHDF5SetTimestep(o->h5, o->nsteps - 1));
  PetscCall(PetscViewerHDF5PushGroup(o->h5, "/restart"));
  PetscCall(DofItemsCreate(a, &dofs));
  PetscCall(PetscMalloc1(dofs.nat.n * dofs.nat.bs + 1, &vals));
  PetscCall(DofValues(PETSC_TRUE, a, &dofs, vals));
  PetscCall(SPNaturalWrite(&dofs.nat, o->h5, "displacement", vals));
  PetscCall(PetscFree(vals));
  PetscCall(DofItemsDestroy(&dofs));
  PetscCall(PointItems(a, &pts));
  PetscCall(PetscMalloc1(pts.n * SP_POINT_NPACK + 1, &vals));
  if (pts.n) PetscCall(SPContactPackPoints(c, vals));
  PetscCall(SPNaturalWrite(&pts, o->h5, "points", vals));
  PetscCall(PetscFree(vals));
  PetscCall(SPNaturalDestroy(&pts));
  PetscCall(PlainVec(a->comm, 1, NCOUNT, "counters", &v));
  PetscCall(VecGetArray(v, &x));
  PetscCall(Counters(PETSC_TRUE, a, &inc, x));
  PetscCall(VecRestoreArray(v, &x));
  PetscCall(VecView(v, o->h5));
  PetscCall(VecDestroy(&v));
  PetscCall(PetscViewerHDF5PopGroup(o->h5));
  if (steps == 1) { /* a restarted run's file starts after the restored step: say where from */
    Identity id;
    PetscInt first = a->stepsDone;
    PetscCall(GetIdentity(a, &id));
    PetscCall(WriteIdentity(a, o->h5, &id));
    PetscCall(PetscViewerHDF5WriteAttribute(o->h5, "/", "first_step", PETSC_INT, &first));
    if (a->restartFile[0]) PetscCall(PetscViewerHDF5WriteAttribute(o->h5, "/", "restarted_from", PETSC_STRING, a->restartFile));
  }
  PetscCall(PetscViewerHDF5WriteAttribute(o->h5, "/restart", "steps", PETSC_INT, &steps));
  PetscCall(PetscViewerHDF5GetFileId(o->h5, &fid));
  PetscCheck(H5Fflush(fid, H5F_SCOPE_GLOBAL) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot flush the output file");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The same as one guarded write: a failure (disk full) ends the run with one line */
PetscErrorCode SPRestartWriteStep(SPApp a, PetscReal inc)
{
  char file[PETSC_MAX_PATH_LEN + 16];

  PetscFunctionBeginUser;
  if (!a->output->enabled || !a->output->h5) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s.h5.part", a->output->prefix));
  PetscCall(SPOutputWriteBegin(a->output, file, PETSC_TRUE));
  PetscCall(SPOutputWriteEnd(a->output, WriteStep(a, inc)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rank 0 checks that the file exists, opens as HDF5 and is not this run's own output file */
static PetscErrorCode CheckFile(SPApp a)
{
  PetscMPIInt rank;
  int         why = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(a->comm, &rank));
  if (rank == 0) {
    FILE       *fp = fopen(a->restartFile, "r");
    struct stat st;
    if (!fp) why = 1;
    else if (!stat(a->restartFile, &st) && S_ISDIR(st.st_mode)) why = 4, fclose(fp); /* fopen opens a directory */
    else {
      hid_t        f;
      H5E_auto2_t  func;
      void        *data;
      fclose(fp);
      H5Eget_auto2(H5E_DEFAULT, &func, &data);
      H5Eset_auto2(H5E_DEFAULT, NULL, NULL); /* a failed open is reported below, in one line */
      f = H5Fopen(a->restartFile, H5F_ACC_RDONLY, H5P_DEFAULT);
      H5Eset_auto2(H5E_DEFAULT, func, data);
      if (f < 0) why = 2;
      else H5Fclose(f);
    }
    if (!why) { /* the output of this run would overwrite it */
      char own[PETSC_MAX_PATH_LEN + 16], r1[PETSC_MAX_PATH_LEN], r2[PETSC_MAX_PATH_LEN];
      for (PetscInt k = 0; k < 2 && !why; ++k) {
        PetscCall(PetscSNPrintf(own, sizeof(own), "%s.h5%s", a->output->prefix, k ? ".part" : ""));
        if (realpath(own, r1) && realpath(a->restartFile, r2) && !strcmp(r1, r2)) why = 3;
      }
    }
  }
  PetscCallMPI(MPI_Bcast(&why, 1, MPI_INT, 0, a->comm));
  PetscCheck(why != 1, a->comm, PETSC_ERR_USER_INPUT, "-restart %s: no such file (give the .h5 or .h5.part file of the interrupted run)", a->restartFile);
  PetscCheck(why != 4, a->comm, PETSC_ERR_USER_INPUT, "-restart %s: a directory, not a file (give the .h5 or .h5.part file of the interrupted run)", a->restartFile);
  PetscCheck(why != 2, a->comm, PETSC_ERR_USER_INPUT, "-restart %s: not a readable HDF5 file (truncated, or not spcontact output)", a->restartFile);
  PetscCheck(why != 3, a->comm, PETSC_ERR_USER_INPUT, "-restart %s: this run would write its output over that file; give the restarted run another -output_name", a->restartFile);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The file's run against this one: one line per mismatch. *ranks: the writing run's rank count */
static PetscErrorCode CheckIdentity(SPApp a, PetscViewer h5, PetscInt *steps, PetscInt *ranks, PetscInt *ncount)
{
  Identity  id;
  PetscBool has;
  char     *method = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5HasAttribute(h5, "/restart", "steps", &has));
  PetscCheck(has, a->comm, PETSC_ERR_USER_INPUT, "-restart %s: the file has no restart data (no converged load step, or written with -output_fields false)", a->restartFile);
  PetscCall(PetscViewerHDF5ReadAttribute(h5, "/restart", "steps", PETSC_INT, NULL, steps));
  PetscCall(PetscViewerHDF5HasAttribute(h5, "/restart", "format", &has));
  PetscCheck(has, a->comm, PETSC_ERR_USER_INPUT, "-restart %s: restart data of an older spcontact (vectors in its partition's order); resume it with that version", a->restartFile);
  {
    PetscInt format;
    PetscCall(PetscViewerHDF5ReadAttribute(h5, "/restart", "format", PETSC_INT, NULL, &format));
    PetscCheck(format >= 6 && format <= FORMAT, a->comm, PETSC_ERR_USER_INPUT, "-restart %s: restart data format %" PetscInt_FMT " of another spcontact version (this one reads 6 to %d); resume it with that version", a->restartFile, format, FORMAT);
    *ncount = format == 6 ? NCOUNT6 : (format == 7 ? NCOUNT7 : (format == 8 ? NCOUNT8 : (format == 9 ? NCOUNT9 : NCOUNT)));
  }
  PetscCall(PetscViewerHDF5ReadAttribute(h5, "/restart", "ranks", PETSC_INT, NULL, ranks));
  PetscCall(GetIdentity(a, &id));
  {
    const PetscInt mine[5] = {id.dim, id.dofs, id.points, -1, id.friction};
    const char *const what[5] = {"mesh dimension", "number of displacement dofs (mesh or -petscspace_degree)", "number of contact points (contact surfaces)", NULL, "friction (0 off, 1 on)"};
    for (PetscInt k = 0; k < 5; ++k) {
      PetscInt theirs;
      if (!what[k]) continue; /* any rank count */
      PetscCall(PetscViewerHDF5ReadAttribute(h5, "/restart", IdNames[k], PETSC_INT, NULL, &theirs));
      PetscCheck(theirs == mine[k], a->comm, PETSC_ERR_USER_INPUT, "-restart %s: %s is %" PetscInt_FMT " there and %" PetscInt_FMT " here; restart with the interrupted run's mesh and options", a->restartFile, what[k], theirs, mine[k]);
    }
  }
  PetscCall(PetscViewerHDF5ReadAttribute(h5, "/restart", "method", PETSC_STRING, NULL, &method));
  PetscCheck(!strcmp(method, id.method), a->comm, PETSC_ERR_USER_INPUT, "-restart %s: contact method %s there and %s here; restart with -contact_method %s", a->restartFile, method, id.method, method);
  PetscCall(PetscFree(method));
  PetscCall(PetscViewerHDF5HasAttribute(h5, "/restart", "physics_options", &has));
  if (has) { /* files of before 2026-12-01 have none */
    char *there, *here;
    PetscCall(PetscViewerHDF5ReadAttribute(h5, "/restart", "physics_options", PETSC_STRING, NULL, &there));
    PetscCall(SPRestartPhysicsOptions(a, &here));
    PetscCall(SPRestartComparePhysics(a->comm, a->restartFile, there, here));
    PetscCall(PetscFree(there));
    PetscCall(PetscFree(here));
  }
  PetscCall(PetscViewerHDF5HasAttribute(h5, "/restart", "mesh_geometry", &has));
  if (has) { /* files of before 2026-12-01 have none */
    char *there, here[512];
    PetscCall(PetscViewerHDF5ReadAttribute(h5, "/restart", "mesh_geometry", PETSC_STRING, NULL, &there));
    PetscCall(SPRestartMeshGeometry(a->dm, here, sizeof(here)));
    PetscCall(SPRestartCompareGeometry(a->comm, a->restartFile, there, here));
    PetscCall(PetscFree(there));
  }
  PetscCall(PetscViewerHDF5ReadAttribute(h5, "/restart", "load_steps", PETSC_INT, NULL, &id.loadSteps));
  if (id.loadSteps != a->loadSteps) a->loadInc = -1.0; /* new -load_steps: go on with 1/N from the restored load factor */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The counters of the writing run's rank r: its own rank's if the rank count is the same, else
   rank 0's (the same on every rank but the exchange statistics: rank 0 takes their total) */
static PetscErrorCode LoadCounters(SPApp a, PetscViewer h5, PetscInt ranks, PetscInt ncount, PetscReal *inc)
{
  Vec          v, all;
  VecScatter   sc;
  PetscMPIInt  size, rank;
  PetscScalar *x;
  PetscReal    b[NCOUNT] = {0};

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(a->comm, &size));
  PetscCallMPI(MPI_Comm_rank(a->comm, &rank));
  PetscCall(VecCreate(a->comm, &v));
  PetscCall(VecSetSizes(v, PETSC_DECIDE, ranks * ncount));
  PetscCall(VecSetBlockSize(v, ncount));
  PetscCall(VecSetType(v, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)v, "counters"));
  PetscCall(VecLoad(v, h5));
  PetscCall(VecScatterCreateToAll(v, &sc, &all));
  PetscCall(VecScatterBegin(sc, v, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, v, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArray(all, &x));
  {
    const PetscInt r = ranks == size ? rank : 0;
    for (PetscInt k = 0; k < ncount; ++k) b[k] = PetscRealPart(x[r * ncount + k]);
    if (ranks != size) { /* received facets (11) summed, exchange time (18) the slowest rank's */
      b[11] = b[18] = 0.0;
      for (PetscInt q = 0; q < ranks && !rank; ++q) b[11] += PetscRealPart(x[q * ncount + 11]), b[18] = PetscMax(b[18], PetscRealPart(x[q * ncount + 18]));
    }
  }
  PetscCall(VecRestoreArray(all, &x));
  PetscCall(Counters(PETSC_FALSE, a, inc, b));
  if (a->solver->reorthogonalise) PetscCall(SPSolverReorthogonalise(a->solver));
  PetscCall(SPSolverResumeDirect(a->solver, a->solver->directStep));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(VecDestroy(&all));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -restart: displacement, contact state, load factor, step and counters of the file's last step */
PetscErrorCode SPRestartLoad(SPApp a)
{
  PetscViewer h5;
  PetscInt    steps = 0, ranks = 0, ncount = NCOUNT;
  PetscReal   inc, *vals;
  PetscBool   same = PETSC_TRUE, all;
  DofItems    dofs;
  SPNatural   pts;

  PetscFunctionBeginUser;
  if (!a->restartFile[0]) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(CheckFile(a));
  PetscCall(PetscViewerHDF5Open(a->comm, a->restartFile, FILE_MODE_READ, &h5));
  PetscCall(CheckIdentity(a, h5, &steps, &ranks, &ncount));
  PetscCall(PetscViewerHDF5PushTimestepping(h5));
  PetscCall(PetscViewerHDF5SetTimestep(h5, steps - 1));
  PetscCall(PetscViewerHDF5PushGroup(h5, "/restart"));
  PetscCall(DofItemsCreate(a, &dofs));
  PetscCall(PetscMalloc1(dofs.nat.n * dofs.nat.bs + 1, &vals));
  PetscCall(SPNaturalRead(&dofs.nat, h5, "displacement", vals));
  PetscCall(DofValues(PETSC_FALSE, a, &dofs, vals));
  PetscCall(PetscFree(vals));
  PetscCall(DofItemsDestroy(&dofs));
  PetscCall(PointItems(a, &pts));
  PetscCall(PetscMalloc1(pts.n * SP_POINT_NPACK + 1, &vals));
  PetscCall(SPNaturalRead(&pts, h5, "points", vals));
  if (pts.n) PetscCall(SPContactUnpackPoints(a->contact, vals, &same));
  PetscCall(PetscFree(vals));
  PetscCall(SPNaturalDestroy(&pts));
  PetscCallMPI(MPI_Allreduce(&same, &all, 1, MPIU_BOOL, MPI_LAND, a->comm));
  PetscCheck(all, a->comm, PETSC_ERR_USER_INPUT, "-restart %s: the contact points lie elsewhere there, or their friction anchors do not exist here (another mesh); restart with the interrupted run's mesh and options", a->restartFile);
  PetscCall(LoadCounters(a, h5, ranks, ncount, &inc));
  PetscCall(PetscViewerHDF5PopGroup(h5));
  PetscCall(PetscViewerHDF5PopTimestepping(h5));
  PetscCall(PetscViewerDestroy(&h5));
  a->loadInc = a->loadInc < 0.0 ? 1.0 / a->loadSteps : inc;
  PetscCheck(a->loadReached < 1.0 - 1e-12, a->comm, PETSC_ERR_USER_INPUT, "-restart %s: that run already reached load factor 1; nothing to resume", a->restartFile);
  PetscCall(PetscPrintf(a->comm, "restart: resuming after load step %" PetscInt_FMT " (load factor %g) of %s\n", a->stepsDone, (double)a->loadReached, a->restartFile));
  PetscFunctionReturn(PETSC_SUCCESS);
}
