/* Boundary conditions from indexed options -bc_<i>_*: Dirichlet per component, traction and
   pressure per label, all scaled by the load factor. */
#include <spcontact-impl.h>
#include <kernels/elastic.h>
#include <kernels/follower.h>

const char *const SPBCTypes[] = {"dirichlet", "traction", "pressure", "force", "SPBCType", "SP_BC_", NULL};

/* given = PETSC_FALSE: only list the options for -help (bc_0 when no condition is set), no checks */
static PetscErrorCode BCSetFromOptions(MPI_Comm comm, PetscInt i, PetscInt dim, PetscBool given, SPBC *bc)
{
  char      prefix[32];
  PetscInt  type = 0, nval = 3, nramp, ngrad;
  PetscBool gradSet;
  PetscBool rampSet;
  PetscBool set, valueSet, followerSet;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "bc_%" PetscInt_FMT "_", i));
  PetscCall(PetscStrcpy(bc->label, "Face Sets"));
  bc->nvalues = SP_MAX_VALUES;
  bc->ncomps  = dim;
  for (PetscInt d = 0; d < 3; ++d) bc->comps[d] = d, bc->value[d] = 0.0, bc->gradient[d] = 0.0;
  bc->ramp[0] = 0.0, bc->ramp[1] = 1.0, bc->slot = -1, bc->follower = PETSC_FALSE;
  PetscOptionsBegin(comm, prefix, "Boundary condition", "spcontact");
  PetscCall(PetscOptionsEList("-type", "Boundary condition type: dirichlet, traction, pressure, force (total force spread uniformly over the faces)", "SPBCSetFromOptions", SPBCTypes, 4, SPBCTypes[0], &type, NULL));
  PetscCall(PetscOptionsString("-label", "Mesh label of the boundary", "SPBCSetFromOptions", bc->label, bc->label, sizeof(bc->label), NULL));
  PetscCall(PetscOptionsIntArray("-values", "Label values (gmsh physical group numbers)", "SPBCSetFromOptions", bc->values, &bc->nvalues, &set));
  if (!set) bc->nvalues = 0;
  PetscCall(PetscOptionsIntArray("-components", "Dirichlet: constrained displacement components (0..dim-1)", "SPBCSetFromOptions", bc->comps, &bc->ncomps, &set));
  if (!set) bc->ncomps = dim;
  PetscCall(PetscOptionsRealArray("-value", "Dirichlet: one displacement per component; traction: vector; pressure: value; force: total force vector (all at load factor 1)", "SPBCSetFromOptions", bc->value, &nval, &valueSet));
  ngrad = 3;
  PetscCall(PetscOptionsRealArray("-gradient", "Pressure: gradient g of a linearly varying pressure p(x) = value + g . x (at load factor 1)", "SPBCSetFromOptions", bc->gradient, &ngrad, &gradSet));
  PetscCall(PetscOptionsBool("-follower", "Pressure: follow the deformed face (p J F^-T N, with its load stiffness; finite-strain laws only) instead of a dead load on the reference face", "SPBCSetFromOptions", bc->follower, &bc->follower, &followerSet));
  nramp = 2;
  PetscCall(PetscOptionsRealArray("-ramp", "Load curve a,b: the condition is off up to load factor a, full from b, linear between (0,1: proportional to the load factor; e.g. a normal phase, then a tangential one)", "SPBCSetFromOptions", bc->ramp, &nramp, &rampSet));
  PetscOptionsEnd();
  {
    const char *const name[] = {"-values", "-components", "-value", "-gradient", "-ramp"};
    const PetscInt    cap[]  = {SP_MAX_VALUES, 3, 3, 3, 2};
    for (PetscInt k = 0; k < 5; ++k) PetscCall(SPOptionsCheckLength(comm, prefix, name[k], cap[k]));
  }
  if (!given) PetscFunctionReturn(PETSC_SUCCESS);
  bc->type = (SPBCType)type;
  {
    const PetscInt want = bc->type == SP_BC_DIRICHLET ? bc->ncomps : bc->type == SP_BC_PRESSURE ? 1 : dim;
    PetscCheck(!valueSet || nval == want, comm, PETSC_ERR_USER_INPUT, "-%svalue: %s needs %" PetscInt_FMT " value(s), got %" PetscInt_FMT, prefix, SPBCTypes[type], want, nval);
  }
  for (PetscInt k = 0; k < 3; ++k) PetscCheck(!PetscIsInfOrNanReal(bc->value[k]) && !PetscIsInfOrNanReal(bc->gradient[k]), comm, PETSC_ERR_USER_INPUT, "-%svalue/-%sgradient: every value must be a finite number", prefix, prefix);
  PetscCheck(!gradSet || bc->type == SP_BC_PRESSURE, comm, PETSC_ERR_USER_INPUT, "-%sgradient: only a pressure condition takes a gradient (this one is %s)", prefix, SPBCTypes[type]);
  PetscCheck(!followerSet || bc->type == SP_BC_PRESSURE, comm, PETSC_ERR_USER_INPUT, "-%sfollower: only a pressure condition follows the deformed face (this one is %s)", prefix, SPBCTypes[type]);
  PetscCheck(!gradSet || ngrad == dim, comm, PETSC_ERR_USER_INPUT, "-%sgradient: give %" PetscInt_FMT " components (one per coordinate), got %" PetscInt_FMT, prefix, dim, ngrad);
  PetscCheck(!rampSet || (nramp == 2 && bc->ramp[0] >= 0.0 && bc->ramp[1] > bc->ramp[0] && bc->ramp[1] <= 1.0), comm, PETSC_ERR_USER_INPUT, "-%sramp: give two load factors 0 <= a < b <= 1", prefix);
  PetscCheck(bc->nvalues > 0, comm, PETSC_ERR_USER_INPUT, "-%svalues: give the label values of boundary condition %" PetscInt_FMT, prefix, i);
  for (PetscInt k = 0; k < bc->ncomps; ++k) {
    PetscCheck(bc->comps[k] >= 0 && bc->comps[k] < dim, comm, PETSC_ERR_USER_INPUT, "-%scomponents: component %" PetscInt_FMT " out of range [0, %" PetscInt_FMT ")", prefix, bc->comps[k], dim);
    for (PetscInt j = 0; j < k; ++j) PetscCheck(bc->comps[j] != bc->comps[k], comm, PETSC_ERR_USER_INPUT, "-%scomponents: component %" PetscInt_FMT " is given twice (one of its two values would be lost); give each component once", prefix, bc->comps[k]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPBCSetFromOptions(MPI_Comm comm, PetscInt dim, PetscInt *nbc, SPBC bc[])
{
  PetscFunctionBeginUser;
  *nbc = 0;
  for (PetscInt i = 0; i < SP_MAX_BC; ++i) {
    char      name[32];
    PetscBool has;
    PetscCall(PetscSNPrintf(name, sizeof(name), "-bc_%" PetscInt_FMT "_type", i));
    PetscCall(PetscOptionsHasName(NULL, NULL, name, &has));
    if (!has && i == 0) { /* -help lists the -bc_<i>_* family even when no condition is set */
      PetscBool help;
      PetscCall(PetscOptionsHasHelp(NULL, &help));
      if (help) PetscCall(BCSetFromOptions(comm, 0, dim, PETSC_FALSE, &bc[0]));
    }
    if (!has) break;
    PetscCall(BCSetFromOptions(comm, i, dim, PETSC_TRUE, &bc[i]));
    (*nbc)++;
  }
  PetscCall(SPOptionsCheckNoGap(comm, "-bc_", *nbc, SP_MAX_BC, "boundary conditions", "boundary condition", "type"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Measure (area in 3D, length in 2D) of the labelled facets; each boundary facet lives on one rank */
static PetscErrorCode LabelMeasure(DM dm, const SPBC *bc, PetscReal *measure)
{
  PetscReal local = 0.0;
  PetscInt  n, *facets;

  PetscFunctionBeginUser;
  PetscCall(SPMeshGetLabelFacets(dm, bc->label, bc->nvalues, bc->values, &n, &facets));
  for (PetscInt k = 0; k < n; ++k) {
    PetscReal vol;
    PetscCall(DMPlexComputeCellGeometryFVM(dm, facets[k], &vol, NULL, NULL));
    local += vol;
  }
  PetscCall(PetscFree(facets));
  PetscCallMPI(MPI_Allreduce(&local, measure, 1, MPIU_REAL, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Amplitude of a condition at load factor `load`: its load curve (proportional by default) */
PetscReal SPBCAmplitude(const SPBC *bc, PetscReal load)
{
  if (bc->ramp[0] == 0.0 && bc->ramp[1] == 1.0) return load;
  return PetscMin(1.0, PetscMax(0.0, (load - bc->ramp[0]) / (bc->ramp[1] - bc->ramp[0])));
}

/* u_c = amplitude * value_k on the constrained components; the load factor arrives as "time". */
static PetscErrorCode DirichletValue(PetscInt dim, PetscReal load, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *ctx)
{
  const SPBC     *bc = (const SPBC *)ctx;
  const PetscReal a  = SPBCAmplitude(bc, load);
  for (PetscInt c = 0; c < Nc; ++c) u[c] = 0.0;
  for (PetscInt k = 0; k < bc->ncomps; ++k) u[bc->comps[k]] = a * bc->value[k];
  return PETSC_SUCCESS;
}

/* Whether every condition moves r times as much over [l[1], l[2]] as over [l[0], l[1]] */
PetscBool SPBCProportional(PetscInt nbc, const SPBC bc[], const PetscReal l[3], PetscReal r)
{
  for (PetscInt i = 0; i < nbc; ++i) {
    const PetscReal a0 = SPBCAmplitude(&bc[i], l[0]), a1 = SPBCAmplitude(&bc[i], l[1]), a2 = SPBCAmplitude(&bc[i], l[2]);
    if (PetscAbsReal((a2 - a1) - r * (a1 - a0)) > 1e-10 * (PetscAbsReal(a2 - a1) + PetscAbsReal(a1 - a0) + 1e-300)) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

/* The Neumann slots of constants[] at load factor `load` */
void SPBCSetLoad(PetscInt nbc, const SPBC bc[], PetscReal load, PetscScalar constants[])
{
  for (PetscInt i = 0; i < nbc; ++i) {
    const PetscReal a = SPBCAmplitude(&bc[i], load);
    if (bc[i].slot < 0) continue;
    for (PetscInt k = 0; k < SP_C_BCW; ++k) constants[SP_C_BC0 + SP_C_BCW * bc[i].slot + k] = a * bc[i].base[k];
  }
}

PetscErrorCode SPBCAddToDS(DM dm, PetscInt nbc, SPBC bc[], PetscScalar constants[])
{
  PetscDS  ds;
  PetscInt slot = 0, one = 1, dim;

  PetscFunctionBeginUser;
  PetscCall(DMGetDS(dm, &ds));
  PetscCall(DMGetDimension(dm, &dim));
  for (PetscInt i = 0; i < nbc; ++i) {
    char    opt[32];
    DMLabel label;
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-bc_%" PetscInt_FMT "_values", i));
    PetscCall(SPMeshCheckLabel(dm, bc[i].label, bc[i].nvalues, bc[i].values, opt));
    if (bc[i].type == SP_BC_DIRICHLET) {
      char name[64];
      PetscCall(PetscSNPrintf(name, sizeof(name), "spcontact_bc_%" PetscInt_FMT, i));
      PetscCall(SPMeshCreateCompletedLabel(dm, bc[i].label, bc[i].nvalues, bc[i].values, name, &label));
      PetscCall(DMAddBoundary(dm, DM_BC_ESSENTIAL, opt + 1, label, 1, &one, 0, bc[i].ncomps, bc[i].comps, (void (*)(void))DirichletValue, NULL, &bc[i], NULL));
    } else {
      PetscWeakForm wf;
      PetscInt      bd;
      PetscCall(DMGetLabel(dm, bc[i].label, &label));
      PetscCall(DMAddBoundary(dm, DM_BC_NATURAL, opt + 1, label, bc[i].nvalues, bc[i].values, 0, 0, NULL, NULL, NULL, NULL, &bd));
      PetscCall(PetscDSGetBoundary(ds, bd, &wf, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL));
      for (PetscInt v = 0; v < bc[i].nvalues; ++v) {
        if (!bc[i].follower) PetscCall(PetscWeakFormSetIndexBdResidual(wf, label, bc[i].values[v], 0, 0, 0, SPNeumannKernels[slot], 0, NULL));
        else {
          PetscCall(PetscWeakFormSetIndexBdResidual(wf, label, bc[i].values[v], 0, 0, 0, SPFollowerF0[slot], 0, NULL));
          PetscCall(PetscWeakFormSetIndexBdJacobian(wf, label, bc[i].values[v], 0, 0, 0, 0, NULL, 0, SPFollowerG1[slot], 0, NULL, 0, NULL));
        }
      }
      PetscReal scale = 1.0;
      if (bc[i].type == SP_BC_FORCE) {
        PetscCall(LabelMeasure(dm, &bc[i], &scale));
        scale = 1.0 / scale;
      }
      bc[i].slot    = slot;
      bc[i].base[0] = bc[i].type == SP_BC_PRESSURE ? bc[i].value[0] : 0.0;
      for (PetscInt d = 0; d < 3; ++d) bc[i].base[1 + d] = d < dim && bc[i].type != SP_BC_PRESSURE ? scale * bc[i].value[d] : 0.0;
      for (PetscInt d = 0; d < 3; ++d) bc[i].base[4 + d] = bc[i].type == SP_BC_PRESSURE ? bc[i].gradient[d] : 0.0;
      slot++;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
