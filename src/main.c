static const char help[] = "spcontact: parallel FEM contact mechanics with the shifted penalty method.\n"
                           "Run `spcontact -help` for every option; the README documents them.\n";

#define _POSIX_C_SOURCE 200112L /* setenv */
#include <ctype.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <spcontact.h>
#include <version.h>

/* Open MPI started without mpiexec (a singleton: OMPI_COMM_WORLD_SIZE unset) spent 0.35 s of B2's
   0.7 s in MPI_Init: probing network transports (UCX) and starting a runtime daemon, neither of
   which one process uses. It then takes the shared-memory path and no daemon (0.02 s), unless the
   user set these MCA parameters. Of those 0.02 s, 0.01 s was hwloc's discovery of PCI devices
   (network-card locality for transports one process does not use): off too. Runs under mpiexec
   are left to the site's configuration. Other MPI implementations ignore the variables. */
static void SingletonMPI(void)
{
  if (getenv("OMPI_COMM_WORLD_SIZE")) return;
  (void)setenv("OMPI_MCA_pml", "ob1", 0);
  (void)setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  (void)setenv("HWLOC_COMPONENTS", "-linuxio,-pci", 0);
}

/* The errors reported in one line: bad input (an unknown type is a misspelt PETSc option such as
   -ksp_type: every type the code sets itself exists; a factorization that does not exist for the
   matrix, e.g. -pc_type ilu on several ranks: the code's own factorizations exist), and a failed
   write of an output file (output-guard.c) */
static int OneLine(PetscErrorCode n)
{
  return n == PETSC_ERR_USER_INPUT || n == PETSC_ERR_USER || n == PETSC_ERR_ARG_OUTOFRANGE || n == PETSC_ERR_ARG_WRONG || n == PETSC_ERR_ARG_UNKNOWN_TYPE || n == PETSC_ERR_FILE_WRITE || n == PETSC_ERR_MISSING_FACTOR;
}

/* The first one-line error of this rank (main prints it once it knows which ranks raised it) */
typedef struct {
  char message[512];
  int  set;
} OneLineError;

/* User-input errors are kept for one line (no PETSc traceback); everything else keeps PETSc's
   full traceback. Set SPCONTACT_TRACEBACK=1 to see the traceback for input errors. */
static PetscErrorCode ErrorHandler(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  OneLineError *e = (OneLineError *)ctx;
  if (p != PETSC_ERROR_INITIAL) return n;
  if (OneLine(n) && !getenv("SPCONTACT_TRACEBACK")) {
    if (e->set) return n;
    (void)snprintf(e->message, sizeof(e->message), "%s%s", mess ? mess : "(no message)", n == PETSC_ERR_ARG_UNKNOWN_TYPE ? "; check the option's spelling (-help lists the types)" : (n == PETSC_ERR_MISSING_FACTOR ? " (-pc_type: ILU and ICC factor on 1 rank only; in parallel use -pc_type lu or cholesky with -pc_factor_mat_solver_type mumps, or leave the preconditioner to spcontact)" : ""));
    for (char *c = e->message; *c; ++c)
      if (*c == '\n') *c = ' ';
    e->set = 1;
    return n;
  }
  return PetscTraceBackErrorHandler(comm, line, fun, file, n, p, mess, ctx);
}

/* Whether every rank stopped with the error within 10 s: input errors are checked collectively
   (every rank raises them at the same point). A rank that raised one alone (an internal error)
   would otherwise wait forever in MPI_Finalize while the others wait in the run's next
   collective. */
static int EveryRankFailed(void)
{
  MPI_Request           req;
  int                   size, done = 0;
  const double          t0 = MPI_Wtime();
  const struct timespec ms = {0, 1000000};

  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  if (size == 1) return 1;
  if (MPI_Ibarrier(PETSC_COMM_WORLD, &req) != MPI_SUCCESS) return 0;
  while (!done && MPI_Wtime() - t0 < 10.0) {
    if (MPI_Test(&req, &done, MPI_STATUS_IGNORE) != MPI_SUCCESS) return 0;
    if (!done) (void)nanosleep(&ms, NULL);
  }
  return done;
}

/* PETSc's messages for a value it cannot read name the value, not the option ("Input string abc
   has no numeric value", "Unknown logical value: abc"): the option whose value, or one element of
   whose comma list, is exactly that string (spaces included) is found in the database and named
   (not one that takes a word, such as a label: never read as a number or true/false):
   "-contact_alpha abc: not a number", "-bc_1_value \"0.0015,0 \": its element \"0 \" is not a
   number (a space inside a value)" */
