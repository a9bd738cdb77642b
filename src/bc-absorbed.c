/* A load that only a support feels: a component of a traction, pressure or force condition whose
   every facet has that component fixed by Dirichlet conditions is taken by the support's
   reaction and never reaches the body (a traction along x on the symmetry edge that -bc_0 holds
   in x left the solution unchanged to the last digit, without a word). Refused before the solve,
   per component: the part along a free component (a shear along a roller) stays allowed, and so
   does a load that only shares an edge or a vertex with a held face. */
#include <spcontact-impl.h>

/* Whether every dof point in facet f's closure has component d constrained (and there is one);
   a point's dofs are its nodes' dim components in turn */
static PetscErrorCode FacetHeld(DM dm, PetscSection ls, PetscInt dim, PetscInt f, PetscInt d, PetscBool *held)
{
  PetscInt *cl = NULL, ncl, withDofs = 0;

  PetscFunctionBeginUser;
  *held = PETSC_TRUE;
  PetscCall(DMPlexGetTransitiveClosure(dm, f, PETSC_TRUE, &ncl, &cl));
  for (PetscInt k = 0; k < ncl && *held; ++k) {
    const PetscInt *cind;
    PetscInt        dof, cdof, nheld = 0;
    PetscCall(PetscSectionGetDof(ls, cl[2 * k], &dof));
    if (dof <= 0) continue;
    withDofs++;
    PetscCall(PetscSectionGetConstraintDof(ls, cl[2 * k], &cdof));
    if (cdof > 0) PetscCall(PetscSectionGetConstraintIndices(ls, cl[2 * k], &cind));
    for (PetscInt j = 0; j < cdof; ++j) nheld += cind[j] % dim == d;
    *held = nheld == dof / dim ? PETSC_TRUE : PETSC_FALSE;
  }
  PetscCall(DMPlexRestoreTransitiveClosure(dm, f, PETSC_TRUE, &ncl, &cl));
  if (!withDofs) *held = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Condition bc's load magnitude per component over its facets (tot[d]) and the part on facets
   that hold component d (lost[d]), this rank's */
static PetscErrorCode Magnitudes(DM dm, PetscSection ls, PetscInt dim, const SPBC *bc, PetscReal tot[3], PetscReal lost[3])
{
  PetscInt n, *facets;

  PetscFunctionBeginUser;
  PetscCall(SPMeshGetLabelFacets(dm, bc->label, bc->nvalues, bc->values, &n, &facets));
  for (PetscInt k = 0; k < n; ++k) {
    PetscReal nf[3] = {0, 0, 0}, x[3] = {0, 0, 0}, area, p = bc->value[0];
    PetscCall(SPMeshFacetGeometry(dm, dim, facets[k], nf, x, &area));
    for (PetscInt d = 0; bc->type == SP_BC_PRESSURE && d < dim; ++d) p += bc->gradient[d] * x[d];
    for (PetscInt d = 0; d < dim; ++d) {
      const PetscReal f = PetscAbsReal(bc->type == SP_BC_PRESSURE ? p * nf[d] : bc->value[d]) * area;
      PetscBool       held;
      if (f == 0.0) continue;
      PetscCall(FacetHeld(dm, ls, dim, facets[k], d, &held));
      tot[d] += f;
      if (held) lost[d] += f;
    }
  }
  PetscCall(PetscFree(facets));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: one line if a Neumann condition's component acts only on held dofs */
PetscErrorCode SPBCCheckAbsorbed(DM dm, SPProblem p)
{
  MPI_Comm     comm = PetscObjectComm((PetscObject)dm);
  PetscSection ls;
  PetscReal    loc[6 * SP_MAX_BC], all[6 * SP_MAX_BC];

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm, &ls));
  PetscCall(PetscArrayzero(loc, 6 * SP_MAX_BC));
  for (PetscInt i = 0; i < p->nbc; ++i)
    if (p->bc[i].type != SP_BC_DIRICHLET) PetscCall(Magnitudes(dm, ls, p->dim, &p->bc[i], &loc[6 * i], &loc[6 * i + 3]));
  PetscCallMPI(MPI_Allreduce(loc, all, 6 * SP_MAX_BC, MPIU_REAL, MPI_SUM, comm));
  for (PetscInt i = 0; i < p->nbc; ++i) {
    const PetscReal *tot = &all[6 * i], *lost = &all[6 * i + 3];
    const PetscReal  sum = tot[0] + tot[1] + tot[2];
    for (PetscInt d = 0; d < p->dim; ++d)
      PetscCheck(!(tot[d] > 1e-8 * sum && lost[d] >= (1.0 - 1e-12) * tot[d]), comm, PETSC_ERR_USER_INPUT,
                 "-bc_%" PetscInt_FMT "_type %s: its %c component acts only where a Dirichlet condition fixes %c (on every facet of -bc_%" PetscInt_FMT "_values): the support takes it and the body never feels it. Drop that part of the load, or the Dirichlet condition on %c there",
                 i, SPBCTypes[p->bc[i].type], "xyz"[d], "xyz"[d], i, "xyz"[d]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
