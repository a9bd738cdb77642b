/* Problem: displacement field (PetscFE, degree from -petscspace_degree), material, boundary
   conditions and the load factor that scales every load. */
#include <spcontact-impl.h>
#include <kernels/elastic.h>
#include <kernels/neohookean.h>

/* The material laws. A law declares what the solver may assume: `linear` (stiffness reuse is
   exact) and `fastOperator` (the fast element operator implements it; fast-elastic.c: in closed
   form for linear isotropic elasticity, through the law's pointwise stress/tangent otherwise), and
   whether a converged state needs det F > 0 at the cells' vertices (`cornerCheck`). */
static const SPMaterialLaw SPMaterialLaws[] = {
  /* name            parameters                          setup                          linear       fastOperator manufactured body force  fast stress, tangent                                      corner check */
  {"linear_elastic", SPMaterialParameters_LinearElastic, SPMaterialSetUp_LinearElastic, PETSC_TRUE,  PETSC_TRUE, SPElasticF0MMS,    NULL,                        NULL,                        PETSC_FALSE},
  {"neo_hookean",    SPMaterialParameters_LinearElastic, SPMaterialSetUp_NeoHookean,    PETSC_FALSE, PETSC_TRUE, SPNeoHookeanF0MMS, SPMaterialStress_NeoHookean, SPMaterialTangent_NeoHookean, PETSC_TRUE },
};
#define SP_NLAWS ((PetscInt)(sizeof(SPMaterialLaws) / sizeof(SPMaterialLaws[0])))

/* The law of a material, its name in any case as PETSc's lists (-contact_method) take theirs, and
   then spelt as the law's; NULL if the name is unknown. `list` receives the known names. */
