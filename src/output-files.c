#define _XOPEN_SOURCE 700 /* lstat */
/* The output files' names: -output_dir and -output_name checked before the solve (characters the
   XDMF cannot carry, the directories created and writable, no directory in the place of a file),
   the h5 as the XDMF files name it, and the files of an earlier run with the same name removed
   (its .part files when the run opens its own, its final files at the run's first converged step). */
#include <spcontact-impl.h>
#include <errno.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Every file a run may write, after <dir>/<name> (each also as .part) */
static const char *const Files[] = {".csv", "_contact.csv", ".xmf", "-xdmf2.xmf", "-surface.xmf", ".h5"};
#define NFILES ((PetscInt)(sizeof(Files) / sizeof(Files[0])))

/* The name without its directories: the XDMF files sit beside the h5 and name it relative */
static const char *Base(const char name[])
{
  const char *slash = strrchr(name, '/');

  return slash ? slash + 1 : name;
}

/* The h5 as the XDMF files beside it name it: final (complete run) or .part */
PetscErrorCode SPOutputH5Reference(SPOutput o, PetscBool complete, char ref[], size_t len)
{
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(ref, len, "%s.h5%s", Base(o->name), complete ? "" : ".part"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* XML markup and the colon that separates the file from the dataset in an XDMF HDF item */
static PetscErrorCode CheckName(MPI_Comm comm, const char name[])
{
  const char *bad = strpbrk(Base(name), "&<>\"':");

  PetscFunctionBeginUser;
  PetscCheck(Base(name)[0], comm, PETSC_ERR_USER_INPUT, "-output_name %s: the name ends with '/'; give a file name (e.g. -output_name run or sub/run)", name);
  PetscCheck(name[0] != '/', comm, PETSC_ERR_USER_INPUT, "-output_name %s: an absolute name; the name is relative to -output_dir: give the directory as -output_dir and the file name as -output_name", name);
  PetscCheck(!bad, comm, PETSC_ERR_USER_INPUT, "-output_name %s: the XDMF file cannot name an HDF5 file with '%c' in it; use letters, digits and - _ . in the name", name, *bad);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Every missing directory of path, as mkdir -p (a failure shows up as the probe after it) */
static void MakeDirectories(char path[])
{
  for (char *p = path + 1; *p; ++p)
    if (*p == '/') *p = 0, (void)mkdir(path, 0777), *p = '/';
  (void)mkdir(path, 0777);
}

/* Rank 0: -output_dir and the directory part of -output_name created if missing (every level),
   then probed with a file. *err: the errno if it cannot, *which: 1 -output_dir, 2 -output_name */
static PetscErrorCode Probe(SPOutput o, int *err, PetscInt *which)
{
  char  path[PETSC_MAX_PATH_LEN + 32], *slash;
  FILE *fp;

  PetscFunctionBeginUser;
  *err = 0, *which = 1;
  PetscCall(PetscStrncpy(path, o->dir, sizeof(path)));
  MakeDirectories(path);
  PetscCall(PetscStrncpy(path, o->prefix, sizeof(path)));
  slash = strrchr(path, '/');
  if (slash && slash > path + strlen(o->dir)) *slash = 0, MakeDirectories(path), *which = 2;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s.probe", o->prefix));
  errno = 0;
  fp    = fopen(path, "w");
  if (!fp) *err = errno ? errno : EACCES;
  else fclose(fp), remove(path);
  if (*err == ENAMETOOLONG) *which = 2;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rank 0: the first .part file of the run that is a directory (-1: none) */
static PetscErrorCode FindDirectory(SPOutput o, PetscInt *k)
{
  char        path[PETSC_MAX_PATH_LEN + 32];
  struct stat st;

  PetscFunctionBeginUser;
  *k = -1;
  for (PetscInt f = 0; f < NFILES && *k < 0; ++f) {
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s%s.part", o->prefix, Files[f]));
    if (!lstat(path, &st) && S_ISDIR(st.st_mode)) *k = f; /* a link to a directory is removed as a link */
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* path removed if it is a regular file (what a run writes; not a directory), or a symbolic link
   and links (the link alone goes, not what it points at: a run writing its .part file through a
   link would overwrite that file) */
static void RemoveFile(const char path[], PetscBool links)
{
  struct stat st;

  if (!lstat(path, &st) && (S_ISREG(st.st_mode) || (links && S_ISLNK(st.st_mode)))) (void)unlink(path);
}

/* Rank 0: an earlier run's files of this name removed (tail "" the final names, ".part" the
   others), so that the files beside a run's .part files are its own, not a complete-looking result
   of another run: the .part files as the run opens its own, the final ones when it writes its first
   converged step (a run refused at its first solve keeps an earlier complete result) */
static PetscErrorCode RemoveEarlier(SPOutput o, const char tail[])
{
  char path[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBeginUser;
  for (PetscInt f = 0; f < NFILES; ++f) {
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s%s%s", o->prefix, Files[f], tail));
    RemoveFile(path, tail[0] ? PETSC_TRUE : PETSC_FALSE); /* a link at a final name is the user's */
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: at the run's first converged step, an earlier run's final files of this name go */
PetscErrorCode SPOutputRemoveEarlierResults(SPOutput o)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  if (o->earlierRemoved) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)o->dm), &rank));
  if (!rank) PetscCall(RemoveEarlier(o, ""));
  o->earlierRemoved = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective, before the solve */
PetscErrorCode SPOutputCheckFiles(SPOutput o)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)o->dm);
  PetscMPIInt rank;
  PetscInt    which = 1, dir = -1;
  int         err   = 0;

  PetscFunctionBeginUser;
  PetscCall(CheckName(comm, o->name));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) PetscCall(Probe(o, &err, &which));
  if (!rank && !err) PetscCall(FindDirectory(o, &dir));
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(&which, 1, MPIU_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(&dir, 1, MPIU_INT, 0, comm));
  PetscCheck(!err || which == 2, comm, PETSC_ERR_USER_INPUT, "-output_dir %s: cannot create or write the output directory (%s); choose a writable one", o->dir, strerror(err));
  PetscCheck(err != ENAMETOOLONG, comm, PETSC_ERR_USER_INPUT, "-output_name %s: %s; give a shorter name", o->name, strerror(err));
  PetscCheck(!err, comm, PETSC_ERR_USER_INPUT, "-output_name %s: cannot create or write its directory %.*s (%s); create it, or give another -output_name", o->name, (int)(strrchr(o->prefix, '/') - o->prefix), o->prefix, strerror(err));
  PetscCheck(dir < 0, comm, PETSC_ERR_USER_INPUT, "%s%s.part is a directory: the run cannot write that file; remove it or give another -output_name", o->prefix, dir < 0 ? "" : Files[dir]);
  if (!rank) PetscCall(RemoveEarlier(o, ".part"));
  PetscFunctionReturn(PETSC_SUCCESS);
}
