/* Unit checks of the master-facet choice of a pair (SPContactPairsProject, src/contact-pairs.c):
   the nearest segment wins, and a point keeps the segment of the last Newton iterate near a
   vertex (the hysteresis of "Keeping the segment at a vertex" in the README).

   Geometry (2D, lengths times L): a convex master kink, segment 0 from (-1, -0.1) to the vertex
   V = (0, 0), segment 1 from V to (1, -0.1); a slave point P = V + (delta, -epsilon) just below V,
   h = 1. For epsilon = 1e-3 the point projects into both segments (segment 0 within 1 % of its
   end); its distances differ by about 0.2 delta: delta = 1e-4 gives 2e-5 (within the keep
   tolerance 1e-4 h), delta = 1e-3 gives 5.2e-4 (beyond it). A point whose kept segment went back
   to the one before it twice in the step (an oscillation about the vertex) keeps it within the
   wide band, 1e-2 h: delta = 1e-3 is kept then, delta = 2e-2 (2 % beyond the segment's end, past
   the end tolerance) not. Every case runs at L = 1 and
   L = 1e-3: the tolerances are relative to h.

   Exit code 0 when every case returns the expected segment. */
#include <spcontact-impl.h>

static const char help[] = "Unit checks of the pair segment choice and its hysteresis at a vertex (see the header of tests/unit/test-pairs.c)\n";

/* The two-segment master of the header at scale L, one slave point at V + L (delta, -epsilon)
   keeping facet `keep` (-1: none); returns the facet chosen (-1: no contact) */
static PetscErrorCode Choose(PetscReal L, PetscReal delta, PetscReal epsilon, PetscInt keep, PetscInt returns, PetscInt *facet)
{
  const PetscReal seg[2][4] = {{-1.0, -0.1, 0.0, 0.0}, {0.0, 0.0, 1.0, -0.1}};
  SPContact       c;
  PetscReal       xi[2], g, n[3];

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&c));
  c->dim = 2, c->nmf = 2, c->n = 1;
  PetscCall(PetscCalloc1(2, &c->mf));
  PetscCall(PetscCalloc1(1, &c->pt));
  for (PetscInt f = 0; f < 2; ++f) {
    SPMasterFacet *m = &c->mf[f];
    m->pair = 0, m->nv = 2, m->gid = f, m->sid = f;
    m->vid[0] = f, m->vid[1] = f + 1;
    m->cp[0] = m->cp[1] = -1;
    m->freeSide[0] = f == 0 ? PETSC_TRUE : PETSC_FALSE; /* the outer ends are free, V is shared */
    m->freeSide[1] = f == 1 ? PETSC_TRUE : PETSC_FALSE;
    for (PetscInt k = 0; k < 4; ++k) m->X[k] = m->x[k] = L * seg[f][k];
  }
  c->pt[0].pairMask  = 1;
  c->pt[0].h         = L;
  c->pt[0].keepFacet = keep;
  c->pt[0].facetReturns = returns;
  c->pt[0].geo.x[0]  = L * delta;
  c->pt[0].geo.x[1]  = -L * epsilon;
  PetscCall(SPContactPairsProject(c, 0, facet, xi, &g, n));
  if (*facet >= 0) *facet = c->mf[*facet].gid;
  PetscCall(PetscFree(c->pt));
  PetscCall(PetscFree(c->mf));
  PetscCall(PetscFree(c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Case(const char name[], PetscReal delta, PetscInt keep, PetscInt returns, PetscInt expect, PetscInt *nchecks, PetscInt *nfail)
{
  const PetscReal scales[2] = {1.0, 1e-3};

  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) {
    PetscInt got;
    PetscCall(Choose(scales[s], delta, 1e-3, keep, returns, &got));
    ++*nchecks;
    if (got != expect) ++*nfail;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%-44s L %-6g delta %-7g keep %2" PetscInt_FMT ": segment %2" PetscInt_FMT " (expected %" PetscInt_FMT ") %s\n", name, (double)scales[s], (double)delta, keep, got, expect, got == expect ? "ok" : "FAILED"));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The returns SPContactPairsKeepFacets counts over a sequence of evaluated facets (-1: open) */
static PetscErrorCode Returns(const char name[], const PetscInt seq[], PetscInt n, PetscInt expect, PetscInt *nchecks, PetscInt *nfail)
{
  SPContact c;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&c));
  c->dim = 2, c->nmf = 3, c->n = 1;
  PetscCall(PetscCalloc1(3, &c->mf));
  PetscCall(PetscCalloc1(1, &c->pt));
  for (PetscInt f = 0; f < 3; ++f) c->mf[f].gid = 10 + f;
  SPContactPairsForgetFacets(&c->pt[0]);
  for (PetscInt k = 0; k < n; ++k) {
    c->pt[0].geo.elem = seq[k];
    SPContactPairsKeepFacets(c);
  }
  ++*nchecks;
  if (c->pt[0].facetReturns != expect) ++*nfail;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%-44s returns %" PetscInt_FMT " (expected %" PetscInt_FMT ") %s\n", name, c->pt[0].facetReturns, expect, c->pt[0].facetReturns == expect ? "ok" : "FAILED"));
  PetscCall(PetscFree(c->pt));
  PetscCall(PetscFree(c->mf));
  PetscCall(PetscFree(c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscInt nchecks = 0, nfail = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(Case("nearest, nothing kept", 1e-4, -1, 0, 1, &nchecks, &nfail));
  PetscCall(Case("nearest, nothing kept (mirrored)", -1e-4, -1, 0, 0, &nchecks, &nfail));
  PetscCall(Case("kept: within 1e-4 h of the nearest", 1e-4, 0, 0, 0, &nchecks, &nfail));
  PetscCall(Case("kept: within 1e-4 h of the nearest (mirrored)", -1e-4, 1, 0, 1, &nchecks, &nfail));
  PetscCall(Case("kept: the nearest itself", 1e-4, 1, 0, 1, &nchecks, &nfail));
  PetscCall(Case("not kept: 5.2e-4 h farther than the nearest", 1e-3, 0, 0, 1, &nchecks, &nfail));
  PetscCall(Case("not kept: 2 % beyond its end, 0.019 h farther", 2e-2, 0, 0, 1, &nchecks, &nfail));
  PetscCall(Case("kept after 2 returns: 5.2e-4 h farther", 1e-3, 0, 2, 0, &nchecks, &nfail));
  PetscCall(Case("kept after 2 returns (mirrored)", -1e-3, 1, 2, 1, &nchecks, &nfail));
  PetscCall(Case("not kept after 1 return: 5.2e-4 h farther", 1e-3, 0, 1, 1, &nchecks, &nfail));
  PetscCall(Case("not kept after 2 returns: 2 % beyond its end", 2e-2, 0, 2, 1, &nchecks, &nfail));
  {
    const PetscInt cycle[] = {0, 1, 0, 1}, slide[] = {0, 1, 2, 2}, stay[] = {0, 0, 0, 0};
    PetscCall(Returns("returns: a 2-cycle 0 1 0 1", cycle, 4, 2, &nchecks, &nfail));
    PetscCall(Returns("returns: sliding over vertices 0 1 2 2", slide, 4, 0, &nchecks, &nfail));
    PetscCall(Returns("returns: one facet throughout", stay, 4, 0, &nchecks, &nfail));
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "test-pairs: %" PetscInt_FMT " checks, %" PetscInt_FMT " failed\n", nchecks, nfail));
  PetscCall(PetscFinalize());
  return nfail ? 1 : 0;
}
