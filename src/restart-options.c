/* The options that set the problem a restart resumes: materials, boundary conditions and loads,
   obstacles, pairs and friction (and, with penalty, whose solution depends on eps, the penalty
   factors). They are stored with the first step as one string of sorted "-name value" lines
   (attribute physics_options of /restart) and compared on restart: a changed friction coefficient,
   obstacle point or load would otherwise continue a run whose converged steps solved another
   problem. Solver options, output options and -load_steps may change. The values are read from
   PetscOptionsGetAll's string, which does not mark an option used (the unused-option report);
   options the run does not use (a plane's radius, put back as unread) are left out on both sides.
   The string holds the options given, not the defaults taken: one given on one side only is
   refused even at its default, and the line says so. */
#include <spcontact-impl.h>
#include <ctype.h>
#include <stdlib.h>
#include <strings.h>

/* Names (with their dash) that set the problem; a key ending in '_' is a prefix */
static const char *const Physics[] = {"-material_", "-bc_", "-contact_obstacle_", "-contact_pair_", "-contact_friction_mu", "-contact_label", "-contact_values", "-contact_two_pass"};
static const char *const Penalty[] = {"-contact_alpha", "-contact_penalty", "-contact_friction_alpha"}; /* set the penalty method's solution */
static const char *const Solver[]  = {"-contact_pair_exchange_all"}; /* communication only */

