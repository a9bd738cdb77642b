/* Problem: displacement field (PetscFE, degree from -petscspace_degree), material, boundary
   conditions and the load factor that scales every load. */
#include <spcontact-impl.h>
#include <kernels/elastic.h>

static const SPMaterialEntry SPMaterials[] = {
  /* name            setup                          linear      isotropic */
  {"linear_elastic", SPMaterialSetUp_LinearElastic, PETSC_TRUE, PETSC_TRUE},
};

PetscErrorCode SPProblemCreate(DM dm, SPProblem *problem)
{
  SPProblem p;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&p));
  p->dm   = dm;
  p->E    = 1.0;
  p->nu   = 0.3;
  p->load = 1.0;
  PetscCall(PetscStrcpy(p->material, "linear_elastic"));
  PetscCall(DMGetDimension(dm, &p->dim));
  *problem = p;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPProblemSetFromOptions(SPProblem p)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)p->dm);

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Material options", "spcontact");
  PetscCall(PetscOptionsString("-material_model", "Material model: linear_elastic", "SPProblemSetFromOptions", p->material, p->material, sizeof(p->material), NULL));
  PetscCall(PetscOptionsReal("-material_E", "Young's modulus E > 0", "SPProblemSetFromOptions", p->E, &p->E, NULL));
  PetscCall(PetscOptionsReal("-material_nu", "Poisson's ratio, -1 < nu < 0.5", "SPProblemSetFromOptions", p->nu, &p->nu, NULL));
  PetscCall(PetscOptionsReal("-material_mms", "Verification: amplitude of the manufactured body force/solution on the unit box (0 = off)", "SPProblemSetFromOptions", p->mmsAmp, &p->mmsAmp, NULL));
  PetscOptionsEnd();
  PetscCheck(p->E > 0.0, comm, PETSC_ERR_USER_INPUT, "-material_E %g: Young's modulus must be positive", (double)p->E);
  PetscCheck(p->nu > -1.0 && p->nu < 0.5, comm, PETSC_ERR_USER_INPUT, "-material_nu %g: Poisson's ratio must satisfy -1 < nu < 0.5", (double)p->nu);
  PetscCall(SPBCSetFromOptions(comm, p->dim, &p->nbc, p->bc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SetUpMaterial(SPProblem p, PetscDS ds, PetscScalar constants[])
{
  MPI_Comm comm = PetscObjectComm((PetscObject)p->dm);
  size_t   n    = sizeof(SPMaterials) / sizeof(SPMaterials[0]);

  PetscFunctionBeginUser;
  for (size_t i = 0; i < n; ++i) {
    PetscBool match;
    PetscCall(PetscStrcmp(p->material, SPMaterials[i].name, &match));
    if (match) {
      PetscCall(SPMaterials[i].setup(ds, p->E, p->nu, constants));
      p->linear    = SPMaterials[i].linear;
      p->isotropic = SPMaterials[i].isotropic;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  }
  SETERRQ(comm, PETSC_ERR_USER_INPUT, "-material_model %s: unknown material (available: linear_elastic)", p->material);
}

PetscErrorCode SPProblemSetUp(SPProblem p)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)p->dm);
  PetscFE     fe;
  PetscSpace  sp;
  PetscDS     ds;
  PetscBool   simplex;
  PetscScalar constants[SP_C_NUM] = {0};

  PetscFunctionBeginUser;
  PetscCall(DMPlexIsSimplex(p->dm, &simplex));
  { /* PETSc's own default degree is 0; spcontact's is 1 (P1/Q1), -petscspace_degree overrides */
    PetscBool set;
    PetscCall(PetscOptionsHasName(NULL, NULL, "-petscspace_degree", &set));
    if (!set) PetscCall(PetscOptionsSetValue(NULL, "-petscspace_degree", "1"));
  }
  PetscCall(PetscFECreateDefault(comm, p->dim, p->dim, simplex, NULL, PETSC_DETERMINE, &fe));
  PetscCall(PetscObjectSetName((PetscObject)fe, "displacement"));
  PetscCall(PetscFEGetBasisSpace(fe, &sp));
  PetscCall(PetscSpaceGetDegree(sp, &p->degree, NULL)); /* (degree, max total degree) */
  PetscCheck(p->degree >= 1, comm, PETSC_ERR_USER_INPUT, "-petscspace_degree %" PetscInt_FMT ": displacement needs degree >= 1", p->degree);
  PetscCall(DMSetField(p->dm, 0, NULL, (PetscObject)fe));
  PetscCall(PetscFEDestroy(&fe));
  PetscCall(DMCreateDS(p->dm));
  PetscCall(DMGetDS(p->dm, &ds));
  PetscCall(SetUpMaterial(p, ds, constants));
  constants[SP_C_LOAD] = p->load;
  constants[SP_C_MMS]  = p->mmsAmp;
  if (p->mmsAmp != 0.0) {
    PetscCall(PetscDSSetResidual(ds, 0, SPElasticF0MMS, SPElasticF1));
    PetscCall(PetscDSSetExactSolution(ds, 0, SPMMSExact, &p->mmsAmp));
  }
  PetscCall(SPBCAddToDS(p->dm, p->nbc, p->bc, constants));
  PetscCall(PetscDSSetConstants(ds, SP_C_NUM, constants));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPProblemSetLoadFactor(SPProblem p, PetscReal load)
{
  PetscDS            ds;
  PetscInt           n;
  const PetscScalar *c;
  PetscScalar        constants[SP_C_NUM];

  PetscFunctionBeginUser;
  p->load = load;
  PetscCall(DMGetDS(p->dm, &ds));
  PetscCall(PetscDSGetConstants(ds, &n, &c));
  for (PetscInt i = 0; i < n; ++i) constants[i] = c[i];
  constants[SP_C_LOAD] = load;
  PetscCall(PetscDSSetConstants(ds, n, constants));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPProblemGetLoadFactor(SPProblem p, PetscReal *load)
{
  PetscFunctionBeginUser;
  *load = p->load;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPProblemGetYoung(SPProblem p, PetscReal *E)
{
  PetscFunctionBeginUser;
  *E = p->E;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPProblemGetDegree(SPProblem p, PetscInt *degree)
{
  PetscFunctionBeginUser;
  *degree = p->degree;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Local state of a global vector: unconstrained dofs from X, Dirichlet values of the current load
   factor (projected once per load factor and cached; the projection is costly). */
PetscErrorCode SPProblemGetLocalState(SPProblem p, Vec X, Vec *locX)
{
  PetscFunctionBeginUser;
  if (!p->locBC) {
    PetscCall(DMCreateLocalVector(p->dm, &p->locBC));
    p->bcLoad = PETSC_MAX_REAL;
  }
  if (p->bcLoad != p->load) {
    PetscCall(VecZeroEntries(p->locBC));
    PetscCall(DMPlexInsertBoundaryValues(p->dm, PETSC_TRUE, p->locBC, p->load, NULL, NULL, NULL));
    p->bcLoad = p->load;
  }
  PetscCall(DMGetLocalVector(p->dm, locX));
  PetscCall(VecCopy(p->locBC, *locX));
  PetscCall(DMGlobalToLocal(p->dm, X, INSERT_VALUES, *locX)); /* constrained entries are kept */
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPProblemRestoreLocalState(SPProblem p, Vec *locX)
{
  PetscFunctionBeginUser;
  PetscCall(DMRestoreLocalVector(p->dm, locX));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPProblemIsLinear(SPProblem p, PetscBool *linear)
{
  PetscFunctionBeginUser;
  *linear = p->linear;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* L2 error against the manufactured solution, when one is active */
PetscErrorCode SPProblemComputeError(SPProblem p, Vec u, PetscBool *has, PetscReal *err)
{
  PetscErrorCode (*exact[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {SPMMSExact};
  void *ctx[1] = {&p->mmsAmp};

  PetscFunctionBeginUser;
  *has = p->mmsAmp != 0.0 ? PETSC_TRUE : PETSC_FALSE;
  *err = 0.0;
  if (*has) PetscCall(DMComputeL2Diff(p->dm, p->load, exact, ctx, u, err));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPProblemDestroy(SPProblem *p)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&(*p)->locBC));
  PetscCall(PetscFree(*p));
  PetscFunctionReturn(PETSC_SUCCESS);
}
