/* spcontact's own defaults for PETSc options (a box mesh of tensor cells, P1/Q1, GAMG's level
   smoothers): set only where the user did not give the option. Each one leaves a marker option
   -spcontact_default_<name> in the database, so the report of unused options (main.c) can tell
   a default the run did not need (a GAMG option when another preconditioner runs: not reported)
   from the same option given by the user and not used (reported). The markers are the record;
   no state outside PETSc's options database. */
#include <ctype.h>
#include <spcontact-impl.h>

#define SP_DEFAULT_MARK "spcontact_default_"

/* In the string of PetscOptionsGetAll ("-name value -name ..."): whether an option name starts
   at all[i] and begins with key (case-insensitive, as PETSc compares names). Reading the string
   does not mark options used, as PetscOptionsHasName would. */
PetscBool SPOptionsNameAt(const char all[], size_t i, const char key[])
{
  size_t j = 0;

  if (i > 0 && all[i - 1] != ' ') return PETSC_FALSE;
  while (key[j] && all[i + j] && tolower((unsigned char)all[i + j]) == tolower((unsigned char)key[j])) j++;
  return key[j] ? PETSC_FALSE : PETSC_TRUE;
}

/* The option name that starts at all[i], copied into name (at most len - 1 characters); its length */
size_t SPOptionsNameCopy(const char all[], size_t i, char name[], size_t len)
{
  size_t j = 0;

  while (j < len - 1 && all[i + j] && all[i + j] != ' ') name[j] = all[i + j], j++;
  name[j] = 0;
  return j;
}

/* Whether the database holds option name (with its dash), without marking it used: a user's
   option must stay reportable as unused */
static PetscErrorCode Given(const char name[], PetscBool *given)
{
  const size_t n = strlen(name);
  char        *all;

  PetscFunctionBeginUser;
  *given = PETSC_FALSE;
  PetscCall(PetscOptionsGetAll(NULL, &all));
  for (size_t i = 0; all[i] && !*given; ++i)
    if (SPOptionsNameAt(all, i, name) && (all[i + n] == ' ' || !all[i + n])) *given = PETSC_TRUE;
  PetscCall(PetscFree(all));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* name with its leading dash, as PetscOptionsSetValue takes it */
PetscErrorCode SPOptionsSetDefault(const char name[], const char value[])
{
  char      mark[256];
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(Given(name, &set));
  if (set) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscOptionsSetValue(NULL, name, value));
  PetscCall(PetscSNPrintf(mark, sizeof(mark), "-" SP_DEFAULT_MARK "%s", name + 1));
  PetscCall(PetscOptionsSetValue(NULL, mark, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether an unused option (name without its dash, as PetscOptionsLeftGet gives it) is one of
   spcontact's defaults, or one of their markers */
PetscErrorCode SPOptionsIsDefault(const char name[], PetscBool *own)
{
  char mark[256];

  PetscFunctionBeginUser;
  PetscCall(PetscStrncmp(name, SP_DEFAULT_MARK, sizeof(SP_DEFAULT_MARK) - 1, own));
  if (*own) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(mark, sizeof(mark), "-" SP_DEFAULT_MARK "%s", name));
  PetscCall(PetscOptionsHasName(NULL, NULL, mark, own));
  PetscFunctionReturn(PETSC_SUCCESS);
}
