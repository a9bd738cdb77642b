/* Numbered option families: -bc_<i>_*, -contact_obstacle_<k>_*, -contact_pair_<k>_*,
   -material_<k>_*. A family is read for k = 0, 1, ... up to the first k without its defining
   option (a condition's type, an obstacle's type, a pair's surfaces), so an option of a later k
   (after a gap, or one whose defining option is missing) would be dropped without a word and the
   run would solve another problem. These checks refuse that in one line before the solve. The
   options' names come from PetscOptionsGetAll's string, which marks nothing used. */
#include <ctype.h>
#include <spcontact-impl.h>

/* Which k have an option <key><k>_* in the database (given[0..max)). PetscOptionsHasName cannot
   tell: its "_%d_" lookup finds -material_E for -material_0_E. An index >= max is an error that
   names the option and what the family holds (what: "region materials"). */
PetscErrorCode SPOptionsIndexedGiven(MPI_Comm comm, const char key[], PetscInt max, const char what[], PetscBool given[])
{
  const size_t n = strlen(key);
  char        *all;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < max; ++k) given[k] = PETSC_FALSE;
  PetscCall(PetscOptionsGetAll(NULL, &all)); /* "-name value -name ..." */
  for (size_t i = 0; all[i]; ++i) {
    size_t d;
    long   k = 0;
    if (!SPOptionsNameAt(all, i, key)) continue;
    for (d = i + n; isdigit((unsigned char)all[d]) && k < 1000000; ++d) k = 10 * k + (all[d] - '0');
    if (d == i + n || all[d] != '_') continue; /* not <key><k>_ */
    if (k >= max) {
      char name[64];
      (void)SPOptionsNameCopy(all, i, name, sizeof(name));
      PetscCall(PetscFree(all));
      SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s: at most %" PetscInt_FMT " %s (numbered 0..%" PetscInt_FMT ")", name, max, what, max - 1);
    }
    given[k] = PETSC_TRUE;
  }
  PetscCall(PetscFree(all));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The family <key><k>_* was read for k < n (n: the first k without <key><k>_<defining>): refuse
   an option of any k >= n, naming it and the missing defining option. what: "boundary
   conditions"; one: "boundary condition". */
PetscErrorCode SPOptionsCheckNoGap(MPI_Comm comm, const char key[], PetscInt n, PetscInt max, const char what[], const char one[], const char defining[])
{
  PetscBool given[64];

  PetscFunctionBeginUser;
  PetscCheck(max <= (PetscInt)PETSC_STATIC_ARRAY_LENGTH(given), comm, PETSC_ERR_PLIB, "%s: family too large", key);
  PetscCall(SPOptionsIndexedGiven(comm, key, max, what, given));
  for (PetscInt k = n; k < max; ++k) {
    char *all, head[64], name[64] = "";
    if (!given[k]) continue;
    PetscCall(PetscSNPrintf(head, sizeof(head), "%s%" PetscInt_FMT "_", key, k));
    PetscCall(PetscOptionsGetAll(NULL, &all));
    for (size_t i = 0; all[i] && !name[0]; ++i)
      if (SPOptionsNameAt(all, i, head)) (void)SPOptionsNameCopy(all, i, name, sizeof(name));
    PetscCall(PetscFree(all));
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s: %s %" PetscInt_FMT " is not read because %s%" PetscInt_FMT "_%s is missing (%s are numbered 0, 1, 2, ... without gaps, each with its %s<i>_%s)", name, one, k, key, n, defining, what, key, defining);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
