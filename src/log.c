/* Named log stages and events, so -log_view shows where the time goes. */
#include <spcontact-impl.h>

PetscErrorCode SPLogRegister(SPLog *log)
{
  PetscClassId id;

  PetscFunctionBeginUser;
  PetscCall(PetscClassIdRegister("spcontact", &id));
  PetscCall(PetscLogStageRegister("SP mesh", &log->mesh));
  PetscCall(PetscLogStageRegister("SP setup", &log->setup));
  PetscCall(PetscLogStageRegister("SP solve", &log->solve));
  PetscCall(PetscLogStageRegister("SP output", &log->output));
  PetscCall(PetscLogEventRegister("SPBulkResidual", id, &log->bulkResidual));
  PetscCall(PetscLogEventRegister("SPBulkJacobian", id, &log->bulkJacobian));
  PetscCall(PetscLogEventRegister("SPContactSearch", id, &log->contactSearch));
  PetscCall(PetscLogEventRegister("SPContactAssem", id, &log->contactAssembly));
  PetscCall(PetscLogEventRegister("SPShiftUpdate", id, &log->shiftUpdate));
  PetscCall(PetscLogEventRegister("SPMatCreate", id, &log->matCreate));
  PetscCall(PetscLogEventRegister("SPNearNullSpace", id, &log->nearNullSpace));
  PetscCall(PetscLogEventRegister("SPFastSetUp", id, &log->fastSetUp));
  PetscFunctionReturn(PETSC_SUCCESS);
}
