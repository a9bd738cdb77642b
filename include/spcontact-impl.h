/* spcontact: private struct layouts, included by src/ only. */
#ifndef SPCONTACT_IMPL_H
#define SPCONTACT_IMPL_H

#include <spcontact.h>
#include <hdf5.h>
#include <kernels/contact-law.h>
#include <kernels/contact-pair.h>

typedef enum { SP_BC_DIRICHLET, SP_BC_TRACTION, SP_BC_PRESSURE, SP_BC_FORCE } SPBCType;
PETSC_EXTERN const char *const SPBCTypes[];

typedef struct {
  SPBCType  type;
  char      label[PETSC_MAX_PATH_LEN];
  PetscInt  nvalues, values[SP_MAX_VALUES];
  PetscInt  ncomps, comps[3];
  PetscReal value[3]; /* Dirichlet: displacement per component; traction: vector; pressure: value[0];
                         force: total force vector, applied as the uniform traction force/area */
  PetscReal load;     /* Dirichlet only: the load factor the bc function scales by (set on insert) */
  PetscReal ramp[2];  /* load curve: amplitude 0 up to load factor ramp[0], 1 from ramp[1], linear between */
  PetscInt  slot;     /* Neumann: constants[] slot; -1 for Dirichlet */
  PetscReal gradient[3]; /* pressure: p(x) = value + gradient . x */
  PetscReal base[7];  /* Neumann: [pressure, t_x, t_y, t_z, dp/dx, dp/dy, dp/dz] at amplitude 1 */
  PetscBool follower; /* pressure: acts on the deformed face (finite-strain laws; kernels/follower.h) */
} SPBC;

/* A material law (the table in problem.c). Its parameters come from a material's (E, nu); the
   kernels read them from constants[] (one material everywhere) or, with region materials, from
   the auxiliary cell field (one value per cell, components SP_A_*; kernels/elastic.h). */
#define SP_MAX_MATERIALS 8 /* region materials per run (-material_0_.. -material_7_) */
#define SP_LAW_NPARAM    2 /* parameters per cell of a law (linear_elastic: lambda, mu) */
typedef struct {
  const char *name;
  /* E, nu -> the law's per-cell parameters param[SP_LAW_NPARAM] */
  void (*parameters)(PetscReal E, PetscReal nu, PetscReal param[]);
  /* residual/Jacobian kernels on ds; param != NULL: one material, its parameters go into constants[];
     param == NULL: per-cell parameters from the auxiliary field */
  PetscErrorCode (*setup)(PetscDS ds, const PetscReal param[], PetscScalar constants[]);
  PetscBool linear;       /* stress linear in the strain: stiffness reuse is exact */
  PetscBool fastOperator; /* the fast element operator applies: isotropic linear elasticity with
                             param = (lambda, mu) in closed form, or a nonlinear law through its
                             stress/tangent below (fast-elastic.c); otherwise PetscFE only */
  PetscPointFunc mmsSource; /* the body force of the manufactured solution for this law (NULL: none) */
  /* a nonlinear law's fast element operator: first Piola stress P[i dim + J] and tangent
     A[((i dim + k) dim + J) dim + L] = dP_iJ/dF_kL from u_x and the cell's parameters, hyperelastic
     (A_iJkL = A_kLiJ: the fast operator assembles half the element matrix and mirrors it) (NULL: the
     law is linear, or PetscFE only) */
  void (*stress)(PetscInt dim, const PetscReal param[], const PetscScalar u_x[], PetscScalar P[]);
  void (*tangent)(PetscInt dim, const PetscReal param[], const PetscScalar u_x[], PetscScalar A[]);
  PetscBool cornerCheck; /* finite strain, W undefined for J <= 0: a converged state with det F <= 0
                            at a cell vertex is refused and the load step cut back (SPCornerCheck) */
} SPMaterialLaw;
PETSC_EXTERN void           SPMaterialParameters_LinearElastic(PetscReal, PetscReal, PetscReal[]);
PETSC_EXTERN PetscErrorCode SPMaterialSetUp_LinearElastic(PetscDS, const PetscReal[], PetscScalar[]);
PETSC_EXTERN PetscErrorCode SPMaterialSetUp_NeoHookean(PetscDS, const PetscReal[], PetscScalar[]);
PETSC_EXTERN void           SPMaterialStress_NeoHookean(PetscInt, const PetscReal[], const PetscScalar[], PetscScalar[]);
PETSC_EXTERN void           SPMaterialTangent_NeoHookean(PetscInt, const PetscReal[], const PetscScalar[], PetscScalar[]);

/* materials/neo_hookean-check.c: det F at every cell's vertices of a converged state */
typedef struct _n_SPCornerCheck *SPCornerCheck;
PETSC_EXTERN PetscErrorCode SPCornerCheckCreate(DM, PetscFE, SPCornerCheck *);
PETSC_EXTERN PetscErrorCode SPCornerCheckEvaluate(SPCornerCheck, Vec, PetscReal *, PetscInt *);
PETSC_EXTERN PetscErrorCode SPCornerCheckDestroy(SPCornerCheck *);
/* mesh.c: the coordinate field tabulated at a quadrature (NULL: PETSc per cell) and a cell's
   reference Jacobians at its points (at most 8) */
PETSC_EXTERN PetscErrorCode SPMeshCoordinateTabulation(DM, PetscQuadrature, PetscTabulation *);
/* mesh.c: simplex cells, collective (PETSc's answer is per rank) */
PETSC_EXTERN PetscErrorCode SPMeshIsSimplex(DM, PetscBool *);
PETSC_EXTERN PetscErrorCode SPMeshCellJacobians(DM, Vec, PetscTabulation, PetscQuadrature, PetscInt, PetscReal[], PetscReal[]);

/* One material: a law and its data, on the cells of one label value (region materials) or on
   every cell (the default material, value -1) */
typedef struct {
  PetscInt             k;     /* option index of -material_<k>_* (0 for the default material) */
  PetscInt             value; /* -material_<k>_label_value; -1: every cell */
  char                 lawName[64];
  const SPMaterialLaw *law;
  PetscReal            E, nu;
  PetscReal            param[SP_LAW_NPARAM];
} SPMaterial;

