/* Write failures (disk full, quota, file-size limit, I/O error): every write of an output file runs
   between SPOutputWriteBegin and SPOutputWriteEnd. Inside, PETSc's and HDF5's error printing is
   off and the first failure's errno is kept; SPOutputWriteEnd agrees on every rank whether a write
   failed, stops writing (the files keep their .part names: no final-named file) and ends the run
   with one line naming the file and the cause (PETSC_ERR_FILE_WRITE: main() exits at once). */
#include <spcontact-impl.h>
#include <petscviewerhdf5.h>
#include <hdf5.h>
#include <errno.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <string.h>

/* Error handler inside a write: silent, keeps the errno of the first failure (a failed write(),
   fflush() or fclose() leaves it set; HDF5 and PETSc return right after) */
static PetscErrorCode Record(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  SPOutput o = (SPOutput)ctx;

  if (p == PETSC_ERROR_INITIAL && !o->guard.err) o->guard.err = errno ? errno : EIO;
  if (getenv("SPCONTACT_TRACEBACK")) return PetscTraceBackErrorHandler(comm, line, fun, file, n, p, mess, NULL);
  return n;
}

/* collective: the writes are collective HDF5 calls (a rank whose write failed cannot wait for
   the others: they may be inside the next collective call) */
PetscErrorCode SPOutputWriteBegin(SPOutput o, const char file[], PetscBool collective)
{
  PetscFunctionBeginUser;
  PetscCheck(!o->guard.open, PETSC_COMM_SELF, PETSC_ERR_PLIB, "nested output write guards");
  PetscCall(PetscStrncpy(o->guard.file, file, sizeof(o->guard.file)));
  o->guard.open       = PETSC_TRUE;
  o->guard.collective = collective;
  o->guard.err        = 0;
  H5Eget_auto2(H5E_DEFAULT, &o->guard.func, &o->guard.data);
  if (!getenv("SPCONTACT_TRACEBACK")) H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  PetscCall(PetscPushErrorHandler(Record, o));
  errno = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The files of a run whose write failed: the CSV history closed (errors ignored); the h5 is left
   open: HDF5 1.10 cannot close a file whose writes fail (a failed H5Fclose leaves a dangling id
   that crashes the library's shutdown), so main() ends such a run without finalizing it */
static void Abandon(SPOutput o)
{
  PetscMPIInt rank;

  o->h5 = NULL;
  MPI_Comm_rank(PetscObjectComm((PetscObject)o->dm), &rank);
  if (o->csv && !rank) (void)fclose(o->csv);
  o->csv = NULL;
}

/* The cause of a failed write of file: no space left, the file-size limit, or else the errno the
   failure left (HDF5 and MPI-IO may overwrite the one of the failed write()) */
static int Cause(const char file[], int err)
{
  struct statvfs fs;
  struct rlimit  lim;
  struct stat    st;
  char           dir[PETSC_MAX_PATH_LEN + 32], *slash;

  if (err == ENOSPC || err == EFBIG || err == EDQUOT) return err;
  (void)PetscStrncpy(dir, file, sizeof(dir));
  slash = strrchr(dir, '/');
  if (slash) *slash = 0;
  else (void)PetscStrncpy(dir, ".", sizeof(dir));
  if (!statvfs(dir, &fs) && fs.f_bavail == 0) return ENOSPC;
  if (!getrlimit(RLIMIT_FSIZE, &lim) && lim.rlim_cur != RLIM_INFINITY && !stat(file, &st) && (rlim_t)st.st_size >= lim.rlim_cur) return EFBIG;
  return err ? err : EIO;
}

#define WRITE_FAILED "writing %s failed: %s (%s); the files keep their .part names"

/* What to look at for a failure's cause: the space for a full disk, else the file's path */
static const char *Hint(int err)
{
  return err == ENOSPC || err == EFBIG || err == EDQUOT || err == EIO ? "disk full? check the free space and -output_dir" : "check -output_dir and -output_name";
}

/* ierr: what the guarded writes returned on this rank. Collective, except when a collective HDF5
   write failed on a rank of several: that rank prints the line and ends the job (MPI_Abort), since
   the others may be waiting inside HDF5 for the call it abandoned. */
PetscErrorCode SPOutputWriteEnd(SPOutput o, PetscErrorCode ierr)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)o->dm);
  int         mine = ierr ? Cause(o->guard.file, o->guard.err) : 0, err;
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (mine && o->guard.collective && size > 1) {
    fprintf(stderr, "spcontact: error: " WRITE_FAILED "\n", o->guard.file, strerror(mine), Hint(mine));
    fflush(stderr);
    PetscCallMPI(MPI_Abort(comm, 1));
  }
  PetscCallMPI(MPI_Allreduce(&mine, &err, 1, MPI_INT, MPI_MAX, comm));
  if (err) Abandon(o); /* still silent */
  PetscCall(PetscPopErrorHandler());
  H5Eset_auto2(H5E_DEFAULT, o->guard.func, o->guard.data);
  o->guard.open = PETSC_FALSE;
  PetscCheck(!err, comm, PETSC_ERR_FILE_WRITE, WRITE_FAILED, o->guard.file, strerror(err), Hint(err));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A stdio stream after writing: its error state (or that of closing it, close true) as errno and
   a PETSc error, for a guarded write */
PetscErrorCode SPOutputCheckStream(FILE *fp, const char file[], PetscBool close)
{
  int bad, e;

  PetscFunctionBeginUser;
  errno = 0;
  bad   = fflush(fp) != 0 || ferror(fp);
  e     = errno;
  if (close && fclose(fp) != 0 && !bad) bad = 1, e = errno;
  errno = e ? e : EIO;
  PetscCheck(!bad, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "writing %s failed", file);
  PetscFunctionReturn(PETSC_SUCCESS);
}
