/* Material law: compressible Neo-Hookean, total Lagrangian (kernels/neohookean.h gives the
   strain energy and why that form). Its parameters are the Lame constants of (E, nu), the same
   as linear_elastic's, so both laws agree in the small-strain limit. */
#include <spcontact-impl.h>
#include <kernels/neohookean.h>

PetscErrorCode SPMaterialSetUp_NeoHookean(PetscDS ds, const PetscReal param[], PetscScalar constants[])
{
  PetscFunctionBeginUser;
  if (param) { /* one material: Lame constants in constants[] */
    constants[SP_C_LAMBDA] = param[SP_A_LAMBDA];
    constants[SP_C_MU]     = param[SP_A_MU];
    PetscCall(PetscDSSetResidual(ds, 0, NULL, SPNeoHookeanF1));
    PetscCall(PetscDSSetJacobian(ds, 0, 0, NULL, NULL, NULL, SPNeoHookeanG3));
  } else { /* region materials: Lame constants per cell, from the auxiliary field */
    PetscCall(PetscDSSetResidual(ds, 0, NULL, SPNeoHookeanF1Aux));
    PetscCall(PetscDSSetJacobian(ds, 0, 0, NULL, NULL, NULL, SPNeoHookeanG3Aux));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The fast element operator's pointwise stress and tangent (param: lambda, mu) */
void SPMaterialStress_NeoHookean(PetscInt dim, const PetscReal param[], const PetscScalar u_x[], PetscScalar P[])
{
  SPNeoHookeanStress(dim, param[SP_A_LAMBDA], param[SP_A_MU], u_x, P);
}

void SPMaterialTangent_NeoHookean(PetscInt dim, const PetscReal param[], const PetscScalar u_x[], PetscScalar A[])
{
  SPNeoHookeanTangent(dim, param[SP_A_LAMBDA], param[SP_A_MU], u_x, A);
}
