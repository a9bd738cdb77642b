/* Material law: small-strain isotropic linear elasticity (plane strain in 2D).
   To add a law: write SPMaterialParameters_<Name> (E, nu -> its per-cell parameters) and
   SPMaterialSetUp_<Name> (residual/Jacobian kernels reading the parameters from constants[] or
   from the auxiliary cell field) like these, and add one line to the law table in problem.c. */
#include <spcontact-impl.h>
#include <kernels/elastic.h>

void SPMaterialParameters_LinearElastic(PetscReal E, PetscReal nu, PetscReal param[])
{
  param[SP_A_LAMBDA] = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  param[SP_A_MU]     = E / (2.0 * (1.0 + nu));
}

PetscErrorCode SPMaterialSetUp_LinearElastic(PetscDS ds, const PetscReal param[], PetscScalar constants[])
{
  PetscFunctionBeginUser;
  if (param) { /* one material: Lame constants in constants[] */
    constants[SP_C_LAMBDA] = param[SP_A_LAMBDA];
    constants[SP_C_MU]     = param[SP_A_MU];
    PetscCall(PetscDSSetResidual(ds, 0, NULL, SPElasticF1));
    PetscCall(PetscDSSetJacobian(ds, 0, 0, NULL, NULL, NULL, SPElasticG3));
  } else { /* region materials: Lame constants per cell, from the auxiliary field */
    PetscCall(PetscDSSetResidual(ds, 0, NULL, SPElasticF1Aux));
    PetscCall(PetscDSSetJacobian(ds, 0, 0, NULL, NULL, NULL, SPElasticG3Aux));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
