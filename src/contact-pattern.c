/* The Jacobian's nonzero pattern with the contact-pair couplings (slave vertex <-> master facet
   vertices, possibly on other ranks). DMCreateMatrix preallocates the bulk pattern only. Before
   each Jacobian assembly, SPContactSetUpJacobian checks that every active pair element's block is
   already in the pattern (each point remembers the global numbers of the master facets it was coupled to, with
   its friction anchor's facet: the friction element couples both); if any is
   missing on any rank, the pattern is rebuilt: a MATPREALLOCATOR receives the current pattern of P
   (row by row) plus the blocks of every current pair element (active or not, to anticipate), and
   MatPreallocatorPreallocate re-preallocates P in place and fills it with zeros. The pattern only
   grows (the solver then refills the bulk stiffness: solver-stiffness.c). No new-nonzero malloc ever
   happens during assembly (MAT_NEW_NONZERO_ALLOCATION_ERR stays on). */
#include <spcontact-impl.h>


/* Whether point i's element on master facet f with its friction anchor on facet a (a = f: the
   normal element alone) is in the pattern. The pair matters: the friction element couples the two
   facets' vertices, a block that neither facet's element alone holds. */
static PetscBool Known(SPContact c, PetscInt i, PetscInt f, PetscInt a)
{
  const PetscInt *k = &c->known[2 * i * SP_KNOWN_FACETS];
  for (PetscInt j = 0; j < SP_KNOWN_FACETS; ++j)
    if (k[2 * j] == f && k[2 * j + 1] == a) return PETSC_TRUE;
  return PETSC_FALSE;
}

static void Remember(SPContact c, PetscInt i, PetscInt f, PetscInt a)
{
  PetscInt *k = &c->known[2 * i * SP_KNOWN_FACETS];
  if (Known(c, i, f, a)) return;
  for (PetscInt j = SP_KNOWN_FACETS - 1; j > 0; --j) k[2 * j] = k[2 * (j - 1)], k[2 * j + 1] = k[2 * (j - 1) + 1]; /* forget the oldest: at worst a spurious rebuild */
  k[0] = f, k[1] = a;
}