struct _n_SPProblem {
  DM        dm; /* not owned */
  PetscInt  dim, degree;
  char      material[64]; /* the default material: -material_model, -material_E, -material_nu */
  PetscReal E, nu;
  char      matLabel[PETSC_MAX_PATH_LEN]; /* cell label of the region materials ("Cell Sets") */
  PetscBool regions;                      /* region materials given (-material_<k>_*) */
  PetscInt  nmat;                         /* materials: 1 (the default) or the region materials */
  SPMaterial mat[SP_MAX_MATERIALS];
  PetscInt   cStart, cEnd;
  PetscInt  *cellMat;   /* per local cell: index into mat[] */
  PetscReal *cellParam; /* per local cell: the law's parameters, SP_LAW_NPARAM each */
  PetscInt   vStart, vEnd;
  PetscReal *vertexE;   /* region materials: per local vertex, the largest E of the cells around it (all ranks) */
  PetscReal load;
  PetscInt  nbc;
  SPBC      bc[SP_MAX_BC];
  PetscReal mmsAmp; /* manufactured-solution amplitude; 0 = off */
  PetscBool linear;       /* residual affine in u: stiffness reuse is exact */
  PetscBool fastOperator; /* every cell's law has the fast element operator (SPMaterialLaw.fastOperator) */
  Vec       locBC;  /* local vector holding the Dirichlet values of load factor bcLoad */
  PetscReal bcLoad;
  SPCornerCheck corner; /* the law's corner check (SPMaterialLaw.cornerCheck; NULL: none) */
};

/* bc.c */
PETSC_EXTERN PetscErrorCode SPBCSetFromOptions(MPI_Comm, PetscInt, PetscInt *, SPBC[]);
PETSC_EXTERN PetscErrorCode SPBCAddToDS(DM, PetscInt, SPBC[], PetscScalar[]);
PETSC_EXTERN PetscErrorCode SPBCCheckBalance(DM, SPProblem, SPContact); /* bc-balance.c: loads the supports cannot hold, refused */
PETSC_EXTERN PetscErrorCode SPBCCheckAbsorbed(DM, SPProblem); /* bc-absorbed.c: a load component only a support feels, refused */
PETSC_EXTERN PetscErrorCode SPBCFreeRotation(DM, SPContact, PetscInt *, PetscReal[3], PetscReal[3]); /* bc-rotation.c: a rigid rotation the supports leave free */
#define SP_RIGID_MAX 6 /* rigid modes in 3D: 3 translations, 3 rotations */
PETSC_EXTERN void           SPBCRigidAddRow(PetscInt, const PetscReal[3], const PetscReal[3], PetscReal[][SP_RIGID_MAX]); /* bc-rotation.c: G += phi phi^T of one support */
PETSC_EXTERN PetscErrorCode SPBCRigidSupports(DM, SPContact, PetscBool, const PetscInt[], PetscInt, const PetscReal[][3], const PetscReal[], PetscReal[][SP_RIGID_MAX][SP_RIGID_MAX]); /* bc-rotation.c: the supports' rows per group of vertices */
PETSC_EXTERN PetscErrorCode SPBCRigidKernel(PetscInt, PetscReal[][SP_RIGID_MAX], const PetscReal[3], PetscReal, PetscReal, PetscBool *, PetscReal[3], PetscInt *, PetscReal[3], PetscReal[3]); /* bc-rotation.c: the rigid modes they leave free */
PETSC_EXTERN PetscErrorCode SPBCCheckBodies(DM, SPContact); /* bc-bodies.c: a body (or bodies linked by pairs) that nothing holds, refused */
PETSC_EXTERN PetscErrorCode SPBCCheckBodiesInPairs(DM, SPContact); /* bc-bodies.c: a body in a pair held with the others still */
PETSC_EXTERN PetscReal      SPBCAmplitude(const SPBC *, PetscReal); /* a condition's load curve at a load factor */
PETSC_EXTERN void           SPBCSetLoad(PetscInt, const SPBC[], PetscReal, PetscScalar[]);
PETSC_EXTERN PetscBool      SPBCProportional(PetscInt, const SPBC[], const PetscReal[3], PetscReal);

/* Enforcement methods (src/methods/<name>.c, table in src/contact-methods.c). A method is a normal
   law (traction and its tangent) plus an update rule for the point's shift and the moment it runs:
   never, at every Newton-iteration boundary, or after every converged inner solve (the outer loop
   is in loading.c). Nothing outside those files names a method. */
typedef enum { SP_UPDATE_NONE, SP_UPDATE_NEWTON, SP_UPDATE_SOLVE } SPUpdateTiming;
/* acceleration of the in-Newton update over all active points (contact-accel.c) */
typedef enum { SP_ACCEL_NONE, SP_ACCEL_ANDERSON, SP_ACCEL_SCHUR } SPShiftAccelType;
PETSC_EXTERN const char *const SPShiftAccelTypes[];
typedef struct {
  PetscInt history;    /* (s, g) pairs kept per point for the update rule (>= 1) */
  SPShiftAccelType accel; /* the shifted method's -contact_shift_accel (none for the others) */
  PetscInt accelDepth;    /* -contact_shift_accel_depth: differences kept by Anderson */
  PetscInt maxUpdates; /* SP_UPDATE_SOLVE: updates per load step before the step fails */
  const char *maxOption; /* the option that sets maxUpdates (named in the failure message) */
} SPMethodParams;
typedef struct {
  const char       *name, *help;
  SPUpdateTiming    timing;
  const SPNormalLaw *law;
  /* new shift of one point from its history (s_k, g_k), k = 0..nh-1, newest last (NULL: none) */
  PetscReal (*update)(PetscInt nh, const PetscReal hs[], const PetscReal hg[]);
  /* the method's own options (may be NULL); every method's are registered, so -help lists them */
  PetscErrorCode (*setFromOptions)(PetscOptionItems *, SPMethodParams *);
  PetscBool friction; /* applies the same timing to the tangential shift (Coulomb friction) */
} SPMethod;
PETSC_EXTERN const SPMethod *const SPMethodTable[];

/* contact-accel.c: Anderson acceleration of the in-Newton shift update, a vector over the points
   (distributed: every inner product is a global reduction) */
