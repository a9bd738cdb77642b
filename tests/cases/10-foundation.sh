# Foundation cases (elasticity only, no contact): manufactured-solution convergence rates,
# Jacobian checks, closed-form elasticity, parallel invariance, HDF5/XDMF output, bad input.
# Run: bash tests/run.sh foundation   (or a single case: bash tests/run.sh foundation_mms_q1_2d)
# Every helper here is prefixed fnd_ so it cannot collide with other case files.

# Open MPI busy-polls while waiting; on a machine with as many cores as ranks and any other load
# that makes a 1-second run take 10 s or more. Yielding costs nothing measurable here.
fnd_setup() {
  export OMPI_MCA_mpi_yield_when_idle=${OMPI_MCA_mpi_yield_when_idle:-1}
}

# fnd_gmsh_geo DIM N FILE S: the unit square (DIM 2), or the cube extruded from it (DIM 3)
fnd_gmsh_geo() {
  local dim=$1 n=$2 out=$3 s=$4 geo=${3%.msh}.geo
  cat >"$geo" <<'EOF'
If (!Exists(N)) N = 4; EndIf
If (!Exists(S)) S = 1; EndIf
Point(1) = {0, 0, 0, 1.0 / N}; Point(2) = {1, 0, 0, 1.0 / N};
Point(3) = {1, 1, 0, 1.0 / N}; Point(4) = {0, 1, 0, 1.0 / N};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
If (S)
  Transfinite Curve{1, 2, 3, 4} = N + 1; Transfinite Surface{1};
EndIf
If (D == 2)
  Physical Curve(1) = {1}; Physical Curve(2) = {2}; Physical Curve(3) = {3}; Physical Curve(4) = {4};
  Physical Surface(10) = {1};
Else
  If (S)
    out[] = Extrude {0, 0, 1} { Surface{1}; Layers{N}; };
  Else
    out[] = Extrude {0, 0, 1} { Surface{1}; };
  EndIf
  // out[0] top z=1, out[1] volume, out[2..5] sides extruded from lines 1..4 (y=0, x=1, y=1, x=0)
  Physical Surface(1) = {1}; Physical Surface(2) = {out[0]}; Physical Surface(3) = {out[2]};
  Physical Surface(4) = {out[4]}; Physical Surface(5) = {out[3]}; Physical Surface(6) = {out[5]};
  Physical Volume(10) = {out[1]};
EndIf
EOF
  gmsh -v 2 -"$dim" -format msh22 -setnumber D "$dim" -setnumber N "$n" -setnumber S "$s" -o "$out" "$geo" >/dev/null ||
    { echo "gmsh failed on $geo (is gmsh installed?)"; return 1; }
}

# fnd_gmsh_square N FILE [S]: unit square, N x N edges, structured triangles (S=1, default) or an
# unstructured triangulation (S=0). Physical curves numbered like the PETSc box "Face Sets":
# 1 bottom y=0, 2 right x=1, 3 top y=1, 4 left x=0; surface 10.
fnd_gmsh_square() { fnd_gmsh_geo 2 "$1" "$2" "${3:-1}"; }

# fnd_gmsh_cube N FILE [S]: unit cube of tetrahedra, N edges per side (S=1: structured, extruded
# layers split into tets; S=0: unstructured). Physical surfaces numbered like the PETSc 3D box:
# 1 z=0, 2 z=1, 3 y=0, 4 y=1, 5 x=1, 6 x=0; volume 10.
fnd_gmsh_cube() { fnd_gmsh_geo 3 "$1" "$2" "${3:-1}"; }

FND_MMS2D="-bc_0_type dirichlet -bc_0_values 1,2,3,4 -material_mms 0.01"
FND_MMS3D="-bc_0_type dirichlet -bc_0_values 1,2,3,4,5,6 -material_mms 0.01"

# fnd_mms LABEL NP RATE_LO RATE_HI MESHARGS1 MESHARGS2 MESHARGS3 [...] -- COMMON ARGS
# Runs the manufactured solution on successively halved meshes (each MESHARGS one word list,
# quoted), prints every L2 error and observed rate log2(e_{k-1}/e_k), and asserts: every run
# converged, the error decreases, and the finest rate lies in [RATE_LO, RATE_HI].
fnd_mms() {
  local label=$1 np=$2 lo=$3 hi=$4 rc=0 k=0 prev="" rate=""; shift 4
  local meshes=()
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do meshes+=("$1"); shift; done
  [ "$1" = "--" ] && shift
  for m in "${meshes[@]}"; do
    k=$((k + 1))
    local out="$CASE_DIR/$label.$k.out"
    # shellcheck disable=SC2086
    spc "$out" "$np" $m "$@" -output_dir "$CASE_DIR" -output_name "$label.$k" ||
      { echo "$label level $k: spcontact exited with $? ($m)"; tail -n 5 "$out"; return 1; }
    local err cells conv
    err=$(sval "$out" l2_error); cells=$(sval "$out" cells); conv=$(sval "$out" converged)
    assert_eq "$label level $k converged" "$conv" yes || rc=1
    assert_ge "$label level $k l2_error is printed" "${err:--1}" 0 || rc=1
    if [ -n "$prev" ]; then
      rate=$(awk -v a="$prev" -v b="$err" 'BEGIN{ if (a > 0 && b > 0) printf "%.4f", log(a / b) / log(2); else print "nan" }')
      echo "$label level $k: cells $cells l2_error $err rate $rate"
      assert_le "$label level $k error decreases" "$err" "$prev" || rc=1
    else
      echo "$label level $k: cells $cells l2_error $err"
    fi
    prev=$err
  done
  [ "$k" -ge 3 ] || { echo "$label: need at least three refinements"; return 1; }
  assert_ge "$label finest rate" "$rate" "$lo" || rc=1
  assert_le "$label finest rate" "$rate" "$hi" || rc=1
  return $rc
}

