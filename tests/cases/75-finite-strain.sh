# Finite strain (issue 15, first part): the compressible Neo-Hookean law (kernels/neohookean.h)
# against the closed-form homogeneous uniaxial state (scripts/neohookean_uniaxial.py solves the
# stress-stretch equations independently of the code), in two unit systems and on 1, 2, 3 ranks;
# a Newton iterate that turns cells inside out is cut back, and so is a converged state with a cell
# inverted at a vertex (the corner check); the small-load limit is linear
# elasticity to first order in the load; the assembled Jacobian (bulk + contact) at deformed,
# penetrated states against finite differences.

# nh_uniaxial NAME DIM Q L NP OPTS... : a unit (or L-sided) block of E = 1 (or as OPTS set)
# pressed by a dead nominal pressure Q onto a rigid frictionless plane; displacement_max against
# the closed form (the stretches depend on Q/E only) to 1e-8 relative
nh_uniaxial() {
  local name=$1 dim=$2 q=$3 L=$4 np=$5 E=1; shift 5
  local out=$CASE_DIR/$name.txt ref prev=
  for a in "$@"; do [ "$prev" = -material_E ] && E=$a; prev=$a; done
  spc "$out" "$np" -options_file input/block${dim}d.opts -material_model neo_hookean -output_dir "$CASE_DIR" -output_name "$name" "$@" || return 1
  ref=$($PYTHON scripts/neohookean_uniaxial.py "$dim" 1 0.3 "$(awk -v q="$q" -v E="$E" 'BEGIN{print q / E}')" "$L" ${FOLLOWER:+follower} | awk '{print $6}')
  echo "$name: newton $(sval "$out" newton_iterations) cutbacks $(sval "$out" cutbacks) penetration $(sval "$out" contact_max_penetration)"
  assert_eq "converged_$name" "$(sval "$out" converged)" yes && assert_close "displacement_max_$name" "$(sval "$out" displacement_max)" "$ref" 1e-8
}

# 2D plane strain at q = 0.1 and 0.5 (stretch 0.68), 3D at q = 0.3 (stretch 0.76); the 2D q = 0.5
# case again in mm-N-MPa with a 1000 mm block of steel (E = 210000 MPa, q = 105000 MPa): the same
# stretches, displacement x 1000, Newton iterations within 1
test_finite_strain_uniaxial() {
  local rc=0
  nh_uniaxial nh2d_q0.1 2 0.1 1 1 -bc_1_value 0.1 || rc=1
  nh_uniaxial nh2d_q0.5 2 0.5 1 1 -bc_1_value 0.5 -load_steps 2 || rc=1
  nh_uniaxial nh2d_q0.5_mm 2 105000 1000 1 -bc_1_value 105000 -material_E 210000 -dm_plex_box_upper 1000,1000 -load_steps 2 || rc=1
  nh_uniaxial nh3d_q0.3 3 0.3 1 1 -bc_2_value 0.3 -load_steps 2 || rc=1
  local n1 n2; n1=$(sval "$CASE_DIR/nh2d_q0.5.txt" newton_iterations); n2=$(sval "$CASE_DIR/nh2d_q0.5_mm.txt" newton_iterations)
  assert_close newton_units "$n2" "$n1" 0 1 || rc=1
  return $rc
}

# Follower pressure (-bc_<i>_follower): the pressure acts on the deformed top face, so the axial
# Cauchy stress is -q and the nominal stress -q l1^(dim-1) (closed form with `follower`), 2D and
# 3D, 1 and 2 ranks; it compresses more than the dead load (2D q = 0.3: 0.2379 against 0.2185).
# The load stiffness is FD-checked in bin/test-kernels and assembled (the Newton iterations stay
# quadratic: 5 per step); a follower pressure on small-strain elasticity is refused.
test_finite_strain_follower() {
  local rc=0
  FOLLOWER=1 nh_uniaxial fol2d 2 0.3 1 1 -bc_1_value 0.3 -bc_1_follower -load_steps 2 || rc=1
  FOLLOWER=1 nh_uniaxial fol2d_np2 2 0.3 1 2 -bc_1_value 0.3 -bc_1_follower -load_steps 2 || rc=1
  FOLLOWER=1 nh_uniaxial fol3d 3 0.3 1 1 -bc_2_value 0.3 -bc_2_follower -load_steps 2 || rc=1
  nh_uniaxial dead2d 2 0.3 1 1 -bc_1_value 0.3 -load_steps 2 || rc=1
  assert_le newton_per_step "$(sval "$CASE_DIR/fol2d.txt" newton_iterations)" 12 || rc=1
  bad_input_cases <<'CASES' || rc=1
follower on small-strain elasticity|input/block2d.opts|-bc_1_follower
follower on a traction condition|input/block2d.opts|-material_model neo_hookean -bc_1_type traction -bc_1_value 0,0.1 -bc_1_follower
CASES
  return $rc
}