typedef struct _n_SPShiftAccel *SPShiftAccel;
PETSC_EXTERN PetscErrorCode SPShiftAccelCreate(MPI_Comm, PetscInt, PetscInt, SPShiftAccel *);
PETSC_EXTERN PetscErrorCode SPShiftAccelReset(SPShiftAccel);
PETSC_EXTERN PetscErrorCode SPShiftAccelUpdate(SPShiftAccel, const PetscBool[], const PetscReal[], const PetscReal[], PetscReal[], PetscBool *);
PETSC_EXTERN PetscErrorCode SPShiftAccelGetSteps(SPShiftAccel, PetscInt *);
PETSC_EXTERN PetscErrorCode SPShiftAccelDestroy(SPShiftAccel *);
PETSC_EXTERN const SPMethod SPMethodPenalty, SPMethodShifted, SPMethodShiftedRegression, SPMethodALM;

/* A contact pair: slave and master surfaces, label values of one label (contact-pairs.c) */
#define SP_MAX_PAIRS 8 /* user pairs per run (-contact_pair_0_.. ); -contact_two_pass mirrors them */
#define SP_RTOL_MIN  1e-15 /* the finest relative contact tolerance (gap, creep, slip shift): about 5 round-offs of double precision */
typedef struct {
  char      label[PETSC_MAX_PATH_LEN];
  PetscInt  nslave, slave[SP_MAX_VALUES], nmaster, master[SP_MAX_VALUES];
  PetscReal mu; /* friction coefficient (default -contact_friction_mu) */
  PetscBool mirror; /* added by -contact_two_pass: the user pair with slave and master swapped */
} SPPair;

/* One master facet as every rank sees it after the exchange. The vertex order makes the facet
   normal point out of the master body (see kernels/contact-pair.h). */
#define SP_FACET_MAXV 4
#define SP_ELEM_MAXD (3 * (1 + SP_FACET_MAXV)) /* dofs of one contact element: slave vertex and master facet */
typedef struct {
  PetscInt  pair, nv, gid;               /* gid: global facet number (owner rank's offset + index) */
  PetscInt  sid;                         /* the facet's serial mesh point number (rank-count free) */
  PetscInt  vid[SP_FACET_MAXV];         /* global vertex numbers (junctions, free ends) */
  PetscInt  cp[SP_FACET_MAXV];          /* global contact-point number of each vertex, -1 if none */
  PetscInt  dof[SP_FACET_MAXV * 3];     /* global displacement dofs; constrained: -(i+1) */
  PetscBool freeSide[SP_FACET_MAXV];    /* side s (2D: vertex s; 3D: edge s -> s+1) belongs to no other master facet of the pair */
  PetscReal X[SP_FACET_MAXV * 3];       /* reference coordinates */
  PetscReal x[SP_FACET_MAXV * 3];       /* deformed coordinates at the last evaluation */
  PetscReal u[SP_FACET_MAXV * 3];       /* their displacements (x - X without X's round-off: friction's slip) */
} SPMasterFacet;

/* element kinds of a contact point (geo.elem >= 0: a master facet) */
#define SP_ELEM_NONE     (-2)
#define SP_ELEM_OBSTACLE (-1)
#define SP_KNOWN_FACETS  16
typedef enum { SP_TANGENT_AUTO, SP_TANGENT_FULL, SP_TANGENT_FROZEN } SPTangent;

/* The contact-point record (src/contact-point.c owns it). Geometry is evaluated once per iterate
   (the displacement and load factor it was evaluated at are remembered; SPContactEvaluate returns
   at once for the same state); state is what the method updates and a cut-back restores. */
typedef enum { SP_POINT_OPEN, SP_POINT_STICK, SP_POINT_SLIP } SPPointStatus;
typedef struct {
  PetscInt  elem;          /* master facet (index into c->mf), SP_ELEM_OBSTACLE or SP_ELEM_NONE */
  PetscInt  obstacle;      /* elem == SP_ELEM_OBSTACLE: which obstacle */
  PetscReal x[3];          /* deformed slave position */
  PetscReal u[3];          /* its displacement (x - X without X's round-off: friction's slip) */
  PetscReal xi[2];         /* local coordinates of the projection on the master facet */
  PetscReal gap;           /* normal gap (< 0: penetration) */
  PetscReal normal[3];     /* unit normal, pointing from the master (obstacle) to the slave */
  PetscReal tangent[2][3]; /* orthonormal tangent basis (dim - 1 vectors) */
  PetscReal mu;            /* friction coefficient of the element (0: frictionless) */
  PetscReal dgT[2];        /* tangential relative displacement in the step, committed basis */
  PetscBool anchorLost;    /* the anchor facet is not among this rank's master facets */
} SPPointGeometry;
typedef struct {
  PetscReal     sN;            /* normal shift (a scaled multiplier: lambda_N = -eps sN) */
  PetscReal     sT[2];         /* tangential shift slots (dim - 1); zero without friction */
  PetscReal     slip[3];       /* tangential slip accumulated over the converged steps (vector) */
  PetscReal     creep[3];      /* slip accumulated while stuck (reset when the point slips or opens) */
  PetscReal     tCommit[3];    /* tangential traction at the last converged step (vector) */
  SPPointStatus status;        /* open / stick / slip (frictionless: open or stick = closed) */
  PetscBool     noFriction;    /* closed at the last bookkeeping with no friction there (mu 0, or fresh) */
  PetscBool     active;        /* g + sN <= 0 at the last bookkeeping */
  PetscBool     heldStick;     /* stuck before this boundary's update (its branch held with `held`) */
  PetscBool     held;          /* active before this boundary's shift update: its linear branch is held (branchHold) */
  PetscInt      inactiveCount; /* consecutive inactive iterates (shift reset after two) */
  PetscInt      flips;         /* stick/slip changes in this step (status frozen after 3) */
  PetscBool     released;      /* its frozen direction was let go once in this step (SPFrictionReleaseFrozen) */
  PetscInt      flipsN;        /* open/closed changes in this Newton solve (SPContactChatterHeld) */
  PetscBool     holdOff;       /* the chatter hold let it go in this solve: held at the shift's clip (s = 0) with an open gap */
  PetscInt      obstacle;      /* the rigid obstacle it held when last active in this solve (-1: none) */
  PetscInt      otherObstacle; /* the one it held before its last switch (-1: none) */
  PetscInt      switchesN;     /* switches between obstacles in this Newton solve (SPContactObstacleCycle) */
  PetscReal     dir[2];        /* slip direction at the last bookkeeping (basis T) */
  PetscBool     reversed;      /* the slip direction reversed at the last bookkeeping */
  /* friction anchor, committed at the last converged step (kept through a cut-back) */
  PetscBool     anchored;
  PetscBool     fresh;         /* anchored while open: frictionless until a commit anchors it closed (its
                                  closest point is not the point it will touch) */
  PetscInt      anchor;        /* master facet gid, or -(k + 1) for obstacle k */
  PetscReal     anchorXi[2];   /* local coordinates of the anchor on its facet */
  PetscReal     us[3], um[3];  /* slave displacement and anchor (master) displacement at commit */
  PetscReal     n[3], T[2][3]; /* normal and tangent basis at commit (fixed in the step) */
  PetscReal     tT[2];         /* tangential traction at commit (penalty restarts from it) */
  PetscBool     basisStale;    /* the basis of the converged step kept at commit (the committed state
                                  stays in equilibrium); refreshed at the next solve's start */
} SPPointState;
typedef struct {
  PetscReal     tCommit[3]; /* committed traction */
  SPPointStatus status;
} SPPointPrev;