fnd_box2() { echo "-dm_plex_dim 2 -dm_plex_simplex 0 -dm_plex_box_faces $1,$1"; }
fnd_box3() { echo "-dm_plex_dim 3 -dm_plex_simplex 0 -dm_plex_box_faces $1,$1,$1"; }

# Three mesh levels in FND_LEVELS: a box of N cells per side refined 0, 1, 2 times (-dm_refine
# refines the serial mesh, labels carried over), or gmsh simplex meshes with 4, 8, 16 per side.
fnd_levels_box() { local b; b=$(fnd_box"$1" "$2"); FND_LEVELS=("$b" "$b -dm_refine 1" "$b -dm_refine 2"); }
fnd_levels_gmsh() { # square|cube
  FND_LEVELS=()
  for n in 4 8 16; do
    fnd_gmsh_"$1" $n "$CASE_DIR/$1$n.msh" || return 1
    FND_LEVELS+=("-mesh_file $CASE_DIR/$1$n.msh")
  done
}

# --- manufactured solutions: u = A prod sin(pi x_d) (c+1), homogeneous Dirichlet on every face ---
# fnd_mms_case LABEL NP RATE_LO RATE_HI DEGREE DIM [ARGS...]: on the levels in FND_LEVELS
fnd_mms_case() {
  local mms=$FND_MMS2D; [ "$6" = 3 ] && mms=$FND_MMS3D
  # shellcheck disable=SC2086
  fnd_mms "$1" "$2" "$3" "$4" "${FND_LEVELS[@]}" -- $mms -petscspace_degree "$5" "${@:7}"
}

test_foundation_mms_p1_2d() { fnd_setup; fnd_levels_gmsh square || return 1; fnd_mms_case mms_p1_2d 1 1.8 2.3 1 2; }
test_foundation_mms_q1_2d() { fnd_setup; fnd_levels_box 2 4; fnd_mms_case mms_q1_2d 1 1.8 2.3 1 2; }
test_foundation_mms_p2_2d() { fnd_setup; fnd_levels_gmsh square || return 1; fnd_mms_case mms_p2_2d 1 2.7 3.4 2 2; }
test_foundation_mms_q2_2d() { fnd_setup; fnd_levels_box 2 4; fnd_mms_case mms_q2_2d 1 2.7 3.4 2 2; }
test_foundation_mms_q1_3d() { fnd_setup; fnd_levels_box 3 2; fnd_mms_case mms_q1_3d 2 1.8 2.3 1 3; }
# P1 tetrahedra are pre-asymptotic on 2-8 (rate 1.75), so 4, 8, 16 (the finest has 24576 cells)
test_foundation_mms_p1_3d() { fnd_setup; fnd_levels_gmsh cube || return 1; fnd_mms_case mms_p1_3d 2 1.8 2.3 1 3; }
# Q2 hexahedra: 1, 2, 4 cells per side on 1 rank (a 1-cell mesh cannot go on 2 ranks; 8^3 Q2
# takes ~20 s, too slow for this suite)
test_foundation_mms_q2_3d() { fnd_setup; fnd_levels_box 3 1; fnd_mms_case mms_q2_3d 1 2.7 3.4 2 3; }

# --- hand-coded Jacobian against finite differences (PETSc -snes_test_jacobian) ---
# fnd_jacobian LABEL NP ARGS... : asserts every ||J - Jfd||_F/||J||_F printed is < 1e-6
fnd_jacobian() {
  local label=$1 np=$2; shift 2
  local out="$CASE_DIR/$label.out"
  spc "$out" "$np" "$@" -snes_test_jacobian -output_dir "$CASE_DIR" -output_name "$label" ||
    { echo "$label: spcontact exited with $?"; tail -n 5 "$out"; return 1; }
  local ratios n max
  ratios=$(sed -n 's/.*||J - Jfd||_F\/||J||_F = \([^,]*\),.*/\1/p' "$out")
  n=$(echo "$ratios" | grep -c .)
  echo "$label: $n Jacobian test(s), ratios: $(echo $ratios)"
  [ "$n" -ge 1 ] || { echo "$label: no '||J - Jfd||_F/||J||_F' line in the output FAILED"; return 1; }
  max=$(echo "$ratios" | awk 'BEGIN{m=0} {v=$1+0; if (v>m) m=v} END{printf "%.6g", m}')
  assert_le "$label max ||J - Jfd||_F/||J||_F" "$max" 1e-6
}

