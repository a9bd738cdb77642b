/* spcontact: public API of the modules.  Opaque handles; layouts live in spcontact-impl.h. */
#ifndef SPCONTACT_H
#define SPCONTACT_H

#include <petscdmplex.h>
#include <petscsnes.h>
#include <petscsf.h>
#include <petscds.h>

#if PETSC_VERSION_LT(3, 19, 0)
  #define PETSC_SUCCESS 0 /* spelled out from PETSc 3.19 on */
#endif

#define SP_MAX_BC        8 /* Neumann/Dirichlet conditions per run (-bc_0_.. -bc_7_) */
#define SP_MAX_OBSTACLES 8 /* rigid obstacles per run (-contact_obstacle_0_.. ) */
#define SP_MAX_VALUES    16

typedef struct _n_SPProblem *SPProblem; /* material, FE space, boundary conditions, load factor */
typedef struct _n_SPContact *SPContact; /* contact points, obstacles, method, shift vector */
typedef struct _n_SPOutput  *SPOutput;  /* HDF5 + XDMF fields, CSV history */
typedef struct _n_SPSolver  *SPSolver;  /* SNES with the contact-aware callbacks */
typedef struct _n_SPApp     *SPApp;     /* owns every module object */
typedef struct _n_SPFastElastic *SPFastElastic; /* element-level linear elasticity, first order */

/* Log stages and events: one per module, so -log_view tells where time goes. */
typedef struct {
  PetscLogStage mesh, setup, solve, output;
  PetscLogEvent bulkResidual, bulkJacobian, contactSearch, contactAssembly, shiftUpdate;
  PetscLogEvent matCreate, nearNullSpace, fastSetUp;
} SPLog;
PETSC_EXTERN PetscErrorCode SPLogRegister(SPLog *);

/* The progress lines on stdout (log.c): one per converged load step and, within a long step, one
   per Newton iteration at most every -progress_interval seconds; none with -quiet */
typedef struct {
  PetscBool      quiet;
  PetscReal      interval; /* seconds between the lines within a step (0: every Newton iteration) */
  PetscLogDouble t0, last; /* the run's start; the last line printed */
} SPProgress;
PETSC_EXTERN PetscErrorCode SPProgressIteration(SPProgress *, MPI_Comm, PetscInt, PetscInt, PetscInt, PetscReal, PetscReal, PetscInt, PetscReal);

/* mesh.c, partition-metis.c */
PETSC_EXTERN PetscErrorCode SPMeshCreate(MPI_Comm, DM *);
PETSC_EXTERN PetscErrorCode SPMeshCheckSize(MPI_Comm, DM);
PETSC_EXTERN PetscErrorCode SPOptionsCheckLength(MPI_Comm, const char[], const char[], PetscInt);
PETSC_EXTERN PetscErrorCode SPMeshGetSerialNumbers(DM, const PetscInt **);
PETSC_EXTERN PetscErrorCode SPMeshCheckLabel(DM, const char[], PetscInt, const PetscInt[], const char[]);
PETSC_EXTERN PetscErrorCode SPPartitionerSetMetis(DM);
PETSC_EXTERN PetscErrorCode SPMeshGetLabelFacets(DM, const char[], PetscInt, const PetscInt[], PetscInt *, PetscInt **);
PETSC_EXTERN PetscErrorCode SPMeshPointVertices(DM, PetscInt, PetscInt, PetscInt, PetscInt *, PetscInt[], PetscInt); /* a cell's or facet's vertices by a cone walk */
PETSC_EXTERN PetscErrorCode SPMeshFacetGeometry(DM, PetscInt, PetscInt, PetscReal[3], PetscReal[3], PetscReal *);
PETSC_EXTERN PetscErrorCode SPMeshCreateCompletedLabel(DM, const char[], PetscInt, const PetscInt[], const char[], DMLabel *);

/* problem.c, bc.c, materials/ */
PETSC_EXTERN PetscErrorCode SPProblemCreate(DM, SPProblem *);
PETSC_EXTERN PetscErrorCode SPProblemSetFromOptions(SPProblem);
PETSC_EXTERN PetscErrorCode SPProblemSetUp(SPProblem);
PETSC_EXTERN PetscErrorCode SPProblemSetLoadFactor(SPProblem, PetscReal);
PETSC_EXTERN PetscReal      SPProblemLoadRatio(SPProblem, const PetscReal[3]);
PETSC_EXTERN PetscErrorCode SPProblemGetLoadFactor(SPProblem, PetscReal *);
PETSC_EXTERN PetscErrorCode SPProblemGetYoung(SPProblem, PetscReal *);
PETSC_EXTERN PetscErrorCode SPProblemGetVertexYoung(SPProblem, PetscInt, PetscReal *);
PETSC_EXTERN PetscErrorCode SPProblemGetDegree(SPProblem, PetscInt *);
PETSC_EXTERN PetscErrorCode SPProblemGetLocalState(SPProblem, Vec, Vec *);
PETSC_EXTERN PetscErrorCode SPProblemRestoreLocalState(SPProblem, Vec *);
PETSC_EXTERN PetscErrorCode SPProblemIsLinear(SPProblem, PetscBool *);
PETSC_EXTERN PetscErrorCode SPProblemComputeError(SPProblem, Vec, PetscBool *, PetscReal *);
PETSC_EXTERN PetscErrorCode SPProblemCheckState(SPProblem, Vec, PetscBool *, char[], size_t);
PETSC_EXTERN PetscErrorCode SPProblemDestroy(SPProblem *);