typedef struct {
  PetscInt        vertex, sdof[3]; /* plex vertex; global dofs of its displacement (constrained < 0) */
  PetscInt        pairMask;        /* bit k: slave of pair k */
  PetscBool       onObstacle;      /* slave of the rigid obstacles */
  PetscBool       primary;         /* counts in the slave force (obstacle slave or user pair slave) */
  PetscReal       X[3], area, h, eps; /* reference position, tributary area, facet size, penalty */
  PetscReal       nIn[3];          /* unit normal of its own surface into its body (reference): the
                                      normal of the force it receives with no contact element (SPContactPointNormal) */
  PetscReal       gap0;            /* gap at the first evaluation (u = 0): locates the contact centre */
  SPPointGeometry geo;
  SPPointState    st;
  PetscReal       press, f[3];     /* recovered pressure and nodal contact force */
  PetscReal       ft[3];           /* recovered tangential traction (vector) */
  PetscReal       epsT;            /* tangential penalty alpha_T E / h */
  PetscReal       t[2];            /* tangential traction of the last evaluated state (basis T) */
  PetscBool       stick;           /* its return-map status */
  PetscReal       frozenDev;       /* friction, slipping in a frozen direction: its FrozenDeviation at
                                      the last bookkeeping (0 otherwise) */
  SPPointPrev     prev;            /* the converged step before the last (the stuck points' predictor) */
  PetscInt        keepFacet;       /* pairs: master facet gid of the last Newton iterate in this step
                                      (-1: none), kept while it stays a near-best candidate */
  PetscInt        lastFacet;       /* pairs: the facet kept before keepFacet in this step (-1: none) */
  PetscInt        facetReturns;    /* pairs: times in this step the kept facet went back to lastFacet */
} SPContactPoint;

