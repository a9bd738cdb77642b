/* A rigid rotation that nothing holds. bc-balance.c refuses a free rigid translation; a body held
   against every translation can still turn: rollers whose fixed component lies along their face
   (u_x = 0 on the bottom y = 0 and u_y = 0 on the left x = 0 leave the rotation about the origin
   free, the roller's component swapped), or every Dirichlet condition on one line. The stiffness is
   then singular whatever the loads: the solve stalled into every cut-back (2D) or every linear
   solve failed (3D), exit 2 with no word of the cause.

   Each support is a row: a vertex's constrained component (the displacement section's
   constraints, as the solve sees them) or a slave vertex against a frictionless plane's normal
   (every slave vertex counted as touching, so this is a necessary condition: a rotation it finds
   free is free in every active set). A rigid mode u(y) = t + w x y, y = (X - centre) / size of
   the mesh's bounding box (so the test does not depend on the units), is held when some row
   moves it: the free modes are the kernel of G = sum over rows of phi phi^T, phi = (r, y x r)
   the row's work on the translations and rotations. Each vertex counts once, at its owner, so G
   is the same on any rank count. Checked in the cases of bc-balance.c's translation check, once
   the translations are held. */
#include <spcontact-impl.h>

/* G += phi phi^T for the support of direction r (unit) at the scaled position y */
void SPBCRigidAddRow(PetscInt dim, const PetscReal y[3], const PetscReal r[3], PetscReal G[][SP_RIGID_MAX])
{
  const PetscInt  m = dim * (dim + 1) / 2;
  const PetscReal rot[3] = {y[1] * r[2] - y[2] * r[1], y[2] * r[0] - y[0] * r[2], y[0] * r[1] - y[1] * r[0]};
  PetscReal       phi[SP_RIGID_MAX];

  for (PetscInt d = 0; d < dim; ++d) phi[d] = r[d];
  for (PetscInt j = 0; j < m - dim; ++j) phi[dim + j] = dim == 2 ? rot[2] : rot[j];
  for (PetscInt i = 0; i < m; ++i)
    for (PetscInt j = 0; j < m; ++j) G[i][j] += phi[i] * phi[j];
}

/* This rank's rows: its owned vertices' constrained components and, with planes, its contact points
   against every plane; each into G[g] of its vertex's group g = vgroup[v - vStart] (NULL: all in
   group 0; < 0: none), at its position scaled by the group's centre and size */
