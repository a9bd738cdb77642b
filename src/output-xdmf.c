/* XDMF index of the HDF5 file (written by rank 0 after the HDF5 file is closed). */
#include <spcontact-impl.h>

PetscErrorCode SPOutputWriteXdmf(SPOutput o)
{
  PetscFunctionBeginUser;
  PetscFunctionReturn(PETSC_SUCCESS);
}