struct _n_SPContact {
  DM              dm; /* displacement DM, not owned */
  SPProblem       problem;
  DM              dmC; /* one dof per slave vertex: layout of the contact points */
  PetscBool       enabled;
  const SPMethod *method;
  SPMethodParams  params;
  char            label[PETSC_MAX_PATH_LEN];
  PetscInt        nvalues, values[SP_MAX_VALUES];
  PetscInt        nob;
  SPObstacle      ob[SP_MAX_OBSTACLES];
  PetscReal       penalty, alpha, gapTol, stepCap;
  PetscReal       capSaved;     /* the user's -contact_step_cap while a tighter one is in force (SPContactTightenStepCap) */
  PetscInt        capLevel;     /* 0: the user's cap in force, 1: a tenth, 2: a hundredth */
  PetscInt        capRetries;   /* solves of a load step repeated with a tighter cap (up to two per step) */
  PetscReal       gapRtol, lengthScale; /* gapTol = gapRtol x lengthScale unless -contact_gap_tol is given */
  PetscBool       gapTolSet;
  PetscReal       mu, alphaT, creepRtol, slipRtol; /* friction (-contact_friction_*) */
  PetscBool       alphaTGiven;                      /* -contact_friction_alpha given (else alpha_T = alpha) */
  PetscReal       roundOff;                         /* SPContactGetRoundOffForce, evaluated once (< 0: not yet) */
  PetscBool       stickHold;                       /* -contact_friction_stick_hold (contact-friction.c) */
  PetscReal       obMu[SP_MAX_OBSTACLES];          /* per obstacle (default mu) */
  PetscBool       friction;                        /* some obstacle or pair has mu > 0 */
  PetscReal       creepRel;                        /* max stick creep in the step / h, last bookkeeping */
  PetscInt        maxFlips;                        /* stick/slip changes per step before a status is frozen */
  PetscInt        chatterFlips;                    /* -contact_chatter_flips (0: off; SPContactChatterHeld) */
  PetscReal       chatterTension;                  /* -contact_chatter_tension, relative to peakIterate */
  PetscReal       peakIterate;                     /* the largest pressure -eps (g + s) at the last bookkeeping */
  PetscInt        chatterHolds;                    /* boundaries x points at which the chatter hold kept a point closed */
  PetscInt        accelStepsBefore;                /* accelerated shift updates of the run before a restart (summary) */
  PetscBool       safeguard, settled;
  PetscReal       jumpWait;   /* -contact_friction_jump_wait (contact-friction.c) */
  PetscInt        jumpWaits;  /* boundaries at which it held the shifts back */
  PetscInt        boundary;   /* Newton-iteration boundaries since the solve began */
  PetscBool       branchHold, holding, holdNext; /* -contact_branch_hold; the linearisation after an update holds the branches; holdNext: from the next solve's start (an augmentation) */
  PetscBool       predict, havePrev;   /* -contact_shift_predict; SPContactPoint.prev holds the step before the last */
  PetscReal       predictRatio;        /* pending prediction for the next solve (0: none), contact-predict.c */
  PetscInt        predictions;         /* load steps started from predicted tangential shifts */
  PetscBool       monitor;
  PetscInt        dim;
  /* owned contact points, in the order of the contact-point layout */
  PetscInt        n, rstart;
  SPContactPoint *pt;
  SPPointState   *saved;     /* state at the start of the load step (cut-back) */
  PetscReal      *gapStart;  /* gaps at the start of the Newton step (step control) */
  PetscReal      *slipStart; /* per point (3): trial and cone radius of a slipping point at the start of the Newton step, else 0 */
  PetscBool       slipLimited; /* the last Newton step was cut by the tangential step control */
  PetscReal      *hist;      /* update history: params.history (s, g) pairs per point, newest last */
  PetscInt       *nhist;
  SPShiftAccel    accel;     /* NULL: the plain update (params.accel none) */
  PetscReal      *accS, *accG, *accNew; /* per point scratch of the accelerated update */
  PetscBool      *accIn;
  SPShiftAccel    accelT;    /* the same for the tangential shifts of stuck points (2 slots per point) */
  PetscReal      *accTS, *accTG, *accTNew;
  PetscBool      *accTIn;
  PetscBool      *accTSlip;  /* schur only (else NULL): slipping points the tangential rule updated (accTS: their old shifts) */
  PetscInt        schurSteps, schurSolves; /* -contact_shift_accel schur: updates, back-substitutions (contact-schur.c) */
  PetscBool       schurSaid;               /* it said once that it has no factorization to use */
  PetscErrorCode (*jsolve)(void *, Vec, Vec, PetscBool *); /* solve with the last Newton step's Jacobian (NULL vectors: ask whether it can) */
  void           *jctx;
  PetscInt       *known;     /* per point: (facet, anchor facet) pairs already in the Jacobian pattern */
  /* evaluation cache: the state the geometry was last evaluated at */
  Vec             evalX;       /* copy of the displacement of the last evaluation (NULL: none yet) */
  PetscReal       evalLoad;    /* its load factor */
  PetscInt        evaluations; /* evaluations done (requests for an unchanged state cost nothing) */
  PetscInt        pinnedCount, pinnedPoint, pinnedObstacle; /* this search: points that penetrate an obstacle
                                  they cannot move against (a Dirichlet condition along its normal), one of them */
  PetscBool       pinnedWarned; /* that was reported once in this run */
  PetscInt        stepLimits;  /* Newton steps scaled by the step control (their trial iterate is evaluated too) */
  PetscReal       alphaMax;      /* the largest eps h / E at a contact point (the effective alpha) */
  PetscInt        activeVersion; /* moves when the active set (with friction: the stick/slip state) may have changed */
  PetscInt        activeChanges; /* points whose active state changed, summed over every bookkeeping of the run */
  PetscInt        shiftUpdates; /* Newton-iteration boundaries and converged solves at which the shifts moved */
  PetscBool       centreSet;
  PetscReal       centre[3];
  /* contact pairs (contact-pairs.c); a point may be a slave of obstacles and of several pairs */
  PetscInt        npair, nuser; /* all pairs (mirrors included), user pairs */
  SPPair          pair[2 * SP_MAX_PAIRS];
  PetscBool       twoPass;
  SPTangent       tangent;
  PetscLogEvent   searchEvent; /* SPContactSearch: gaps, projections and the master exchange */
  PetscBool       setSettled; /* the last Newton iteration of this solve left the active set unchanged */
  PetscInt        nmfAll, mfStart, nmfOwned; /* master facets: global count, this rank's first gid and count */
  PetscInt       *mfKey; /* per gid: sid * 2 SP_MAX_PAIRS + pair, a name free of the rank count (restart) */
  SPMasterFacet  *own;             /* this rank's owned master facets */
  PetscInt       *mfVert;          /* owned master facets: local plex vertices, SP_FACET_MAXV each */
  PetscInt        nmf, mfCap;      /* received master facets (from every rank, this one included) */
  SPMasterFacet  *mf;
  PetscBool       exchangeAll;     /* -contact_pair_exchange all: no bounding-box filter */
  PetscReal       margin;          /* bounding boxes are inflated by this (2 x the largest facet size) */
  PetscLogDouble  exchangeTime;
  PetscInt        exchanges, rebuilds;
  PetscInt64      received;        /* facets received, summed over exchanges and ranks */
  Vec             Fc, fvec;        /* global contact residual; nodal forces at contact points */
  Mat             Jref;            /* last Jacobian whose pattern was extended (not owned) */
  SPContactStats  stats;
};