static PetscBool Matches(const char name[], const char *const keys[], size_t n)
{
  for (size_t k = 0; k < n; ++k) {
    const size_t l = strlen(keys[k]);
    if (keys[k][l - 1] == '_' ? !strncasecmp(name, keys[k], l) : !strcasecmp(name, keys[k])) return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

static PetscBool IsName(const char *t)
{
  return t[0] == '-' && isalpha((unsigned char)t[1]) ? PETSC_TRUE : PETSC_FALSE;
}

static int CompareLines(const void *a, const void *b)
{
  return strcasecmp(*(const char *const *)a, *(const char *const *)b);
}

/* *str: the problem's options as sorted "-name value" lines (an empty string if none) */
PetscErrorCode SPRestartPhysicsOptions(SPApp a, char **str)
{
  const PetscBool penalty = a->contact->enabled && a->contact->method->timing == SP_UPDATE_NONE;
  char           *all, **tok, **line;
  size_t          ntok = 0, nline = 0, len = 1;
  PetscBool       used;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(NULL, &all));
  PetscCall(PetscMalloc2(strlen(all) / 2 + 2, &tok, strlen(all) / 2 + 2, &line));
  for (char *t = strtok(all, " "); t; t = strtok(NULL, " ")) tok[ntok++] = t;
  for (size_t k = 0; k < ntok; ++k) {
    size_t n = strlen(tok[k]) + 2, j;
    if (!IsName(tok[k]) || Matches(tok[k], Solver, PETSC_STATIC_ARRAY_LENGTH(Solver))) continue;
    if (!Matches(tok[k], Physics, PETSC_STATIC_ARRAY_LENGTH(Physics)) && !(penalty && Matches(tok[k], Penalty, PETSC_STATIC_ARRAY_LENGTH(Penalty)))) continue;
    PetscCall(PetscOptionsUsed(NULL, tok[k] + 1, &used));
    if (!used) continue; /* not this run's (a plane's radius): the unused-option report names it */
    for (j = k + 1; j < ntok && !IsName(tok[j]); ++j) n += strlen(tok[j]) + 1; /* a value with spaces ("0.1, 0") is several tokens */
    PetscCall(PetscMalloc1(n, &line[nline]));
    PetscCall(PetscStrncpy(line[nline], tok[k], n));
    PetscCall(PetscStrlcat(line[nline], " ", n));
    for (size_t m = k + 1; m < j; ++m) {
      if (m > k + 1) PetscCall(PetscStrlcat(line[nline], " ", n));
      PetscCall(PetscStrlcat(line[nline], tok[m], n));
    }
    len += strlen(line[nline++]) + 1;
  }
  qsort(line, nline, sizeof(char *), CompareLines);
  PetscCall(PetscMalloc1(len, str));
  (*str)[0] = 0;
  for (size_t k = 0; k < nline; ++k) {
    PetscCall(PetscStrlcat(*str, line[k], len));
    PetscCall(PetscStrlcat(*str, "\n", len));
    PetscCall(PetscFree(line[k]));
  }
  PetscCall(PetscFree2(tok, line));
  PetscCall(PetscFree(all));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A value as a comma-separated list of numbers (n of them, at most 16); false if it is not one */
static PetscBool Numbers(const char v[], PetscReal x[], PetscInt *n)
{
  const char *p = v;

  *n = 0;
  while (*p && *n < 16) {
    char *end;
    x[(*n)++] = strtod(p, &end);
    if (end == p || (*end && *end != ',')) return PETSC_FALSE;
    p = *end ? end + 1 : end;
  }
  return *p || !*n ? PETSC_FALSE : PETSC_TRUE;
}

/* A flag's value: 1 true, 0 false, -1 not a flag word ("" is a flag given without a value) */
static int Truth(const char v[])
{
  static const char *const yes[] = {"", "1", "true", "yes", "on"}, *const no[] = {"0", "false", "no", "off"};

  for (size_t k = 0; k < 5; ++k)
    if (!strcasecmp(v, yes[k])) return 1;
  for (size_t k = 0; k < 4; ++k)
    if (!strcasecmp(v, no[k])) return 0;
  return -1;
}

/* The same value written two ways (0.3 and 3e-1, true and 1) */
static PetscBool SameValue(const char a[], const char b[])
{
  PetscReal x[16], y[16];
  PetscInt  n, m;

  if (!strcasecmp(a, b)) return PETSC_TRUE;
  if (Numbers(a, x, &n) && Numbers(b, y, &m)) {
    if (n != m) return PETSC_FALSE;
    for (PetscInt k = 0; k < n; ++k)
      if (PetscAbsReal(x[k] - y[k]) > 1e-14 * PetscMax(PetscAbsReal(x[k]), PetscAbsReal(y[k]))) return PETSC_FALSE;
    return PETSC_TRUE;
  }
  return Truth(a) >= 0 && Truth(a) == Truth(b) ? PETSC_TRUE : PETSC_FALSE;
}

/* The value of option name in a string of "-name value" lines; NULL if absent. Copied into v */
static const char *Find(const char lines[], const char name[], char v[], size_t len)
{
  const size_t n = strlen(name);

  for (const char *p = lines; p && *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL) {
    if (strncasecmp(p, name, n) || p[n] != ' ') continue;
    size_t k = 0;
    for (p += n + 1; *p && *p != '\n' && k < len - 1; ++p) v[k++] = *p;
    v[k] = 0;
    return v;
  }
  return NULL;
}

/* Each option of a (there: the file's run) against b (here), the first difference in one line */
static PetscErrorCode CompareOneWay(MPI_Comm comm, const char file[], const char a[], const char b[], PetscBool there)
{
  char name[256], va[PETSC_MAX_PATH_LEN], vb[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  for (const char *p = a; *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : p + strlen(p)) {
    const size_t n = SPOptionsNameCopy(p, 0, name, sizeof(name));
    const size_t m = strcspn(p + n + 1, "\n"); /* the line's value, after "name " */
    const char  *found;
    PetscCall(PetscSNPrintf(va, sizeof(va), "%.*s", (int)PetscMin(m, sizeof(va) - 1), p + n + 1));
    found = Find(b, name, vb, sizeof(vb));
    PetscCheck(found || !there, comm, PETSC_ERR_USER_INPUT, "-restart %s: %s %s was given to the interrupted run and is not given here; give it here too (the problem would change)", file, name, va);
    PetscCheck(found, comm, PETSC_ERR_USER_INPUT, "-restart %s: %s %s is given here and was not given to the interrupted run, which took its default; leave it out if %s is the default (-help shows it), else restart with the interrupted run's options (the problem would change)", file, name, va, va);
    PetscCheck(SameValue(va, vb), comm, PETSC_ERR_USER_INPUT, "-restart %s: %s is %s there and %s here; restart with the interrupted run's options (the problem would change)", file, name, there ? va : vb, there ? vb : va);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* there: the file's attribute, here: this run's string */
PetscErrorCode SPRestartComparePhysics(MPI_Comm comm, const char file[], const char there[], const char here[])
{
  PetscFunctionBeginUser;
  PetscCall(CompareOneWay(comm, file, there, here, PETSC_TRUE));
  PetscCall(CompareOneWay(comm, file, here, there, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The mesh's place and size, independent of the partition: per coordinate the smallest and largest
   value and the 2-norm over the vertices ("lo,hi,norm" per coordinate). The counts (dofs, contact
   points) are checked with the run's identity; a box of other extent or a scaled mesh has the same
   counts (-dm_plex_box_upper, -dm_plex_scale, another mesh file) */
PetscErrorCode SPRestartMeshGeometry(DM dm, char str[], size_t len)
{
  Vec      X;
  PetscInt dim;

  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDim(dm, &dim));
  PetscCall(DMGetCoordinates(dm, &X));
  str[0] = 0;
  for (PetscInt d = 0; d < dim; ++d) {
    PetscReal lo, hi, nrm;
    char      part[96];
    PetscCall(VecStrideMin(X, d, NULL, &lo));
    PetscCall(VecStrideMax(X, d, NULL, &hi));
    PetscCall(VecStrideNorm(X, d, NORM_2, &nrm));
    PetscCall(PetscSNPrintf(part, sizeof(part), "%s%.17g,%.17g,%.17g", d ? "," : "", (double)lo, (double)hi, (double)nrm));
    PetscCall(PetscStrlcat(str, part, len));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The extents to 1e-12 of the largest one, the norms to 1e-10 (their sums' order follows the
   partition) */
PetscErrorCode SPRestartCompareGeometry(MPI_Comm comm, const char file[], const char there[], const char here[])
{
  PetscReal a[16], b[16], ext = 0.0;
  PetscInt  n, m;
  PetscBool same;

  PetscFunctionBeginUser;
  same = Numbers(there, a, &n) && Numbers(here, b, &m) && n == m ? PETSC_TRUE : PETSC_FALSE;
  for (PetscInt k = 0; same && k < n; k += 3) ext = PetscMax(ext, PetscMax(PetscAbsReal(b[k + 1] - b[k]), PetscMax(PetscAbsReal(b[k]), PetscAbsReal(b[k + 1]))));
  for (PetscInt k = 0; same && k < n; ++k) {
    const PetscReal tol = k % 3 == 2 ? 1e-10 * PetscMax(PetscAbsReal(a[k]), PetscAbsReal(b[k])) : 1e-12 * ext;
    if (PetscAbsReal(a[k] - b[k]) > tol) same = PETSC_FALSE;
  }
  PetscCheck(same, comm, PETSC_ERR_USER_INPUT, "-restart %s: the mesh lies elsewhere or has another size there (per coordinate: smallest, largest, 2-norm over the vertices: %s there, %s here); restart with the interrupted run's mesh", file, there, here);
  PetscFunctionReturn(PETSC_SUCCESS);
}
