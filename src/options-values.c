/* Options given without a value. PETSc leaves a number at its default when its option has no value
   (PetscOptionsGetInt/GetReal: not set), so "-load_steps" whose value was lost ran one load step
   without a word, and so did "-ksp_rtol" or "-snes_max_it". After set-up, an option that the run
   read and that has no value is refused in one line if
   - it is one of spcontact's families, unless it is one of spcontact's flags (Flags below: every
     PetscOptionsBool name in src/, checked by the test help_complete; an indexed flag such as
     -bc_<i>_follower by its tail), or
   - it is one of PETSc's families (-ksp_, -snes_, -pc_, -mg_, -dm_, -mat_, -petscpartitioner_)
     and its name ends with a numeric tail (NumericTails: tolerances, iteration limits, restart,
     thresholds, mesh sizes; no PETSc flag ends so), read or not (-mg_levels_* are read at the
     first solve). PETSc's flags, which take no value, keep working, and so does every PETSc
     option outside that list.
   The options' names come from PetscOptionsGetAll's string; spcontact's are checked only once
   read, which leaves the report of unused (misspelt) options as it was.
   PETSc's named values (PETSC_DEFAULT, DEFAULT, PETSC_DECIDE, DECIDE, any case) are refused
   before the set-up in the same options (but those taking a word: a type, label, name, file):
   PETSc reads them as -2 and -1 and stores them, so "-contact_penalty PETSC_DEFAULT" was refused
   as "-contact_penalty -2" and "-ksp_rtol PETSC_DEFAULT" set rtol -2. A value joined to its name by
   '=' (-contact_method=alm) is refused then too. */
#include <ctype.h>
#include <strings.h>
#include <spcontact-impl.h>

static const char *const Families[] = {"-contact_", "-solver_", "-load_", "-material_", "-bc_", "-output_", "-mesh_", "-restart", "-max_wall_time", "-debug_"};

static const char *const PetscFamilies[] = {"-ksp_", "-snes_", "-pc_", "-mg_", "-dm_", "-mat_", "-petscpartitioner_"};

static const char *const NumericTails[] = {"_rtol", "_atol", "_stol", "_dtol", "_divtol", "_max_it", "_max_funcs", "_max_fail", "_max_linear_solve_fail", "_restart", "_threshold", "_eq_limit", "_nsmooths", "_square_graph", "_lag_preconditioner", "_lag_jacobian", "_levels", "_refine", "_faces", "_lower", "_upper", "_dim", "_esteig", "_damping"};

static const char *const Flags[] = {"-contact_branch_hold", "-contact_friction_stick_hold", "-contact_monitor", "-contact_pair_exchange_all", "-contact_safeguard", "-contact_shift_predict", "-contact_shift_settled", "-contact_two_pass", "-dm_plex_gmsh_highorder", "_follower", "-output_fields", "-quiet", "-solver_check_fast", "-solver_direct_cholesky", "-solver_fast_bulk", "-solver_fast_prealloc", "-solver_gamg_shared_graph", "-solver_inexact", "-solver_inexact_inner", "-solver_inexact_measured", "-solver_inexact_refine", "-solver_linear_reuse", "-solver_target_floor"};

/* name ends with one of tails[0..n) (and is longer) */
static PetscBool HasTail(const char name[], const char *const tails[], size_t n)
{
  const size_t len = strlen(name);

  for (size_t k = 0; k < n; ++k) {
    const size_t m = strlen(tails[k]);
    if (len > m && !strcasecmp(name + len - m, tails[k])) return PETSC_TRUE; /* PETSc's names ignore case */
  }
  return PETSC_FALSE;
}

/* name (with its dash, lower case) is a flag: equal to a full flag name, or ending with a tail */
static PetscBool IsFlag(const char name[])
{
  for (size_t k = 0; k < PETSC_STATIC_ARRAY_LENGTH(Flags); ++k)
    if (Flags[k][0] == '-' ? !strcmp(name, Flags[k]) : HasTail(name, Flags + k, 1)) return PETSC_TRUE;
  return PETSC_FALSE;
}