/* contact.c (points, areas), contact-search.c (obstacles), contact-enforce.c (methods),
   contact-update.c (shift update) */
typedef struct {
  PetscInt  activePoints, activeChanged, augmentations;
  PetscReal maxPenetration, maxShiftChange, peakPressure, contactRadius;
  PetscReal gapError; /* max over points of the penetration and, on active points, |g| */
  PetscReal force[3];
  PetscReal forceMaster[3]; /* contact pairs: force on the master vertices of the user pairs' elements */
  PetscInt  remoteElements; /* contact pairs: elements whose master facet is owned by another rank */
  PetscInt  stickPoints, slipPoints, statusChanged; /* friction: return-map status, changes since the last iterate */
  PetscInt  freshPoints;   /* friction: closed points carrying none because they were open when the step began */
  PetscReal maxStickCreep;  /* friction: max |Dg_T| over stick points in the current step */
  PetscReal maxSlipShiftResidual; /* friction: max over slip points of eps_T |s_T' - s_T| / (mu p), s_T' one more update at the state of the last one */
  PetscReal tangentialForce[3]; /* friction: resultant tangential force on the slave bodies */
  PetscInt  frozenPoints;       /* friction: chattering points slipping in their frozen direction */
  PetscReal frozenDeviation;    /* friction: max over them of |t_return - t_frozen| / (mu p), t_return the return map's */
} SPContactStats;

PETSC_EXTERN PetscErrorCode SPContactCreate(DM, SPProblem, PetscLogEvent, SPContact *);
PETSC_EXTERN PetscErrorCode SPContactSetFromOptions(SPContact);
PETSC_EXTERN PetscErrorCode SPContactSetUp(SPContact);
PETSC_EXTERN PetscErrorCode SPContactIsActive(SPContact, PetscBool *);
PETSC_EXTERN PetscErrorCode SPContactAddResidual(SPContact, Vec, Vec);
PETSC_EXTERN PetscErrorCode SPContactAddJacobian(SPContact, Vec, Mat);
PETSC_EXTERN PetscErrorCode SPContactSetUpJacobian(SPContact, Vec, Mat);
PETSC_EXTERN PetscErrorCode SPContactMarkRows(SPContact, Vec);
PETSC_EXTERN PetscErrorCode SPContactBeginSolve(SPContact, Vec);
PETSC_EXTERN PetscErrorCode SPContactNewtonUpdate(SPContact, Vec, PetscBool *);
PETSC_EXTERN PetscErrorCode SPContactLimitStep(SPContact, Vec, Vec, Vec, PetscBool *);
PETSC_EXTERN PetscErrorCode SPContactTightenStepCap(SPContact, PetscBool *);
PETSC_EXTERN void           SPContactRestoreStepCap(SPContact);
PETSC_EXTERN PetscErrorCode SPContactSolveUpdate(SPContact, Vec, PetscInt, PetscBool *, PetscBool *);
PETSC_EXTERN PetscErrorCode SPContactConverged(SPContact, PetscBool *);
PETSC_EXTERN PetscErrorCode SPContactGetStats(SPContact, SPContactStats *);
PETSC_EXTERN PetscErrorCode SPContactGetIterationStats(SPContact, SPContactStats *);
PETSC_EXTERN PetscErrorCode SPContactHasFriction(SPContact, PetscBool *);
PETSC_EXTERN PetscErrorCode SPContactObstacleCycle(SPContact, PetscInt *, PetscInt[2]);
PETSC_EXTERN PetscErrorCode SPContactHasPairs(SPContact, PetscBool *);
PETSC_EXTERN PetscErrorCode SPContactShiftsInNewton(SPContact, PetscBool *);
PETSC_EXTERN PetscErrorCode SPContactUpdatesShifts(SPContact, PetscBool *);
PETSC_EXTERN PetscErrorCode SPContactGetAccelSteps(SPContact, PetscInt *);
PETSC_EXTERN PetscErrorCode SPContactGetGapTolerance(SPContact, PetscReal *, PetscBool *);
PETSC_EXTERN void           SPContactSetJacobianSolve(SPContact, PetscErrorCode (*)(void *, Vec, Vec, PetscBool *), void *);
PETSC_EXTERN PetscErrorCode SPContactGetActiveVersion(SPContact, PetscInt *);
PETSC_EXTERN PetscBool      SPContactTangentFixed(SPContact);
PETSC_EXTERN PetscErrorCode SPContactGetActiveChanges(SPContact, PetscInt *, PetscInt *);
PETSC_EXTERN PetscErrorCode SPContactGetShiftContraction(SPContact, PetscReal *);
PETSC_EXTERN PetscErrorCode SPContactGetUpdateForce(SPContact, PetscReal *);
PETSC_EXTERN PetscErrorCode SPContactGetRoundOffForce(SPContact, PetscReal *);
PETSC_EXTERN PetscErrorCode SPContactStepFeedsUpdate(SPContact, Vec, PetscBool *);
PETSC_EXTERN PetscErrorCode SPContactCommitStep(SPContact, Vec);
PETSC_EXTERN PetscErrorCode SPContactPredictRecord(SPContact);
PETSC_EXTERN void           SPContactPredictNext(SPContact, PetscReal);
PETSC_EXTERN PetscErrorCode SPContactMonitor(SPContact, PetscInt, PetscReal);
PETSC_EXTERN PetscErrorCode SPContactReportStep(SPContact, Vec, PetscInt, PetscReal, PetscBool);
PETSC_EXTERN PetscErrorCode SPContactSaveState(SPContact);
PETSC_EXTERN PetscErrorCode SPContactRestoreState(SPContact);
PETSC_EXTERN PetscErrorCode SPContactGetFields(SPContact, Vec, Vec, Vec, Vec, Vec);
PETSC_EXTERN PetscErrorCode SPContactGetFrictionFields(SPContact, Vec, Vec, Vec, Vec);
PETSC_EXTERN PetscErrorCode SPContactWritePoints(SPContact, Vec, const char[]);
PETSC_EXTERN PetscErrorCode SPContactEvaluateFinal(SPContact, Vec);
PETSC_EXTERN PetscErrorCode SPContactView(SPContact, PetscViewer);
PETSC_EXTERN PetscErrorCode SPContactDescribe(SPContact, char *, size_t);
PETSC_EXTERN PetscErrorCode SPContactDestroy(SPContact *);

