/* Tributary area of each contact point, A_i = sum over slave facets of int N_i dA (exact for
   segments and triangles, 2x2 Gauss for bilinear quadrilaterals), and the local facet size h_i
   used by eps = alpha E / h_i.  Facet contributions are summed across ranks through the
   contact-point layout, so a vertex on a partition boundary gets its full area exactly once. */
#include <spcontact-impl.h>

/* int N_a dA for the facet with nv vertices x (dim each), returned in w[]; measure in *meas */
static void FacetWeights(PetscInt dim, PetscInt nv, const PetscReal x[], PetscReal w[], PetscReal *meas)
{
  if (nv == 2) { /* segment (2D) */
    PetscReal d[2] = {x[2] - x[0], x[3] - x[1]};
    *meas = SPNorm(2, d);
    w[0] = w[1] = 0.5 * *meas;
  } else if (nv == 3) { /* triangle (3D) */
    PetscReal a[3], b[3], n[3];
    for (PetscInt d = 0; d < 3; ++d) a[d] = x[3 + d] - x[d], b[d] = x[6 + d] - x[d];
    n[0]  = a[1] * b[2] - a[2] * b[1];
    n[1]  = a[2] * b[0] - a[0] * b[2];
    n[2]  = a[0] * b[1] - a[1] * b[0];
    *meas = 0.5 * SPNorm(3, n);
    w[0] = w[1] = w[2] = *meas / 3.0;
  } else { /* bilinear quadrilateral (3D), vertices in cyclic order */
    const PetscReal xi[4] = {-1, 1, 1, -1}, eta[4] = {-1, -1, 1, 1}, gp = 1.0 / PetscSqrtReal(3.0);
    *meas = 0.0;
    for (PetscInt a = 0; a < 4; ++a) w[a] = 0.0;
    for (PetscInt q = 0; q < 4; ++q) {
      const PetscReal s = xi[q] * gp, t = eta[q] * gp;
      PetscReal       ds[3] = {0, 0, 0}, dt[3] = {0, 0, 0}, n[3], J;
      for (PetscInt a = 0; a < 4; ++a)
        for (PetscInt d = 0; d < 3; ++d) {
          ds[d] += 0.25 * xi[a] * (1 + t * eta[a]) * x[a * 3 + d];
          dt[d] += 0.25 * eta[a] * (1 + s * xi[a]) * x[a * 3 + d];
        }
      n[0] = ds[1] * dt[2] - ds[2] * dt[1];
      n[1] = ds[2] * dt[0] - ds[0] * dt[2];
      n[2] = ds[0] * dt[1] - ds[1] * dt[0];
      J    = SPNorm(3, n);
      *meas += J;
      for (PetscInt a = 0; a < 4; ++a) w[a] += 0.25 * (1 + s * xi[a]) * (1 + t * eta[a]) * J;
    }
  }
  (void)dim;
}

