/* Contact points: the vertices of the slave boundary, their tributary areas and penalties, the
   contact-point vector layout (dmC: one dof per slave vertex), options and output fields. */
#include <spcontact-impl.h>

const char *const SPContactMethods[] = {"penalty", "shifted", "shifted_regression", "alm", "SPContactMethod", "SP_METHOD_", NULL};
static const char *const ObstacleTypes[] = {"plane", "sphere", "cylinder", "SPObstacleType", "SP_OBSTACLE_", NULL};
static const char *const Tangents[]      = {"auto", "full", "frozen", "SPTangent", "SP_TANGENT_", NULL};

PetscErrorCode SPContactCreate(DM dm, SPProblem problem, SPContact *contact)
{
  SPContact c;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&c));
  c->dm      = dm;
  c->problem = problem;
  c->method  = SP_METHOD_SHIFTED;
  c->alpha   = 10.0;
  c->gapTol  = 1e-10;
  c->regM    = 4;
  c->almMax  = 30;
  c->stepCap = 1.0;
  c->safeguard = PETSC_TRUE;
  c->settled   = PETSC_TRUE;
  c->nvalues = SP_MAX_VALUES;
  PetscCall(PetscStrcpy(c->label, "Face Sets"));
  PetscCall(DMGetDimension(dm, &c->dim));
  *contact = c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ObstacleSetFromOptions(MPI_Comm comm, PetscInt i, PetscInt dim, SPObstacle *ob)
{
  char      prefix[48];
  PetscInt  type = 0, n;
  PetscBool set;
  PetscReal len;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "contact_obstacle_%" PetscInt_FMT "_", i));
  PetscCall(PetscMemzero(ob, sizeof(*ob)));
  ob->normal[dim - 1] = 1.0;
  ob->radius          = -1.0;
  PetscOptionsBegin(comm, prefix, "Rigid obstacle", "spcontact");
  PetscCall(PetscOptionsEList("-type", "Obstacle: plane (point, normal), sphere (centre=point, radius; a circle in 2D), cylinder (point on axis, axis=normal, radius)", "SPContactSetFromOptions", ObstacleTypes, 3, ObstacleTypes[0], &type, NULL));
  n = 3;
  PetscCall(PetscOptionsRealArray("-point", "Plane point, or sphere/cylinder centre", "SPContactSetFromOptions", ob->point, &n, NULL));
  n = 3;
  PetscCall(PetscOptionsRealArray("-normal", "Plane normal (towards the body) or cylinder axis", "SPContactSetFromOptions", ob->normal, &n, &set));
  PetscCall(PetscOptionsReal("-radius", "Sphere/cylinder radius > 0", "SPContactSetFromOptions", ob->radius, &ob->radius, NULL));
  n = 3;
  PetscCall(PetscOptionsRealArray("-motion", "Rigid displacement of the obstacle at load factor 1", "SPContactSetFromOptions", ob->motion, &n, NULL));
  PetscOptionsEnd();
  ob->type = (SPObstacleType)type;
  len      = SPNorm(dim, ob->normal);
  PetscCheck(len > 0.0, comm, PETSC_ERR_USER_INPUT, "-%snormal: the normal/axis must be a nonzero vector", prefix);
  for (PetscInt d = 0; d < dim; ++d) ob->normal[d] /= len;
  if (ob->type != SP_OBSTACLE_PLANE) PetscCheck(ob->radius > 0.0, comm, PETSC_ERR_USER_INPUT, "-%sradius %g: a %s needs a radius > 0", prefix, (double)ob->radius, ObstacleTypes[type]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactSetFromOptions(SPContact c)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)c->dm);
  PetscInt  method = (PetscInt)c->method, tangent = (PetscInt)c->tangent;
  PetscBool setValues, setPenalty;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Contact options", "spcontact");
  PetscCall(PetscOptionsEList("-contact_method", "Contact method: penalty, shifted (Delta s = g before each Newton iteration), shifted_regression (least-squares shift over the last m iterates), alm (nested augmented Lagrangian)", "SPContactSetFromOptions", SPContactMethods, 4, SPContactMethods[method], &method, NULL));
  PetscCall(PetscOptionsString("-contact_label", "Mesh label of the slave boundary", "SPContactSetFromOptions", c->label, c->label, sizeof(c->label), NULL));
  PetscCall(PetscOptionsIntArray("-contact_values", "Label values of the slave boundary", "SPContactSetFromOptions", c->values, &c->nvalues, &setValues));
  PetscCall(PetscOptionsReal("-contact_penalty", "Absolute penalty eps per unit area (stress/length); default: alpha E / h", "SPContactSetFromOptions", c->penalty, &c->penalty, &setPenalty));
  PetscCall(PetscOptionsReal("-contact_alpha", "Penalty factor: eps = alpha E / h, h the mean slave facet size at the point", "SPContactSetFromOptions", c->alpha, &c->alpha, NULL));
  PetscCall(PetscOptionsReal("-contact_gap_tol", "Shifted/alm methods: converged only when no point penetrates more than gap_tol and every active point has |gap| <= gap_tol", "SPContactSetFromOptions", c->gapTol, &c->gapTol, NULL));
  PetscCall(PetscOptionsInt("-contact_regression_m", "shifted_regression: number of (shift, gap) pairs in the fit (>= 3)", "SPContactSetFromOptions", c->regM, &c->regM, NULL));
  PetscCall(PetscOptionsInt("-contact_alm_max", "alm: maximum number of augmentations", "SPContactSetFromOptions", c->almMax, &c->almMax, NULL));
  PetscCall(PetscOptionsReal("-contact_step_cap", "Newton step control: scale a step so no point penetrates deeper than step_cap x h in one step (0: off)", "SPContactSetFromOptions", c->stepCap, &c->stepCap, NULL));
  PetscCall(PetscOptionsBool("-contact_safeguard", "Update the shift only of points active in both the previous and the new iterate (method.md 4.1); false only to demonstrate chatter", "SPContactSetFromOptions", c->safeguard, &c->safeguard, NULL));
  PetscCall(PetscOptionsBool("-contact_shift_settled", "In-Newton shift update only at iterations whose active set did not change (the contraction rate holds only then)", "SPContactSetFromOptions", c->settled, &c->settled, NULL));
  PetscCall(PetscOptionsEList("-contact_tangent", "Second variation of the gap in the tangent (obstacle curvature; pair projection and normal variation): auto (once a Newton iteration left the active set unchanged), full (always: the consistent tangent), frozen (never)", "SPContactSetFromOptions", Tangents, 3, Tangents[tangent], &tangent, NULL));
  PetscCall(PetscOptionsBool("-contact_monitor", "Print one line per Newton iteration: residual, active points, max penetration, max shift change", "SPContactSetFromOptions", c->monitor, &c->monitor, NULL));
  PetscOptionsEnd();
  if (!setValues) c->nvalues = 0;
  c->method  = (SPContactMethod)method;
  c->tangent = (SPTangent)tangent;
  c->entry  = SPContactMethodEntry(c->method);
  PetscCheck(!setPenalty || c->penalty > 0.0, comm, PETSC_ERR_USER_INPUT, "-contact_penalty %g: the penalty must be positive", (double)c->penalty);
  PetscCheck(c->alpha > 0.0, comm, PETSC_ERR_USER_INPUT, "-contact_alpha %g: the penalty factor must be positive", (double)c->alpha);
  PetscCheck(c->gapTol > 0.0, comm, PETSC_ERR_USER_INPUT, "-contact_gap_tol %g: must be positive", (double)c->gapTol);
  PetscCheck(c->regM >= 3, comm, PETSC_ERR_USER_INPUT, "-contact_regression_m %" PetscInt_FMT ": the fit needs at least 3 pairs", c->regM);
  PetscCheck(c->stepCap >= 0.0, comm, PETSC_ERR_USER_INPUT, "-contact_step_cap %g: must be >= 0 (0 disables the step control)", (double)c->stepCap);
  PetscCheck(c->almMax >= 1, comm, PETSC_ERR_USER_INPUT, "-contact_alm_max %" PetscInt_FMT ": need at least 1 augmentation", c->almMax);
  for (c->nob = 0; c->nob < SP_MAX_OBSTACLES; ++c->nob) {
    char      name[48];
    PetscBool has;
    PetscCall(PetscSNPrintf(name, sizeof(name), "-contact_obstacle_%" PetscInt_FMT "_type", c->nob));
    PetscCall(PetscOptionsHasName(NULL, NULL, name, &has));
    if (!has) break;
    PetscCall(ObstacleSetFromOptions(comm, c->nob, c->dim, &c->ob[c->nob]));
  }
  PetscCall(SPContactPairsSetFromOptions(c));
  c->enabled = c->nob > 0 || c->npair > 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscCheck(c->nob > 0 || !setValues, comm, PETSC_ERR_USER_INPUT, "-contact_values given but no obstacle: add -contact_obstacle_0_type plane|sphere|cylinder (deformable bodies: -contact_pair_0_slave_values/-contact_pair_0_master_values)");
  PetscCheck(c->nob == 0 || setValues, comm, PETSC_ERR_USER_INPUT, "contact obstacle given but no slave boundary: add -contact_values <label values> (and -contact_label)");
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactIsActive(SPContact c, PetscBool *on)
{
  PetscFunctionBeginUser;
  *on = c && c->enabled;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactGetMethod(SPContact c, SPContactMethod *m)
{
  PetscFunctionBeginUser;
  *m = c->method;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* dmC: a clone of the mesh with one dof on every vertex of the (completed) slave label */
static PetscErrorCode CreatePointDM(SPContact c, DMLabel slave)
{
  PetscSection s;
  PetscInt     pStart, pEnd, vStart, vEnd;

  PetscFunctionBeginUser;
  PetscCall(DMClone(c->dm, &c->dmC));
  PetscCall(DMPlexGetChart(c->dm, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(c->dm, 0, &vStart, &vEnd));
  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)c->dm), &s));
  PetscCall(PetscSectionSetChart(s, pStart, pEnd));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt val;
    PetscCall(DMLabelGetValue(slave, v, &val));
    if (val == 1) PetscCall(PetscSectionSetDof(s, v, 1));
  }
  PetscCall(PetscSectionSetUp(s));
  PetscCall(DMSetLocalSection(c->dmC, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CollectPoints(SPContact c)
{
  PetscSection gs;
  PetscInt     vStart, vEnd, rstart, k = 0;
  Vec          coords;
  PetscSection cs;
  const PetscScalar *ca;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(c->dmC, &gs));
  PetscCall(DMPlexGetDepthStratum(c->dm, 0, &vStart, &vEnd));
  PetscCall(DMCreateGlobalVector(c->dmC, &c->shift));
  PetscCall(PetscObjectSetName((PetscObject)c->shift, "shift"));
  PetscCall(VecDuplicate(c->shift, &c->shiftSaved));
  PetscCall(VecDuplicate(c->shift, &c->pressure));
  PetscCall(VecGetLocalSize(c->shift, &c->n));
  PetscCall(VecGetOwnershipRange(c->shift, &rstart, NULL));
  PetscCall(PetscCalloc5(c->n, &c->vertex, c->n, &c->area, c->n, &c->eps, c->n * c->dim, &c->coord, c->n, &c->gap));
  PetscCall(PetscCalloc2(c->n, &c->h, c->n, &c->gapStart));
  PetscCall(PetscCalloc5(c->n * c->dim, &c->normal, c->n, &c->active, c->n, &c->activePrev, c->n, &c->inactiveCount, c->n, &c->nhist));
  PetscCall(PetscCalloc2(c->n * c->regM, &c->histS, c->n * c->regM, &c->histG));
  PetscCall(PetscCalloc5(c->n * c->dim, &c->sdof, c->n, &c->pairMask, c->n, &c->onObstacle, c->n, &c->primary, c->n, &c->facet));
  PetscCall(PetscCalloc5(2 * c->n, &c->xi, c->n * c->dim, &c->xs, c->n, &c->press, c->n * c->dim, &c->fpt, c->n * SP_KNOWN_FACETS, &c->known));
  for (PetscInt i = 0; i < c->n * SP_KNOWN_FACETS; ++i) c->known[i] = -1;
  PetscCall(DMGetCoordinatesLocal(c->dm, &coords));
  PetscCall(DMGetCoordinateSection(c->dm, &cs));
  PetscCall(VecGetArrayRead(coords, &ca));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt dof, off, coff;
    PetscCall(PetscSectionGetDof(gs, v, &dof));
    PetscCall(PetscSectionGetOffset(gs, v, &off));
    if (dof <= 0 || off < 0) continue; /* not a slave vertex, or owned by another rank */
    k = off - rstart;
    c->vertex[k] = v;
    PetscCall(PetscSectionGetOffset(cs, v, &coff));
    for (PetscInt d = 0; d < c->dim; ++d) c->coord[k * c->dim + d] = PetscRealPart(ca[coff + d]);
  }
  PetscCall(VecRestoreArrayRead(coords, &ca));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Which slave sets each point belongs to: the obstacles' and each pair's (bit k of pairMask) */
static PetscErrorCode MarkPoints(SPContact c)
{
  DMLabel lab;

  PetscFunctionBeginUser;
  if (c->nob) {
    PetscCall(SPMeshCreateCompletedLabel(c->dm, c->label, c->nvalues, c->values, "spcontact_obstacle_slave", &lab));
    for (PetscInt i = 0; i < c->n; ++i) {
      PetscInt val;
      PetscCall(DMLabelGetValue(lab, c->vertex[i], &val));
      c->onObstacle[i] = c->primary[i] = val == 1 ? PETSC_TRUE : PETSC_FALSE;
    }
    PetscCall(DMRemoveLabel(c->dm, "spcontact_obstacle_slave", NULL));
  }
  for (PetscInt k = 0; k < c->npair; ++k) {
    const SPPair *p = &c->pair[k];
    PetscCall(SPMeshCreateCompletedLabel(c->dm, p->label, p->nslave, p->slave, "spcontact_pair_slave", &lab));
    for (PetscInt i = 0; i < c->n; ++i) {
      PetscInt val;
      PetscCall(DMLabelGetValue(lab, c->vertex[i], &val));
      if (val != 1) continue;
      c->pairMask[i] |= (PetscInt)1 << k;
      if (!p->mirror) c->primary[i] = PETSC_TRUE;
    }
    PetscCall(DMRemoveLabel(c->dm, "spcontact_pair_slave", NULL));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Global dofs of each point's vertex (constrained ones negative) */
static PetscErrorCode PointGlobalDofs(SPContact c)
{
  PetscSection ls, gs;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(c->dm, &ls));
  PetscCall(DMGetGlobalSection(c->dm, &gs));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt *idx = NULL, nidx;
    PetscCall(DMPlexGetClosureIndices(c->dm, ls, gs, c->vertex[i], PETSC_TRUE, &nidx, &idx, NULL, NULL));
    PetscCheck(nidx == c->dim, PETSC_COMM_SELF, PETSC_ERR_PLIB, "vertex with %" PetscInt_FMT " dofs", nidx);
    for (PetscInt d = 0; d < c->dim; ++d) c->sdof[i * c->dim + d] = idx[d];
    PetscCall(DMPlexRestoreClosureIndices(c->dm, ls, gs, c->vertex[i], PETSC_TRUE, &nidx, &idx, NULL, NULL));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactSetUp(SPContact c)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)c->dm);
  DMLabel  slave = NULL;
  PetscInt degree, nAll;

  PetscFunctionBeginUser;
  if (!c->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SPProblemGetDegree(c->problem, &degree));
  PetscCheck(degree == 1, comm, PETSC_ERR_USER_INPUT, "contact needs first-order elements (P1/Q1); -petscspace_degree %" PetscInt_FMT " is not supported with contact (vertex contact points with lumped areas are not sound for higher orders)", degree);
  if (c->nob) {
    PetscCall(SPMeshCheckLabel(c->dm, c->label, c->nvalues, c->values, "-contact_values"));
    PetscCall(SPMeshCreateCompletedLabel(c->dm, c->label, c->nvalues, c->values, "spcontact_slave", &slave));
  }
  PetscCall(SPContactPairsCheckLabels(c));
  for (PetscInt k = 0; k < c->npair; ++k) /* the union of every slave surface */
    PetscCall(SPMeshCreateCompletedLabel(c->dm, c->pair[k].label, c->pair[k].nslave, c->pair[k].slave, "spcontact_slave", &slave));
  PetscCall(CreatePointDM(c, slave));
  PetscCall(CollectPoints(c));
  PetscCall(MarkPoints(c));
  PetscCall(PointGlobalDofs(c));
  PetscCall(SPContactComputeAreas(c));
  PetscCall(DMCreateGlobalVector(c->dm, &c->Fc));
  PetscCall(VecCreateMPI(comm, c->n * c->dim, PETSC_DETERMINE, &c->fvec));
  PetscCall(VecSetOption(c->fvec, VEC_IGNORE_NEGATIVE_INDICES, PETSC_TRUE));
  PetscCall(VecSetOption(c->Fc, VEC_IGNORE_NEGATIVE_INDICES, PETSC_TRUE));
  PetscCall(SPContactPairsSetUp(c));
  PetscCall(VecGetSize(c->shift, &nAll));
  PetscCheck(nAll > 0, comm, PETSC_ERR_USER_INPUT, "-contact_values: the slave boundary has no vertices");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Vertex fields for output: pressure, gap, shift, active on the vertex DM of `pressure` */
PetscErrorCode SPContactGetFields(SPContact c, Vec X, Vec pressure, Vec gap, Vec shift, Vec active)
{
  DM                 dmS;
  PetscSection       gs;
  PetscInt           rstart;
  const PetscScalar *s;
  PetscScalar       *p, *g, *sh, *a;
  Vec                locX;

  PetscFunctionBeginUser;
  PetscCall(SPProblemGetLocalState(c->problem, X, &locX));
  PetscCall(SPContactEvaluate(c, locX));
  PetscCall(SPProblemRestoreLocalState(c->problem, &locX));
  PetscCall(VecGetArrayRead(c->shift, &s));
  PetscCall(SPContactRecoverForces(c, s));
  PetscCall(VecRestoreArrayRead(c->shift, &s));
  PetscCall(VecGetDM(pressure, &dmS));
  PetscCall(DMGetGlobalSection(dmS, &gs));
  PetscCall(VecGetOwnershipRange(pressure, &rstart, NULL));
  PetscCall(VecZeroEntries(pressure));
  PetscCall(VecZeroEntries(gap));
  PetscCall(VecZeroEntries(shift));
  PetscCall(VecZeroEntries(active));
  PetscCall(VecGetArrayRead(c->shift, &s));
  PetscCall(VecGetArray(pressure, &p));
  PetscCall(VecGetArray(gap, &g));
  PetscCall(VecGetArray(shift, &sh));
  PetscCall(VecGetArray(active, &a));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(gs, c->vertex[i], &off));
    off -= rstart;
    p[off]  = c->press[i];
    g[off]  = c->gap[i];
    sh[off] = s[i];
    a[off]  = c->active[i] ? 1.0 : 0.0;
  }
  PetscCall(VecRestoreArrayRead(c->shift, &s));
  PetscCall(VecRestoreArray(pressure, &p));
  PetscCall(VecRestoreArray(gap, &g));
  PetscCall(VecRestoreArray(shift, &sh));
  PetscCall(VecRestoreArray(active, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Every contact point on rank 0 as CSV: reference coordinates, area, eps, gap, shift, pressure */
PetscErrorCode SPContactWritePoints(SPContact c, Vec X, const char file[])
{
  MPI_Comm           comm = PetscObjectComm((PetscObject)c->dm);
  const PetscInt     nc   = 9;
  PetscMPIInt        size, rank, mine = (PetscMPIInt)(c->n * nc), *counts = NULL, *displs = NULL;
  PetscReal         *row, *all = NULL;
  const PetscScalar *s;
  Vec                locX;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(SPProblemGetLocalState(c->problem, X, &locX));
  PetscCall(SPContactEvaluate(c, locX));
  PetscCall(SPProblemRestoreLocalState(c->problem, &locX));
  PetscCall(PetscCalloc1(c->n * nc + 1, &row));
  PetscCall(VecGetArrayRead(c->shift, &s));
  PetscCall(SPContactRecoverForces(c, s));
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscReal *r = &row[i * nc];
    for (PetscInt d = 0; d < c->dim; ++d) r[d] = c->coord[i * c->dim + d];
    r[3] = c->area[i];
    r[4] = c->eps[i];
    r[5] = c->gap[i];
    r[6] = PetscRealPart(s[i]);
    r[7] = c->press[i];
    r[8] = c->active[i];
  }
  PetscCall(VecRestoreArrayRead(c->shift, &s));
  if (rank == 0) PetscCall(PetscMalloc2(size, &counts, size + 1, &displs));
  PetscCallMPI(MPI_Gather(&mine, 1, MPI_INT, counts, 1, MPI_INT, 0, comm));
  if (rank == 0) {
    displs[0] = 0;
    for (PetscMPIInt r = 0; r < size; ++r) displs[r + 1] = displs[r] + counts[r];
    PetscCall(PetscMalloc1(displs[size] + 1, &all));
  }
  PetscCallMPI(MPI_Gatherv(row, mine, MPIU_REAL, all, counts, displs, MPIU_REAL, 0, comm));
  if (rank == 0) {
    FILE *fp = fopen(file, "w");
    PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write %s", file);
    fprintf(fp, "x,y,z,area,eps,gap,shift,pressure,active\n");
    for (PetscInt i = 0; i < displs[size] / nc; ++i) {
      const PetscReal *r = &all[i * nc];
      fprintf(fp, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d\n", r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], (int)r[8]);
    }
    fclose(fp);
    PetscCall(PetscFree2(counts, displs));
    PetscCall(PetscFree(all));
  }
  PetscCall(PetscFree(row));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactView(SPContact c, PetscViewer v)
{
  PetscInt  nAll;
  PetscReal emin = PETSC_MAX_REAL, emax = 0.0, gmin, gmax;

  PetscFunctionBeginUser;
  if (!c->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecGetSize(c->shift, &nAll));
  for (PetscInt i = 0; i < c->n; ++i) emin = PetscMin(emin, c->eps[i]), emax = PetscMax(emax, c->eps[i]);
  PetscCallMPI(MPI_Allreduce(&emin, &gmin, 1, MPIU_REAL, MPI_MIN, PetscObjectComm((PetscObject)c->dm)));
  PetscCallMPI(MPI_Allreduce(&emax, &gmax, 1, MPIU_REAL, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_method %s\n", c->entry->name));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_points %" PetscInt_FMT "\n", nAll));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_obstacles %" PetscInt_FMT "\n", c->nob));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_pairs %" PetscInt_FMT "\ncontact_two_pass %s\n", c->nuser, c->twoPass ? "yes" : "no"));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_master_facets %" PetscInt_FMT "\n", c->nmfAll));
  {
    PetscInt64     rec;
    PetscLogDouble tmax;
    PetscMPIInt    size;
    PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)c->dm), &size));
    PetscCallMPI(MPI_Allreduce(&c->received, &rec, 1, MPIU_INT64, MPI_SUM, PetscObjectComm((PetscObject)c->dm)));
    PetscCallMPI(MPI_Allreduce(&c->exchangeTime, &tmax, 1, MPI_DOUBLE, MPI_MAX, PetscObjectComm((PetscObject)c->dm)));
    PetscCall(PetscViewerASCIIPrintf(v, "contact_exchanges %" PetscInt_FMT "\ncontact_exchange_time %.6f\n", c->exchanges, (double)tmax));
    PetscCall(PetscViewerASCIIPrintf(v, "contact_exchange_facets_per_rank %.1f\n", c->exchanges ? (double)rec / (double)(c->exchanges * size) : 0.0));
  }
  PetscCall(PetscViewerASCIIPrintf(v, "contact_pattern_rebuilds %" PetscInt_FMT "\n", c->rebuilds));
  if (c->npair) { /* mallocs during MatSetValues on the Jacobian (0: the preallocation held) */
    MatInfo info;
    PetscCall(MatGetInfo(c->Jref, MAT_GLOBAL_SUM, &info));
    PetscCall(PetscViewerASCIIPrintf(v, "contact_jacobian_mallocs %g\n", (double)info.mallocs));
  }
  PetscCall(PetscViewerASCIIPrintf(v, "contact_alpha %g\n", c->penalty > 0.0 ? 0.0 : (double)c->alpha));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_eps_min %.10e\ncontact_eps_max %.10e\n", (double)gmin, (double)gmax));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_gap_tol %g\n", (double)c->gapTol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactDestroy(SPContact *contact)
{
  SPContact c = *contact;

  PetscFunctionBeginUser;
  if (!c) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecDestroy(&c->shift));
  PetscCall(VecDestroy(&c->shiftSaved));
  PetscCall(VecDestroy(&c->pressure));
  PetscCall(DMDestroy(&c->dmC));
  if (c->dmC) {
    PetscCall(PetscFree5(c->vertex, c->area, c->eps, c->coord, c->gap));
    PetscCall(PetscFree5(c->normal, c->active, c->activePrev, c->inactiveCount, c->nhist));
    PetscCall(PetscFree2(c->histS, c->histG));
    PetscCall(PetscFree2(c->h, c->gapStart));
    PetscCall(PetscFree5(c->sdof, c->pairMask, c->onObstacle, c->primary, c->facet));
    PetscCall(PetscFree5(c->xi, c->xs, c->press, c->fpt, c->known));
  }
  PetscCall(VecDestroy(&c->Fc));
  PetscCall(VecDestroy(&c->fvec));
  PetscCall(SPContactPairsDestroy(c));
  PetscCall(PetscFree(*contact));
  PetscFunctionReturn(PETSC_SUCCESS);
}