# The same figures on 1, 2 and 3 ranks
test_finite_strain_ranks() {
  local rc=0
  for np in 1 2 3; do nh_uniaxial nh2d_np$np 2 0.5 1 $np -bc_1_value 0.5 -load_steps 2 || rc=1; done
  for np in 2 3; do same_summary "$CASE_DIR/nh2d_np1.txt" "$CASE_DIR/nh2d_np$np.txt" 1e-8 displacement_max contact_force_y newton_iterations || rc=1; done
  return $rc
}

# q = 1.2 in one load step: the first Newton iterate inverts cells (stretch < 0), the NaN stress
# stops the solve (DIVERGED_FNORM_NAN), the step is cut back once and the run reaches the exact
# stretch 0.476
test_finite_strain_inversion() {
  local out=$CASE_DIR/nh2d_q1.2.txt rc=0
  nh_uniaxial nh2d_q1.2 2 1.2 1 1 -bc_1_value 1.2 -load_steps 1 || rc=1
  grep -q "DIVERGED_FNORM_NAN" "$out" || { echo "no inverted iterate was caught"; rc=1; }
  assert_ge cutbacks "$(sval "$out" cutbacks)" 1 || rc=1
  grep -qi "nan" <(sval "$out" displacement_max) && { echo "NaN in the result"; rc=1; }
  return $rc
}