test_foundation_jacobian_2d() {
  fnd_setup
  local rc=0 loads="-bc_0_type dirichlet -bc_0_values 1 -bc_1_type traction -bc_1_values 2 -bc_1_value 0.1,0.05 -bc_2_type pressure -bc_2_values 3 -bc_2_value 0.02 -material_E 3 -material_nu 0.35"
  fnd_jacobian jac_q1_2d 1 $(fnd_box2 4) $loads || rc=1
  fnd_gmsh_square 4 "$CASE_DIR/sq4u.msh" 0 || return 1
  fnd_jacobian jac_p2_2d 2 -mesh_file "$CASE_DIR/sq4u.msh" -petscspace_degree 2 $loads || rc=1
  fnd_jacobian jac_q1_2d_mms 1 $(fnd_box2 4) $FND_MMS2D || rc=1
  return $rc
}

test_foundation_jacobian_3d() {
  fnd_setup
  local rc=0 loads="-bc_0_type dirichlet -bc_0_values 1 -bc_1_type traction -bc_1_values 5 -bc_1_value 0.1,0.05,-0.02 -bc_2_type pressure -bc_2_values 2 -bc_2_value 0.02 -material_E 3 -material_nu 0.35"
  fnd_jacobian jac_q1_3d 2 $(fnd_box3 3) $loads || rc=1
  fnd_gmsh_cube 2 "$CASE_DIR/cube2u.msh" 0 || return 1
  fnd_jacobian jac_p1_3d 2 -mesh_file "$CASE_DIR/cube2u.msh" $loads || rc=1
  return $rc
}

# --- closed-form elasticity: uniform biaxial stress (input/elastic{2,3}d.opts), u linear ---
# fnd_h5_linear H5 DIM STEPSCALES EPS... : every vertex value of every step k equals
# scale_k * eps_d * x_d (checks values and their parallel ordering against /geometry/vertices)
fnd_h5_linear() {
  "$PYTHON" - "$@" <<'EOF'
import sys, h5py, numpy as np
h5, dim, scales, eps = sys.argv[1], int(sys.argv[2]), [float(s) for s in sys.argv[3].split(",")], np.array([float(e) for e in sys.argv[4:]])
with h5py.File(h5, "r") as f:
    x = f["/geometry/vertices"][()]
    u = f["/vertex_fields/displacement_Field_0"][()]
ok = u.shape == (len(scales), x.shape[0], dim)
print("h5 displacement shape %s, expected %s %s" % (u.shape, (len(scales), x.shape[0], dim), "ok" if ok else "FAILED"))
if not ok: sys.exit(1)
worst = 0.0
for k, s in enumerate(scales):
    err = np.abs(u[k] - s * x[:, :dim] * eps).max() / (np.abs(eps).max() * max(s, 1e-300))
    worst = max(worst, err)
    print("step %d (load %g): max |u - u_exact| / (load max|eps|) = %.3e" % (k, s, err))
ok = worst < 1e-8
print("vertex values match the closed form to 1e-8: %s" % ("ok" if ok else "FAILED"))
sys.exit(0 if ok else 1)
EOF
}