static PetscErrorCode FindLaw(char name[], const SPMaterialLaw **law, char list[], size_t len)
{
  PetscFunctionBeginUser;
  *law    = NULL;
  list[0] = 0;
  for (PetscInt i = 0; i < SP_NLAWS; ++i) {
    PetscBool match;
    PetscCall(PetscStrcasecmp(name, SPMaterialLaws[i].name, &match));
    if (match) *law = &SPMaterialLaws[i];
    if (match) PetscCall(PetscStrcpy(name, SPMaterialLaws[i].name)); /* no longer: both buffers hold any law's name */
    if (i) PetscCall(PetscStrlcat(list, ", ", len));
    PetscCall(PetscStrlcat(list, SPMaterialLaws[i].name, len));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

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
  PetscCall(PetscStrcpy(p->matLabel, "Cell Sets"));
  PetscCall(DMGetDimension(dm, &p->dim));
  *problem = p;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Region material k from -material_<k>_* when given. The k = 0 family is always queried (when
   not given nothing is recorded), so that -help lists it. own[0..2]: incremented where the region
   gives its own law, E, nu (then -material_model/_E/_nu are not its defaults) */
static PetscErrorCode RegionSetFromOptions(SPProblem p, PetscInt k, PetscBool given, SPMaterial *m, PetscInt own[3])
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)p->dm);
  char      prefix[32], list[256];
  PetscBool set, setOwn[3];

  PetscFunctionBeginUser;
  if (!given && k > 0) PetscFunctionReturn(PETSC_SUCCESS);
  m->k     = k;
  m->value = -1;
  m->E     = p->E;
  m->nu    = p->nu;
  PetscCall(PetscStrcpy(m->lawName, p->material));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "material_%" PetscInt_FMT "_", k));
  PetscOptionsBegin(comm, prefix, "Region materials -material_<k>_*, k = 0..7 (shown for k = 0; without any, -material_model/_E/_nu apply to every cell)", "spcontact");
  PetscCall(PetscOptionsInt("-label_value", "Region material k = 0..7: the cells of this value of -material_label (a gmsh physical surface in 2D, volume in 3D); with region materials every cell needs exactly one", "SPProblemSetFromOptions", m->value, &m->value, &set));
  PetscCall(PetscOptionsString("-law", "Region material k: material law, linear_elastic or neo_hookean (default: -material_model)", "SPProblemSetFromOptions", m->lawName, m->lawName, sizeof(m->lawName), &setOwn[0]));
  PetscCall(PetscOptionsReal("-E", "Region material k: Young's modulus E > 0 (default: -material_E)", "SPProblemSetFromOptions", m->E, &m->E, &setOwn[1]));
  PetscCall(PetscOptionsReal("-nu", "Region material k: Poisson's ratio, -1 < nu < 0.5 (default: -material_nu)", "SPProblemSetFromOptions", m->nu, &m->nu, &setOwn[2]));
  PetscOptionsEnd();
  if (!given) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt j = 0; j < 3; ++j) own[j] += setOwn[j] ? 1 : 0;
  PetscCheck(set, comm, PETSC_ERR_USER_INPUT, "-material_%" PetscInt_FMT "_label_value: give the \"%s\" value of region material %" PetscInt_FMT " (other -material_%" PetscInt_FMT "_* options are set)", k, p->matLabel, k, k);
  PetscCheck(m->E > 0.0 && !PetscIsInfOrNanReal(m->E), comm, PETSC_ERR_USER_INPUT, "-material_%" PetscInt_FMT "_E %.6g: Young's modulus must be a positive finite number", k, (double)m->E);
  PetscCheck(m->nu > -1.0 && m->nu < 0.5, comm, PETSC_ERR_USER_INPUT, "-material_%" PetscInt_FMT "_nu %.6g: Poisson's ratio must satisfy -1 < nu < 0.5", k, (double)m->nu);
  PetscCall(FindLaw(m->lawName, &m->law, list, sizeof(list)));
  PetscCheck(m->law, comm, PETSC_ERR_USER_INPUT, "-material_%" PetscInt_FMT "_law %s: unknown material law (available: %s)", k, m->lawName, list);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One warning for a Poisson's ratio near 0.5 (lambda / mu = 2 nu / (1 - 2 nu) > 49): P1/Q1 elements
   lock there, and eps = alpha E / h is small against the bulk stiffness, so the shift update
   contracts slowly (QA helper 28: B2 at nu 0.4999 with shifted, 20 cut-backs; peak pressure 80 %
   above Hertz's once converged). Collective (the same options on every rank). */
static PetscErrorCode WarnNearlyIncompressible(MPI_Comm comm, SPProblem p)
{
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < p->nmat; ++j) {
    char name[64] = "-material_nu";
    if (p->mat[j].nu <= 0.49) continue;
    if (p->regions) PetscCall(PetscSNPrintf(name, sizeof(name), "-material_%" PetscInt_FMT "_nu", p->mat[j].k));
    PetscCall(PetscFPrintf(comm, PETSC_STDERR, "spcontact: warning: %s %g is near 0.5: P1/Q1 elements lock there (too stiff: B2's peak pressure is 80 %% above Hertz's at 0.4999), and with contact eps = alpha E / h is small against the bulk stiffness, so the shift update contracts slowly (B2 at 0.4999: 20 cut-backs); with contact give -contact_shift_accel schur or -contact_alpha 1000; the locking itself needs mixed or B-bar elements, which spcontact does not have\n", name, (double)p->mat[j].nu));
    break;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -material_model/_E/_nu where every region material gives its own, and -material_label without
   region materials, are reported unused (the end-of-run report names them, as a misspelt one) */
static PetscErrorCode ReportUnusedDefaults(SPProblem p, const PetscInt own[3])
{
  static const char *const defaults[3] = {"-material_model", "-material_E", "-material_nu"};

  PetscFunctionBeginUser;
  if (!p->regions) PetscCall(SPOptionsUnread("-material_label"));
  for (PetscInt j = 0; j < 3; ++j)
    if (p->regions && own[j] == p->nmat) PetscCall(SPOptionsUnread(defaults[j]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPProblemSetFromOptions(SPProblem p)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)p->dm);
  char      list[256];
  PetscBool given[SP_MAX_MATERIALS];
  PetscInt  own[3] = {0, 0, 0};

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Material options", "spcontact");
  PetscCall(PetscOptionsString("-material_model", "Material law of every cell (without -material_<k>_*; else the default of -material_<k>_law): linear_elastic (small strain) or neo_hookean (compressible, finite strain)", "SPProblemSetFromOptions", p->material, p->material, sizeof(p->material), NULL));
  PetscCall(PetscOptionsReal("-material_E", "Young's modulus E > 0 (of every cell; with region materials the default of -material_<k>_E)", "SPProblemSetFromOptions", p->E, &p->E, NULL));
  PetscCall(PetscOptionsReal("-material_nu", "Poisson's ratio, -1 < nu < 0.5 (of every cell; with region materials the default of -material_<k>_nu)", "SPProblemSetFromOptions", p->nu, &p->nu, NULL));
  PetscCall(PetscOptionsString("-material_label", "Cell label whose values -material_<k>_label_value select the region materials (gmsh physical surfaces/volumes)", "SPProblemSetFromOptions", p->matLabel, p->matLabel, sizeof(p->matLabel), NULL));
  PetscCall(PetscOptionsReal("-material_mms", "Verification: amplitude of the manufactured body force/solution on the unit box (0 = off)", "SPProblemSetFromOptions", p->mmsAmp, &p->mmsAmp, NULL));
  PetscOptionsEnd();
  PetscCheck(p->E > 0.0 && !PetscIsInfOrNanReal(p->E), comm, PETSC_ERR_USER_INPUT, "-material_E %.6g: Young's modulus must be a positive finite number", (double)p->E);
  PetscCheck(p->nu > -1.0 && p->nu < 0.5, comm, PETSC_ERR_USER_INPUT, "-material_nu %.6g: Poisson's ratio must satisfy -1 < nu < 0.5", (double)p->nu);
  /* region materials -material_<k>_*, k = 0..7 (gaps allowed) */
  p->nmat = 0;
  PetscCall(SPOptionsIndexedGiven(comm, "-material_", SP_MAX_MATERIALS, "region materials", given));
  for (PetscInt k = 0; k < SP_MAX_MATERIALS; ++k) {
    SPMaterial m;
    PetscCall(RegionSetFromOptions(p, k, given[k], &m, own));
    if (!given[k]) continue;
    for (PetscInt j = 0; j < p->nmat; ++j)
      PetscCheck(p->mat[j].value != m.value, comm, PETSC_ERR_USER_INPUT, "-material_%" PetscInt_FMT "_label_value %" PetscInt_FMT ": -material_%" PetscInt_FMT "_label_value has the same value; every cell needs exactly one material", k, m.value, p->mat[j].k);
    p->mat[p->nmat++] = m;
  }
  p->regions = p->nmat > 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(ReportUnusedDefaults(p, own));
  if (!p->regions) { /* the default material on every cell */
    p->nmat         = 1;
    p->mat[0].k     = 0;
    p->mat[0].value = -1;
    p->mat[0].E     = p->E;
    p->mat[0].nu    = p->nu;
    PetscCall(PetscStrcpy(p->mat[0].lawName, p->material));
    PetscCall(FindLaw(p->material, &p->mat[0].law, list, sizeof(list)));
    PetscCheck(p->mat[0].law, comm, PETSC_ERR_USER_INPUT, "-material_model %s: unknown material (available: %s)", p->material, list);
  }
  /* one set of kernels serves every cell, with per-cell parameters: the regions share one law */
  for (PetscInt j = 1; j < p->nmat; ++j)
    PetscCheck(p->mat[j].law == p->mat[0].law, comm, PETSC_ERR_USER_INPUT, "-material_%" PetscInt_FMT "_law %s differs from -material_%" PetscInt_FMT "_law %s: the region materials of a run must share one law", p->mat[j].k, p->mat[j].lawName, p->mat[0].k, p->mat[0].lawName);
  PetscCheck(!(p->regions && p->mmsAmp != 0.0), comm, PETSC_ERR_USER_INPUT, "-material_mms: the manufactured solution needs one material (-material_E, -material_nu); drop the -material_<k>_* options");
  for (PetscInt j = 0; j < p->nmat; ++j) p->mat[j].law->parameters(p->mat[j].E, p->mat[j].nu, p->mat[j].param);
  PetscCall(WarnNearlyIncompressible(comm, p));
  PetscCall(SPBCSetFromOptions(comm, p->dim, &p->nbc, p->bc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The union over ranks of local integer lists (sorted, without duplicates); free *V */
static PetscErrorCode GatherValues(MPI_Comm comm, PetscInt n, const PetscInt v[], PetscInt *N, PetscInt **V)
{
  PetscMPIInt size, nl = (PetscMPIInt)n, *counts, *displs, total = 0;
  PetscInt    nall;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscMalloc2(size, &counts, size, &displs));
  PetscCallMPI(MPI_Allgather(&nl, 1, MPI_INT, counts, 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < size; ++r) {
    displs[r] = total;
    total += counts[r];
  }
  PetscCall(PetscMalloc1(total + 1, V));
  PetscCallMPI(MPI_Allgatherv(v, nl, MPIU_INT, *V, counts, displs, MPIU_INT, comm));
  nall = total;
  PetscCall(PetscSortRemoveDupsInt(&nall, *V));
  *N = nall;
  PetscCall(PetscFree2(counts, displs));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* "10, 20, 30" (negative values skipped) */
static PetscErrorCode FormatValues(PetscInt n, const PetscInt v[], char s[], size_t len)
{
  PetscFunctionBeginUser;
  s[0] = 0;
  for (PetscInt i = 0; i < n; ++i) {
    char one[32];
    if (v[i] < 0) continue;
    PetscCall(PetscSNPrintf(one, sizeof(one), "%s%" PetscInt_FMT, s[0] ? ", " : "", v[i]));
    PetscCall(PetscStrlcat(s, one, len));
  }
  if (!s[0]) PetscCall(PetscStrncpy(s, "none", len));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Region materials: each local cell gets the material of its label value. Every cell must get
   exactly one, and every material must reach at least one cell (globally). */
static PetscErrorCode AssignRegions(SPProblem p)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)p->dm);
  DMLabel   label;
  PetscInt  nc = p->cEnd - p->cStart, count[SP_MAX_MATERIALS] = {0}, countAll[SP_MAX_MATERIALS];
  PetscInt  clash[2] = {-1, -1}, clashAll[2], has, hasAll, nv = 0, nu = 0, nAll, nuAll, *vals, *unc, *all, *uncAll, nmiss[2] = {0, 0}, nmissAll[2];
  char      s[256];

  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(p->dm, p->matLabel, &label));
  has = label ? 1 : 0;
  PetscCallMPI(MPI_Allreduce(&has, &hasAll, 1, MPIU_INT, MPI_MAX, comm));
  PetscCheck(hasAll, comm, PETSC_ERR_USER_INPUT, "-material_label %s: the mesh has no label \"%s\"; region materials (-material_<k>_label_value) need one (gmsh physical surfaces/volumes become \"Cell Sets\")", p->matLabel, p->matLabel);
  for (PetscInt c = 0; c < nc; ++c) p->cellMat[c] = -1;
  for (PetscInt k = 0; k < p->nmat && label; ++k) {
    IS              is;
    const PetscInt *pts;
    PetscInt        n;
    PetscCall(DMLabelGetStratumIS(label, p->mat[k].value, &is));
    if (!is) continue;
    PetscCall(ISGetLocalSize(is, &n));
    PetscCall(ISGetIndices(is, &pts));
    for (PetscInt i = 0; i < n; ++i) {
      const PetscInt c = pts[i] - p->cStart;
      if (c < 0 || c >= nc) continue; /* not a cell */
      if (p->cellMat[c] >= 0) clash[0] = p->cellMat[c], clash[1] = k;
      p->cellMat[c] = k;
      count[k]++;
    }
    PetscCall(ISRestoreIndices(is, &pts));
    PetscCall(ISDestroy(&is));
  }
  PetscCallMPI(MPI_Allreduce(clash, clashAll, 2, MPIU_INT, MPI_MAX, comm));
  PetscCheck(clashAll[0] < 0, comm, PETSC_ERR_USER_INPUT, "-material_%" PetscInt_FMT "_label_value %" PetscInt_FMT " and -material_%" PetscInt_FMT "_label_value %" PetscInt_FMT ": some cells carry both \"%s\" values; every cell needs exactly one material", p->mat[clashAll[0]].k, p->mat[clashAll[0]].value, p->mat[clashAll[1]].k, p->mat[clashAll[1]].value, p->matLabel);
  /* the label values of all cells and of the cells without a material (-1: no value) */
  PetscCall(PetscMalloc2(nc + 1, &vals, nc + 1, &unc));
  for (PetscInt c = 0; c < nc; ++c) {
    PetscInt v = -1;
    if (label) PetscCall(DMLabelGetValue(label, p->cStart + c, &v));
    vals[nv++] = v;
    if (p->cellMat[c] < 0) {
      unc[nu++] = v;
      nmiss[v < 0 ? 1 : 0]++;
    }
  }
  PetscCall(PetscSortRemoveDupsInt(&nv, vals));
  PetscCall(PetscSortRemoveDupsInt(&nu, unc));
  PetscCall(GatherValues(comm, nv, vals, &nAll, &all));
  PetscCall(GatherValues(comm, nu, unc, &nuAll, &uncAll));
  PetscCall(PetscFree2(vals, unc));
  PetscCallMPI(MPI_Allreduce(count, countAll, SP_MAX_MATERIALS, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(nmiss, nmissAll, 2, MPIU_INT, MPI_SUM, comm));
  PetscCall(FormatValues(nAll, all, s, sizeof(s)));
  for (PetscInt k = 0; k < p->nmat; ++k)
    PetscCheck(countAll[k] > 0, comm, PETSC_ERR_USER_INPUT, "-material_%" PetscInt_FMT "_label_value %" PetscInt_FMT ": no cell has \"%s\" value %" PetscInt_FMT " (the cells' values: %s)", p->mat[k].k, p->mat[k].value, p->matLabel, p->mat[k].value, s);
  PetscCall(FormatValues(nuAll, uncAll, s, sizeof(s)));
  PetscCall(PetscFree(all));
  PetscCall(PetscFree(uncAll));
  PetscCheck(nmissAll[0] == 0, comm, PETSC_ERR_USER_INPUT, "%" PetscInt_FMT " cell(s) have no material: \"%s\" value(s) %s match no -material_<k>_label_value; add a region material for each (-material_<k>_label_value V -material_<k>_E ... -material_<k>_nu ..., k = 0..7)", nmissAll[0], p->matLabel, s);
  PetscCheck(nmissAll[1] == 0, comm, PETSC_ERR_USER_INPUT, "%" PetscInt_FMT " cell(s) have no material: they carry no \"%s\" value, so no -material_<k>_label_value reaches them; put every cell in a physical group of the mesh, or drop the -material_<k>_* options to use -material_E/-material_nu everywhere", nmissAll[1], p->matLabel);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Per local vertex, the largest E of the cells around it, over every rank (the point SF carries
   the maximum to the owner and back to the ghost copies) */
static PetscErrorCode VertexYoung(SPProblem p)
{
  PetscSF         sf;
  PetscInt        pStart, pEnd, nroots, nleaves;
  const PetscInt *ilocal;
  PetscReal      *e, *leaf;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(p->dm, &pStart, &pEnd));
  PetscCall(PetscCalloc2(pEnd, &e, pEnd, &leaf));
  for (PetscInt c = p->cStart; c < p->cEnd; ++c) {
    const PetscReal E   = p->mat[p->cellMat[c - p->cStart]].E;
    PetscInt       *pts = NULL, n;
    PetscCall(DMPlexGetTransitiveClosure(p->dm, c, PETSC_TRUE, &n, &pts));
    for (PetscInt i = 0; i < n; ++i) {
      const PetscInt v = pts[2 * i];
      if (v >= p->vStart && v < p->vEnd) e[v] = PetscMax(e[v], E);
    }
    PetscCall(DMPlexRestoreTransitiveClosure(p->dm, c, PETSC_TRUE, &n, &pts));
  }
  PetscCall(DMGetPointSF(p->dm, &sf));
  PetscCall(PetscSFGetGraph(sf, &nroots, &nleaves, &ilocal, NULL));
  if (nroots >= 0) {
    PetscCall(PetscArraycpy(leaf, e, pEnd));
    PetscCall(PetscSFReduceBegin(sf, MPIU_REAL, leaf, e, MPI_MAX));
    PetscCall(PetscSFReduceEnd(sf, MPIU_REAL, leaf, e, MPI_MAX));
    PetscCall(PetscSFBcastBegin(sf, MPIU_REAL, e, leaf, MPI_REPLACE));
    PetscCall(PetscSFBcastEnd(sf, MPIU_REAL, e, leaf, MPI_REPLACE));
    for (PetscInt l = 0; l < nleaves; ++l) {
      const PetscInt q = ilocal ? ilocal[l] : l;
      e[q] = leaf[q];
    }
  }
  PetscCall(PetscMalloc1(p->vEnd - p->vStart, &p->vertexE));
  for (PetscInt v = p->vStart; v < p->vEnd; ++v) p->vertexE[v - p->vStart] = e[v];
  PetscCall(PetscFree2(e, leaf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Per local cell: material and law parameters; with region materials also the vertex moduli */
static PetscErrorCode SetUpCells(SPProblem p)
{
  PetscInt nc;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(p->dm, 0, &p->cStart, &p->cEnd));
  PetscCall(DMPlexGetDepthStratum(p->dm, 0, &p->vStart, &p->vEnd));
  nc = p->cEnd - p->cStart;
  PetscCall(PetscMalloc2(nc, &p->cellMat, nc * SP_LAW_NPARAM, &p->cellParam));
  if (p->regions) PetscCall(AssignRegions(p));
  else
    for (PetscInt c = 0; c < nc; ++c) p->cellMat[c] = 0;
  for (PetscInt c = 0; c < nc; ++c)
    for (PetscInt i = 0; i < SP_LAW_NPARAM; ++i) p->cellParam[c * SP_LAW_NPARAM + i] = p->mat[p->cellMat[c]].param[i];
  if (p->regions) PetscCall(VertexYoung(p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Region materials for the PetscFE path: a cellwise-constant (P0) auxiliary field with the law's
   parameters, on the quadrature of the displacement FE (PETSc evaluates both at the same points,
   in the cell and on the Neumann faces) */
static PetscErrorCode SetUpAuxiliary(SPProblem p, PetscFE fe, PetscBool simplex)
{
  MPI_Comm     comm = PetscObjectComm((PetscObject)p->dm);
  DM           dmAux;
  PetscFE      feAux;
  PetscSection s;
  Vec          aux;
  PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(DMClone(p->dm, &dmAux));
  PetscCall(PetscFECreateLagrange(comm, p->dim, SP_LAW_NPARAM, simplex, 0, PETSC_DETERMINE, &feAux));
  PetscCall(PetscFECopyQuadrature(fe, feAux));
  PetscCall(PetscObjectSetName((PetscObject)feAux, "material"));
  PetscCall(DMSetField(dmAux, 0, NULL, (PetscObject)feAux));
  PetscCall(PetscFEDestroy(&feAux));
  PetscCall(DMCreateDS(dmAux));
  PetscCall(DMCreateLocalVector(dmAux, &aux));
  PetscCall(DMGetLocalSection(dmAux, &s));
  PetscCall(VecGetArray(aux, &a));
  for (PetscInt c = p->cStart; c < p->cEnd; ++c) {
    PetscInt off, dof;
    PetscCall(PetscSectionGetDof(s, c, &dof));
    PetscCall(PetscSectionGetOffset(s, c, &off));
    PetscCheck(dof == SP_LAW_NPARAM, PETSC_COMM_SELF, PETSC_ERR_PLIB, "material field: %" PetscInt_FMT " dofs on cell %" PetscInt_FMT, dof, c);
    for (PetscInt i = 0; i < SP_LAW_NPARAM; ++i) a[off + i] = p->cellParam[(c - p->cStart) * SP_LAW_NPARAM + i];
  }
  PetscCall(VecRestoreArray(aux, &a));
  PetscCall(DMSetAuxiliaryVec(p->dm, NULL, 0, 0, aux));
  PetscCall(VecDestroy(&aux));
  PetscCall(DMDestroy(&dmAux));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPProblemSetUp(SPProblem p)
{
  MPI_Comm             comm = PetscObjectComm((PetscObject)p->dm);
  PetscFE              fe;
  PetscSpace           sp;
  PetscDS              ds;
  PetscBool            simplex;
  PetscScalar          constants[SP_C_NUM] = {0};
  const SPMaterialLaw *law                 = p->mat[0].law; /* every material's (checked) */

  PetscFunctionBeginUser;
  PetscCall(SPMeshIsSimplex(p->dm, &simplex));
  /* PETSc's own default degree is 0; spcontact's is 1 (P1/Q1), -petscspace_degree overrides */
  PetscCall(SPOptionsSetDefault("-petscspace_degree", "1"));
  PetscCall(PetscFECreateDefault(comm, p->dim, p->dim, simplex, NULL, PETSC_DETERMINE, &fe));
  PetscCall(PetscObjectSetName((PetscObject)fe, "displacement"));
  PetscCall(PetscFEGetBasisSpace(fe, &sp));
  PetscCall(PetscSpaceGetDegree(sp, &p->degree, NULL)); /* (degree, max total degree) */
  PetscCheck(p->degree >= 1, comm, PETSC_ERR_USER_INPUT, "-petscspace_degree %" PetscInt_FMT ": displacement needs degree >= 1", p->degree);
  PetscCall(DMSetField(p->dm, 0, NULL, (PetscObject)fe));
  PetscCall(DMCreateDS(p->dm));
  PetscCall(DMGetDS(p->dm, &ds));
  PetscCall(SetUpCells(p));
  /* one material: its parameters in constants[] (as before region materials existed); region
     materials: per cell, from the auxiliary field */
  PetscCall(law->setup(ds, p->regions ? NULL : p->mat[0].param, constants));
  if (p->regions) PetscCall(SetUpAuxiliary(p, fe, simplex));
  if (law->cornerCheck) PetscCall(SPCornerCheckCreate(p->dm, fe, &p->corner));
  PetscCall(PetscFEDestroy(&fe));
  p->linear       = law->linear;
  for (PetscInt i = 0; i < p->nbc; ++i)
    PetscCheck(!p->bc[i].follower || !p->linear, PetscObjectComm((PetscObject)p->dm), PETSC_ERR_USER_INPUT, "-bc_%" PetscInt_FMT "_follower: a follower pressure needs a finite-strain law (-material_model neo_hookean); small-strain elasticity has no deformed face", i);
  p->fastOperator = law->fastOperator;
  constants[SP_C_LOAD] = p->load;
  constants[SP_C_MMS]  = p->mmsAmp;
  if (p->mmsAmp != 0.0) { /* the law's own stress kernel, plus its manufactured body force */
    PetscPointFunc f0, f1;
    PetscCheck(law->mmsSource, comm, PETSC_ERR_USER_INPUT, "-material_mms: the law %s has no manufactured solution; use linear_elastic", law->name);
    PetscCall(PetscDSGetResidual(ds, 0, &f0, &f1));
    PetscCall(PetscDSSetResidual(ds, 0, law->mmsSource, f1));
    PetscCall(PetscDSSetExactSolution(ds, 0, SPMMSExact, &p->mmsAmp));
  }
  PetscCall(SPBCAddToDS(p->dm, p->nbc, p->bc, constants));
  SPBCSetLoad(p->nbc, p->bc, p->load, constants);
  PetscCall(PetscDSSetConstants(ds, SP_C_NUM, constants));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The ratio r of the load increment l[1] -> l[2] to the increment l[0] -> l[1] when every
   condition (and the obstacles' motion, proportional to the load factor) moves in proportion over
   the two; 0 when the load curves bend between them (a normal phase, then a tangential one) */
PetscReal SPProblemLoadRatio(SPProblem p, const PetscReal l[3])
{
  const PetscReal r = l[1] > l[0] ? (l[2] - l[1]) / (l[1] - l[0]) : 0.0;
  return r > 0.0 && SPBCProportional(p->nbc, p->bc, l, r) ? r : 0.0;
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
  SPBCSetLoad(p->nbc, p->bc, load, constants);
  PetscCall(PetscDSSetConstants(ds, n, constants));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPProblemGetLoadFactor(SPProblem p, PetscReal *load)
{
  PetscFunctionBeginUser;
  *load = p->load;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The largest Young's modulus of the run (with one material, its E) */
PetscErrorCode SPProblemGetYoung(SPProblem p, PetscReal *E)
{
  PetscFunctionBeginUser;
  *E = p->mat[0].E;
  for (PetscInt k = 1; k < p->nmat; ++k) *E = PetscMax(*E, p->mat[k].E);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The Young's modulus at a local mesh vertex: with one material its E; with region materials
   the largest E of the cells around the vertex (on any rank). Contact uses it for the penalty
   eps = alpha E / h at a slave vertex (contact-area.c). Valid after SPProblemSetUp. */
PetscErrorCode SPProblemGetVertexYoung(SPProblem p, PetscInt vertex, PetscReal *E)
{
  PetscFunctionBeginUser;
  if (!p->vertexE) *E = p->mat[0].E;
  else {
    PetscCheck(vertex >= p->vStart && vertex < p->vEnd, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "point %" PetscInt_FMT " is not a vertex [%" PetscInt_FMT ", %" PetscInt_FMT ")", vertex, p->vStart, p->vEnd);
    *E = p->vertexE[vertex - p->vStart];
  }
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

/* Whether the converged state u is one the law admits (the corner check, SPMaterialLaw.cornerCheck;
   always with the other laws); if not, why[] says why. Collective, once per converged load step. */
PetscErrorCode SPProblemCheckState(SPProblem p, Vec u, PetscBool *ok, char why[], size_t len)
{
  Vec       locX;
  PetscReal minJ;
  PetscInt  inverted;

  PetscFunctionBeginUser;
  *ok    = PETSC_TRUE;
  why[0] = 0;
  if (!p->corner) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPProblemGetLocalState(p, u, &locX));
  PetscCall(SPCornerCheckEvaluate(p->corner, locX, &minJ, &inverted));
  PetscCall(SPProblemRestoreLocalState(p, &locX));
  PetscCall(PetscInfo(p->dm, "corner check: smallest det F at a cell vertex %.10g, %" PetscInt_FMT " cells with one <= 0\n", (double)minJ, inverted));
  if (!inverted) PetscFunctionReturn(PETSC_SUCCESS);
  *ok = PETSC_FALSE;
  PetscCall(PetscSNPrintf(why, len, "inverted cell corner (J = %.3g at a vertex; cells with J <= 0 at a corner: %" PetscInt_FMT ")", (double)minJ, inverted));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPProblemDestroy(SPProblem *p)
{
  PetscFunctionBeginUser;
  PetscCall(SPCornerCheckDestroy(&(*p)->corner));
  PetscCall(VecDestroy(&(*p)->locBC));
  PetscCall(PetscFree2((*p)->cellMat, (*p)->cellParam));
  PetscCall(PetscFree((*p)->vertexE));
  PetscCall(PetscFree(*p));
  PetscFunctionReturn(PETSC_SUCCESS);
}