# nh_corner NAME NP OPTS... : a Neo-Hookean run whose equilibrium turns a Q1 cell inside out at a
# corner. Asserted: the corner check caught it (an "inverted cell corner" line), no written step
# has a corner J <= 0 (scripts/corner_jacobian.py on the h5, independent of the code), and the run
# either converged or stopped with one 'stopping:' line and no final-named output file
nh_corner() {
  local name=$1 np=$2 rc=0 h5; shift 2
  local out=$CASE_DIR/$name.txt
  mkdir -p "$CASE_DIR/$name"
  spc "$out" "$np" -material_model neo_hookean -output_dir "$CASE_DIR/$name" "$@"
  h5=$(ls "$CASE_DIR/$name"/*.h5 "$CASE_DIR/$name"/*.h5.part 2>/dev/null | head -n 1)
  [ -n "$h5" ] || { echo "$name: no h5 written"; return 1; }
  $PYTHON scripts/corner_jacobian.py "$h5" > "$CASE_DIR/$name.cj" || return 1
  echo "$name: $(tail -n 1 "$CASE_DIR/$name.cj"); caught $(grep -c 'inverted cell corner' "$out"); converged $(sval "$out" converged) load_factor $(sval "$out" load_factor) cutbacks $(sval "$out" cutbacks) newton $(sval "$out" newton_iterations)"
  grep -m 1 'inverted cell corner' "$out"
  assert_ge "caught_$name" "$(grep -c 'inverted cell corner' "$out")" 1 || rc=1
  assert_eq "written_steps_inverted_$name" "$(awk '$1 == "all" {print $5}' "$CASE_DIR/$name.cj")" 0 || rc=1
  if [ "$(sval "$out" converged)" != yes ]; then
    assert_eq "stop_lines_$name" "$(grep -c '^stopping: ' "$out")" 1 || rc=1
    assert_eq "final_files_$name" "$(find "$CASE_DIR/$name" \( -name '*.h5' -o -name '*.xmf' -o -name '*.csv' \) | wc -l)" 0 || rc=1
  fi
  return $rc
}

# A Q1 cell inside out at a corner only (J <= 0 at a vertex, J > 0 at every Gauss point) gives a
# finite stress, so its solve converges. Before the corner check the QA case (block3d 4^3, q = 1.2,
# friction 0.3) wrote steps 4 and 5 with corner J -0.0263 and -0.0120 (2 cells), and its 2D variant
# (block2d 4x4 in 16 steps) 12 steps with inverted corners, J down to -0.110 (4 cells), up to load
# factor 0.872. Now those states are cut back and both runs stop at the cut-back floor (the
# equilibrium just beyond inverts a corner) with every written step's corner J > 0: 2D at load
# factor 0.578003 (J >= 4.59e-4, 464 Newton iterations on 1 and 2 ranks), 3D at 0.434814 (J >=
# 0.0564). 2D: the same figures on 1, 2 and 3 ranks (in one step, its 0.375 -> 0.5 increment
# converges or not by MUMPS's round-off on 2 ranks); 3D: the same load factor and displacement,
# GMRES/GAMG's Newton iterations within 2 (675, 674).
test_finite_strain_corner_inversion() {
  local rc=0 np
  for np in 1 2 3; do
    nh_corner q2d_np$np $np -options_file input/block2d.opts -bc_1_value 1.2 -contact_friction_mu 0.3 -dm_plex_box_faces 4,4 -load_steps 16 || rc=1
    nh_corner qa3d_np$np $np -options_file input/block3d.opts -bc_2_value 1.2 -contact_friction_mu 0.3 -dm_plex_box_faces 4,4,4 || rc=1
  done
  # 2D's Newton counts are not compared across ranks: its parallel MUMPS factorization is not
  # bit-reproducible from one run to the next (Known limits), and in this run, which ends at the
  # cut-back floor, a chattering point's frozen direction is let go twice (-info: released), so
  # identical 2-rank runs took 544 and 567 Newton iterations (1 rank: 543) to the same figures
  same_summary "$CASE_DIR/q2d_np1.txt" "$CASE_DIR/q2d_np2.txt" 1e-8 load_factor load_steps cutbacks displacement_max || rc=1
  same_summary "$CASE_DIR/qa3d_np1.txt" "$CASE_DIR/qa3d_np2.txt" 1e-8 load_factor load_steps cutbacks displacement_max || rc=1
  assert_close newton_3d "$(sval "$CASE_DIR/qa3d_np2.txt" newton_iterations)" "$(sval "$CASE_DIR/qa3d_np1.txt" newton_iterations)" 0 2 || rc=1
  # 3 ranks: the same figures (3D's GMRES/GAMG takes other Newton counts there: 723 against 675)
  same_summary "$CASE_DIR/q2d_np1.txt" "$CASE_DIR/q2d_np3.txt" 1e-8 load_factor load_steps cutbacks displacement_max || rc=1
  same_summary "$CASE_DIR/qa3d_np1.txt" "$CASE_DIR/qa3d_np3.txt" 1e-8 load_factor load_steps cutbacks displacement_max || rc=1
  return $rc
}

# The corner check's J (its -info line, the last converged step's smallest det F at a vertex)
# against scripts/corner_jacobian.py on the h5 (1e-8): Q1 and Q2 in the homogeneous biaxial state
# of elastic2d (E = 20: J = 0.9746; Q2 through the displacement FE tabulated at the vertices, the
# script from the vertex values, exact for a linear field), the Hertz disc's triangles (PETSc's
# geometry per cell: the gmsh coordinates are no PetscFE) and the 3D block's hexes, on 2 ranks
test_finite_strain_corner_j() {
  local rc=0 name out j ref
  cj_case() { # NAME OPTS...
    name=$1; shift
    out=$CASE_DIR/$name.txt
    spc "$out" 2 "$@" -material_model neo_hookean -output_dir "$CASE_DIR" -output_name "$name" -info :dm || return 1
    j=$(grep 'corner check:' "$out" | tail -n 1 | sed 's/.*at a cell vertex \([^,]*\),.*/\1/')
    ref=$($PYTHON scripts/corner_jacobian.py "$CASE_DIR/$name.h5" | awk '$1 == "all" {print $3}')
    assert_close "corner_J_$name" "$j" "$ref" 1e-8
  }
  cj_case el2d_q1 -options_file input/elastic2d.opts -material_E 20 || rc=1
  cj_case el2d_q2 -options_file input/elastic2d.opts -material_E 20 -petscspace_degree 2 || rc=1
  cj_case hertz2d_p1 -options_file input/hertz2d.opts -bc_1_value 0.05 -load_steps 1 || rc=1
  cj_case block3d_q1 -options_file input/block3d.opts -bc_2_value 0.3 || rc=1
  return $rc
}