static PetscErrorCode AddSupports(DM dm, SPContact c, PetscBool planes, PetscInt dim, const PetscInt vgroup[], const PetscReal centre[][3], const PetscReal size[], PetscReal G[][SP_RIGID_MAX][SP_RIGID_MAX])
{
  PetscSection       ls, cs;
  PetscSF            sf;
  Vec                coords;
  const PetscScalar *x;
  const PetscInt    *leaves;
  PetscInt           vStart, vEnd, nleaves;
  PetscBool         *ghost;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm, &ls));
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, NULL, &nleaves, &leaves, NULL));
  PetscCall(PetscCalloc1(vEnd - vStart + 1, &ghost));
  for (PetscInt l = 0; l < (nleaves > 0 ? nleaves : 0); ++l) {
    const PetscInt p = leaves ? leaves[l] : l;
    if (p >= vStart && p < vEnd) ghost[p - vStart] = PETSC_TRUE;
  }
  PetscCall(VecGetArrayRead(coords, &x));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt        ncon = 0, off, g = vgroup ? vgroup[v - vStart] : 0;
    const PetscInt *cind = NULL;
    PetscReal       y[3] = {0, 0, 0};
    if (ghost[v - vStart] || g < 0) continue;
    PetscCall(PetscSectionGetConstraintDof(ls, v, &ncon));
    if (!ncon) continue;
    PetscCall(PetscSectionGetConstraintIndices(ls, v, &cind));
    PetscCall(PetscSectionGetOffset(cs, v, &off));
    for (PetscInt d = 0; d < dim; ++d) y[d] = (PetscRealPart(x[off + d]) - centre[g][d]) / size[g];
    for (PetscInt k = 0; k < ncon; ++k) {
      PetscReal e[3] = {0, 0, 0};
      if (cind[k] >= dim) continue;
      e[cind[k]] = 1.0;
      SPBCRigidAddRow(dim, y, e, G[g]);
    }
  }
  PetscCall(VecRestoreArrayRead(coords, &x));
  PetscCall(PetscFree(ghost));
  for (PetscInt i = 0; planes && c && c->enabled && i < c->n; ++i) {
    const PetscInt g = vgroup ? vgroup[c->pt[i].vertex - vStart] : 0;
    for (PetscInt k = 0; c->pt[i].onObstacle && g >= 0 && k < c->nob; ++k) { /* a pair's slave points hold nothing: their forces are internal */
      PetscReal y[3] = {0, 0, 0}, n[3] = {0, 0, 0}, len = 0.0;
      for (PetscInt d = 0; d < dim; ++d) y[d] = (c->pt[i].X[d] - centre[g][d]) / size[g], len += c->ob[k].normal[d] * c->ob[k].normal[d];
      for (PetscInt d = 0; d < dim; ++d) n[d] = c->ob[k].normal[d] / PetscSqrtReal(len);
      SPBCRigidAddRow(dim, y, n, G[g]);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: G[g] = the sum over every rank's rows of group g (ngroup groups; see AddSupports) */
PetscErrorCode SPBCRigidSupports(DM dm, SPContact c, PetscBool planes, const PetscInt vgroup[], PetscInt ngroup, const PetscReal centre[][3], const PetscReal size[], PetscReal G[][SP_RIGID_MAX][SP_RIGID_MAX])
{
  PetscReal(*loc)[SP_RIGID_MAX][SP_RIGID_MAX];
  PetscInt dim;

  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDim(dm, &dim));
  PetscCall(PetscCalloc1(ngroup, &loc));
  PetscCall(AddSupports(dm, c, planes, dim, vgroup, centre, size, loc));
  PetscCallMPI(MPI_Allreduce(&loc[0][0][0], &G[0][0][0], (PetscMPIInt)(ngroup * SP_RIGID_MAX * SP_RIGID_MAX), MPIU_REAL, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscCall(PetscFree(loc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Eigenvalues w[m] and eigenvectors (the columns of v) of the symmetric a[m][m], a overwritten:
   cyclic Jacobi, at most 50 sweeps (a 6 x 6 matrix needs about 10) */
static void Eigen(PetscInt m, PetscReal a[][SP_RIGID_MAX], PetscReal w[], PetscReal v[][SP_RIGID_MAX])
{
  for (PetscInt i = 0; i < m; ++i)
    for (PetscInt j = 0; j < m; ++j) v[i][j] = i == j ? 1.0 : 0.0;
  for (PetscInt sweep = 0; sweep < 50; ++sweep) {
    PetscReal off = 0.0, diag = 0.0;
    for (PetscInt i = 0; i < m; ++i) {
      diag += a[i][i] * a[i][i];
      for (PetscInt j = i + 1; j < m; ++j) off += a[i][j] * a[i][j];
    }
    if (off <= 1e-32 * diag) break;
    for (PetscInt p = 0; p < m; ++p)
      for (PetscInt q = p + 1; q < m; ++q) {
        PetscReal theta, t, cs, sn;
        if (a[p][q] == 0.0) continue;
        theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        t     = (theta >= 0.0 ? 1.0 : -1.0) / (PetscAbsReal(theta) + PetscSqrtReal(theta * theta + 1.0));
        cs    = 1.0 / PetscSqrtReal(t * t + 1.0);
        sn    = t * cs;
        for (PetscInt k = 0; k < m; ++k) { /* a J, then J^T a, then v J */
          const PetscReal akp = a[k][p], akq = a[k][q];
          a[k][p] = cs * akp - sn * akq, a[k][q] = sn * akp + cs * akq;
        }
        for (PetscInt k = 0; k < m; ++k) {
          const PetscReal apk = a[p][k], aqk = a[q][k];
          a[p][k] = cs * apk - sn * aqk, a[q][k] = sn * apk + cs * aqk;
        }
        for (PetscInt k = 0; k < m; ++k) {
          const PetscReal vkp = v[k][p], vkq = v[k][q];
          v[k][p] = cs * vkp - sn * vkq, v[k][q] = sn * vkp + cs * vkq;
        }
      }
  }
  for (PetscInt i = 0; i < m; ++i) w[i] = a[i][i];
}

/* The free mode shown: the projection onto the kernel (columns kern[nk] of v) of the rotation
   about the axis it moves most, so the choice does not depend on the kernel's basis */
static void ShownMode(PetscInt dim, PetscReal v[][SP_RIGID_MAX], const PetscInt kern[], PetscInt nk, PetscReal mode[])
{
  const PetscInt m = dim * (dim + 1) / 2;
  PetscReal      best = -1.0;

  for (PetscInt j = dim; j < m; ++j) {
    PetscReal proj[SP_RIGID_MAX] = {0, 0, 0, 0, 0, 0}, len = 0.0;
    for (PetscInt k = 0; k < nk; ++k)
      for (PetscInt i = 0; i < m; ++i) proj[i] += v[j][kern[k]] * v[i][kern[k]];
    for (PetscInt i = 0; i < m; ++i) len += proj[i] * proj[i];
    if (len <= best * (1.0 + 1e-8)) continue;
    best = len;
    for (PetscInt i = 0; i < m; ++i) mode[i] = proj[i] / PetscSqrtReal(len);
  }
}

/* A free rigid translation of G (rows of any group): *free, and its unit direction t (the
   translations' block G_tt is singular exactly when every row is normal to some t; or has an
   eigenvalue at most `floor`) */
static void FreeTranslation(PetscInt dim, PetscReal G[][SP_RIGID_MAX], PetscReal floor, PetscBool *free, PetscReal t[3])
{
  PetscReal a[SP_RIGID_MAX][SP_RIGID_MAX], w[SP_RIGID_MAX], v[SP_RIGID_MAX][SP_RIGID_MAX], wmax = 0.0;
  PetscInt  lo = 0;

  for (PetscInt i = 0; i < dim; ++i)
    for (PetscInt j = 0; j < dim; ++j) a[i][j] = G[i][j];
  Eigen(dim, a, w, v);
  for (PetscInt i = 0; i < dim; ++i) {
    wmax = PetscMax(wmax, w[i]);
    if (w[i] < w[lo]) lo = i;
  }
  *free = w[lo] <= PetscMax(1e-10 * wmax, floor) ? PETSC_TRUE : PETSC_FALSE;
  for (PetscInt d = 0; d < 3; ++d) t[d] = d < dim && PetscAbsReal(v[d][lo]) > 1e-10 ? v[d][lo] : 0.0;
}

/* The rigid modes G (a group's rows, positions scaled by centre and size) leaves free: *ntrans > 0
   with a free translation (its direction t), else *nfree the free rotations and one of them: its
   axis (3D; (0, 0, 1) in 2D) through point (in the mesh's units). Free: an eigenvalue of G at most
   1e-10 of its largest (singular in floating point) or at most `floor` (in units of one support
   at the scaled distance 1: nearly free, 0 for none) */
PetscErrorCode SPBCRigidKernel(PetscInt cdim, PetscReal G[][SP_RIGID_MAX], const PetscReal centre[3], PetscReal size, PetscReal floor, PetscBool *trans, PetscReal t[3], PetscInt *nfree, PetscReal axis[3], PetscReal point[3])
{
  const PetscInt m = cdim * (cdim + 1) / 2;
  PetscInt       kern[SP_RIGID_MAX], nk = 0;
  PetscReal      w[SP_RIGID_MAX], v[SP_RIGID_MAX][SP_RIGID_MAX], mode[SP_RIGID_MAX], wl = 0.0, wmax = 0.0;

  PetscFunctionBeginUser;
  *nfree = 0;
  FreeTranslation(cdim, G, floor, trans, t);
  if (*trans) PetscFunctionReturn(PETSC_SUCCESS);
  Eigen(m, G, w, v);
  for (PetscInt i = 0; i < m; ++i) wmax = PetscMax(wmax, w[i]);
  for (PetscInt i = 0; i < m; ++i)
    if (w[i] <= PetscMax(1e-10 * wmax, floor)) kern[nk++] = i;
  if (!nk) PetscFunctionReturn(PETSC_SUCCESS);
  ShownMode(cdim, v, kern, nk, mode);
  axis[0] = axis[1] = 0.0, axis[2] = 1.0;
  for (PetscInt j = 0; cdim == 3 && j < 3; ++j) axis[j] = mode[3 + j];
  for (PetscInt j = 0; j < 3; ++j) wl += axis[j] * axis[j];
  wl = cdim == 2 ? mode[2] : PetscSqrtReal(wl);
  if (wl < 1e-8) PetscFunctionReturn(PETSC_SUCCESS); /* a free translation, found above (not reached) */
  *nfree = nk;
  for (PetscInt j = 0; cdim == 3 && j < 3; ++j) axis[j] /= wl;
  { /* the axis point nearest the centre: y = w x t / |w|^2 (2D: (-t_y, t_x) / w) */
    const PetscReal *tr = mode, wz = cdim == 2 ? mode[2] : 0.0;
    PetscReal        y[3] = {0, 0, 0};
    if (cdim == 2) y[0] = -tr[1] / wz, y[1] = tr[0] / wz;
    else y[0] = (axis[1] * tr[2] - axis[2] * tr[1]) / wl, y[1] = (axis[2] * tr[0] - axis[0] * tr[2]) / wl, y[2] = (axis[0] * tr[1] - axis[1] * tr[0]) / wl;
    for (PetscInt d = 0; d < 3; ++d) {
      point[d] = d < cdim ? centre[d] + size * y[d] : 0.0;
      if (PetscAbsReal(point[d]) < 1e-10 * size) point[d] = 0.0;
      if (PetscAbsReal(axis[d]) < 1e-10) axis[d] = 0.0;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: whether the supports of the whole mesh leave a rigid rotation free (*nfree: how
   many independent ones), and one of them (SPBCRigidKernel); translations are checked before */
PetscErrorCode SPBCFreeRotation(DM dm, SPContact c, PetscInt *nfree, PetscReal axis[3], PetscReal point[3])
{
  PetscInt  cdim;
  PetscReal lo[3], hi[3], centre[1][3] = {{0, 0, 0}}, size[1] = {0.0}, G[1][SP_RIGID_MAX][SP_RIGID_MAX], t[3];
  PetscBool trans;

  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDim(dm, &cdim));
  PetscCall(DMGetBoundingBox(dm, lo, hi));
  for (PetscInt d = 0; d < cdim; ++d) centre[0][d] = 0.5 * (lo[d] + hi[d]), size[0] = PetscMax(size[0], hi[d] - lo[d]);
  PetscCall(SPBCRigidSupports(dm, c, PETSC_TRUE, NULL, 1, centre, size, G));
  PetscCall(SPBCRigidKernel(cdim, G[0], centre[0], size[0], 0.0, &trans, t, nfree, axis, point));
  PetscFunctionReturn(PETSC_SUCCESS);
}