# fnd_analytic_variants DIM UMAX EPS... -- NAME:NP:EXTRA...: input/elastic{DIM}d.opts with each
# variant's extra options on NP ranks; converged, displacement_max and every vertex value exact
fnd_analytic_variants() {
  local dim=$1 umax=$2 rc=0 eps=() out v; shift 2
  while [ "$1" != "--" ]; do eps+=("$1"); shift; done
  shift
  for v in "$@"; do
    local name=${v%%:*} rest=${v#*:}; local np=${rest%%:*} extra=${rest#*:}
    out="$CASE_DIR/an${dim}d_$name.out"
    # shellcheck disable=SC2086
    spc "$out" "$np" -options_file input/elastic${dim}d.opts $extra -output_dir "$CASE_DIR" -output_name "an${dim}d_$name" ||
      { echo "analytic ${dim}d $name: spcontact exited with $?"; tail -n 5 "$out"; rc=1; continue; }
    assert_eq "analytic ${dim}d $name converged" "$(sval "$out" converged)" yes || rc=1
    assert_close "analytic ${dim}d $name displacement_max" "$(sval "$out" displacement_max)" "$umax" 1e-8 || rc=1
    fnd_h5_linear "$CASE_DIR/an${dim}d_$name.h5" "$dim" 1 "${eps[@]}" || rc=1
  done
  return $rc
}

test_foundation_analytic_2d() {
  fnd_setup
  local rc=0 nu=0.3 E=1000 s=1 p=2 exx eyy umax
  exx=$(awk -v nu=$nu -v E=$E -v s=$s -v p=$p 'BEGIN{printf "%.17g", ((1-nu*nu)*s + nu*(1+nu)*p)/E}')
  eyy=$(awk -v nu=$nu -v E=$E -v s=$s -v p=$p 'BEGIN{printf "%.17g", (-(1-nu*nu)*p - nu*(1+nu)*s)/E}')
  umax=$(awk -v a=$exx -v b=$eyy 'BEGIN{a = (a < 0) ? -a : a; b = (b < 0) ? -b : b; m = (a > b) ? a : b; printf "%.17g", m}')
  echo "closed form (plane strain): eps_xx $exx eps_yy $eyy displacement_max $umax"
  # Q1 box (the .opts file as is), Q2 box, P1 and P2 on an unstructured gmsh triangulation
  fnd_gmsh_square 6 "$CASE_DIR/sq6u.msh" 0 || return 1
  local variants=("q1:1:" "q2:2:-petscspace_degree 2" "p1u:2:-mesh_file $CASE_DIR/sq6u.msh" "p2u:3:-mesh_file $CASE_DIR/sq6u.msh -petscspace_degree 2")
  fnd_analytic_variants 2 "$umax" "$exx" "$eyy" -- "${variants[@]}" || rc=1
  return $rc
}

test_foundation_analytic_3d() {
  fnd_setup
  local rc=0 nu=0.3 E=1000 s=1 p=2 exx eyy ezz umax
  exx=$(awk -v nu=$nu -v E=$E -v s=$s -v p=$p 'BEGIN{printf "%.17g", (s + nu*p)/E}')
  eyy=$(awk -v nu=$nu -v E=$E -v s=$s -v p=$p 'BEGIN{printf "%.17g", -nu*(s - p)/E}')
  ezz=$(awk -v nu=$nu -v E=$E -v s=$s -v p=$p 'BEGIN{printf "%.17g", (-p - nu*s)/E}')
  umax=$(awk -v a=$exx -v b=$eyy -v c=$ezz 'BEGIN{a = (a < 0) ? -a : a; b = (b < 0) ? -b : b; c = (c < 0) ? -c : c; m = (a > b) ? a : b; m = (m > c) ? m : c; printf "%.17g", m}')
  echo "closed form: eps_xx $exx eps_yy $eyy eps_zz $ezz displacement_max $umax"
  fnd_gmsh_cube 3 "$CASE_DIR/cube3u.msh" 0 || return 1
  local variants=("q1:2:" "p1u:3:-mesh_file $CASE_DIR/cube3u.msh")
  fnd_analytic_variants 3 "$umax" "$exx" "$eyy" "$ezz" -- "${variants[@]}" || rc=1
  return $rc
}

# --- parallel invariance: same figures on 1, 2, 3 ranks and with other partitioners ---
test_foundation_parallel_invariance() {
  fnd_setup
  local rc=0 keys="displacement_max dofs cells vertices"
  local msh=build/mesh/hertz2d.msh
  [ -f "$msh" ] || { echo "$msh missing: run make (it builds input/*.geo with gmsh)"; return 1; }
  # hertz2d quarter disc as a plain elastic body: symmetry u_x = 0 on x = 0 (1), arc clamped (3),
  # pressure on the top (2); unstructured triangles, 9576 cells
  local A="-mesh_file $msh -bc_0_type dirichlet -bc_0_values 1 -bc_0_components 0 -bc_1_type dirichlet -bc_1_values 3 -bc_2_type pressure -bc_2_values 2 -bc_2_value 0.01"
  local runs=("np1:1:" "np2:2:" "np3:3:" "np2_ptscotch:2:-mesh_partitioner ptscotch" "np3_simple:3:-mesh_partitioner simple")
  for r in "${runs[@]}"; do
    local name=${r%%:*} rest=${r#*:}; local np=${rest%%:*} extra=${rest#*:}
    # shellcheck disable=SC2086
    spc "$CASE_DIR/h2d_$name.out" "$np" $A $extra -output_dir "$CASE_DIR" -output_name "h2d_$name" ||
      { echo "hertz2d elastic $name: spcontact exited with $?"; tail -n 5 "$CASE_DIR/h2d_$name.out"; rc=1; continue; }
    echo "hertz2d elastic $name: ranks $(sval "$CASE_DIR/h2d_$name.out" ranks) displacement_max $(sval "$CASE_DIR/h2d_$name.out" displacement_max) linear_iterations $(sval "$CASE_DIR/h2d_$name.out" linear_iterations)"
    [ "$name" = np1 ] && continue
    echo "-- $name vs np1:"
    same_summary "$CASE_DIR/h2d_np1.out" "$CASE_DIR/h2d_$name.out" 1e-8 $keys || rc=1
  done
  # 3D hex box, bottom clamped, oblique traction on the top: a non-uniform 3D state, Q2
  local B="$(fnd_box3 4) -petscspace_degree 2 -bc_0_type dirichlet -bc_0_values 1 -bc_1_type traction -bc_1_values 2 -bc_1_value 0.1,0.05,-0.2"
  for np in 1 3; do
    spc "$CASE_DIR/box3_np$np.out" $np $B -output_dir "$CASE_DIR" -output_name "box3_np$np" ||
      { echo "fnd_box3 np$np: spcontact exited with $?"; tail -n 5 "$CASE_DIR/box3_np$np.out"; rc=1; }
  done
  echo "box3 Q2 np1 displacement_max $(sval "$CASE_DIR/box3_np1.out" displacement_max); -- np3 vs np1:"
  same_summary "$CASE_DIR/box3_np1.out" "$CASE_DIR/box3_np3.out" 1e-8 $keys || rc=1
  # empty ranks: 2 cells on 3 ranks with the simple partitioner (METIS refuses more ranks than
  # cells; the others leave a rank empty, which must still give the serial answer and valid output)
  local C="-dm_plex_dim 2 -dm_plex_simplex 0 -dm_plex_box_faces 2,1 -bc_0_type dirichlet -bc_0_values 4 -bc_1_type traction -bc_1_values 2 -bc_1_value 0.1,0.02"
  spc "$CASE_DIR/tiny_np1.out" 1 $C -output_dir "$CASE_DIR" -output_name tiny_np1 || { echo "tiny np1: exit $?"; rc=1; }
  spc "$CASE_DIR/tiny_np3.out" 3 $C -mesh_partitioner simple -output_dir "$CASE_DIR" -output_name tiny_np3 || { echo "tiny np3 simple: exit $?"; rc=1; }
  echo "2 cells, np1 displacement_max $(sval "$CASE_DIR/tiny_np1.out" displacement_max); -- np3 (simple, one rank empty) vs np1:"
  same_summary "$CASE_DIR/tiny_np1.out" "$CASE_DIR/tiny_np3.out" 1e-8 $keys || rc=1
  "$PYTHON" scripts/check_xdmf.py "$CASE_DIR/tiny_np3.xmf" >"$CASE_DIR/tiny_np3.check_xdmf.txt" 2>&1
  assert_eq "check_xdmf.py tiny_np3.xmf exit code" "$?" 0 || { grep -v '^ok' "$CASE_DIR/tiny_np3.check_xdmf.txt"; rc=1; }
  return $rc
}

# A rank without cells on a simplex mesh: METIS puts both triangles of a unit square on rank 1
# of 2. PETSc's simplex test is per rank (a rank with no cell says "tensor"), so rank 0 built a Q1
# field beside rank 1's P1, their PETSc objects stopped matching, and the run hung after step 1
# in the restart writer. Square [0,1]^2 on the rigid plane y = 0, u_x = 0 on both sides, pressure
# q on the top: uniaxial strain, exact in P1, |u|max = q (1+nu)(1-2nu)/((1-nu) E), contact force q.
test_foundation_empty_rank_simplex() {
  fnd_setup
  local rc=0 q=0.01 nu=0.3 ref
  printf '%s\n' '$MeshFormat' '2.2 0 8' '$EndMeshFormat' '$Nodes' 4 '1 0 0 0' '2 1 0 0' '3 1 1 0' '4 0 1 0' \
    '$EndNodes' '$Elements' 6 '1 1 2 1 1 1 2' '2 1 2 2 2 3 4' '3 1 2 3 3 4 1' '4 1 2 3 3 2 3' \
    '5 2 2 10 1 1 2 3' '6 2 2 10 1 1 3 4' '$EndElements' >"$CASE_DIR/square2.msh"
  local A="-mesh_file $CASE_DIR/square2.msh -material_nu $nu -bc_0_type dirichlet -bc_0_values 3 -bc_0_components 0 -bc_1_type pressure -bc_1_values 2 -bc_1_value $q -contact_values 1 -contact_obstacle_0_type plane -contact_obstacle_0_point 0,0 -contact_obstacle_0_normal 0,1 -output_dir $CASE_DIR"
  ref=$(awk -v q=$q -v nu=$nu 'BEGIN{printf "%.12e", q * (1 + nu) * (1 - 2 * nu) / (1 - nu)}')
  local runs=("np1:1:" "np2:2:" "np3:3:-mesh_partitioner simple")
  for r in "${runs[@]}"; do
    local name=${r%%:*} rest=${r#*:}; local np=${rest%%:*} extra=${rest#*:} out="$CASE_DIR/$name.out"
    # shellcheck disable=SC2086
    SPC_TIMEOUT=60 spc "$out" "$np" $A $extra -output_name "sq2_$name"
    assert_eq "$name ($np ranks $extra) exit code (124: hung)" "$?" 0 || { tail -n 3 "$out"; rc=1; continue; }
    assert_close "$name displacement_max" "$(sval "$out" displacement_max)" "$ref" 1e-8 || rc=1
    assert_close "$name contact_force_y" "$(sval "$out" contact_force_y)" $q 1e-8 || rc=1
  done
  return $rc
}

# A second-order gmsh mesh (Mesh.ElementOrder = 2) is read by its corner nodes, with one warning:
# the same figures as the first-order mesh of the same geometry (gmsh places the corners alike).
# It stopped in the facet geometry with PETSc's "Edge has 0 coordinates != 4". B2 (6-node
# triangles, msh 2.2 and 4.1, 1 and 2 ranks) and the 3D tetrahedral patch test (10-node tetrahedra).
test_foundation_second_order_mesh() {
  fnd_setup
  local rc=0 keys="displacement_max vertices cells contact_force_y"
  command -v gmsh >/dev/null || { echo "gmsh missing (make installs it)"; return 1; }
  sed 's/Mesh.ElementOrder = 1;/Mesh.ElementOrder = 2;/' input/hertz2d.geo >"$CASE_DIR/h2.geo"
  sed 's/Mesh.ElementOrder = 1;/Mesh.ElementOrder = 2;/' input/patch3d_4_5.geo >"$CASE_DIR/patch3d_4_5.geo"
  cp input/patch3d_tet.geo "$CASE_DIR/tet2.geo" # includes patch3d_4_5.geo from its own folder
  gmsh -v 2 -2 "$CASE_DIR/h2.geo" -format msh22 -o "$CASE_DIR/h2_22.msh" >/dev/null &&
    gmsh -v 2 -2 "$CASE_DIR/h2.geo" -format msh41 -o "$CASE_DIR/h2_41.msh" >/dev/null &&
    gmsh -v 2 -3 "$CASE_DIR/tet2.geo" -format msh22 -o "$CASE_DIR/tet2.msh" >/dev/null || { echo "gmsh failed"; return 1; }
  spc "$CASE_DIR/b2_p1.out" 1 -options_file input/hertz2d.opts -output_dir "$CASE_DIR" -output_name b2_p1 || { echo "B2 first order: exit $?"; return 1; }
  for r in 22:1 41:1 22:2; do
    local f=${r%%:*} np=${r#*:} out
    out="$CASE_DIR/b2_${f}_np$np.out"
    spc "$out" "$np" -options_file input/hertz2d.opts -mesh_file "$CASE_DIR/h2_$f.msh" -output_dir "$CASE_DIR" -output_name "b2_${f}_np$np" ||
      { echo "B2 second order msh$f on $np ranks: exit $?"; tail -n 3 "$out"; rc=1; continue; }
    assert_eq "B2 msh$f np$np: one warning naming 6-node triangles" "$(grep -c '^spcontact: warning: -mesh_file .* holds higher-order elements (gmsh type 9, 6-node triangles): read by their corner nodes' "$out")" 1 || rc=1
    same_summary "$CASE_DIR/b2_p1.out" "$out" 1e-12 $keys || rc=1
  done
  local P="-options_file input/patch3d_4_5.opts -output_dir $CASE_DIR"
  spc "$CASE_DIR/tet1.out" 1 $P -mesh_file build/mesh/patch3d_tet.msh -output_name tet1 || { echo "tet first order: exit $?"; rc=1; }
  spc "$CASE_DIR/tet2.out" 1 $P -mesh_file "$CASE_DIR/tet2.msh" -output_name tet2 || { echo "tet second order: exit $?"; rc=1; }
  assert_eq "tet10: one warning" "$(grep -c '^spcontact: warning: -mesh_file .* (gmsh type 11, 10-node tetrahedra)' "$CASE_DIR/tet2.out")" 1 || rc=1
  same_summary "$CASE_DIR/tet1.out" "$CASE_DIR/tet2.out" 1e-12 displacement_max vertices cells contact_force_z || rc=1
  assert_eq "first-order mesh: no warning" "$(grep -c '^spcontact: warning' "$CASE_DIR/b2_p1.out" "$CASE_DIR/tet1.out" | awk -F: '{s += $2} END {print s}')" 0 || rc=1
  return $rc
}

# --- HDF5/XDMF/CSV output of a multi-step parallel run ---
# fnd_output_check NAME NSTEPS : .xmf consistent with .h5, no *.part left, CSV header + rows per step
fnd_output_check() {
  local name=$1 nsteps=$2 rc=0
  for ext in h5 xmf csv; do
    [ -s "$CASE_DIR/$name.$ext" ] && echo "$name.$ext written ok" || { echo "$name.$ext missing FAILED"; rc=1; }
  done
  "$PYTHON" scripts/check_xdmf.py "$CASE_DIR/$name.xmf" >"$CASE_DIR/$name.check_xdmf.txt" 2>&1
  local xrc=$?
  grep -v '^ok' "$CASE_DIR/$name.check_xdmf.txt"
  assert_eq "check_xdmf.py $name.xmf exit code" "$xrc" 0 || rc=1
  local parts
  parts=$(find "$CASE_DIR" -name '*.part' | wc -l)
  assert_eq "no *.part files left in $CASE_DIR" "$parts" 0 || rc=1
  local csv="$CASE_DIR/$name.csv"
  assert_eq "$name.csv header" "$(head -n 1 "$csv" | cut -d, -f1-4)" "step,augmentation,iteration,residual_norm" || rc=1
  for k in $(seq 1 "$nsteps"); do
    local rows
    rows=$(awk -F, -v k="$k" 'NR > 1 && $1 == k' "$csv" | wc -l)
    assert_ge "$name.csv rows for step $k" "$rows" 1 || rc=1
  done
  local bad
  bad=$(awk -F, -v n="$(head -n 1 "$csv" | awk -F, '{print NF}')" 'NR > 1 && NF != n' "$csv" | wc -l)
  assert_eq "$name.csv rows with the header's column count" "$bad" 0 || rc=1
  return $rc
}

test_foundation_output_hdf5() {
  fnd_setup
  local rc=0 out
  # 2D Q1 box, uniaxial case, 2 load steps on 3 ranks; values checked against the closed form
  out="$CASE_DIR/out2d.out"
  spc "$out" 3 -options_file input/elastic2d.opts -load_steps 2 -output_dir "$CASE_DIR" -output_name out2d ||
    { echo "out2d: spcontact exited with $?"; tail -n 5 "$out"; return 1; }
  assert_eq "out2d load_steps" "$(sval "$out" load_steps)" 2 || rc=1
  assert_eq "out2d output_prefix" "$(sval "$out" output_prefix)" "$CASE_DIR/out2d" || rc=1
  fnd_output_check out2d 2 || rc=1
  fnd_h5_linear "$CASE_DIR/out2d.h5" 2 0.5,1 0.00169 -0.00221 || rc=1
  # 3D hex Q2 (vertex output of a degree-2 field), 3 load steps on 3 ranks
  out="$CASE_DIR/out3d.out"
  spc "$out" 3 -options_file input/elastic3d.opts -dm_plex_box_faces 3,3,3 -petscspace_degree 2 -load_steps 3 -output_dir "$CASE_DIR" -output_name out3d ||
    { echo "out3d: spcontact exited with $?"; tail -n 5 "$out"; return 1; }
  fnd_output_check out3d 3 || rc=1
  fnd_h5_linear "$CASE_DIR/out3d.h5" 3 0.333333333333333333,0.666666666666666667,1 0.0016 0.0003 -0.0023 || rc=1
  # unstructured triangles from gmsh, 2 steps on 2 ranks
  fnd_gmsh_square 5 "$CASE_DIR/sq5u.msh" 0 || return 1
  out="$CASE_DIR/outtri.out"
  spc "$out" 2 -options_file input/elastic2d.opts -mesh_file "$CASE_DIR/sq5u.msh" -load_steps 2 -output_dir "$CASE_DIR" -output_name outtri ||
    { echo "outtri: spcontact exited with $?"; tail -n 5 "$out"; return 1; }
  fnd_output_check outtri 2 || rc=1
  fnd_h5_linear "$CASE_DIR/outtri.h5" 2 0.5,1 0.00169 -0.00221 || rc=1
  return $rc
}

# --- bad input: one clean line on stderr, exit code 1..127, no PETSc traceback, no hang ---
# The cases run concurrently (at most FND_BAD_JOBS at a time): each one mostly waits (Open MPI
# takes ~2 s to tear a failed job down), and a hang costs FND_BAD_TIMEOUT once, not per case.
FND_BAD_TIMEOUT=${FND_BAD_TIMEOUT:-60}
FND_BAD_JOBS=${FND_BAD_JOBS:-6}

# fnd_bad_start NAME NP EXPECT ARGS... : launch one case in the background; EXPECT is a string the
# error line must contain (the bad option or value). Each case writes to its own output dir.
fnd_bad_start() {
  local name=$1 np=$2 expect=$3; shift 3
  local pre="$CASE_DIR/bad_$name"
  printf '%s\n' "$expect" >"$pre.expect"
  RERUN="${RERUN:+$RERUN ; }$MPIEXEC -n $np $SPC -output_dir $CASE_DIR/out_$name $*"
  while [ "$(jobs -rp | wc -l)" -ge "$FND_BAD_JOBS" ]; do wait -n; done
  (
    t0=$(date +%s.%N)
    timeout -k 5 "$FND_BAD_TIMEOUT" $MPIEXEC -n "$np" $SPC -output_dir "$CASE_DIR/out_$name" "$@" >"$pre.out" 2>"$pre.err"
    rc=$?
    t1=$(date +%s.%N)
    echo "$rc $(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.1f", b - a}')" >"$pre.rc"
  ) &
}

# fnd_bad_check NAME NP : judge a finished case; prints one line and ok/FAILED with the reasons
fnd_bad_check() {
  local name=$1 np=$2 ok=1 why="" rc secs expect lines n nerr npetsc
  local pre="$CASE_DIR/bad_$name"
  read -r rc secs <"$pre.rc" || { rc=999; secs=0; }
  expect=$(cat "$pre.expect")
  # drop Open MPI's own notices (blocks between lines of dashes) and its signal-forwarding line
  lines=$(awk '/^------------------------------*$/{inblk = !inblk; next} !inblk && NF && !/^mpiexec: Forwarding signal/' "$pre.err")
  n=$(printf '%s' "$lines" | grep -c .)
  nerr=$(printf '%s\n' "$lines" | grep -c '^spcontact: error:')
  npetsc=$(cat "$pre.out" "$pre.err" | grep -c 'PETSC ERROR')
  if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then ok=0; why="$why; hung: killed by timeout after ${FND_BAD_TIMEOUT}s"
  elif [ "$rc" -eq 0 ]; then ok=0; why="$why; exit code 0 (input accepted)"
  elif [ "$rc" -ge 128 ]; then ok=0; why="$why; exit code $rc (signal/abort)"; fi
  [ "$n" -eq 1 ] && [ "$nerr" -eq 1 ] || { ok=0; why="$why; stderr has $n line(s), $nerr starting with 'spcontact: error:' (want exactly 1)"; }
  [ "$npetsc" -eq 0 ] || { ok=0; why="$why; $npetsc 'PETSC ERROR' line(s)"; }
  printf '%s\n' "$lines" | grep '^spcontact: error:' | grep -qF -- "$expect" || { ok=0; why="$why; error line does not name '$expect'"; }
  printf 'bad input %-26s np %d rc %3d %5.1fs: %s\n' "$name" "$np" "$rc" "$secs" "$(printf '%s\n' "$lines" | grep '^spcontact: error:' | head -n 1 | cut -c1-150)"
  if [ $ok -eq 1 ]; then echo "    ok"; else echo "    FAILED${why}"; printf '%s\n' "$lines" | head -n 4 | cut -c1-160 | sed 's/^/    | /'; fi
  [ $ok -eq 1 ]
}

test_foundation_bad_input() {
  fnd_setup
  local rc=0 nfail=0 cases=()
  local B="$(fnd_box2 4) -bc_0_type dirichlet -bc_0_values 1"
  local M="-bc_0_type dirichlet -bc_0_values 1"
  echo "this is not a mesh" >"$CASE_DIR/notamesh.msh"
  # a gmsh file cut off inside $Nodes (the header check passes; PETSc's reader fails)
  printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n100\n1 0 0 0\n2 1 0 0\n3 1 1' >"$CASE_DIR/truncated.msh"
  _fnd_case() { cases+=("$1:$2"); fnd_bad_start "$@"; }
  _fnd_case missing_mesh_file        2 nosuch.msh          -mesh_file "$CASE_DIR/nosuch.msh" $M
  _fnd_case not_a_mesh               2 notamesh.msh        -mesh_file "$CASE_DIR/notamesh.msh" $M
  _fnd_case truncated_mesh           2 truncated.msh       -mesh_file "$CASE_DIR/truncated.msh" $M
  _fnd_case missing_label            2 nosuch              $B -bc_0_label nosuch
  _fnd_case label_value_no_points    2 99                  $B -bc_0_values 99
  _fnd_case bc_values_missing        1 bc_0_values         $(fnd_box2 4) -bc_0_type traction -bc_0_value 1,0
  _fnd_case nu_half                  1 material_nu         $B -material_nu 0.5
  _fnd_case E_negative               1 material_E          $B -material_E -1
  _fnd_case E_not_a_number           1 abc                 $B -material_E abc
  _fnd_case bc_type_unknown          2 foo                 $B -bc_0_type foo
  _fnd_case material_unknown         1 material_model      $B -material_model foo
  _fnd_case output_dir_unwritable    2 output_dir          $B -output_dir /proc/forbidden
  _fnd_case load_steps_zero          1 load_steps          $B -load_steps 0
  _fnd_case load_max_cutbacks_neg    1 load_max_cutbacks   $B -load_max_cutbacks -1
  _fnd_case load_grow_after_neg      1 load_grow_after     $B -load_grow_after -1
  _fnd_case bc_component_2_in_2d     2 bc_0_components     $B -bc_0_components 2
  _fnd_case bc_component_negative    1 bc_0_components     $B -bc_0_components -1
  _fnd_case bc_component_3_in_3d     1 bc_0_components     $(fnd_box3 2) -bc_0_type dirichlet -bc_0_values 1 -bc_0_components 3
  _fnd_case dirichlet_value_count    1 bc_0_value          $B -bc_0_components 0,1 -bc_0_value 0.1
  _fnd_case partitioner_unknown      2 nosuch              $B -mesh_partitioner nosuch
  _fnd_case partitioner_unknown_np1  1 nosuch              $B -mesh_partitioner nosuch
  _fnd_case more_ranks_than_cells    3 ranks               $(fnd_box2 1) -bc_0_type dirichlet -bc_0_values 1
  _fnd_case degree_zero              1 petscspace_degree   $B -petscspace_degree 0
  wait
  local failed=""
  for c in "${cases[@]}"; do
    fnd_bad_check "${c%%:*}" "${c#*:}" || { rc=1; nfail=$((nfail + 1)); failed="$failed ${c%%:*}"; }
  done
  echo "bad input: ${#cases[@]} cases, $((${#cases[@]} - nfail)) ok, $nfail failed${failed:+:$failed}"
  return $rc
}
