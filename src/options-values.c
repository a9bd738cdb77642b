/* spcontact's own options given without a value. PETSc leaves a number at its default when its
   option has no value (PetscOptionsGetInt/GetReal: not set), so "-load_steps" whose value was
   lost ran one load step without a word. After set-up, an option of spcontact's families that
   the run read and that has no value is refused in one line, unless it is one of spcontact's
   flags (Flags below: every PetscOptionsBool name in src/, checked by the test help_complete;
   an indexed flag such as -bc_<i>_follower by its tail). Reading the options' names from
   PetscOptionsGetAll's string, and only those already read, leaves the report of unused
   (misspelt) options as it was. */
#include <ctype.h>
#include <spcontact-impl.h>

static const char *const Families[] = {"-contact_", "-solver_", "-load_", "-material_", "-bc_", "-output_", "-mesh_", "-restart", "-max_wall_time", "-debug_"};

static const char *const Flags[] = {"-contact_branch_hold", "-contact_friction_stick_hold", "-contact_monitor", "-contact_pair_exchange_all", "-contact_safeguard", "-contact_shift_predict", "-contact_shift_settled", "-contact_two_pass", "_follower", "-output_fields", "-quiet", "-solver_check_fast", "-solver_fast_bulk", "-solver_fast_prealloc", "-solver_gamg_shared_graph", "-solver_inexact", "-solver_inexact_inner", "-solver_inexact_measured", "-solver_inexact_refine", "-solver_linear_reuse", "-solver_target_floor"};

/* name (with its dash, lower case) is a flag: equal to a full flag name, or ending with a tail */
static PetscBool IsFlag(const char name[])
{
  const size_t n = strlen(name);

  for (size_t k = 0; k < PETSC_STATIC_ARRAY_LENGTH(Flags); ++k) {
    const size_t m = strlen(Flags[k]);
    if (Flags[k][0] == '-' ? !strcmp(name, Flags[k]) : (n > m && !strcmp(name + n - m, Flags[k]))) return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

static PetscBool InFamily(const char name[])
{
  for (size_t k = 0; k < PETSC_STATIC_ARRAY_LENGTH(Families); ++k)
    if (!strncmp(name, Families[k], strlen(Families[k]))) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* One option name of the database: refused if it is spcontact's, was read, is not a flag and has
   no value */
static PetscErrorCode CheckOne(MPI_Comm comm, const char name[])
{
  PetscBool used, set;
  char      value[8];

  PetscFunctionBeginUser;
  if (!InFamily(name) || IsFlag(name)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscOptionsUsed(NULL, name + 1, &used)); /* the database keeps names without the dash */
  if (!used) PetscFunctionReturn(PETSC_SUCCESS); /* not read: the unused-option report names it */
  PetscCall(PetscOptionsGetString(NULL, NULL, name, value, sizeof(value), &set));
  PetscCheck(!set || value[0], comm, PETSC_ERR_USER_INPUT, "%s needs a value (-help gives its meaning and default)", name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPOptionsCheckValues(MPI_Comm comm)
{
  char *all;
  char  name[256];

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(NULL, &all));
  for (size_t i = 0; all[i]; ++i) {
    size_t n;
    if (!SPOptionsNameAt(all, i, "-") || !isalpha((unsigned char)all[i + 1])) continue;
    n = SPOptionsNameCopy(all, i, name, sizeof(name));
    for (size_t j = 0; j < n; ++j) name[j] = (char)tolower((unsigned char)name[j]); /* PETSc's names ignore case */
    PetscCall(CheckOne(comm, name));
    i += n - 1;
  }
  PetscCall(PetscFree(all));
  PetscFunctionReturn(PETSC_SUCCESS);
}