/* matrix.c, matrix-graph.c */
PETSC_EXTERN PetscErrorCode SPMatrixCreate(DM, PetscBool, Mat *);
PETSC_EXTERN PetscErrorCode SPMatrixSetRigidBodyModes(DM, PetscBool, Mat);
PETSC_EXTERN PetscErrorCode SPMatrixShareGraph(Mat);
PETSC_EXTERN PetscErrorCode SPVertexGlobalIndices(PetscSection, PetscSection, PetscInt, PetscInt, PetscInt[]);

/* fast-elastic.c */
PETSC_EXTERN PetscErrorCode SPFastElasticCreate(DM, SPProblem, SPFastElastic *);
PETSC_EXTERN PetscErrorCode SPFastElasticAddJacobian(SPFastElastic, Vec, Mat);
PETSC_EXTERN PetscErrorCode SPFastElasticAddResidual(SPFastElastic, Vec, Vec);
PETSC_EXTERN PetscErrorCode SPFastElasticDestroy(SPFastElastic *);

/* solver.c */
PETSC_EXTERN PetscErrorCode SPSolverCreate(DM, SPProblem, SPContact, SPLog *, SPSolver *);
PETSC_EXTERN PetscErrorCode SPSolverSetFromOptions(SPSolver);
PETSC_EXTERN PetscErrorCode SPSolverSolve(SPSolver, Vec, SNESConvergedReason *);
PETSC_EXTERN PetscErrorCode SPSolverSetHistory(SPSolver, FILE *, PetscInt);
PETSC_EXTERN void           SPSolverSetProgress(SPSolver, SPProgress *);
PETSC_EXTERN PetscErrorCode SPSolverGetCounts(SPSolver, PetscInt *, PetscInt *, PetscInt *);
PETSC_EXTERN PetscErrorCode SPSolverGetJacobianReuses(SPSolver, PetscInt *);
PETSC_EXTERN PetscErrorCode SPSolverGetPCKeeps(SPSolver, PetscInt *);
PETSC_EXTERN PetscErrorCode SPSolverGetRefinements(SPSolver, PetscInt *, PetscInt *);
PETSC_EXTERN PetscErrorCode SPSolverGetAccepted(SPSolver, PetscInt *);
PETSC_EXTERN PetscErrorCode SPSolverRecoverBreakdown(SPSolver, PetscBool *);
PETSC_EXTERN PetscErrorCode SPSolverRecoverDirect(SPSolver, PetscBool *);
PETSC_EXTERN PetscErrorCode SPSolverGetDirectStep(SPSolver, PetscInt *);
PETSC_EXTERN PetscErrorCode SPSolverResumeDirect(SPSolver, PetscInt);
PETSC_EXTERN PetscErrorCode SPSolverReorthogonalise(SPSolver);
PETSC_EXTERN PetscBool      SPSolverReorthogonalises(SPSolver);
PETSC_EXTERN PetscBool      SPSolverStalled(SPSolver);
PETSC_EXTERN const char    *SPSolverReasonName(SPSolver, SNESConvergedReason);
PETSC_EXTERN PetscErrorCode SPSolverGetBulkOperator(SPSolver, const char **);
PETSC_EXTERN PetscErrorCode SPSolverGetLinearSolver(SPSolver, const char **, const char **);
PETSC_EXTERN PetscErrorCode SPSolverDescribeLinear(SPSolver, char *, size_t);
PETSC_EXTERN PetscErrorCode SPSolverDestroy(SPSolver *);