/* Vertices (in closure order) and coordinates of facet f */
PetscErrorCode SPContactFacetVertices(DM dm, PetscInt f, PetscInt *nv, PetscInt vert[], PetscReal x[])
{
  PetscInt          *cl = NULL, ncl, vStart, vEnd, dim;
  Vec                coords;
  PetscSection       cs;
  const PetscScalar *ca;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(VecGetArrayRead(coords, &ca));
  PetscCall(DMPlexGetTransitiveClosure(dm, f, PETSC_TRUE, &ncl, &cl));
  *nv = 0;
  for (PetscInt p = 0; p < 2 * ncl; p += 2) {
    PetscInt off;
    if (cl[p] < vStart || cl[p] >= vEnd) continue;
    PetscCheck(*nv < 4, PETSC_COMM_SELF, PETSC_ERR_SUP, "slave facet %" PetscInt_FMT " has more than 4 vertices", f);
    PetscCall(PetscSectionGetOffset(cs, cl[p], &off));
    vert[*nv] = cl[p];
    for (PetscInt d = 0; d < dim; ++d) x[*nv * dim + d] = PetscRealPart(ca[off + d]);
    (*nv)++;
  }
  PetscCall(DMPlexRestoreTransitiveClosure(dm, f, PETSC_TRUE, &ncl, &cl));
  PetscCall(VecRestoreArrayRead(coords, &ca));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The local facets of every slave surface (obstacle slaves and each pair's slave), each once */
static PetscErrorCode SlaveFacets(SPContact c, PetscInt *nf, PetscInt **facets)
{
  PetscInt  n = 0, *all = NULL;

  PetscFunctionBeginUser;
  for (PetscInt k = -1; k < c->npair; ++k) {
    PetscInt nk = 0, *fk = NULL, *tmp;
    if (k < 0 && !c->nob) continue;
    if (k < 0) PetscCall(SPMeshGetLabelFacets(c->dm, c->label, c->nvalues, c->values, &nk, &fk));
    else PetscCall(SPMeshGetLabelFacets(c->dm, c->pair[k].label, c->pair[k].nslave, c->pair[k].slave, &nk, &fk));
    PetscCall(PetscMalloc1(n + nk + 1, &tmp));
    if (n) PetscCall(PetscArraycpy(tmp, all, n));
    if (nk) PetscCall(PetscArraycpy(tmp + n, fk, nk));
    n += nk;
    PetscCall(PetscFree(all));
    PetscCall(PetscFree(fk));
    all = tmp;
  }
  PetscCall(PetscSortRemoveDupsInt(&n, all));
  *nf     = n;
  *facets = all;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Sum facet contributions into local vectors (area, facet measure, facet count, and the measure-
   weighted outward normal's components), then to owners */
static PetscErrorCode AccumulateFacets(SPContact c, Vec area, Vec meas, Vec count, Vec nrm[])
{
  PetscSection ls;
  PetscInt     nf = 0, *facets = NULL;
  Vec          la, lm, lc, ln[3];
  PetscScalar *pa, *pm, *pc, *pn[3];

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(c->dmC, &ls));
  PetscCall(DMGetLocalVector(c->dmC, &la));
  PetscCall(DMGetLocalVector(c->dmC, &lm));
  PetscCall(DMGetLocalVector(c->dmC, &lc));
  PetscCall(VecZeroEntries(la));
  PetscCall(VecZeroEntries(lm));
  PetscCall(VecZeroEntries(lc));
  PetscCall(VecGetArray(la, &pa));
  PetscCall(VecGetArray(lm, &pm));
  PetscCall(VecGetArray(lc, &pc));
  for (PetscInt d = 0; d < c->dim; ++d) {
    PetscCall(DMGetLocalVector(c->dmC, &ln[d]));
    PetscCall(VecZeroEntries(ln[d]));
    PetscCall(VecGetArray(ln[d], &pn[d]));
  }
  PetscCall(SlaveFacets(c, &nf, &facets));
  for (PetscInt k = 0; k < nf; ++k) {
    PetscInt  nv = 0, vert[4], off;
    PetscReal x[12], w[4], m, n[3] = {0, 0, 0}, xc[3], mf;
    PetscCall(SPContactFacetVertices(c->dm, facets[k], &nv, vert, x));
    PetscCall(SPMeshFacetGeometry(c->dm, c->dim, facets[k], n, xc, &mf));
    FacetWeights(c->dim, nv, x, w, &m);
    for (PetscInt a = 0; a < nv; ++a) {
      PetscCall(PetscSectionGetOffset(ls, vert[a], &off));
      pa[off] += w[a];
      pm[off] += m;
      pc[off] += 1.0;
      for (PetscInt d = 0; d < c->dim; ++d) pn[d][off] += m * n[d];
    }
  }
  PetscCall(PetscFree(facets));
  PetscCall(VecRestoreArray(la, &pa));
  PetscCall(VecRestoreArray(lm, &pm));
  PetscCall(VecRestoreArray(lc, &pc));
  PetscCall(VecZeroEntries(area));
  PetscCall(VecZeroEntries(meas));
  PetscCall(VecZeroEntries(count));
  PetscCall(DMLocalToGlobal(c->dmC, la, ADD_VALUES, area));
  PetscCall(DMLocalToGlobal(c->dmC, lm, ADD_VALUES, meas));
  PetscCall(DMLocalToGlobal(c->dmC, lc, ADD_VALUES, count));
  PetscCall(DMRestoreLocalVector(c->dmC, &la));
  PetscCall(DMRestoreLocalVector(c->dmC, &lm));
  PetscCall(DMRestoreLocalVector(c->dmC, &lc));
  for (PetscInt d = 0; d < c->dim; ++d) {
    PetscCall(VecRestoreArray(ln[d], &pn[d]));
    PetscCall(VecZeroEntries(nrm[d]));
    PetscCall(DMLocalToGlobal(c->dmC, ln[d], ADD_VALUES, nrm[d]));
    PetscCall(DMRestoreLocalVector(c->dmC, &ln[d]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Each point's unit normal into its own body (minus its facets' outward normals, summed): the
   direction of the force a point with no contact element of its own receives (a two-pass vertex
   that overhangs the other surface's end carries force only as a master) */
static PetscErrorCode SetInwardNormals(SPContact c, Vec nrm[])
{
  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < c->dim; ++d) {
    const PetscScalar *pv;
    PetscCall(VecGetArrayRead(nrm[d], &pv));
    for (PetscInt i = 0; i < c->n; ++i) c->pt[i].nIn[d] = -PetscRealPart(pv[i]);
    PetscCall(VecRestoreArrayRead(nrm[d], &pv));
  }
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscReal len = SPNorm(c->dim, c->pt[i].nIn);
    for (PetscInt d = 0; d < c->dim; ++d) c->pt[i].nIn[d] = len > 0.0 ? c->pt[i].nIn[d] / len : 0.0;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SPContactComputeAreas(SPContact c)
{
  Vec                area, meas, count, nrm[3];
  const PetscScalar *pa, *pm, *pc;
  PetscReal          E, range[2] = {PETSC_MIN_REAL, 0.0};

  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(c->dmC, &area));
  PetscCall(VecDuplicate(area, &meas));
  PetscCall(VecDuplicate(area, &count));
  for (PetscInt d = 0; d < c->dim; ++d) PetscCall(VecDuplicate(area, &nrm[d]));
  PetscCall(AccumulateFacets(c, area, meas, count, nrm));
  PetscCall(SetInwardNormals(c, nrm));
  for (PetscInt d = 0; d < c->dim; ++d) PetscCall(VecDestroy(&nrm[d]));
  PetscCall(VecGetArrayRead(area, &pa));
  PetscCall(VecGetArrayRead(meas, &pm));
  PetscCall(VecGetArrayRead(count, &pc));
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscReal h = PetscPowReal(PetscRealPart(pm[i] / pc[i]), 1.0 / (c->dim - 1));
    c->pt[i].area     = PetscRealPart(pa[i]);
    c->pt[i].h        = h;
    /* E of the material at the slave vertex: the largest E of the cells around it (one material:
       its E). The stiffer side governs the stiffness entries of the vertex, so eps stays alpha
       times the local stiffness scale, as with one material: not smaller (slow shift contraction,
       penalty penetration), and no larger than with the stiffer material alone (conditioning). */
    PetscCall(SPProblemGetVertexYoung(c->problem, c->pt[i].vertex, &E));
    c->pt[i].eps = c->penalty > 0.0 ? c->penalty : c->alpha * E / h;
    range[0]     = PetscMax(range[0], -c->pt[i].eps * h / E); /* -min and max of eps h / E */
    range[1]     = PetscMax(range[1], c->pt[i].eps * h / E);
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, range, 2, MPIU_REAL, MPIU_MAX, PetscObjectComm((PetscObject)c->dm)));
  c->alphaMax = range[1];
  PetscCheck(c->penalty <= 0.0 || range[1] == 0.0 || (-range[0] >= 1e-3 && range[1] <= 1e8), PetscObjectComm((PetscObject)c->dm), PETSC_ERR_USER_INPUT, "-contact_penalty %.6g: eps h / E is %.6g..%.6g at the contact points, outside 1e-3..1e8 (below, the penetration is of the order of the load over E; above, the Jacobian loses all digits); give -contact_alpha (eps = alpha E / h) instead", (double)c->penalty, (double)-range[0], (double)range[1]);
  PetscCall(VecRestoreArrayRead(area, &pa));
  PetscCall(VecRestoreArrayRead(meas, &pm));
  PetscCall(VecRestoreArrayRead(count, &pc));
  PetscCall(VecDestroy(&area));
  PetscCall(VecDestroy(&meas));
  PetscCall(VecDestroy(&count));
  PetscFunctionReturn(PETSC_SUCCESS);
}
