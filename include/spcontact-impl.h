/* spcontact: private struct layouts, included by src/ only. */
#ifndef SPCONTACT_IMPL_H
#define SPCONTACT_IMPL_H

#include <spcontact.h>
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
  PetscBool fastOperator; /* isotropic linear elasticity with param = (lambda, mu): the fast element
                             operator (fast-elastic.c) implements it and may replace PetscFE */
} SPMaterialLaw;
PETSC_EXTERN void           SPMaterialParameters_LinearElastic(PetscReal, PetscReal, PetscReal[]);
PETSC_EXTERN PetscErrorCode SPMaterialSetUp_LinearElastic(PetscDS, const PetscReal[], PetscScalar[]);

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

/* A contact pair: slave and master surfaces, label values of one label (contact-pairs.c) */
#define SP_MAX_PAIRS 8 /* user pairs per run (-contact_pair_0_.. ); -contact_two_pass mirrors them */
typedef struct {
  char      label[PETSC_MAX_PATH_LEN];
  PetscInt  nslave, slave[SP_MAX_VALUES], nmaster, master[SP_MAX_VALUES];
  PetscBool mirror; /* added by -contact_two_pass: the user pair with slave and master swapped */
} SPPair;

/* One master facet as every rank sees it after the exchange. The vertex order makes the facet
   normal point out of the master body (see kernels/contact-pair.h). */
#define SP_FACET_MAXV 4
typedef struct {
  PetscInt  pair, nv, gid;               /* gid: global facet number (owner rank's offset + index) */
  PetscInt  vid[SP_FACET_MAXV];         /* global vertex numbers (junctions, free ends) */
  PetscInt  cp[SP_FACET_MAXV];          /* global contact-point number of each vertex, -1 if none */
  PetscInt  dof[SP_FACET_MAXV * 3];     /* global displacement dofs; constrained: -(i+1) */
  PetscBool freeSide[SP_FACET_MAXV];    /* side s (2D: vertex s; 3D: edge s -> s+1) belongs to no other master facet of the pair */
  PetscReal X[SP_FACET_MAXV * 3];       /* reference coordinates */
  PetscReal x[SP_FACET_MAXV * 3];       /* deformed coordinates at the last evaluation */
} SPMasterFacet;

/* element kinds of a contact point (c->facet[i] >= 0: a master facet) */
#define SP_ELEM_NONE     (-2)
#define SP_ELEM_OBSTACLE (-1)
#define SP_KNOWN_FACETS  16
typedef enum { SP_TANGENT_AUTO, SP_TANGENT_FULL, SP_TANGENT_FROZEN } SPTangent; /* master facets per point remembered as being in the Jacobian pattern */

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
  PetscBool            safeguard, settled;
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
  /* contact pairs (contact-pairs.c); a point may be a slave of obstacles and of several pairs */
  PetscInt        npair, nuser; /* all pairs (mirrors included), user pairs */
  SPPair          pair[2 * SP_MAX_PAIRS];
  PetscBool       twoPass;
  SPTangent       tangent;
  PetscLogEvent   searchEvent; /* SPContactSearch: gaps, projections and the master exchange */
  PetscBool       setSettled; /* the last Newton iteration of this solve left the active set unchanged */
  PetscInt        nmfAll, mfStart, nmfOwned; /* master facets: global count, this rank's first gid and count */
  SPMasterFacet  *own;             /* this rank's owned master facets */
  PetscInt       *mfVert;          /* owned master facets: local plex vertices, SP_FACET_MAXV each */
  PetscInt        nmf, mfCap;      /* received master facets (from every rank, this one included) */
  SPMasterFacet  *mf;
  PetscBool       exchangeAll;     /* -contact_pair_exchange all: no bounding-box filter */
  PetscReal       margin;          /* bounding boxes are inflated by this (2 x the largest facet size) */
  PetscLogDouble  exchangeTime;
  PetscInt        exchanges, rebuilds;
  PetscInt64      received;        /* facets received, summed over exchanges and ranks */
  PetscInt       *sdof;            /* per point: dim global dofs of the slave vertex */
  PetscInt       *pairMask;        /* per point: bit k set = slave of pair k */
  PetscBool      *onObstacle, *primary; /* slave of the obstacles; counts in the force */
  PetscInt       *facet;           /* per point: master facet, SP_ELEM_OBSTACLE or SP_ELEM_NONE */
  PetscReal      *xi, *xs;         /* projection parameters (2 per point; 2D uses the first), deformed slave position (dim) */
  PetscReal      *press, *fpt;     /* recovered pressure, nodal contact force (dim) */
  PetscInt       *known;           /* per point: master facets already in the Jacobian pattern */
  Vec             Fc, fvec;        /* global contact residual; nodal forces at contact points */
  Mat             Jref;            /* last Jacobian whose pattern was extended (not owned) */
  Vec        shift, shiftSaved;  /* global vectors on dmC */
  Vec        pressure;           /* recovered pressure (global on dmC) */
  SPContactStats stats;
};

/* contact.c helpers shared by the contact files */
PETSC_EXTERN PetscErrorCode SPContactEvaluate(SPContact, Vec);
PETSC_EXTERN PetscErrorCode SPContactComputeStats(SPContact, const PetscScalar *);
PETSC_EXTERN PetscErrorCode SPContactComputeAreas(SPContact);
PETSC_EXTERN PetscErrorCode SPContactPointDofs(SPContact, PetscInt, PetscInt[]);
PETSC_EXTERN PetscErrorCode SPContactRecoverForces(SPContact, const PetscScalar *);
PETSC_EXTERN PetscErrorCode SPContactPointElement(SPContact, PetscInt, PetscInt *, PetscInt[], PetscReal *, PetscReal *, PetscReal[], PetscReal[]);
PETSC_EXTERN PetscErrorCode SPContactFacetVertices(DM, PetscInt, PetscInt *, PetscInt[], PetscReal[]);
/* contact-pairs.c */
PETSC_EXTERN PetscErrorCode SPContactPairsSetFromOptions(SPContact);
PETSC_EXTERN PetscErrorCode SPContactPairsCheckLabels(SPContact);
PETSC_EXTERN PetscErrorCode SPContactPairsSetUp(SPContact);
PETSC_EXTERN PetscErrorCode SPContactPairsExchange(SPContact, const PetscScalar[]);
PETSC_EXTERN PetscErrorCode SPContactPairsProject(SPContact, PetscInt, PetscInt *, PetscReal *, PetscReal *, PetscReal[]);
PETSC_EXTERN PetscErrorCode SPContactPairsDestroy(SPContact);
PETSC_EXTERN PetscBool      SPContactGeometricTangent(SPContact);
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
  const PetscReal *lame;        /* per cell: lambda, mu (the problem's per-cell parameters, not owned) */
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