# Growth after a cut-back (-load_grow_after 1): q = 1.6 in two steps, started iterative
# (-solver_direct_dofs 0: with the default factorization both steps converge without a cut-back),
# cuts back three times; each converged step but the last doubles the increment again (0.25 ->
# 0.5, 0.125 -> 0.25), so the run ends in 4 steps at the closed-form stretch instead of crawling
# at the smallest increment
test_finite_strain_load_regrow() {
  local out=$CASE_DIR/nh2d_q1.6.txt rc=0
  nh_uniaxial nh2d_q1.6 2 1.6 1 1 -bc_1_value 1.6 -load_steps 2 -load_grow_after 1 -solver_direct_dofs 0 || rc=1
  assert_eq regrowths "$(grep -c 'load increment doubled' "$out")" 2 || rc=1
  assert_eq load_steps "$(sval "$out" load_steps)" 4 || rc=1
  return $rc
}

# Small-load limit: the Neo-Hookean block's displacement differs from linear elasticity's by a
# relative amount proportional to the load (ratio 10 +- 20 % between q = 1e-2 and 1e-3, and
# below 1e-3 at q = 1e-3)
test_finite_strain_small_load() {
  local rc=0 d=()
  for q in 0.01 0.001; do
    spc "$CASE_DIR/lin_$q.txt" 1 -options_file input/block2d.opts -bc_1_value $q -output_dir "$CASE_DIR" -output_name lin_$q || return 1
    spc "$CASE_DIR/nh_$q.txt" 1 -options_file input/block2d.opts -bc_1_value $q -material_model neo_hookean -output_dir "$CASE_DIR" -output_name nh_$q || return 1
    d+=("$(awk -v a="$(sval "$CASE_DIR/lin_$q.txt" displacement_max)" -v b="$(sval "$CASE_DIR/nh_$q.txt" displacement_max)" 'BEGIN{d = (a - b) / a; print d < 0 ? -d : d}')")
  done
  echo "relative difference neo_hookean vs linear: q = 1e-2: ${d[0]}, q = 1e-3: ${d[1]}"
  assert_close first_order_ratio "$(awk -v a="${d[0]}" -v b="${d[1]}" 'BEGIN{print a / b}')" 10 0.2 || rc=1
  assert_le difference_q1e-3 "${d[1]}" 1e-3 || rc=1
  return $rc
}

# The small-load limit on every other B-case (B1 is the block above): Neo-Hookean against linear
# elasticity at 10 % and 1 % of the benchmark's load (B4: of its indentation), the relative
# difference of a global figure: displacement_max under load control (B2, B3, B5 two-pass, B6),
# the contact force under displacement control (B4, 12^3). The difference is the geometric
# nonlinearity, of the order of the strain: the bulk strain (first order in the load, ratio 10
# per decade: B5 measured 10.0) or the contact strain a/R (P^(1/2) in 2D, P^(1/3) in 3D load
# control: ratios 3.2 and 2.2). Asserted: at 1 % below 1e-3, and at least the 3D Hertz order
# (ratio >= 2) from 10 % to 1 %. Measured ratios: B2 6.0, B3 4.1, B4 4.5, B5 10.0, B6 5.2.
sl_diff() { # NAME KEY OPTS...: relative difference NH vs linear of KEY, into $CASE_DIR/NAME.diff
  local name=$1 key=$2; shift 2
  spc "$CASE_DIR/${name}_lin.txt" 1 "$@" -output_dir "$CASE_DIR" -output_name ${name}_lin -output_fields false || return 1
  spc "$CASE_DIR/${name}_nh.txt" 1 "$@" -material_model neo_hookean -output_dir "$CASE_DIR" -output_name ${name}_nh -output_fields false || return 1
  awk -v a="$(sval "$CASE_DIR/${name}_lin.txt" "$key")" -v b="$(sval "$CASE_DIR/${name}_nh.txt" "$key")" 'BEGIN{d = (b - a) / a; print d < 0 ? -d : d}' > "$CASE_DIR/$name.diff"
}
test_finite_strain_small_load_bcases() {
  local rc=0 c s d1 d2
  declare -A key=([B2]=displacement_max [B3]=displacement_max [B4]=contact_force_z [B5]=displacement_max [B6]=displacement_max)
  for c in B2 B3 B4 B5 B6; do
    for s in 0.1 0.01; do
      case $c in
        B2) set -- -options_file input/hertz2d.opts -bc_1_value "$(awk -v s=$s 'BEGIN{print 0.005 * s}')" ;;
        B3) set -- -options_file input/hertz3d.opts -bc_2_value "0,0,$(awk -v s=$s 'BEGIN{print -5e-4 * s}')" ;;
        B4) set -- -options_file input/indent3d.opts -dm_plex_box_faces 12,12,12 -contact_obstacle_0_motion "0,0,$(awk -v s=$s 'BEGIN{print -0.01 * s}')" ;;
        B5) set -- -options_file input/patch_4_5.opts -contact_two_pass -bc_2_value "$(awk -v s=$s 'BEGIN{print 0.01 * s}')" ;;
        B6) set -- -options_file input/hertz2d_twobody.opts -bc_2_value "$(awk -v s=$s 'BEGIN{print 0.005 * s}')" ;;
      esac
      sl_diff ${c}_$s ${key[$c]} "$@" || return 1
    done
    d1=$(cat "$CASE_DIR/${c}_0.1.diff"); d2=$(cat "$CASE_DIR/${c}_0.01.diff")
    echo "$c (${key[$c]}): relative difference at 10 % $d1, at 1 % $d2, ratio $(awk -v a="$d1" -v b="$d2" 'BEGIN{print a / b}')"
    assert_le "${c}_difference_at_1_percent" "$d2" 1e-3 || rc=1
    assert_ge "${c}_order_ratio" "$(awk -v a="$d1" -v b="$d2" 'BEGIN{print a / b}')" 2 || rc=1
  done
  return $rc
}

