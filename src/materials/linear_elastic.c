/* Material model: small-strain isotropic linear elasticity (plane strain in 2D).
   To add a material: write SPMaterialSetUp_<Name> like this one (set residual/Jacobian kernels and
   its constants[] slots) and add one line to the table in problem.c. */
#include <spcontact-impl.h>
#include <kernels/elastic.h>

PetscErrorCode SPMaterialSetUp_LinearElastic(PetscDS ds, PetscReal E, PetscReal nu, PetscScalar constants[])
{
  PetscFunctionBeginUser;
  constants[SP_C_LAMBDA] = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  constants[SP_C_MU]     = E / (2.0 * (1.0 + nu));
  PetscCall(PetscDSSetResidual(ds, 0, NULL, SPElasticF1));
  PetscCall(PetscDSSetJacobian(ds, 0, 0, NULL, NULL, NULL, SPElasticG3));
  PetscFunctionReturn(PETSC_SUCCESS);
}
