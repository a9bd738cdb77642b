/* Contact points: the vertices of the slave boundary, their tributary areas and penalties, the
   contact-point vector layout (dmC: one dof per slave vertex), options and output fields. */
#include <spcontact-impl.h>

static const char *const ObstacleTypes[] = {"plane", "sphere", "cylinder", "SPObstacleType", "SP_OBSTACLE_", NULL};
static const char *const Tangents[]      = {"auto", "full", "frozen", "SPTangent", "SP_TANGENT_", NULL};

/* search: the log event the contact geometry evaluations are timed under */
PetscErrorCode SPContactCreate(DM dm, SPProblem problem, PetscLogEvent search, SPContact *contact)
{
  SPContact c;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&c));
  c->dm      = dm;
  c->problem = problem;
  c->searchEvent = search;
  c->method  = SPMethodTable[0]; /* the table's first row is the default */
  c->alpha   = 10.0;
  c->gapRtol = 1e-10;
  c->creepRtol = 1e-10;
  c->stickHold = PETSC_TRUE;
  c->slipRtol  = 1e-8;
  c->maxFlips  = 3;
  c->roundOff  = -1.0;
  c->chatterFlips = 3;
  c->chatterTension = 1e-2;
  c->jumpWait  = 10.0;
  c->stepCap = 1.0;
  c->safeguard = PETSC_TRUE;
  c->settled   = PETSC_TRUE;
  c->branchHold = PETSC_TRUE;
  c->predict    = PETSC_TRUE;
  c->nvalues = SP_MAX_VALUES;
  PetscCall(PetscStrcpy(c->label, "Face Sets"));
  PetscCall(DMGetDimension(dm, &c->dim));
  *contact = c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* An obstacle option vector, if given: one finite value per mesh dimension (a 2D point on a 3D mesh
   would silently take z = 0) */