/* P's pattern plus the blocks of every current pair element, into P (zero filled) */
static PetscErrorCode Rebuild(SPContact c, Mat P)
{
  Mat         pre;
  PetscInt    m, n, M, N, bs, rstart, rend, maxr = SP_FRIC_MAXD * SP_FRIC_MAXD;
  PetscScalar *zeros;

  PetscFunctionBeginUser;
  PetscCall(MatGetLocalSize(P, &m, &n));
  PetscCall(MatGetSize(P, &M, &N));
  PetscCall(MatGetBlockSize(P, &bs));
  PetscCall(MatGetOwnershipRange(P, &rstart, &rend));
  for (PetscInt r = rstart; r < rend; ++r) {
    PetscInt nc;
    PetscCall(MatGetRow(P, r, &nc, NULL, NULL));
    maxr = PetscMax(maxr, nc);
    PetscCall(MatRestoreRow(P, r, &nc, NULL, NULL));
  }
  PetscCall(PetscCalloc1(maxr, &zeros));
  PetscCall(MatCreate(PetscObjectComm((PetscObject)P), &pre));
  PetscCall(MatSetType(pre, MATPREALLOCATOR));
  PetscCall(MatSetSizes(pre, m, n, M, N));
  PetscCall(MatSetBlockSize(pre, bs));
  PetscCall(MatSetUp(pre));
  for (PetscInt r = rstart; r < rend; ++r) {
    PetscInt        nc;
    const PetscInt *cols;
    PetscCall(MatGetRow(P, r, &nc, &cols, NULL));
    PetscCall(MatSetValues(pre, 1, &r, nc, cols, zeros, INSERT_VALUES));
    PetscCall(MatRestoreRow(P, r, &nc, &cols, NULL));
  }
  for (PetscInt i = 0; i < c->n; ++i) {
    PetscInt  nd, dofs[SP_FRIC_MAXD];
    PetscReal A, Nv[SP_FRIC_MAXD], BT[2 * SP_FRIC_MAXD];
    if (c->pt[i].geo.elem < 0) continue;
    PetscCall(SPContactPointElement(c, i, &nd, dofs, &A, Nv, NULL));
    PetscCall(MatSetValues(pre, nd, dofs, nd, dofs, zeros, INSERT_VALUES));
    Remember(c, i, c->mf[c->pt[i].geo.elem].gid, c->mf[c->pt[i].geo.elem].gid);
    if (!c->friction || !c->pt[i].st.anchored || c->pt[i].st.anchor < 0) continue;
    PetscCall(SPFrictionElementDofs(c, i, &nd, dofs, Nv, BT, &A)); /* the anchor facet's block too, and the two facets' cross block */
    if (!nd) continue;
    PetscCall(MatSetValues(pre, nd, dofs, nd, dofs, zeros, INSERT_VALUES));
    Remember(c, i, c->mf[c->pt[i].geo.elem].gid, c->pt[i].st.anchor);
  }
  PetscCall(MatAssemblyBegin(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatPreallocatorPreallocate(pre, PETSC_TRUE, P));
  PetscCall(MatDestroy(&pre));
  PetscCall(PetscFree(zeros));
  c->rebuilds++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Before a Jacobian assembly at X: make P's pattern hold the pair couplings (P is zero filled if it grew) */
PetscErrorCode SPContactSetUpJacobian(SPContact c, Vec X, Mat P)
{
  PetscInt missing = 0, any;

  PetscFunctionBeginUser;
  if (!c || !c->enabled || !c->npair) PetscFunctionReturn(PETSC_SUCCESS);
  c->Jref = P;
  PetscCall(SPContactEvaluate(c, X));
  for (PetscInt i = 0; i < c->n && !missing; ++i) {
    const SPContactPoint *pt = &c->pt[i];
    if (pt->geo.elem < 0 || !SPContactPointActive(c, i)) continue;
    if (!Known(c, i, c->mf[pt->geo.elem].gid, c->mf[pt->geo.elem].gid)) missing = 1;
    if (c->friction && pt->geo.mu > 0.0 && pt->st.anchored && pt->st.anchor >= 0 && !pt->geo.anchorLost && !Known(c, i, c->mf[pt->geo.elem].gid, pt->st.anchor)) missing = 1;
  }
  PetscCallMPI(MPI_Allreduce(&missing, &any, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)P)));
  if (!any) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(Rebuild(c, P));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Mark (1 in the global vector mark) every row the contact Jacobian can touch: the slave
   vertices' dofs and the dofs of every master facet (friction anchors are master facets), each
   rank its owned facets, all of them: the facets it received are only those near its slave
   points now (the exchange's bounding-box filter), and a facet that comes near later may be
   one whose pattern is already in J (the point's known facets), so no growth of J would mark
   it (a body drifting over its master surface: "New nonzero ... caused a malloc" in the contact
   part C). Constrained dofs are negative and ignored. Collective. */
PetscErrorCode SPContactMarkRows(SPContact c, Vec mark)
{
  PetscFunctionBeginUser;
  if (c && c->enabled) {
    PetscScalar one[SP_FACET_MAXV * 3];
    for (PetscInt k = 0; k < SP_FACET_MAXV * 3; ++k) one[k] = 1.0;
    for (PetscInt i = 0; i < c->n; ++i) PetscCall(VecSetValues(mark, c->dim, c->pt[i].sdof, one, INSERT_VALUES));
    for (PetscInt f = 0; f < c->nmfOwned; ++f) PetscCall(VecSetValues(mark, c->own[f].nv * c->dim, c->own[f].dof, one, INSERT_VALUES));
  }
  PetscCall(VecAssemblyBegin(mark));
  PetscCall(VecAssemblyEnd(mark));
  PetscFunctionReturn(PETSC_SUCCESS);
}
