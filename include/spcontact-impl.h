/* spcontact: private struct layouts, included by src/ only. */
#ifndef SPCONTACT_IMPL_H
#define SPCONTACT_IMPL_H

#include <spcontact.h>
#include <kernels/contact-law.h>

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
} SPBC;

typedef PetscErrorCode (*SPMaterialSetUpFn)(PetscDS, PetscReal, PetscReal, PetscScalar[]);
typedef struct {
  const char       *name;
  SPMaterialSetUpFn setup;
  PetscBool         linear;    /* stress linear in the strain */
  PetscBool         isotropic; /* isotropic linear elastic, Lame constants in SP_C_LAMBDA/SP_C_MU:
                                  the fast element operator (fast-elastic.c) may replace PetscFE */
} SPMaterialEntry;
PETSC_EXTERN PetscErrorCode SPMaterialSetUp_LinearElastic(PetscDS, PetscReal, PetscReal, PetscScalar[]);

struct _n_SPProblem {
  DM        dm; /* not owned */
  PetscInt  dim, degree;
  char      material[64];
  PetscReal E, nu;
  PetscReal load;
  PetscInt  nbc;
  SPBC      bc[SP_MAX_BC];
  PetscReal mmsAmp; /* manufactured-solution amplitude; 0 = off */
  PetscBool linear;    /* residual affine in u: stiffness reuse is exact */
  PetscBool isotropic; /* isotropic linear elastic material (SPMaterialEntry.isotropic) */
  Vec       locBC;  /* local vector holding the Dirichlet values of load factor bcLoad */
  PetscReal bcLoad;
};

/* bc.c */
PETSC_EXTERN PetscErrorCode SPBCSetFromOptions(MPI_Comm, PetscInt, PetscInt *, SPBC[]);
PETSC_EXTERN PetscErrorCode SPBCAddToDS(DM, PetscInt, SPBC[], PetscScalar[]);

typedef struct {
  SPContactMethod method;
  const char     *name;
  PetscBool       updatesInNewton; /* shift updated at every Newton-iteration boundary */
  PetscBool       augments;        /* shift updated after a converged Newton solve (Uzawa) */
  PetscBool       checksGap;       /* convergence requires max penetration <= gap_tol */
  /* new shift of one point from its history (s_k, g_k), k = 0..nh-1, newest last */
  PetscReal (*shift)(PetscInt nh, const PetscReal hs[], const PetscReal hg[]);
} SPMethodEntry;
PETSC_EXTERN const SPMethodEntry *SPContactMethodEntry(SPContactMethod);

struct _n_SPContact {
  DM                   dm; /* displacement DM, not owned */
  SPProblem            problem;
  DM                   dmC; /* one dof per slave vertex: layout of the contact points */
  PetscBool            enabled;
  SPContactMethod      method;
  const SPMethodEntry *entry;
  char                 label[PETSC_MAX_PATH_LEN];
  PetscInt             nvalues, values[SP_MAX_VALUES];
  PetscInt             nob;
  SPObstacle           ob[SP_MAX_OBSTACLES];
  PetscReal            penalty, alpha, gapTol, stepCap;
  PetscBool            safeguard;
  PetscInt             regM, almMax;
  PetscBool            monitor;
  PetscInt             dim;
  /* owned contact points, in the order of the global contact vector */
  PetscInt   n;
  PetscInt  *vertex;
  PetscReal *area, *eps, *h, *coord; /* coord: reference position, dim per point; h: facet size */
  PetscReal *gapStart;             /* gaps at the start of the Newton step (step control) */
  PetscReal *gap, *normal;        /* at the last evaluated state */
  PetscBool *active, *activePrev; /* activePrev: active set of the solve that produced the iterate */
  PetscInt  *inactiveCount;
  PetscReal *histS, *histG; /* regression history, regM per point, newest last */
  PetscInt  *nhist;
  Vec        shift, shiftSaved;  /* global vectors on dmC */
  Vec        pressure;           /* recovered pressure (global on dmC) */
  SPContactStats stats;
};

/* contact.c helpers shared by the contact files */
PETSC_EXTERN PetscErrorCode SPContactEvaluate(SPContact, Vec);
PETSC_EXTERN PetscErrorCode SPContactComputeStats(SPContact, const PetscScalar *);
PETSC_EXTERN PetscErrorCode SPContactComputeAreas(SPContact);
PETSC_EXTERN PetscErrorCode SPContactPointDofs(SPContact, PetscInt, PetscInt[]);
PETSC_EXTERN PetscErrorCode SPContactPointLaw(SPContact, PetscInt, const PetscScalar[], PetscReal, PetscReal[], PetscReal[]);
PETSC_EXTERN PetscErrorCode SPContactRecoverPressure(SPContact, const PetscScalar *);
PETSC_EXTERN PetscErrorCode SPOutputWriteXdmf(SPOutput);

/* fast-elastic.c: element-level isotropic linear elasticity on first-order cells */
struct _n_SPFastElastic {
  DM               dm; /* not owned */
  PetscInt         dim, nb, nq, nidx, cStart, cEnd; /* nb nodes per cell, nidx = nb dim */
  PetscQuadrature  quad;                            /* the FE's cell quadrature, not owned */
  const PetscReal *w;                               /* its weights */
  PetscReal       *dN;          /* reference gradients of the scalar basis, (q nb + a) dim + k */
  PetscInt        *gidx, *lidx; /* per cell: global (constrained < 0) and local closure indices */
  PetscReal       *xc;          /* per cell: node coordinates, closure order */
};

struct _n_SPSolver {
  DM                  dm;
  SPProblem           problem;
  SPContact           contact;
  SPLog              *log;
  SNES                snes;
  Mat                 J;
  Vec                 r;
  FILE               *history; /* CSV rows, rank 0 only; may be NULL */
  PetscInt            step;
  PetscInt            newtonTotal, linearTotal, lastLinear;
  PetscBool           reuse;  /* linear material: K assembled once, r(u) = r0(load) + K u */
  Mat                 K;
  Vec                 r0;
  SPFastElastic       fast;      /* NULL: the generic PetscFE bulk operator */
  PetscBool           checkFast; /* compare the fast and the generic operator once, print the differences */
  PetscReal           r0Load;
};

struct _n_SPOutput {
  DM          dm;  /* not owned */
  DM          dmV; /* vertex DM with dim dofs, for displacement */
  DM          dmS; /* vertex DM with 1 dof, for contact fields */
  char        dir[PETSC_MAX_PATH_LEN], name[PETSC_MAX_PATH_LEN], prefix[PETSC_MAX_PATH_LEN];
  PetscBool   enabled;
  PetscViewer h5;
  FILE       *csv;
  PetscInt    nsteps;
  PetscReal   times[1024];
  PetscBool   contactFields;
};

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
  PetscBool converged;
  PetscReal loadReached;
  PetscLogDouble t0;
};

#endif
