/* Options a run read but does not use (an option of another method, friction options without
   friction, contact options without contact) are put back as unread, so that the end-of-run
   report of unused options (main.c) names them as it names a misspelt one. PETSc marks an option
   used once read and has no call to unmark it: the option is removed and set again with its value
   (a new entry is unread). */
#include <spcontact-impl.h>

/* Every option given whose name is key (with its dash) or, for a key ending in '_' (such as
   "-contact_"), begins with it: "-solver_direct_switch" is not "-solver_direct_switch_3d" */
PetscErrorCode SPOptionsUnread(const char key[])
{
  char        *all, name[256], value[PETSC_MAX_PATH_LEN];
  const size_t kl     = strlen(key);
  const int    prefix = kl > 0 && key[kl - 1] == '_';

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(NULL, &all));
  for (size_t i = 0; all[i]; ++i) {
    PetscBool set;
    if (!SPOptionsNameAt(all, i, key) || (!prefix && all[i + kl] && all[i + kl] != ' ')) continue;
    i += SPOptionsNameCopy(all, i, name, sizeof(name)) - 1;
    value[0] = 0;
    PetscCall(PetscOptionsGetString(NULL, NULL, name, value, sizeof(value), &set));
    if (!set) continue;
    PetscCall(PetscOptionsClearValue(NULL, name));
    PetscCall(PetscOptionsSetValue(NULL, name, value[0] ? value : NULL));
  }
  PetscCall(PetscFree(all));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Options read between SPOptionsLeftBegin and SPOptionsLeftEnd that were unused before (read only
   there: e.g. the options of a method the run did not choose, read so that -help lists them) */
PetscErrorCode SPOptionsLeftBegin(SPOptionsLeft *l)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsLeftGet(NULL, &l->n, &l->names, &l->values));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPOptionsLeftEnd(SPOptionsLeft *l)
{
  char name[256];

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < l->n; ++k) {
    PetscBool used;
    PetscCall(PetscOptionsUsed(NULL, l->names[k], &used)); /* PETSc's stored name: without the dash */
    PetscCall(PetscSNPrintf(name, sizeof(name), "-%s", l->names[k]));
    if (used) PetscCall(SPOptionsUnread(name));
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &l->n, &l->names, &l->values));
  PetscFunctionReturn(PETSC_SUCCESS);
}