static PetscBool OptionHolding(const char bad[], char name[], size_t nname, char whole[], size_t nwhole)
{
  char *all = NULL, *tok, *save = NULL;

  name[0] = 0;
  if (PetscOptionsGetAll(NULL, &all)) return PETSC_FALSE;
  for (tok = strtok_r(all, " ", &save); tok && !name[0]; tok = strtok_r(NULL, " ", &save)) {
    const char *val = NULL;
    PetscBool   set = PETSC_FALSE;
    size_t      len = strlen(bad);
    if (tok[0] != '-' || !isalpha((unsigned char)tok[1])) continue;
    if (SPOptionsTakesWord(tok)) continue; /* a label or name holding the same word is not read as a number */
    if (PetscOptionsFindPair(NULL, NULL, tok, &val, &set) || !set || !val) continue;
    for (const char *e = val; e && !name[0]; e = strchr(e, ',') ? strchr(e, ',') + 1 : NULL) /* each element of the list */
      if (!strncmp(e, bad, len) && (e[len] == ',' || e[len] == 0)) (void)snprintf(name, nname, "%s", tok), (void)snprintf(whole, nwhole, "%s", val);
  }
  (void)PetscFree(all);
  return name[0] ? PETSC_TRUE : PETSC_FALSE;
}

static void NameTheOption(char msg[], size_t n)
{
  static const char *const lead[2] = {"Input string ", "Unknown logical value: "};
  static const char *const what[2] = {"not a number", "not true or false"};
  char                     bad[128] = "", name[256], whole[256];

  for (int k = 0; k < 2; ++k) {
    const char *kind = strstr(msg, "integer") ? "not an integer" : what[k], *end;
    if (strncmp(msg, lead[k], strlen(lead[k]))) continue;
    (void)snprintf(bad, sizeof(bad), "%s", msg + strlen(lead[k]));
    if (k == 0 && (end = strstr(bad, " has no ")) != NULL) bad[end - bad] = 0; /* the value as PETSc read it, spaces kept */
    if (!bad[0] || !OptionHolding(bad, name, sizeof(name), whole, sizeof(whole))) return;
    if (!strcmp(bad, whole) && !strpbrk(bad, " \t")) (void)snprintf(msg, n, "%s %s: %s", name, bad, kind);
    else (void)snprintf(msg, n, "%s \"%s\": %s \"%s\" is %s%s", name, whole, strcmp(bad, whole) ? "its element" : "the value", bad, kind, strpbrk(bad, " \t") ? " (a space inside a value: remove it)" : "");
    return;
  }
}

/* PETSc messages that name a cure for PETSc's developers (a configure option) told as a user's */
static void UserAdvice(char msg[], size_t n)
{
  const char *g = strstr(msg, "No grid generator of dimension ");
  const int   dim = g ? atoi(g + strlen("No grid generator of dimension ")) : 0;

  if (!g) return;
  (void)snprintf(msg, n, "-dm_plex_simplex 1 on a box mesh needs a %dD mesh generator (%s) that this PETSc was built without: make a simplex mesh with gmsh and give it with -mesh_file, or keep the box's %s (-dm_plex_simplex 0)", dim, dim == 3 ? "TetGen" : "Triangle", dim == 3 ? "hexahedra" : "quadrilaterals");
}

/* One line: on rank 0 when every rank raised the error; else on each rank that did, and every
   rank stops (MPI_Abort) */
static int ReportOneLine(OneLineError *e)
{
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  NameTheOption(e->message, sizeof(e->message));
  UserAdvice(e->message, sizeof(e->message));
  if (EveryRankFailed()) {
    if (rank == 0) fprintf(stderr, "spcontact: error: %s\n", e->message);
    (void)PetscPopErrorHandler();
    (void)PetscFinalize();
    return 1;
  }
  fprintf(stderr, "spcontact: error: %s (raised on rank %d only: the other ranks are stopped)\n", e->message, rank);
  fflush(NULL);
  MPI_Abort(PETSC_COMM_WORLD, 1);
  return 1;
}

/* Options nobody read (a misspelt name, or an option for another kind of run) are reported on
   stderr after a run, one line each, unless -options_left is given (false: silent; true: PETSc's
   own report). Defaults the code itself set for objects a run may not create are not reported
   (option-defaults.c); the same options given by the user are. */