static PetscErrorCode CheckVector(MPI_Comm comm, const char prefix[], const char name[], PetscInt dim, PetscBool set, PetscInt n, const PetscReal v[])
{
  PetscFunctionBeginUser;
  if (!set) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(n == dim, comm, PETSC_ERR_USER_INPUT, "-%s%s: give %" PetscInt_FMT " components on this %" PetscInt_FMT "D mesh, got %" PetscInt_FMT, prefix, name, dim, dim, n);
  for (PetscInt d = 0; d < n; ++d) PetscCheck(!PetscIsInfOrNanReal(v[d]), comm, PETSC_ERR_USER_INPUT, "-%s%s: component %" PetscInt_FMT " is not a finite number", prefix, name, d);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The friction coefficient read from -<prefix>mu (the run's, an obstacle's or a pair's) */
PetscErrorCode SPContactCheckMu(MPI_Comm comm, const char prefix[], PetscReal mu)
{
  PetscFunctionBeginUser;
  PetscCheck(mu >= 0.0 && !PetscIsInfOrNanReal(mu), comm, PETSC_ERR_USER_INPUT, "-%smu %.6g: the friction coefficient must be a number >= 0", prefix, (double)mu);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* An obstacle's place is given, never a default: a point (plane point, centre) always, and the
   normal of a plane and the axis of a 3D cylinder (a default origin and +y/+z normal would put an
   obstacle where the mesh may not be, and the run would report no contact or a wrong one) */
static PetscErrorCode CheckPlaced(MPI_Comm comm, const char prefix[], PetscInt dim, SPObstacleType type, PetscBool setP, PetscBool setN)
{
  const char *what  = ObstacleTypes[type];
  const char *coord = dim == 2 ? "x,y" : "x,y,z";

  PetscFunctionBeginUser;
  PetscCheck(setP, comm, PETSC_ERR_USER_INPUT, "-%spoint missing: a %s needs %s (give -%spoint %s)", prefix, what, type == SP_OBSTACLE_PLANE ? "a point on it" : (type == SP_OBSTACLE_SPHERE ? "its centre" : "a point on its axis"), prefix, coord);
  PetscCheck(setN || !(type == SP_OBSTACLE_PLANE || (type == SP_OBSTACLE_CYLINDER && dim == 3)), comm, PETSC_ERR_USER_INPUT, "-%snormal missing: a %s needs %s (give -%snormal %s)", prefix, what, type == SP_OBSTACLE_PLANE ? "its normal, pointing towards the body" : "its axis", prefix, dim == 2 ? "nx,ny" : "nx,ny,nz");
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ObstacleSetFromOptions(MPI_Comm comm, PetscInt i, PetscInt dim, SPObstacle *ob, PetscReal *mu)
{
  char      prefix[48];
  PetscInt  type = 0, n;
  PetscBool set, setR = PETSC_FALSE, setP, setN = PETSC_FALSE, help;
  PetscReal len;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "contact_obstacle_%" PetscInt_FMT "_", i));
  PetscCall(PetscMemzero(ob, sizeof(*ob)));
  ob->normal[dim - 1] = 1.0;
  ob->radius          = -1.0;
  PetscOptionsBegin(comm, prefix, "Rigid obstacle", "spcontact");
  PetscCall(PetscOptionsEList("-type", "Obstacle: plane (point, normal), sphere (centre=point, radius; a circle in 2D), cylinder (point on axis, axis=normal, radius)", "SPContactSetFromOptions", ObstacleTypes, 3, ObstacleTypes[0], &type, NULL));
  n = 3;
  PetscCall(PetscOptionsRealArray("-point", "Plane point, or sphere/cylinder centre (required)", "SPContactSetFromOptions", ob->point, &n, &setP));
  PetscCall(SPOptionsCheckLength(comm, prefix, "-point", 3));
  PetscCall(CheckVector(comm, prefix, "point", dim, setP, n, ob->point));
  n = 3;
  if (type == SP_OBSTACLE_PLANE || (type == SP_OBSTACLE_CYLINDER && dim == 3)) { /* a sphere, and a cylinder in 2D (a circle), have none: a -normal given is then reported unused */
    PetscCall(PetscOptionsRealArray("-normal", "Plane normal (towards the body) or cylinder axis (3D; a cylinder in 2D is a circle) (required)", "SPContactSetFromOptions", ob->normal, &n, &setN));
    PetscCall(SPOptionsCheckLength(comm, prefix, "-normal", 3));
    PetscCall(CheckVector(comm, prefix, "normal", dim, setN, n, ob->normal));
  }
  if (type != SP_OBSTACLE_PLANE || PetscOptionsObject->printhelp) /* a plane has none: reported unused */
    PetscCall(SPOptionsRealComputed(PetscOptionsObject, "-radius", "Sphere/cylinder radius > 0", "SPContactSetFromOptions", "none: give it", &ob->radius, &setR));
  n = 3;
  PetscCall(PetscOptionsRealArray("-motion", "Rigid displacement of the obstacle at load factor 1", "SPContactSetFromOptions", ob->motion, &n, &set));
  PetscCall(SPOptionsCheckLength(comm, prefix, "-motion", 3));
  PetscCall(CheckVector(comm, prefix, "motion", dim, set, n, ob->motion));
  PetscCall(PetscOptionsReal("-mu", "Coulomb friction coefficient against this obstacle (default -contact_friction_mu)", "SPContactSetFromOptions", *mu, mu, NULL));
  help = PetscOptionsObject->printhelp;
  PetscOptionsEnd();
  PetscCall(SPContactCheckMu(comm, prefix, *mu));
  ob->type = (SPObstacleType)type;
  if (!help) PetscCall(CheckPlaced(comm, prefix, dim, ob->type, setP, setN)); /* -help alone lists an unplaced obstacle 0 */
  len      = SPNorm(dim, ob->normal);
  PetscCheck(len > 0.0, comm, PETSC_ERR_USER_INPUT, "-%snormal: the normal/axis must be a nonzero vector", prefix);
  for (PetscInt d = 0; d < dim; ++d) ob->normal[d] /= len;
  if (ob->type != SP_OBSTACLE_PLANE) PetscCheck(setR, comm, PETSC_ERR_USER_INPUT, "-%sradius missing: a %s needs one (give -%sradius R, R > 0)", prefix, ObstacleTypes[type], prefix);
  if (ob->type != SP_OBSTACLE_PLANE) PetscCheck(ob->radius > 0.0 && !PetscIsInfOrNanReal(ob->radius), comm, PETSC_ERR_USER_INPUT, "-%sradius %.6g: a %s needs a finite radius > 0", prefix, (double)ob->radius, ObstacleTypes[type]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The plain update s <- s + g of shifted (at Newton-iteration boundaries) and alm (between
   augmentations) is a fixed-point iteration; -contact_shift_accel accelerates it (contact-accel.c).
   Two-pass pairs default to Anderson: their redundant constraints make the plain update contract
   by about 0.92 per update at alpha 10 (B6 two-pass, shifted: 3029 Newton iterations and 20
   cut-backs without converging, against 44; B5 two-pass: 102950 against 10; alm on B5 two-pass
   did not converge in 1375) */
static PetscErrorCode AccelSetFromOptions(PetscOptionItems *PetscOptionsObject, SPContact c)
{
  MPI_Comm  comm    = PetscObjectComm((PetscObject)c->dm);
  PetscBool plain   = c->method->update == SPShiftIncrement ? PETSC_TRUE : PETSC_FALSE, set;
  PetscInt  type;

  PetscFunctionBeginUser;
  type = plain && c->twoPass ? SP_ACCEL_ANDERSON : SP_ACCEL_NONE;
  PetscCall(PetscOptionsEList("-contact_shift_accel", "shifted and alm: acceleration of the shift update s <- s + g (shifted: at each Newton-iteration boundary; alm: after each converged solve) on a settled set of active points: none, anderson (Anderson mixing of the last m updates over all active points; plain update when ill-conditioned or when the gap residual grew) or schur (the update that zeroes the linearised gaps of the next step: GMRES on the contact rows, each product one back-substitution with the Newton step's factorization; with an iterative linear solver, as 3D runs have by default, the plain update: give -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps). Default: none, anderson with -contact_two_pass", "SPContactSetFromOptions", SPShiftAccelTypes, 3, SPShiftAccelTypes[type], &type, &set));
  PetscCall(PetscOptionsInt("-contact_shift_accel_depth", "With -contact_shift_accel anderson: number m of past updates combined (1..50)", "SPContactSetFromOptions", c->params.accelDepth, &c->params.accelDepth, NULL));
  PetscCheck(c->params.accelDepth >= 1 && c->params.accelDepth <= 50, comm, PETSC_ERR_USER_INPUT, "-contact_shift_accel_depth %" PetscInt_FMT ": give 1..50 past updates", c->params.accelDepth);
  PetscCheck(!set || type == SP_ACCEL_NONE || plain, comm, PETSC_ERR_USER_INPUT, "-contact_shift_accel %s: -contact_method %s has no plain shift update to accelerate; use shifted or alm", SPShiftAccelTypes[type], c->method->name);
  PetscCheck(type != SP_ACCEL_SCHUR || !c->twoPass, comm, PETSC_ERR_USER_INPUT, "-contact_shift_accel schur with -contact_two_pass: the two passes constrain each gap twice, so the shifts' Schur complement is singular; use anderson (the two-pass default)");
  c->params.accel = (SPShiftAccelType)type;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -contact_method from the method table, then every method's own options (only the chosen
   method's values are kept; the others are read so that -help lists them) */
static PetscErrorCode MethodSetFromOptions(PetscOptionItems *PetscOptionsObject, SPContact c)
{
  const char *names[16], *def = c->method->name;
  char        help[1024] = "Contact method:";
  PetscInt    n = 0, pick = 0;

  PetscFunctionBeginUser;
  for (; SPMethodTable[n]; ++n) {
    names[n] = SPMethodTable[n]->name;
    if (SPMethodTable[n] == c->method) pick = n;
    PetscCall(PetscStrlcat(help, n ? "; " : " ", sizeof(help)));
    PetscCall(PetscStrlcat(help, names[n], sizeof(help)));
    PetscCall(PetscStrlcat(help, " (", sizeof(help)));
    PetscCall(PetscStrlcat(help, SPMethodTable[n]->help, sizeof(help)));
    PetscCall(PetscStrlcat(help, ")", sizeof(help)));
  }
  PetscCall(PetscOptionsEList("-contact_method", help, "SPContactSetFromOptions", names, n, def, &pick, NULL));
  c->method         = SPMethodTable[pick];
  c->params.history    = 1;
  c->params.accel      = SP_ACCEL_NONE;
  c->params.accelDepth = 5;
  for (PetscInt k = 0; k < n; ++k) {
    SPMethodParams other = c->params;
    SPOptionsLeft  left;
    if (!SPMethodTable[k]->setFromOptions) continue;
    if (k == pick) {
      PetscCall(SPMethodTable[k]->setFromOptions(PetscOptionsObject, &c->params));
      continue;
    }
    PetscCall(SPOptionsLeftBegin(&left)); /* another method's options: reported if given (options-unread.c) */
    PetscCall(SPMethodTable[k]->setFromOptions(PetscOptionsObject, &other));
    PetscCall(SPOptionsLeftEnd(&left));
  }
  PetscCall(AccelSetFromOptions(PetscOptionsObject, c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Friction needs contact and a method that can update a tangential shift */
static PetscErrorCode CheckFriction(SPContact c)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)c->dm);
  PetscBool on = c->mu > 0.0;
  char      ok[256] = "";

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < c->nob; ++k) on = on || c->obMu[k] > 0.0;
  for (PetscInt k = 0; k < c->npair; ++k) on = on || c->pair[k].mu > 0.0;
  if (!on) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(c->enabled, comm, PETSC_ERR_USER_INPUT, "-contact_friction_mu %.6g given but the run has no contact: add a slave boundary and an obstacle (-contact_values, -contact_obstacle_0_type) or a pair (-contact_pair_0_slave_values, -contact_pair_0_master_values)", (double)c->mu);
  for (PetscInt k = 0; SPMethodTable[k]; ++k)
    if (SPMethodTable[k]->friction) {
      PetscCall(PetscStrlcat(ok, ok[0] ? ", " : "", sizeof(ok)));
      PetscCall(PetscStrlcat(ok, SPMethodTable[k]->name, sizeof(ok)));
    }
  PetscCheck(c->method->friction, comm, PETSC_ERR_USER_INPUT, "-contact_method %s cannot update a tangential shift: with friction use one of %s", c->method->name, ok);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Options read (for -help, or before the run's kind is known) that this run does not use: put back
   as unread, so the end-of-run report names them (options-unread.c; another method's options:
   MethodSetFromOptions) */
static PetscErrorCode UnreadUnused(SPContact c)
{
  static const char *const updates[]  = {"-contact_branch_hold", "-contact_chatter_flips", "-contact_chatter_tension", "-contact_shift_settled"};
  static const char *const friction[] = {"-contact_friction_alpha", "-contact_friction_creep_rtol", "-contact_friction_max_flips", "-contact_friction_stick_hold", "-contact_friction_jump_wait", "-contact_friction_slip_rtol", "-contact_shift_predict"};

  PetscFunctionBeginUser;
  if (!c->enabled) {
    PetscCall(SPOptionsUnread("-contact_"));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (size_t k = 0; k < sizeof(friction) / sizeof(friction[0]) && !c->friction; ++k) PetscCall(SPOptionsUnread(friction[k]));
  if (c->params.accel != SP_ACCEL_ANDERSON) PetscCall(SPOptionsUnread("-contact_shift_accel_depth"));
  if (!c->nuser) PetscCall(SPOptionsUnread("-contact_pair_exchange_all"));
  if (c->method->timing == SP_UPDATE_NONE) /* penalty: no shift update to hold, settle or chatter over */
    for (size_t k = 0; k < sizeof(updates) / sizeof(updates[0]); ++k) PetscCall(SPOptionsUnread(updates[k]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactSetFromOptions(SPContact c)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)c->dm);
  PetscInt  tangent = (PetscInt)c->tangent;
  PetscBool setValues, setPenalty;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Contact options", "spcontact");
  /* first: the defaults of the shift acceleration and of the chatter hold depend on it */
  PetscCall(PetscOptionsBool("-contact_two_pass", "Contact pairs: each surface also acts as slave of the other (mirrored pair); each pass carries half of the areas", "SPContactSetFromOptions", c->twoPass, &c->twoPass, NULL));
  PetscCall(MethodSetFromOptions(PetscOptionsObject, c));
  PetscCall(PetscOptionsString("-contact_label", "Mesh label of the slave boundary", "SPContactSetFromOptions", c->label, c->label, sizeof(c->label), NULL));
  PetscCall(PetscOptionsIntArray("-contact_values", "Label values of the slave boundary", "SPContactSetFromOptions", c->values, &c->nvalues, &setValues));
  PetscCall(SPOptionsCheckLength(comm, NULL, "-contact_values", SP_MAX_VALUES));
  PetscCall(SPOptionsRealComputed(PetscOptionsObject, "-contact_penalty", "Absolute penalty eps per unit area (stress/length); default: alpha E / h at each point", "SPContactSetFromOptions", "alpha E / h", &c->penalty, &setPenalty));
  PetscCall(PetscOptionsReal("-contact_alpha", "Penalty factor: eps = alpha E / h, h the mean slave facet size at the point", "SPContactSetFromOptions", c->alpha, &c->alpha, NULL));
  PetscCall(SPFrictionSetFromOptions(PetscOptionsObject, c)); /* after -contact_alpha: the default of -contact_friction_alpha */
  PetscCall(PetscOptionsReal("-contact_gap_rtol", "Methods that update the shift: converged only when no point penetrates more than gap_rtol x h_c and every active point has |gap| <= gap_rtol x h_c (h_c: the smallest mean slave facet size at a contact point)", "SPContactSetFromOptions", c->gapRtol, &c->gapRtol, NULL));
  PetscCall(SPOptionsRealComputed(PetscOptionsObject, "-contact_gap_tol", "Absolute gap tolerance (a length); overrides -contact_gap_rtol", "SPContactSetFromOptions", "gap_rtol x h_c", &c->gapTol, &c->gapTolSet));
  PetscCall(PetscOptionsReal("-contact_step_cap", "Newton step control: scale a step so no point penetrates deeper than step_cap x h in one step (0: off); a load step that stalls is solved again with a tenth of it, then a hundredth, kept until a load step converges (with friction only while the chatter hold is on, -contact_chatter_flips)", "SPContactSetFromOptions", c->stepCap, &c->stepCap, NULL));
  PetscCall(PetscOptionsBool("-contact_safeguard", "Update the shift only of points active in both the previous and the new iterate (method.md 4.1); false only to demonstrate chatter", "SPContactSetFromOptions", c->safeguard, &c->safeguard, NULL));
  PetscCall(PetscOptionsBool("-contact_shift_predict", "Friction, shifted: a load step whose increment is proportional to the last one (every condition's amplitude moves in proportion), after a step that changed no point's status, starts the stuck points from the tangential tractions extrapolated from the last two converged steps", "SPContactSetFromOptions", c->predict, &c->predict, NULL));
  PetscCall(PetscOptionsBool("-contact_branch_hold", "Shifted and alm: the Newton step after a shift update (alm: the first of the solve after an augmentation) linearises every point on its branch of the iterate before the update (closed: p = -eps (g + s) even where the new shift opens it; stuck or slipping as it was), not on the one the update gives at the unchanged displacement; not with -contact_shift_accel anderson", "SPContactSetFromOptions", c->branchHold, &c->branchHold, NULL));
  if (c->twoPass) c->chatterFlips = 0; /* the hold's default with two-pass pairs: off (contact-enforce.c) */
  PetscCall(PetscOptionsInt("-contact_chatter_flips", "Shifted and alm: a point that changed between open and closed this many times in a Newton solve stays closed while its tension eps (g + s) is below -contact_chatter_tension times the iterate's peak pressure (0: off; default 3, 0 with -contact_two_pass)", "SPContactSetFromOptions", c->chatterFlips, &c->chatterFlips, NULL));
  PetscCall(PetscOptionsReal("-contact_chatter_tension", "The tension, relative to the iterate's peak contact pressure, below which a chattering point stays closed (-contact_chatter_flips)", "SPContactSetFromOptions", c->chatterTension, &c->chatterTension, NULL));
  PetscCall(PetscOptionsBool("-contact_shift_settled", "In-Newton shift update only at iterations whose active set did not change (the contraction rate holds only then)", "SPContactSetFromOptions", c->settled, &c->settled, NULL));
  PetscCall(PetscOptionsEList("-contact_tangent", "Second variation of the gap in the tangent (obstacle curvature; pair projection and normal variation): auto (once a Newton iteration left the active set unchanged), full (always: the consistent tangent), frozen (never)", "SPContactSetFromOptions", Tangents, 3, Tangents[tangent], &tangent, NULL));
  PetscCall(PetscOptionsBool("-contact_monitor", "Print one line per Newton iteration: residual, active points, max penetration, max shift change", "SPContactSetFromOptions", c->monitor, &c->monitor, NULL));
  PetscOptionsEnd();
  if (!setValues) c->nvalues = 0;
  c->tangent = (SPTangent)tangent;
  PetscCall(SPContactCheckMu(comm, "contact_friction_", c->mu));
  PetscCheck(c->alpha > 0.0, comm, PETSC_ERR_USER_INPUT, "-contact_alpha %.6g: the penalty factor must be positive", (double)c->alpha);
  PetscCheck(c->alpha >= 1e-3 && c->alpha <= 1e8, comm, PETSC_ERR_USER_INPUT, "-contact_alpha %.6g: outside 1e-3..1e8 (eps h / E); below, the penetration is of the order of the load over E; above, the Jacobian loses all digits. 10 to 1000 are usual", (double)c->alpha);
  PetscCheck(c->alphaT > 0.0, comm, PETSC_ERR_USER_INPUT, "-contact_friction_alpha %.6g: the tangential penalty factor must be positive", (double)c->alphaT);
  PetscCheck(c->alphaT >= 1e-3 && c->alphaT <= 1e8, comm, PETSC_ERR_USER_INPUT, "-contact_friction_alpha %.6g: outside 1e-3..1e8 (eps_T h / E)", (double)c->alphaT);
  PetscCheck(c->maxFlips >= 1, comm, PETSC_ERR_USER_INPUT, "-contact_friction_max_flips %" PetscInt_FMT ": give at least 1 (0 would freeze a point's slip direction at its first stick/slip change, before the step has found it)", c->maxFlips);
  PetscCheck(c->jumpWait == 0.0 || (c->jumpWait >= 1.0 && !PetscIsInfOrNanReal(c->jumpWait)), comm, PETSC_ERR_USER_INPUT, "-contact_friction_jump_wait %.6g: must be 0 (off) or a growth factor >= 1", (double)c->jumpWait);
  PetscCheck(c->creepRtol > 0.0 && c->slipRtol > 0.0 && !PetscIsInfOrNanReal(c->creepRtol) && !PetscIsInfOrNanReal(c->slipRtol), comm, PETSC_ERR_USER_INPUT, "-contact_friction_creep_rtol %.6g, -contact_friction_slip_rtol %.6g: must be positive finite numbers", (double)c->creepRtol, (double)c->slipRtol);
  PetscCheck(c->creepRtol >= SP_RTOL_MIN && c->slipRtol >= SP_RTOL_MIN, comm, PETSC_ERR_USER_INPUT, "-contact_friction_creep_rtol %.6g, -contact_friction_slip_rtol %.6g: below %g, finer than double precision resolves (F1 at a creep rtol of 1e-20 stalled at round-off); give at least %g", (double)c->creepRtol, (double)c->slipRtol, SP_RTOL_MIN, SP_RTOL_MIN);
  PetscCheck(!setPenalty || (c->penalty > 0.0 && !PetscIsInfOrNanReal(c->penalty)), comm, PETSC_ERR_USER_INPUT, "-contact_penalty %.6g: the penalty must be a positive number", (double)c->penalty);
  PetscCheck(!c->gapTolSet || (c->gapTol > 0.0 && !PetscIsInfOrNanReal(c->gapTol)), comm, PETSC_ERR_USER_INPUT, "-contact_gap_tol %.6g: must be a positive finite length", (double)c->gapTol);
  PetscCheck(c->gapRtol > 0.0 && c->gapRtol < 1.0, comm, PETSC_ERR_USER_INPUT, "-contact_gap_rtol %.6g: must be in (0, 1) (a fraction of the contact facet size)", (double)c->gapRtol);
  PetscCheck(c->chatterFlips >= 0, comm, PETSC_ERR_USER_INPUT, "-contact_chatter_flips %" PetscInt_FMT ": must be >= 0 (0 disables the chatter hold)", c->chatterFlips);
  PetscCheck(c->chatterTension >= 0.0 && c->chatterTension <= 0.1, comm, PETSC_ERR_USER_INPUT, "-contact_chatter_tension %.6g: must be in [0, 0.1] (a fraction of the peak contact pressure; 0.01 is the default)", (double)c->chatterTension);
  PetscCheck(c->stepCap >= 0.0 && !PetscIsInfOrNanReal(c->stepCap), comm, PETSC_ERR_USER_INPUT, "-contact_step_cap %.6g: must be a finite number >= 0 (0 disables the step control)", (double)c->stepCap);
  for (c->nob = 0; c->nob < SP_MAX_OBSTACLES; ++c->nob) {
    char      name[48];
    PetscBool has;
    PetscCall(PetscSNPrintf(name, sizeof(name), "-contact_obstacle_%" PetscInt_FMT "_type", c->nob));
    PetscCall(PetscOptionsHasName(NULL, NULL, name, &has));
    if (!has && c->nob == 0) { /* -help lists the -contact_obstacle_<k>_* family even when unset */
      PetscBool  help;
      SPObstacle ob;
      PetscReal  mu = c->mu;
      PetscCall(PetscOptionsHasHelp(NULL, &help));
      if (help) PetscCall(ObstacleSetFromOptions(comm, 0, c->dim, &ob, &mu)); /* defaults: valid */
    }
    if (!has) break;
    c->obMu[c->nob] = c->mu;
    PetscCall(ObstacleSetFromOptions(comm, c->nob, c->dim, &c->ob[c->nob], &c->obMu[c->nob]));
  }
  PetscCall(SPOptionsCheckNoGap(comm, "-contact_obstacle_", c->nob, SP_MAX_OBSTACLES, "obstacles", "obstacle", "type"));
  PetscCall(SPContactPairsSetFromOptions(c));
  c->enabled = c->nob > 0 || c->npair > 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(CheckFriction(c));
  PetscCheck(c->nob > 0 || !setValues, comm, PETSC_ERR_USER_INPUT, "-contact_values given but no obstacle: add -contact_obstacle_0_type plane|sphere|cylinder (deformable bodies: -contact_pair_0_slave_values/-contact_pair_0_master_values)");
  PetscCheck(c->nob == 0 || setValues, comm, PETSC_ERR_USER_INPUT, "contact obstacle given but no slave boundary: add -contact_values <label values> (and -contact_label)");
  if (!c->enabled) PetscCall(UnreadUnused(c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactIsActive(SPContact c, PetscBool *on)
{
  PetscFunctionBeginUser;
  *on = c && c->enabled;
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
  PetscCall(SPContactPointsSetUp(c, slave));
  PetscCall(SPContactComputeAreas(c));
  PetscCall(SPContactSetGapTolerance(c));
  PetscCall(SPContactWarnCorners(c));
  PetscCall(SPContactWarnDeepStart(c));
  PetscCall(DMCreateGlobalVector(c->dm, &c->Fc));
  PetscCall(VecCreateMPI(comm, c->n * c->dim, PETSC_DETERMINE, &c->fvec));
  PetscCall(VecSetOption(c->fvec, VEC_IGNORE_NEGATIVE_INDICES, PETSC_TRUE));
  PetscCall(VecSetOption(c->Fc, VEC_IGNORE_NEGATIVE_INDICES, PETSC_TRUE));
  PetscCall(SPContactPairsSetUp(c));
  PetscCall(SPFrictionSetUp(c));
  PetscCallMPI(MPI_Allreduce(&c->n, &nAll, 1, MPIU_INT, MPI_SUM, comm));
  PetscCheck(nAll > 0, comm, PETSC_ERR_USER_INPUT, "-contact_values: the slave boundary has no vertices");
  PetscCall(UnreadUnused(c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Vertex fields for output: pressure, gap, shift, active on the vertex DM of `pressure`; gap is NaN
   on vertices that are not contact points or have no projection (no gap exists there) */
PetscErrorCode SPContactGetFields(SPContact c, Vec X, Vec pressure, Vec gap, Vec shift, Vec active)
{
  DM           dmS;
  PetscSection gs;
  PetscInt     rstart;
  PetscScalar *p, *g, *sh, *a;

  PetscFunctionBeginUser;
  PetscCall(SPContactEvaluate(c, X));
  PetscCall(SPContactRecoverForces(c));
  PetscCall(VecGetDM(pressure, &dmS));
  PetscCall(DMGetGlobalSection(dmS, &gs));
  PetscCall(VecGetOwnershipRange(pressure, &rstart, NULL));
  PetscCall(VecZeroEntries(pressure));
  PetscCall(VecSet(gap, (PetscScalar)NAN)); /* no gap where there is no contact point or projection */
  PetscCall(VecZeroEntries(shift));
  PetscCall(VecZeroEntries(active));
  PetscCall(VecGetArray(pressure, &p));
  PetscCall(VecGetArray(gap, &g));
  PetscCall(VecGetArray(shift, &sh));
  PetscCall(VecGetArray(active, &a));
  for (PetscInt i = 0; i < c->n; ++i) {
    const SPContactPoint *pt = &c->pt[i];
    PetscInt              off;
    PetscCall(PetscSectionGetOffset(gs, pt->vertex, &off));
    off -= rstart;
    p[off]  = pt->press;
    g[off]  = pt->geo.elem != SP_ELEM_NONE ? pt->geo.gap : (PetscReal)NAN;
    sh[off] = pt->st.sN;
    a[off]  = pt->st.active ? 1.0 : 0.0;
  }
  PetscCall(VecRestoreArray(pressure, &p));
  PetscCall(VecRestoreArray(gap, &g));
  PetscCall(VecRestoreArray(shift, &sh));
  PetscCall(VecRestoreArray(active, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Friction vertex fields for output, at the state X: tangential traction sum_a t_a T_a and the
   accumulated slip (vectors, on the vertex DM of `traction`, dim dofs), and the status (0 open,
   1 stick, 2 slip, 3 closed without friction: SPFrictionOutputStatus) on the scalar vertex DM of `status`. Vertices that are not contact points get
   zero traction and slip and status -1. */
PetscErrorCode SPContactGetFrictionFields(SPContact c, Vec X, Vec traction, Vec slip, Vec status)
{
  DM           dmV, dmS;
  PetscSection gsV, gsS;
  PetscInt     rV, rS;
  PetscScalar *t, *s, *st;

  PetscFunctionBeginUser;
  PetscCall(SPContactEvaluate(c, X));
  PetscCall(SPContactRecoverForces(c));
  PetscCall(VecGetDM(traction, &dmV));
  PetscCall(VecGetDM(status, &dmS));
  PetscCall(DMGetGlobalSection(dmV, &gsV));
  PetscCall(DMGetGlobalSection(dmS, &gsS));
  PetscCall(VecGetOwnershipRange(traction, &rV, NULL));
  PetscCall(VecGetOwnershipRange(status, &rS, NULL));
  PetscCall(VecZeroEntries(traction));
  PetscCall(VecZeroEntries(slip));
  PetscCall(VecSet(status, -1.0));
  PetscCall(VecGetArray(traction, &t));
  PetscCall(VecGetArray(slip, &s));
  PetscCall(VecGetArray(status, &st));
  for (PetscInt i = 0; i < c->n; ++i) {
    const SPContactPoint *pt = &c->pt[i];
    PetscInt              offV, offS;
    PetscCall(PetscSectionGetOffset(gsV, pt->vertex, &offV));
    PetscCall(PetscSectionGetOffset(gsS, pt->vertex, &offS));
    offV -= rV;
    offS -= rS;
    for (PetscInt d = 0; d < c->dim; ++d) {
      t[offV + d] = pt->ft[d];
      s[offV + d] = pt->st.slip[d];
    }
    st[offS] = (PetscReal)SPFrictionOutputStatus(c, i);
  }
  PetscCall(VecRestoreArray(traction, &t));
  PetscCall(VecRestoreArray(slip, &s));
  PetscCall(VecRestoreArray(status, &st));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Every contact point on rank 0 as CSV: reference coordinates, area, eps, gap, shift, pressure,
   active; tangential traction (vector), accumulated slip (vector), status (SPFrictionOutputStatus) */
PetscErrorCode SPContactWritePoints(SPContact c, Vec X, const char file[])
{
  MPI_Comm     comm = PetscObjectComm((PetscObject)c->dm);
  const PetscInt nc = 16;
  PetscMPIInt  size, rank, mine = (PetscMPIInt)(c->n * nc), *counts = NULL, *displs = NULL;
  PetscReal   *row, *all = NULL;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(SPContactEvaluate(c, X));
  PetscCall(SPContactRecoverForces(c));
  PetscCall(PetscCalloc1(c->n * nc + 1, &row));
  for (PetscInt i = 0; i < c->n; ++i) {
    const SPContactPoint *pt = &c->pt[i];
    PetscReal            *r  = &row[i * nc];
    for (PetscInt d = 0; d < c->dim; ++d) r[d] = pt->X[d];
    r[3] = pt->area;
    r[4] = pt->eps;
    r[5] = pt->geo.elem != SP_ELEM_NONE ? pt->geo.gap : (PetscReal)NAN; /* as in the h5: no gap exists */
    r[6] = pt->st.sN;
    r[7] = pt->press;
    r[8] = SPContactPointActive(c, i); /* at X, as the summary counts it (st.active is booked at iteration boundaries only) */
    for (PetscInt d = 0; d < c->dim; ++d) r[9 + d] = pt->ft[d];
    for (PetscInt d = 0; d < c->dim; ++d) r[12 + d] = pt->st.slip[d];
    r[15] = SPFrictionOutputStatus(c, i);
  }
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
    fprintf(fp, "x,y,z,area,eps,gap,shift,pressure,active,tx,ty,tz,slip_x,slip_y,slip_z,status\n");
    for (PetscInt i = 0; i < displs[size] / nc; ++i) {
      const PetscReal *r = &all[i * nc];
      fprintf(fp, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d", r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], (int)r[8]);
      for (PetscInt k = 9; k < 15; ++k) fprintf(fp, ",%.17g", r[k]);
      fprintf(fp, ",%d\n", (int)r[15]);
    }
    PetscCall(SPOutputCheckStream(fp, file, PETSC_TRUE));
    PetscCall(PetscFree2(counts, displs));
    PetscCall(PetscFree(all));
  }
  PetscCall(PetscFree(row));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The set-up and cost figures of the summary block */
static PetscErrorCode ViewSetUp(SPContact c, PetscViewer v)
{
  MPI_Comm       comm = PetscObjectComm((PetscObject)c->dm);
  PetscInt       nAll, evals, accelSteps;
  PetscReal      emin = PETSC_MAX_REAL, emax = 0.0, gmin, gmax;
  PetscInt64     rec;
  PetscLogDouble tmax;
  PetscMPIInt    size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Allreduce(&c->n, &nAll, 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&c->evaluations, &evals, 1, MPIU_INT, MPI_MAX, comm));
  for (PetscInt i = 0; i < c->n; ++i) emin = PetscMin(emin, c->pt[i].eps), emax = PetscMax(emax, c->pt[i].eps);
  PetscCallMPI(MPI_Allreduce(&emin, &gmin, 1, MPIU_REAL, MPI_MIN, comm));
  PetscCallMPI(MPI_Allreduce(&emax, &gmax, 1, MPIU_REAL, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(&c->received, &rec, 1, MPIU_INT64, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&c->exchangeTime, &tmax, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_method %s\n", c->method->name));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_law %s\n", c->method->law->name));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_points %" PetscInt_FMT "\n", nAll));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_obstacles %" PetscInt_FMT "\n", c->nob));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_pairs %" PetscInt_FMT "\ncontact_two_pass %s\n", c->nuser, c->twoPass ? "yes" : "no"));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_master_facets %" PetscInt_FMT "\n", c->nmfAll));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_evaluations %" PetscInt_FMT "\ncontact_limited_steps %" PetscInt_FMT "\ncontact_shift_updates %" PetscInt_FMT "\n", evals, c->stepLimits, c->shiftUpdates));
  /* not contact_step_*: lines that start with contact_step are the per-step reports */
  PetscCall(PetscViewerASCIIPrintf(v, "contact_retries_step_cap %" PetscInt_FMT "\n", c->capRetries));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_chatter_holds %" PetscInt_FMT "\n", c->chatterHolds));
  if (c->friction) PetscCall(PetscViewerASCIIPrintf(v, "contact_predicted_steps %" PetscInt_FMT "\n", c->predictions));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_exchanges %" PetscInt_FMT "\ncontact_exchange_time %.6f\n", c->exchanges, (double)tmax));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_exchange_facets_per_rank %.1f\n", c->exchanges ? (double)rec / (double)(c->exchanges * size) : 0.0));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_pattern_rebuilds %" PetscInt_FMT "\n", c->rebuilds));
  if (c->npair) { /* mallocs during MatSetValues on the Jacobian (0: the preallocation held, or no
                     Jacobian yet: a run stopped by -max_wall_time before its first solve) */
    MatInfo info;
    info.mallocs = 0.0;
    if (c->Jref) PetscCall(MatGetInfo(c->Jref, MAT_GLOBAL_SUM, &info));
    PetscCall(PetscViewerASCIIPrintf(v, "contact_jacobian_mallocs %g\n", (double)info.mallocs));
  }
  PetscCall(SPContactGetAccelSteps(c, &accelSteps));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_shift_accel %s\ncontact_shift_accel_steps %" PetscInt_FMT "\n", SPShiftAccelTypes[c->params.accel], accelSteps));
  if (c->params.accel == SP_ACCEL_SCHUR) PetscCall(PetscViewerASCIIPrintf(v, "contact_shift_accel_solves %" PetscInt_FMT "\n", c->schurSolves));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_alpha %g\n", c->penalty > 0.0 ? 0.0 : (double)c->alpha));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_eps_min %.10e\ncontact_eps_max %.10e\n", (double)gmin, (double)gmax));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_length_scale %.10e\ncontact_gap_rtol %g\ncontact_gap_tol %.6e\n", (double)c->lengthScale, c->gapTolSet ? 0.0 : (double)c->gapRtol, (double)c->gapTol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The contact for the run line (app.c): method, penalty, friction, obstacles and pairs */
PetscErrorCode SPContactDescribe(SPContact c, char *buf, size_t len)
{
  char eps[64], fric[64] = "";

  PetscFunctionBeginUser;
  if (!c->enabled) {
    PetscCall(PetscStrncpy(buf, "no contact", len));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (c->penalty > 0.0) PetscCall(PetscSNPrintf(eps, sizeof(eps), "penalty %.6g", (double)c->penalty));
  else PetscCall(PetscSNPrintf(eps, sizeof(eps), "alpha %.6g", (double)c->alpha));
  if (c->friction && c->mu > 0.0) PetscCall(PetscSNPrintf(fric, sizeof(fric), ", friction mu %.6g", (double)c->mu));
  else if (c->friction) PetscCall(PetscStrncpy(fric, ", friction (mu per obstacle or pair)", sizeof(fric)));
  PetscCall(PetscSNPrintf(buf, len, "contact %s (%s%s), %" PetscInt_FMT " obstacle%s, %" PetscInt_FMT " pair%s%s", c->method->name, eps, fric, c->nob, c->nob == 1 ? "" : "s", c->nuser, c->nuser == 1 ? "" : "s", c->twoPass ? " (two-pass)" : ""));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The contact keys of the summary block (figures of the final state). Collective. */
PetscErrorCode SPContactView(SPContact c, PetscViewer v)
{
  SPContactStats st;

  PetscFunctionBeginUser;
  if (!c->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(ViewSetUp(c, v));
  PetscCall(SPContactGetStats(c, &st));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_augmentations %" PetscInt_FMT "\ncontact_active_points %" PetscInt_FMT "\n", st.augmentations, st.activePoints));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_max_penetration %.10e\n", (double)st.maxPenetration));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_gap_error %.10e\n", (double)st.gapError));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_force_x %.12e\ncontact_force_y %.12e\ncontact_force_z %.12e\n", (double)st.force[0], (double)st.force[1], (double)st.force[2]));
  if (c->npair) {
    PetscCall(PetscViewerASCIIPrintf(v, "contact_force_master_x %.12e\ncontact_force_master_y %.12e\ncontact_force_master_z %.12e\n", (double)st.forceMaster[0], (double)st.forceMaster[1], (double)st.forceMaster[2]));
    PetscCall(PetscViewerASCIIPrintf(v, "contact_remote_elements %" PetscInt_FMT "\n", st.remoteElements));
  }
  PetscCall(PetscViewerASCIIPrintf(v, "contact_peak_pressure %.12e\ncontact_radius %.10e\n", (double)st.peakPressure, (double)st.contactRadius));
  PetscCall(PetscViewerASCIIPrintf(v, "contact_friction_mu %g\ncontact_friction %s\n", (double)c->mu, c->friction ? "yes" : "no"));
  if (c->friction) {
    PetscCall(PetscViewerASCIIPrintf(v, "contact_friction_alpha %g\ncontact_stick_points %" PetscInt_FMT "\ncontact_slip_points %" PetscInt_FMT "\n", (double)c->alphaT, st.stickPoints, st.slipPoints));
    PetscCall(PetscViewerASCIIPrintf(v, "contact_fresh_points %" PetscInt_FMT "\n", st.freshPoints)); /* closed in the last step: no friction yet */
    PetscCall(PetscViewerASCIIPrintf(v, "contact_max_stick_creep %.10e\ncontact_friction_stick_hold %s\n", (double)st.maxStickCreep, c->stickHold && c->method->timing == SP_UPDATE_NEWTON ? "yes" : "no")); /* in effect: shifted only */
    PetscCall(PetscViewerASCIIPrintf(v, "contact_friction_jump_waits %" PetscInt_FMT "\n", c->jumpWaits));
    PetscCall(PetscViewerASCIIPrintf(v, "contact_tangential_force_x %.12e\ncontact_tangential_force_y %.12e\ncontact_tangential_force_z %.12e\n", (double)st.tangentialForce[0], (double)st.tangentialForce[1], (double)st.tangentialForce[2]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactDestroy(SPContact *contact)
{
  SPContact c = *contact;

  PetscFunctionBeginUser;
  if (!c) PetscFunctionReturn(PETSC_SUCCESS);
  if (c->dmC) PetscCall(SPContactPointsDestroy(c));
  PetscCall(VecDestroy(&c->Fc));
  PetscCall(VecDestroy(&c->fvec));
  PetscCall(SPContactPairsDestroy(c));
  PetscCall(PetscFree(*contact));
  PetscFunctionReturn(PETSC_SUCCESS);
}