/* helpers shared by the contact files */
PETSC_EXTERN PetscErrorCode SPContactPredictApply(SPContact);
#define SP_SCHUR_MAX_IT 30 /* GMRES products (back-substitutions) per Schur shift update */
PETSC_EXTERN PetscErrorCode SPContactSchurUpdate(SPContact, PetscBool, PetscBool, PetscReal *, PetscReal *);
PETSC_EXTERN void           SPFrictionClipShift(SPContact, PetscInt);
PETSC_EXTERN const SPNormalLaw SPLawShiftedPenalty;
PETSC_EXTERN PetscReal      SPShiftIncrement(PetscInt, const PetscReal[], const PetscReal[]);
PETSC_EXTERN PetscErrorCode SPContactPointsSetUp(SPContact, DMLabel);
PETSC_EXTERN PetscErrorCode SPContactPointsDestroy(SPContact);
PETSC_EXTERN PetscErrorCode SPContactEvaluate(SPContact, Vec);
PETSC_EXTERN PetscErrorCode SPContactSearch(SPContact, const PetscScalar[], PetscReal);
PETSC_EXTERN PetscErrorCode SPContactWarnCorners(SPContact);
PETSC_EXTERN PetscErrorCode SPContactWarnDeepStart(SPContact);
PETSC_EXTERN PetscErrorCode SPContactWarnDeepPairs(SPContact);
/* the cure for a point on two rigid obstacles (one held at a time), in the start warning and the stall line */
#define SP_CORNER_ADVICE "a point holds one obstacle at a time (README, Known limits): round or chamfer the corner, or give one of the two a Dirichlet condition instead of an obstacle where the body stays on it"
PETSC_EXTERN PetscErrorCode SPContactWarnPinned(SPContact);
PETSC_EXTERN const PetscReal *SPContactPointNormal(SPContact, PetscInt);
PETSC_EXTERN PetscErrorCode SPContactPointElement(SPContact, PetscInt, PetscInt *, PetscInt[], PetscReal *, PetscReal[], PetscReal[]);
PETSC_EXTERN void           SPContactPointTraction(SPContact, PetscInt, PetscReal *, PetscReal *);
PETSC_EXTERN PetscBool      SPContactPointActive(SPContact, PetscInt);
PETSC_EXTERN PetscBool      SPContactChatterHeld(SPContact, PetscInt);
PETSC_EXTERN PetscBool      SPContactChatterHolds(SPContact);
PETSC_EXTERN PetscErrorCode SPContactComputeStats(SPContact);
PETSC_EXTERN PetscErrorCode SPContactComputeAreas(SPContact);
PETSC_EXTERN PetscErrorCode SPContactSetGapTolerance(SPContact);
PETSC_EXTERN PetscErrorCode SPContactRecoverForces(SPContact);
PETSC_EXTERN PetscErrorCode SPContactFacetVertices(DM, PetscInt, PetscInt *, PetscInt[], PetscReal[]);
/* contact-friction.c */
#define SP_FRIC_MAXD (3 * (1 + 2 * SP_FACET_MAXV))
#define SP_CONE_EDGE_RTOL 1e-10 /* |y| within this of mu p: on the cone's edge (SlipsOnEdge) */
PETSC_EXTERN PetscErrorCode SPFrictionSetFromOptions(PetscOptionItems *, SPContact);
PETSC_EXTERN PetscErrorCode SPFrictionSetUp(SPContact);
PETSC_EXTERN void           SPFrictionKinematics(SPContact, PetscInt);
PETSC_EXTERN PetscErrorCode SPFrictionElementDofs(SPContact, PetscInt, PetscInt *, PetscInt[], PetscReal[], PetscReal[], PetscReal *);
PETSC_EXTERN void           SPFrictionTraction(SPContact, PetscInt, PetscReal[], PetscReal[], PetscBool *);
PETSC_EXTERN PetscErrorCode SPFrictionAddResidual(SPContact);
PETSC_EXTERN PetscErrorCode SPFrictionAddJacobian(SPContact, Mat);
PETSC_EXTERN PetscErrorCode SPFrictionAnchor(SPContact, PetscBool);
PETSC_EXTERN PetscErrorCode SPFrictionUpdate(SPContact, PetscBool, PetscReal *);
PETSC_EXTERN void           SPFrictionStepStart(SPContact);
PETSC_EXTERN PetscReal      SPFrictionStepLimit(SPContact);
PETSC_EXTERN PetscErrorCode SPFrictionBookkeep(SPContact, PetscBool);
PETSC_EXTERN PetscBool      SPFrictionConverged(SPContact);
PETSC_EXTERN PetscInt       SPFrictionOutputStatus(SPContact, PetscInt);
PETSC_EXTERN PetscErrorCode SPFrictionWarnFresh(SPContact, PetscInt);
PETSC_EXTERN PetscErrorCode SPFrictionReleaseFrozen(SPContact, PetscBool *, PetscBool *);
PETSC_EXTERN PetscErrorCode SPFrictionSettled(SPContact, PetscBool *);
PETSC_EXTERN PetscErrorCode SPFrictionJumped(SPContact, PetscReal, PetscBool *);
PETSC_EXTERN PetscErrorCode SPFrictionForces(SPContact, Vec, PetscReal[]);
/* contact.c: the friction coefficient of -<prefix>mu checked (the run's, an obstacle's, a pair's) */
PETSC_EXTERN PetscErrorCode SPContactCheckMu(MPI_Comm, const char[], PetscReal);
/* contact-pairs.c */
PETSC_EXTERN PetscErrorCode SPContactPairsSetFromOptions(SPContact);
PETSC_EXTERN PetscErrorCode SPContactPairsCheckLabels(SPContact);
PETSC_EXTERN PetscErrorCode SPContactPairsSetUp(SPContact);
PETSC_EXTERN PetscErrorCode SPContactPairsExchange(SPContact, const PetscScalar[]);
PETSC_EXTERN PetscErrorCode SPContactPairsProject(SPContact, PetscInt, PetscInt *, PetscReal *, PetscReal *, PetscReal[]);
PETSC_EXTERN void           SPContactPairsKeepFacets(SPContact);
PETSC_EXTERN void           SPContactPairsForgetFacets(SPContactPoint *);
PETSC_EXTERN PetscErrorCode SPContactPairsDestroy(SPContact);
PETSC_EXTERN PetscBool      SPContactGeometricTangent(SPContact);
PETSC_EXTERN PetscErrorCode SPOutputWriteXdmf(SPOutput, PetscBool);
PETSC_EXTERN PetscErrorCode SPXdmfWriteCollection(SPOutput, const char[], PetscBool, const char[], const char[], void (*)(FILE *, PetscInt, void *), void *);
PETSC_EXTERN const char *const SPOutputContactFields[4], *const SPOutputFrictionFields[3];
PETSC_EXTERN PetscErrorCode SPOutputWriteSurfaceXdmf(SPOutput, SPContact, PetscBool, PetscBool *);

/* fast-elastic.c: element-level isotropic linear elasticity on first-order cells */
struct _n_SPFastElastic {
  DM               dm; /* not owned */
  PetscInt         dim, nb, nq, nidx, cStart, cEnd; /* nb nodes per cell, nidx = nb dim */
  PetscQuadrature  quad;                            /* the FE's cell quadrature, not owned */
  const PetscReal *w;                               /* its weights */
  PetscReal       *dN;          /* reference gradients of the scalar basis, (q nb + a) dim + k */
  PetscInt        *gidx, *lidx; /* per cell: global (constrained < 0) and local closure indices */
  PetscReal       *xc;          /* per cell: node coordinates, closure order */
  const PetscReal *lame;        /* per cell: lambda, mu (the problem's per-cell parameters, not owned) */
  const SPMaterialLaw *law;     /* every cell's law: linear (K_e closed form) or its stress/tangent */
};

/* solver-stiffness.c: the linear stiffness kept inside the Jacobian */
typedef struct _n_SPStiffness *SPStiffness;
PETSC_EXTERN PetscErrorCode SPStiffnessSetUp(SPStiffness *, Mat, SPContact);
PETSC_EXTERN PetscErrorCode SPStiffnessMultAdd(SPStiffness, Mat, Vec, Vec);
PETSC_EXTERN PetscErrorCode SPStiffnessAssemble(SPStiffness, Mat, SPContact, Vec);
PETSC_EXTERN PetscErrorCode SPStiffnessDestroy(SPStiffness *);