static PetscErrorCode ReportUnusedOptions(void)
{
  PetscInt    n;
  char      **names, **values;
  PetscBool   set, mine;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(NULL, NULL, "-options_left", &set));
  if (set) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt i = 0; i < n && rank == 0; ++i) {
    PetscCall(SPOptionsIsDefault(names[i], &mine));
    if (!mine) fprintf(stderr, "spcontact: warning: option -%s was not used (misspelt, or not for this kind of run; see -help); -options_left false silences this\n", names[i]);
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *code: the exit code (0 converged, 2 a step failed, 3 stopped by -max_wall_time, 128 + a signal) */
static PetscErrorCode Run(int *code)
{
  SPApp     app = NULL;
  PetscBool help;

  PetscFunctionBeginUser;
  PetscCall(SPAppCreate(PETSC_COMM_WORLD, &app));
  PetscCall(SPAppSetUp(app));
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (help) { /* -help lists the options of every module (set up above) and stops */
    *code = 0;
    PetscCall(SPAppDestroy(&app));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(SPAppRun(app, code));
  PetscCall(SPAppSummary(app));
  PetscCall(SPAppDestroy(&app));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Before PetscInitialize: -version (or --version) prints spcontact's version and PETSc's and exits
   (PETSc's own -version printed PETSc's and then ran a default box to an error); --help and -h
   are -help; no arguments at all (and no PETSC_OPTIONS, PETSC_OPTIONS_YAML or .petscrc to take
   options from) is a usage line, where a default box ran into "nothing holds the body". A help
   run also gets -no_signal_handler: PETSc prints the first part of the help inside
   PetscInitialize, with its own SIGPIPE handler installed, so "spcontact -help | head -c 10" died
   in an error wall (19 of 20 runs) before main could restore the default action. Returns the exit
   code, or -1 to go on (*argv then possibly a new array, which PETSc keeps). */
static int EarlyArguments(int *argc, char ***argv)
{
  static char helpArg[] = "-help", quietSignals[] = "-no_signal_handler";
  int         help      = 0;
  char      **args;

  if (*argc == 1 && !getenv("PETSC_OPTIONS") && !getenv("PETSC_OPTIONS_YAML") && access(".petscrc", F_OK)) {
    fprintf(stderr, "spcontact: error: no problem given: run spcontact -options_file FILE.opts (the cases of input/, e.g. input/hertz2d.opts; the README's quick start); spcontact -help lists every option\n");
    return 1;
  }
  for (int i = 1; i < *argc; ++i) {
    if (!strcmp((*argv)[i], "-version") || !strcmp((*argv)[i], "--version")) {
      printf("spcontact %s (PETSc %d.%d.%d)\n", SP_VERSION, PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR, PETSC_VERSION_SUBMINOR);
      return 0;
    }
    if (!strcmp((*argv)[i], "--help") || !strcmp((*argv)[i], "-h")) (*argv)[i] = helpArg;
    if (!strcmp((*argv)[i], "-help")) help = 1;
  }
  if (!help || !(args = (char **)malloc((size_t)(*argc + 2) * sizeof(char *)))) return -1;
  for (int i = 0; i < *argc; ++i) args[i] = (*argv)[i];
  args[(*argc)++] = quietSignals;
  args[*argc]     = NULL;
  *argv           = args;
  return -1;
}

int main(int argc, char **argv)
{
  PetscErrorCode ierr;
  int            code    = 2;
  OneLineError   oneLine = {"", 0};

  if ((code = EarlyArguments(&argc, &argv)) >= 0) return code;
  code = 2;
  if (SPCheckOptionsFiles(argc, argv)) return 1; /* before PetscInitialize reads them */
  SingletonMPI();
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  (void)signal(SIGPIPE, SIG_DFL); /* a closed stdout (spcontact -help | head) ends the process quietly, as for any Unix tool; PETSc's handler printed an error wall and MPI_ABORT */
  PetscCall(PetscPushErrorHandler(ErrorHandler, &oneLine));
  ierr = Run(&code);
  if (ierr == PETSC_ERR_FILE_WRITE) { /* an output write failed: its h5 cannot be closed, and */
    PetscMPIInt rank;                 /* HDF5 would crash closing it in MPI_Finalize (output-guard.c) */
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    if (rank == 0 && oneLine.set) fprintf(stderr, "spcontact: error: %s\n", oneLine.message); /* collective (h5) or rank 0 (CSV) */
    fflush(NULL);
    _exit(1);
  }
  if (OneLine(ierr)) return ReportOneLine(&oneLine); /* bad input: one line on stderr */
  if (ierr) PETSCABORT(PETSC_COMM_WORLD, ierr);
  PetscCall(ReportUnusedOptions());
  /* a signal or -max_wall_time: SPLoadingRun printed how to restart */
  if (code == 2) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "spcontact: the run stopped before load factor 1 (the 'stopping:' line above says why); results above are for the last converged load step only\n"));
  PetscCall(PetscPopErrorHandler());
  PetscCall(PetscFinalize());
  return code;
}
