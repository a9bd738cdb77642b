/* An array option given more values than it holds: PETSc's PetscOptions*Array keeps the first n
   and drops the rest without a word, so "-bc_1_ramp 0,1,2" ran as 0,1 and a 3D
   "-contact_obstacle_0_point 0,0,1,5" as 0,0,1. Each array read is followed by this check of the
   given string's count of values (its commas). An integer range a-b (PETSc's a, ..., b-1) counts
   as one: PETSc refuses a range longer than the array itself, so none is dropped. */
#include <spcontact-impl.h>

/* Collective: refuse option name (with its dash; prefix as in PetscOptionsBegin) given more than nmax values */
PetscErrorCode SPOptionsCheckLength(MPI_Comm comm, const char prefix[], const char name[], PetscInt nmax)
{
  const char *v = NULL;
  PetscBool   set;
  PetscInt    n = 1;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsFindPair(NULL, prefix, name, &v, &set));
  if (!set || !v) PetscFunctionReturn(PETSC_SUCCESS);
  for (const char *p = v; *p; ++p) n += *p == ',';
  PetscCheck(n <= nmax, comm, PETSC_ERR_USER_INPUT, "-%s%s %s: %" PetscInt_FMT " values given, and it takes at most %" PetscInt_FMT " (the rest would be dropped without a word)", prefix ? prefix : "", name + 1, v, n, nmax);
  PetscFunctionReturn(PETSC_SUCCESS);
}