struct _n_SPSolver {
  DM                  dm;
  SPProblem           problem;
  SPContact           contact;
  SPLog              *log;
  SNES                snes;
  Mat                 J;
  Vec                 r;
  FILE               *history; /* CSV rows, rank 0 only; may be NULL */
  SPProgress         *progress; /* the app's progress lines (NULL: none) */
  PetscInt            step;
  PetscInt            newtonTotal, linearTotal, lastLinear, funcTotal; /* funcTotal: SNES function evaluations */
  PetscBool           reuse;  /* linear material: K assembled once, r(u) = r0(load) + K u */
  SPStiffness         stiff;  /* reuse: K kept inside J = K + C (solver-stiffness.c) */
  Vec                 r0;
  SPFastElastic       fast;      /* NULL: the generic PetscFE bulk operator */
  PetscBool           checkFast; /* compare the fast and the generic operator once, print the differences */
  PetscReal           r0Load;
  PetscReal           atolRel, fscale; /* residual atol = atolRel x fscale (largest initial |F| of the run) unless -snes_atol */
  PetscBool           userAtol;
  PetscInt            stallIts, sinceProgress, cycling; /* stagnation: stop after stallIts iterations without progress (cycling: of them, with active-set changes) */
  PetscReal           bestF, bestGap;
  PetscReal           prevF;     /* |F| at the previous convergence test of this solve (the round-off floor test) */
  PetscBool           stalled;
  PetscBool           reorthogonalise; /* GMRES re-orthogonalises every Arnoldi vector (after a breakdown) */
  PetscReal           acceptRtol; /* -solver_linear_accept: a solve stopped short with |b - A x| <= this x |b| counts as converged (solver-accept.c) */
  PetscInt            accepted;   /* such solves over the run */
  PetscInt            jacReuseMax, jacReused, jacVersion, jacReuses; /* Jacobian reuse on an unchanged active set */
  PetscBool           jacValid;
  PetscBool           inexact;              /* linear tolerance from the Newton iteration's progress */
  PetscBool           targetFloor;          /* -solver_target_floor: without the inexact Newton, no solve past 1% of the residual target */
  PetscReal           rtolMax, rtolMin, rtol, rtolCap, lastF; /* its range (rtolMin: -ksp_rtol), value, safeguard cap, previous |F| */
  PetscReal           rtolSearch, searchCap; /* -solver_inexact_rtol_search, and its cap in this solve (search steps) */
  PetscReal           rtolLater, laterCap;   /* -solver_inexact_rtol_search_later, and its cap in this solve (search steps after the first) */
  PetscInt            searchSteps;           /* search steps so far in this solve */
  PetscBool           resolve, lastConverged; /* this solve repeats a converged one at the same load (after a shift update) */
  PetscReal           lastLoad, settledFactor;
  PetscBool           measured, measuring; /* -solver_inexact_measured; and this solve's method updates in Newton */
  PetscBool           updates;             /* this solve's method updates the shifts (shifted, alm; not penalty) */
  PetscReal           lastGap, rhoMeas[2]; /* gap error of the last iterate; the last two measured contractions (0: none) */
  PetscBool           lastSettledUpdate, lastUpdate; /* the last iterate's shifts moved (on a settled active set) */
  PetscBool           refine;                /* -solver_inexact_refine */
  PetscReal           refineRtol;            /* the tolerance this step must reach if it feeds a shift update (0: none pending; RefineStep) */
  PetscInt            refineLinear, refineStep; /* linear iterations of refinements in this solve, and in the step not yet logged */
  PetscInt            refinedSteps, refinedLinear; /* over the run: steps refined, their linear iterations (summary) */
  PetscBool           inexactInner;          /* -solver_inexact_inner (methods that update after a converged solve) */
  PetscReal           innerTarget, solveGap[2]; /* this iterate's inner-solve target (0: the residual target alone); gap error after the load step's last two converged solves (0: none) */
  PetscInt            directIts;     /* -solver_direct_switch: a 2D solve with more linear iterations switches to a factorization (solver-direct.c; 0: never) */
  PetscInt            directDofs;    /* -solver_direct_dofs: a 2D run with at most this many dofs factors from the start */
  PetscInt            directIts3, directDofs3; /* -solver_direct_switch_3d, -solver_direct_dofs_3d: the switch of a 3D GMRES run (friction, finite strain) with at most directDofs3 dofs */
  PetscInt            switchIts;     /* this run's switch threshold (directIts in 2D, directIts3 in 3D) */
  PetscBool           directChol;    /* -solver_direct_cholesky: the factorization of a symmetric Jacobian is Cholesky (LDL^T), else LU */
  PetscBool           directStart;   /* this run factors from the start */
  PetscBool           directAllowed; /* this run may still switch */
  PetscInt            directStep;    /* the load step of the switch (0: none) */
  PetscReal           pcLag;         /* -solver_pc_lag: a new Jacobian keeps the preconditioner while the changed points are at most this fraction of its active points (solver-pclag.c; 0: never) */
  PetscBool           pcLagAllowed;  /* this run may keep it (frictionless, no pairs, linear bulk, not the user's lag) */
  PetscInt            pcActive, pcChanges; /* active points and the run's active-state changes at the preconditioner's build (pcActive < 0: not built) */
  PetscBool           pcFresh, pcKept, pcSpent; /* the next solve is the first with a new preconditioner; the current one serves a later Jacobian; it converged too slowly for that */
  PetscReal           pcRate;        /* linear iterations per decade of residual in the first solve with the current preconditioner */
  PetscInt            pcKeeps;       /* new Jacobians that kept the preconditioner, over the run (summary) */
};

PETSC_EXTERN PetscErrorCode SPSolverSetUpAccept(SPSolver);
PETSC_EXTERN PetscErrorCode SPSolverSetUpDirect(SPSolver);
PETSC_EXTERN PetscErrorCode SPSolverDirectCheck(SPSolver, PetscInt);
PETSC_EXTERN PetscErrorCode SPSolverIsDirect(SPSolver, PetscBool *);
PETSC_EXTERN PetscErrorCode SPSolverSetUpPCLag(SPSolver);
PETSC_EXTERN PetscErrorCode SPSolverPCLagJacobian(SPSolver);
PETSC_EXTERN PetscErrorCode SPSolverPCLagSolved(SPSolver);
PETSC_EXTERN PetscErrorCode SPSolverConverged(SNES, PetscInt, PetscReal, PetscReal, PetscReal, SNESConvergedReason *, void *); /* solver-converged.c */
PETSC_EXTERN PetscErrorCode SPSolverRecordSolveGap(SPSolver, SNESConvergedReason);