/* loading.c */
PETSC_EXTERN PetscErrorCode SPLoadingRun(SPApp);
PETSC_EXTERN PetscErrorCode SPLogProgress(SPApp, PetscInt, PetscInt, PetscReal, PetscInt, PetscInt);

/* output.c */
PETSC_EXTERN PetscErrorCode SPOutputCreate(DM, SPOutput *);
PETSC_EXTERN PetscErrorCode SPOutputSetFromOptions(SPOutput);
PETSC_EXTERN PetscErrorCode SPOutputOpen(SPOutput);
PETSC_EXTERN PetscErrorCode SPOutputWriteStep(SPOutput, SPProblem, Vec, SPContact);
PETSC_EXTERN PetscErrorCode SPOutputGetHistoryFile(SPOutput, FILE **);
PETSC_EXTERN PetscErrorCode SPOutputClose(SPOutput, SPContact, const char[], PetscInt, PetscReal);
PETSC_EXTERN PetscErrorCode SPOutputGetPointsFile(SPOutput, char[], size_t);
PETSC_EXTERN PetscErrorCode SPOutputGetPrefix(SPOutput, const char **);
PETSC_EXTERN PetscErrorCode SPOutputDestroy(SPOutput *);

/* options-files.c: before PetscInitialize; nonzero (one line printed) if one is unreadable */
int SPCheckOptionsFiles(int, char **);
int SPCheckYAMLStream(FILE *, char[], size_t); /* options-yaml.c: 0 if PETSc can read it as options */

/* option-defaults.c: spcontact's defaults for PETSc options, set where the user gave none */
PETSC_EXTERN PetscErrorCode SPOptionsSetDefault(const char[], const char[]);
PETSC_EXTERN PetscErrorCode SPOptionsIsDefault(const char[], PetscBool *);
PETSC_EXTERN PetscErrorCode SPOptionsCheckValues(MPI_Comm);
PETSC_EXTERN PetscErrorCode SPOptionsCheckNamedValues(MPI_Comm);
PETSC_EXTERN PetscBool      SPOptionsTakesWord(const char[]);
PETSC_EXTERN PetscErrorCode SPOptionsRealComputed(PetscOptionItems *, const char[], const char[], const char[], const char[], PetscReal *, PetscBool *);
PETSC_EXTERN PetscBool      SPOptionsNameAt(const char[], size_t, const char[]);
PETSC_EXTERN size_t         SPOptionsNameCopy(const char[], size_t, char[], size_t);
PETSC_EXTERN PetscErrorCode SPOptionsUnread(const char[]);
typedef struct {
  PetscInt n;
  char   **names, **values;
} SPOptionsLeft; /* the options unused at SPOptionsLeftBegin (options-unread.c) */
PETSC_EXTERN PetscErrorCode SPOptionsLeftBegin(SPOptionsLeft *);
PETSC_EXTERN PetscErrorCode SPOptionsLeftEnd(SPOptionsLeft *);
PETSC_EXTERN PetscErrorCode SPOptionsIndexedGiven(MPI_Comm, const char[], PetscInt, const char[], PetscBool[]);
PETSC_EXTERN PetscErrorCode SPOptionsCheckNoGap(MPI_Comm, const char[], PetscInt, PetscInt, const char[], const char[], const char[]);

/* app.c */
PETSC_EXTERN PetscErrorCode SPAppCreate(MPI_Comm, SPApp *);
PETSC_EXTERN PetscErrorCode SPAppSetUp(SPApp);
PETSC_EXTERN PetscErrorCode SPAppRun(SPApp, int *);
PETSC_EXTERN PetscErrorCode SPAppSummary(SPApp);
PETSC_EXTERN PetscErrorCode SPAppDestroy(SPApp *);

#endif
