/* Real options whose default is not one number: computed per contact point (-contact_penalty:
   alpha E / h), from another option, or absent (a sphere's radius must be given). PETSc's
   PetscOptionsReal shows its current value as the default in -help, so such an option read it as
   "<0.>" or "<-1.>", values the run then refuses. Here -help shows what the default is
   ("-contact_penalty <alpha E / h>: ..."), and a given value is converted as PETSc converts it (a
   non-number is named by main.c: "-contact_penalty abc: not a number"). */
#include <spcontact-impl.h>

/* *set: given with a value (an option given without one is refused by SPOptionsCheckValues) */
PetscErrorCode SPOptionsRealComputed(PetscOptionItems *PetscOptionsObject, const char name[], const char text[], const char man[], const char deflt[], PetscReal *value, PetscBool *set)
{
  const char *prefix = PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "";
  char        str[256] = "";

  PetscFunctionBeginUser;
  if (PetscOptionsObject->printhelp && PetscOptionsObject->count == 1 && !PetscOptionsObject->alreadyprinted) PetscCall((*PetscHelpPrintf)(PetscOptionsObject->comm, "  -%s%s <%s>: %s (%s)\n", prefix, name + 1, deflt, text, man));
  PetscCall(PetscOptionsGetString(PetscOptionsObject->options, PetscOptionsObject->prefix, name, str, sizeof(str), set));
  if (*set && !str[0]) *set = PETSC_FALSE;
  if (*set) PetscCall(PetscOptionsStringToReal(str, value));
  PetscFunctionReturn(PETSC_SUCCESS);
}