# The assembled Jacobian (Neo-Hookean bulk + contact, consistent contact tangent) against PETSc's
# FD Jacobian at every Newton iterate: a tilted plane pressed into a 6x6 box, the B4 sphere pressed
# 0.03 into a 4x4x4 box (penalty and shifted), and a 2D pair sliding 0.1 (penalty: this solve
# converges before any shift update, which kjac_case requires of shifted) (kjac_case of 05-kernels.sh)
test_finite_strain_jacobian() {
  local rc=0
  for m in penalty shifted; do
    kjac_case nh_plane2d "$m" $(kjac_box2d) -material_model neo_hookean -contact_obstacle_0_type plane -contact_obstacle_0_point 0.5,0.98 -contact_obstacle_0_normal 0.196116135,-0.980580676 || rc=1
    kjac_case nh_sphere3d "$m" -options_file input/indent3d.opts -material_model neo_hookean -dm_plex_box_faces 4,4,4 -contact_obstacle_0_motion 0,0,-0.03 || rc=1
  done
  kjac_case nh_slide2d penalty -options_file input/slide2d.opts -material_model neo_hookean -load_steps 1 -bc_1_value 0.1,0 || rc=1
  return $rc
}

# Large sliding at finite strain: the slide2d blocks (Neo-Hookean) pressed 0.005 and slid 0.6 in
# 12 steps, slave vertices crossing master facets, the blocks cut by the partition on 2 and 3
# ranks. Every step: slave/master force balance to 1e-10, penetration <= the gap tolerance;
# the figures identical on 1, 2, 3 ranks (1e-8).
test_finite_strain_sliding() {
  local rc=0
  for np in 1 2 3; do
    local out=$CASE_DIR/np$np.txt
    spc "$out" $np -options_file input/slide2d.opts -material_model neo_hookean -output_dir "$CASE_DIR" -output_name np$np || return 1
    assert_eq converged_np$np "$(sval "$out" converged)" yes || rc=1
    slide_figures "$out" > "$CASE_DIR/figs$np.txt"
    echo "ranks $np: newton $(sval "$out" newton_iterations) $(tr '\n' ' ' < "$CASE_DIR/figs$np.txt")"
    assert_le force_balance_np$np "$(awk '$1=="force_balance"{print $2}' "$CASE_DIR/figs$np.txt")" 1e-10 || rc=1
    assert_le max_penetration_every_step_np$np "$(awk '$1=="max_penetration_converged"{print $2}' "$CASE_DIR/figs$np.txt")" "$(sval "$out" contact_gap_tol)" || rc=1
    [ $np -gt 1 ] && { same_summary "$CASE_DIR/np1.txt" "$out" 1e-8 contact_force_x contact_force_y displacement_max newton_iterations || rc=1; }
  done
  return $rc
}