struct _n_SPOutput {
  DM          dm;  /* not owned */
  DM          dmV; /* vertex DM with dim dofs, for displacement */
  DM          dmS; /* vertex DM with 1 dof, for contact fields */
  char        dir[PETSC_MAX_PATH_LEN], name[PETSC_MAX_PATH_LEN], prefix[PETSC_MAX_PATH_LEN];
  PetscBool   enabled;
  PetscViewer h5;
  FILE       *csv;
  PetscInt    nsteps, maxSteps;
  PetscReal  *times; /* the load factor of each written step (maxSteps allocated) */
  PetscBool   contactFields;
  PetscBool   frictionFields; /* tangential_traction, slip, status (runs with friction) */
  PetscBool   pointsFile;     /* the contact-points CSV was written (renamed with the others) */
  PetscBool   earlierRemoved; /* an earlier run's final files of this name removed (first converged step) */
  struct {                    /* output-guard.c: the write in progress */
    char      file[PETSC_MAX_PATH_LEN + 32];
    PetscBool open, collective; /* collective: HDF5 writes (SPOutputWriteBegin) */
    int       err;            /* errno of its first failure (0: none yet) */
    H5E_auto2_t func;         /* HDF5's error printing, restored after the write */
    void     *data;
  } guard;
};
PETSC_EXTERN PetscErrorCode SPOutputWriteBegin(SPOutput, const char[], PetscBool);
PETSC_EXTERN PetscErrorCode SPOutputWriteEnd(SPOutput, PetscErrorCode);
PETSC_EXTERN PetscErrorCode SPOutputCheckStream(FILE *, const char[], PetscBool);
PETSC_EXTERN PetscErrorCode SPOutputCheckFiles(SPOutput);
PETSC_EXTERN PetscErrorCode SPOutputRemoveEarlierResults(SPOutput);
PETSC_EXTERN PetscErrorCode SPOutputH5Reference(SPOutput, PetscBool, char[], size_t);

/* signals.c: SIGTERM/SIGINT recorded by a handler, acted on at the load-step loop's safe point */
typedef struct {
  void (*oldTerm)(int), (*oldInt)(int); /* the handlers replaced (restored at the end) */
  PetscBool installed;
  PetscInt  debugStep; /* -debug_interrupt_after_step: rank 0 raises SIGTERM after this step (tests) */
} SPSignals;
PETSC_EXTERN PetscErrorCode SPSignalsInstall(SPSignals *);
PETSC_EXTERN PetscErrorCode SPSignalsRestore(SPSignals *);
PETSC_EXTERN PetscErrorCode SPSignalsPending(MPI_Comm, SPSignals *, PetscInt, int *);

/* restart.c: the state of every converged step in the h5 (/restart), and a run resumed from it */
#define SP_POINT_NPACK 48 /* reals per contact point in /restart/points (contact-point.c) */
PETSC_EXTERN PetscErrorCode SPContactPackPoints(SPContact, PetscReal[]);
PETSC_EXTERN PetscErrorCode SPContactUnpackPoints(SPContact, const PetscReal[], PetscBool *);
PETSC_EXTERN PetscErrorCode SPRestartWriteStep(SPApp, PetscReal);

/* restart-natural.c: vectors in a partition-independent order (items named by serial point numbers) */
typedef struct {
  MPI_Comm  comm;
  PetscInt  n, N, bs; /* this rank's items, all items, reals per item */
  PetscInt *idx;      /* each local item's position in the file */
} SPNatural;
PETSC_EXTERN PetscErrorCode SPNaturalCreate(MPI_Comm, PetscInt, const PetscInt[], PetscInt, SPNatural *);
PETSC_EXTERN PetscErrorCode SPNaturalWrite(SPNatural *, PetscViewer, const char[], const PetscReal[]);
PETSC_EXTERN PetscErrorCode SPNaturalRead(SPNatural *, PetscViewer, const char[], PetscReal[]);
PETSC_EXTERN PetscErrorCode SPNaturalDestroy(SPNatural *);
PETSC_EXTERN PetscErrorCode SPRestartLoad(SPApp);

/* restart-options.c: the options that set the problem and the mesh's place and size, stored with the first step, compared on restart */
PETSC_EXTERN PetscErrorCode SPRestartPhysicsOptions(SPApp, char **);
PETSC_EXTERN PetscErrorCode SPRestartComparePhysics(MPI_Comm, const char[], const char[], const char[]);
PETSC_EXTERN PetscErrorCode SPRestartMeshGeometry(DM, char[], size_t);
PETSC_EXTERN PetscErrorCode SPRestartCompareGeometry(MPI_Comm, const char[], const char[], const char[]);

struct _n_SPApp {
  MPI_Comm  comm;
  SPLog     log;
  DM        dm;
  SPProblem problem;
  SPContact contact;
  SPSolver  solver;
  SPOutput  output;
  Vec       u;
  PetscInt  loadSteps, maxCutbacks, stepsDone, cutbacks;
  PetscInt  debugErrorRank; /* -debug_error_on_rank: this rank alone raises an error before the first step (tests; -1 none) */
  PetscInt  cells, vertices; /* global mesh counts (MeshCounts, once) */
  PetscInt  growAfter, streak; /* the increment doubles after growAfter converged steps in a row (streak) */
  PetscReal minIncrement, maxWallTime; /* cut-back floor (load factor); seconds (0: none) */
  PetscBool converged;
  PetscReal loadReached;
  PetscReal loadBefore;    /* the converged load factor before loadReached (-1: none; the stuck points' predictor) */
  SPProgress progress; /* the progress lines; progress.t0: the run's start */
  SPSignals signals;
  int       interrupted;   /* the signal that stopped the run (0: none) */
  PetscBool wallStopped;   /* -max_wall_time stopped the run (status "stopped": restartable, not failed) */
  char      restartFile[PETSC_MAX_PATH_LEN]; /* -restart: resume from this h5 ("" : from the start) */
  PetscReal loadInc;       /* restart: the load increment to go on with (0: 1/loadSteps) */
};

#endif