static PetscBool InFamily(const char name[], const char *const families[], size_t n)
{
  for (size_t k = 0; k < n; ++k)
    if (!strncmp(name, families[k], strlen(families[k]))) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* Whether the option whose name ends just before rest (in PetscOptionsGetAll's string) has a value:
   a next token that does not start another option. Reading the string marks nothing used. */
static PetscBool HasValue(const char rest[])
{
  return rest[0] == ' ' && rest[1] && !(rest[1] == '-' && isalpha((unsigned char)rest[2])) ? PETSC_TRUE : PETSC_FALSE;
}

/* One option name of the database (rest: the string after it): refused if it needs a value and
   has none. spcontact's (not a flag) only once read: a name that was not read is misspelt, and the
   unused-option report names it. PETSc's numeric ones whether read or not (GAMG's level options
   are read at the first solve, after this check), from the string alone, so that one not read
   stays in the unused-option report */
static PetscErrorCode CheckOne(MPI_Comm comm, const char name[], const char shown[], const char rest[])
{
  PetscBool check;

  PetscFunctionBeginUser;
  if (InFamily(name, Families, PETSC_STATIC_ARRAY_LENGTH(Families))) {
    check = IsFlag(name) ? PETSC_FALSE : PETSC_TRUE;
    if (check) PetscCall(PetscOptionsUsed(NULL, name + 1, &check)); /* the database keeps names without the dash */
  } else check = InFamily(name, PetscFamilies, PETSC_STATIC_ARRAY_LENGTH(PetscFamilies)) && HasTail(name, NumericTails, PETSC_STATIC_ARRAY_LENGTH(NumericTails)) ? PETSC_TRUE : PETSC_FALSE;
  PetscCheck(!check || HasValue(rest), comm, PETSC_ERR_USER_INPUT, "%s needs a value (-help gives its meaning and default)", shown);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const char *const WordTails[] = {"_type", "_label", "_labels", "_name", "_dir", "_file", "_model", "_law", "_method", "_accel", "_tangent", "_partitioner", "-restart"};

/* Whether the option (its name with the dash, in any case) takes a word: a type, label, name, file */
PetscBool SPOptionsTakesWord(const char name[])
{
  return HasTail(name, WordTails, PETSC_STATIC_ARRAY_LENGTH(WordTails)) || !strcasecmp(name, "-restart") ? PETSC_TRUE : PETSC_FALSE;
}

/* Refused if name (lower case; shown: as given) is a numeric option (as in CheckOne, read or not)
   and its value (the next token of the string, rest), or an element of its comma list, is one of
   PETSc's named values */
static PetscErrorCode CheckNamed(MPI_Comm comm, const char name[], const char shown[], const char rest[])
{
  static const char *const named[] = {"petsc_default", "default", "petsc_decide", "decide"};
  const char              *v = rest + 1;
  const size_t             n = strcspn(v, " ");

  PetscFunctionBeginUser;
  if (!HasValue(rest) || SPOptionsTakesWord(name)) PetscFunctionReturn(PETSC_SUCCESS);
  if (InFamily(name, Families, PETSC_STATIC_ARRAY_LENGTH(Families)) ? IsFlag(name) : !(InFamily(name, PetscFamilies, PETSC_STATIC_ARRAY_LENGTH(PetscFamilies)) && HasTail(name, NumericTails, PETSC_STATIC_ARRAY_LENGTH(NumericTails)))) PetscFunctionReturn(PETSC_SUCCESS);
  for (size_t e = 0; e < n;) { /* each element of the comma list */
    const size_t m = strcspn(v + e, ", ");
    for (size_t k = 0; k < PETSC_STATIC_ARRAY_LENGTH(named); ++k) {
      const PetscBool hit = m == strlen(named[k]) && !strncasecmp(v + e, named[k], m) ? PETSC_TRUE : PETSC_FALSE;
      PetscCheck(!hit, comm, PETSC_ERR_USER_INPUT, "%s %.*s: %s%.*s is a named PETSc value, read as the number %d here, not as a default; leave the option out for its default (-help shows it), or give a number", shown, (int)n, v, m < n ? "its element " : "", (int)m, v + e, k < 2 ? (int)PETSC_DEFAULT : (int)PETSC_DECIDE);
    }
    e += m + 1;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Every option name of the database, lower case (PETSc's names ignore case) and as given, with the
   string after it, to check(); collective */
static PetscErrorCode ForEachOption(MPI_Comm comm, PetscErrorCode (*check)(MPI_Comm, const char[], const char[], const char[]))
{
  char *all;
  char  name[256], shown[256];

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(NULL, &all));
  for (size_t i = 0; all[i]; ++i) {
    size_t n;
    if (!SPOptionsNameAt(all, i, "-") || !isalpha((unsigned char)all[i + 1])) continue;
    n = SPOptionsNameCopy(all, i, name, sizeof(name));
    (void)PetscStrncpy(shown, name, sizeof(shown));
    for (size_t j = 0; j < n; ++j) name[j] = (char)tolower((unsigned char)name[j]);
    PetscCall(check(comm, name, shown, all + i + n));
    i += n - 1;
  }
  PetscCall(PetscFree(all));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Refused if the name holds '=': PETSc takes a value after a space, so -contact_method=alm was an
   option nothing reads, and the run went on with the default method to exit 0, saying so only in
   the unused-option report at its end */
static PetscErrorCode CheckGlued(MPI_Comm comm, const char name[], const char shown[], const char rest[])
{
  const char *eq = strchr(shown, '=');

  PetscFunctionBeginUser;
  PetscCheck(!eq, comm, PETSC_ERR_USER_INPUT, "%s: a value joined to its option by '='; PETSc options take their value after a space: %.*s %s", shown, (int)(eq - shown), shown, eq + 1);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Integer options: spcontact's by name (every PetscOptionsInt/IntArray name in src/, an indexed one
   by its tail; checked by the test help_complete), PETSc's by their tails and MUMPS's controls */
static const char *const IntNames[] = {"-load_steps", "-debug_interrupt_after_step", "-debug_error_on_rank", "-load_max_cutbacks", "-load_grow_after", "_values", "_components", "-contact_friction_max_flips", "-contact_shift_accel_depth", "-contact_chatter_flips", "-contact_alm_max", "-contact_regression_m", "_label_value", "-solver_jacobian_reuse", "-solver_direct_switch", "-solver_direct_switch_3d", "-solver_direct_dofs", "-solver_direct_dofs_3d", "-solver_stall_its"};

static const char *const IntTails[] = {"_max_it", "_max_funcs", "_max_fail", "_max_linear_solve_fail", "_restart", "_nsmooths", "_square_graph", "_lag_preconditioner", "_lag_jacobian", "_levels", "_refine", "_refine_pre", "_refine_hierarchy", "_faces", "_dim", "_eq_limit"};

static PetscBool IsInt(const char name[])
{
  for (size_t k = 0; k < PETSC_STATIC_ARRAY_LENGTH(IntNames); ++k)
    if (IntNames[k][0] == '-' ? !strcmp(name, IntNames[k]) : HasTail(name, IntNames + k, 1)) return PETSC_TRUE;
  return HasTail(name, IntTails, PETSC_STATIC_ARRAY_LENGTH(IntTails)) || !strncmp(name, "-mat_mumps_icntl_", 17) ? PETSC_TRUE : PETSC_FALSE;
}

/* Refused if name is an integer option and a run of digits in its value (a number, an element of
   its comma list, an end of a range a-b) is larger than PetscInt holds: PETSc reads it with strtol
   and casts, so "-load_steps 4294967298" ran 2 load steps, "-dm_refine 4294967296" refined 0 times,
   and 99999999999999999999 became -1 */
static PetscErrorCode CheckIntRange(MPI_Comm comm, const char name[], const char shown[], const char rest[])
{
  const char  *v = rest + 1;
  const size_t n = strcspn(v, " ");

  PetscFunctionBeginUser;
  if (!HasValue(rest) || !IsInt(name)) PetscFunctionReturn(PETSC_SUCCESS);
  for (size_t i = 0; i < n;) {
    double d = 0; /* the digits' value, exact far enough past PETSC_MAX_INT to compare */
    size_t j = i;
    for (; j < n && isdigit((unsigned char)v[j]); ++j) d = 10 * d + (v[j] - '0');
    PetscCheck(d <= PETSC_MAX_INT, comm, PETSC_ERR_USER_INPUT, "%s %.*s: %.*s is larger than the largest integer of this PETSc build (%" PetscInt_FMT "), which would read it as another number; give a smaller value", shown, (int)n, v, (int)(j - i), v + i, PETSC_MAX_INT);
    i = j > i ? j : i + 1;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Refused if name is an integer list (label values, components, box faces) and its value holds a
   range a-b: PETSc reads it as a, ..., b-1, so "-bc_0_values 1-3" held labels 1 and 2 and left 3
   free without a word where a user reads 1, 2, 3 (and "3-1" ended in PETSc's line about a
   "decreasing list", which named no option) */
static PetscErrorCode CheckNoRange(MPI_Comm comm, const char name[], const char shown[], const char rest[])
{
  static const char *const lists[] = {"_values", "_components", "_faces"};
  const char              *v = rest + 1, *p = v, *a;
  const size_t             n = strcspn(v, " ");

  PetscFunctionBeginUser;
  if (!HasValue(rest) || !IsInt(name) || !HasTail(name, lists, PETSC_STATIC_ARRAY_LENGTH(lists))) PetscFunctionReturn(PETSC_SUCCESS);
  while (p < v + n && !(p > v && isdigit((unsigned char)p[-1]) && *p == '-' && isdigit((unsigned char)p[1]))) ++p;
  if (p == v + n) PetscFunctionReturn(PETSC_SUCCESS);
  for (a = p; a > v && isdigit((unsigned char)a[-1]);) --a;
  SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s %.*s: PETSc reads a range a-b (here %.*s) without its end, as a, ..., b-1; write the values out as a list", shown, (int)n, v, (int)(p + 1 + strspn(p + 1, "0123456789:") - a), a);
}

/* Collective, before the set-up reads any option: values joined by '=', PETSc's named values in
   numeric options, integers out of PetscInt's range,
   ranges in integer lists */
PetscErrorCode SPOptionsCheckNamedValues(MPI_Comm comm)
{
  PetscFunctionBeginUser;
  PetscCall(ForEachOption(comm, CheckGlued));
  PetscCall(ForEachOption(comm, CheckNamed));
  PetscCall(ForEachOption(comm, CheckIntRange));
  PetscCall(ForEachOption(comm, CheckNoRange));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPOptionsCheckValues(MPI_Comm comm)
{
  PetscFunctionBeginUser;
  PetscCall(ForEachOption(comm, CheckOne));
  PetscFunctionReturn(PETSC_SUCCESS);
}