# Manufactured solution with the nonlinear law (u = 0.01 prod sin(pi x_d) (c+1): strains up to
# ~0.1; body force Div P(F(u)) from kernels/neohookean.h): optimal L2 rates, Q1 2 and Q2 3 in 2D,
# Q1 2 in 3D on 2 ranks (fnd_mms of 10-foundation.sh)
test_finite_strain_mms() {
  local rc=0
  fnd_setup
  fnd_levels_box 2 4; fnd_mms_case nh_mms_q1_2d 1 1.8 2.3 1 2 -material_model neo_hookean || rc=1
  fnd_levels_box 2 4; fnd_mms_case nh_mms_q2_2d 1 2.7 3.4 2 2 -material_model neo_hookean || rc=1
  fnd_levels_box 3 2; fnd_mms_case nh_mms_q1_3d 2 1.8 2.3 1 3 -material_model neo_hookean || rc=1
  return $rc
}

# The fast element operator of the Neo-Hookean law (stress/tangent at the quadrature points)
# against PetscFE's residual and Jacobian at a random state (1e-12; fop_check of
# 60-fast-operator.sh) on quads, triangles (1 and 2 ranks), hexes; and a whole finite-strain
# contact run (the NH block, q/E = 0.5) with either operator: the same Newton and linear
# iterations and figures (fop_same)
test_finite_strain_fast_operator() {
  local rc=0
  fop_check_np12 -options_file input/block2d.opts -material_model neo_hookean || rc=1
  fop_check_np12 -options_file input/hertz2d.opts -material_model neo_hookean || rc=1
  fop_check 1 -options_file input/indent3d.opts -dm_plex_box_faces 6,6,6 -material_model neo_hookean || rc=1
  fop_same 1 -options_file input/block2d.opts -material_model neo_hookean -bc_1_value 0.5 -load_steps 2 || rc=1
  return $rc
}

# The seed's claim at finite strain (README "Finite strain"): the B2 disc, Neo-Hookean, pressed
# with 10x B2's load in 10 steps (contact half-width 0.36 R). At alpha 100 and 1000 shifted
# removes the penetration (to the gap tolerance, 1e-10 h_c; penalty leaves 9.9e-6 and 9.9e-7)
# with at most 3 Newton iterations per load step more than penalty (measured 73 vs 56 and 59 vs
# 56), and the same peak pressure as alm to 1e-8. At alpha 10 the shift contracts by about 0.1 per
# update and the claim is missed (112 vs 56; README), so alpha 10 is not asserted here.
test_finite_strain_claim() {
  local rc=0 a m out np nsh
  for a in 100 1000; do
    for m in penalty shifted alm; do
      out=$CASE_DIR/${m}_$a.txt
      spc "$out" 1 -options_file input/hertz2d.opts -material_model neo_hookean -bc_1_value 0.05 -load_steps 10 -contact_method $m -contact_alpha $a -output_dir "$CASE_DIR" -output_name ${m}_$a -output_fields false || return 1
      assert_eq "converged_${m}_$a" "$(sval "$out" converged)" yes || rc=1
    done
    np=$(sval "$CASE_DIR/penalty_$a.txt" newton_iterations); nsh=$(sval "$CASE_DIR/shifted_$a.txt" newton_iterations)
    echo "alpha $a: newton penalty $np shifted $nsh alm $(sval "$CASE_DIR/alm_$a.txt" newton_iterations); penetration penalty $(sval "$CASE_DIR/penalty_$a.txt" contact_max_penetration) shifted $(sval "$CASE_DIR/shifted_$a.txt" contact_max_penetration)"
    assert_le "shifted_within_penalty_plus_3_per_step_$a" "$nsh" "$((np + 30))" || rc=1
    assert_le "shifted_fewer_than_alm_$a" "$nsh" "$(sval "$CASE_DIR/alm_$a.txt" newton_iterations)" || rc=1
    assert_le "shifted_gap_$a" "$(sval "$CASE_DIR/shifted_$a.txt" contact_gap_error)" "$(sval "$CASE_DIR/shifted_$a.txt" contact_gap_tol)" || rc=1
    assert_close "peak_pressure_shifted_vs_alm_$a" "$(sval "$CASE_DIR/shifted_$a.txt" contact_peak_pressure)" "$(sval "$CASE_DIR/alm_$a.txt" contact_peak_pressure)" 1e-8 || rc=1
    # penalty's penetration p/eps, about 1e-3/alpha here (9.9e-6, 9.9e-7): asserted above 1e-4/alpha
    assert_le "penalty_penetrates_$a" "$(awk -v a="$a" 'BEGIN{print 1e-4 / a}')" "$(sval "$CASE_DIR/penalty_$a.txt" contact_max_penetration)" || rc=1
  done
  return $rc
}
