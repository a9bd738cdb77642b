# The Schur shift update (-contact_shift_accel schur, src/contact-schur.c): at a Newton-iteration
# boundary (alm: after a converged solve) the shifts move by the d that zeroes the linearised gaps of
# the next step, M d = g with M = B J^-1 D, solved by GMRES with back-substitutions of the step's
# factorization. The plain update takes d = g and contracts by k/(k + eps) per update.

# schur_run NAME NP OPTS...: one B-run into $CASE_DIR/NAME.txt
schur_run() {
  local name=$1 np=$2; shift 2
  spc "$CASE_DIR/$name.txt" "$np" "$@" -output_dir "$CASE_DIR" -output_name "$name" -output_fields false
}

# B2 (2D factorization from the start) at alpha 10, 100, 1000: converged to the gap tolerance in at
# most penalty + 1 Newton iterations (measured 3 against penalty's 2; the plain update 9 / 5 / 4),
# the contact force 5e-3 to 1e-8 and the peak pressure of the plain update to 1e-6
test_schur_b2() {
  local rc=0 a np nn
  for a in 10 100 1000; do
    schur_run pen_$a 1 -options_file input/hertz2d.opts -contact_method penalty -contact_alpha $a || return 1
    schur_run none_$a 1 -options_file input/hertz2d.opts -contact_alpha $a || return 1
    schur_run schur_$a 1 -options_file input/hertz2d.opts -contact_alpha $a -contact_shift_accel schur || return 1
    np=$(sval "$CASE_DIR/pen_$a.txt" newton_iterations); nn=$(sval "$CASE_DIR/schur_$a.txt" newton_iterations)
    echo "B2 alpha $a: newton penalty $np plain $(sval "$CASE_DIR/none_$a.txt" newton_iterations) schur $nn ($(sval "$CASE_DIR/schur_$a.txt" contact_shift_accel_solves) back-substitutions), penetration $(sval "$CASE_DIR/schur_$a.txt" contact_max_penetration)"
    assert_eq converged_$a "$(sval "$CASE_DIR/schur_$a.txt" converged)" yes || rc=1
    assert_le newton_$a "$nn" $((np + 1)) || rc=1
    assert_le penetration_$a "$(sval "$CASE_DIR/schur_$a.txt" contact_max_penetration)" "$(sval "$CASE_DIR/schur_$a.txt" contact_gap_tol)" || rc=1
    assert_close force_$a "$(sval "$CASE_DIR/schur_$a.txt" contact_force_y)" 5e-3 1e-8 || rc=1
    assert_close peak_$a "$(sval "$CASE_DIR/schur_$a.txt" contact_peak_pressure)" "$(sval "$CASE_DIR/none_$a.txt" contact_peak_pressure)" 1e-6 || rc=1
    assert_ge steps_$a "$(sval "$CASE_DIR/schur_$a.txt" contact_shift_accel_steps)" 1 || rc=1
  done
  return $rc
}

# The same in another unit system (80-units.sh's mm-N-MPa: R = 10 mm, steel): the same Newton
# iterations, back-substitutions and active points, the penetration below the gap tolerance
test_schur_b2_units() {
  local rc=0
  schur_run base 1 -options_file input/hertz2d.opts -contact_shift_accel schur || return 1
  schur_run mm 1 -options_file input/hertz2d.opts -contact_shift_accel schur -dm_plex_scale 10 -material_E 210000 -bc_1_value 1050 || return 1
  same_summary "$CASE_DIR/base.txt" "$CASE_DIR/mm.txt" 0 newton_iterations contact_shift_accel_solves contact_active_points || rc=1
  assert_le penetration_mm "$(sval "$CASE_DIR/mm.txt" contact_max_penetration)" "$(sval "$CASE_DIR/mm.txt" contact_gap_tol)" || rc=1
  return $rc
}

# Pairs across ranks (B6, the master facets of another rank gathered): 1, 2 and 3 ranks agree
# (figures to 1e-8, the same Newton iterations), at most penalty + 2 Newton iterations at alpha 10
# (measured 9 against 7; the plain update 12)
test_schur_pairs_ranks() {
  local rc=0 np
  schur_run pen 1 -options_file input/hertz2d_twobody.opts -contact_method penalty || return 1
  for np in 1 2 3; do
    schur_run np$np $np -options_file input/hertz2d_twobody.opts -contact_shift_accel schur || return 1
    echo "B6 np$np: newton $(sval "$CASE_DIR/np$np.txt" newton_iterations) (penalty $(sval "$CASE_DIR/pen.txt" newton_iterations)), back-substitutions $(sval "$CASE_DIR/np$np.txt" contact_shift_accel_solves)"
    assert_eq converged_np$np "$(sval "$CASE_DIR/np$np.txt" converged)" yes || rc=1
    assert_le penetration_np$np "$(sval "$CASE_DIR/np$np.txt" contact_max_penetration)" "$(sval "$CASE_DIR/np$np.txt" contact_gap_tol)" || rc=1
  done
  assert_le newton "$(sval "$CASE_DIR/np1.txt" newton_iterations)" $(($(sval "$CASE_DIR/pen.txt" newton_iterations) + 2)) || rc=1
  for np in 2 3; do
    same_summary "$CASE_DIR/np1.txt" "$CASE_DIR/np$np.txt" 1e-8 contact_force_y contact_peak_pressure displacement_max || rc=1
    same_summary "$CASE_DIR/np1.txt" "$CASE_DIR/np$np.txt" 0 newton_iterations contact_active_points || rc=1
  done
  return $rc
}

# B4 (3D, 16^3 Q1) with a factorization at alpha 10: at most penalty + 3 Newton iterations (measured
# 6 against 3; the plain update 9), the force of the plain update to 1e-8
test_schur_b4_direct() {
  local rc=0 o="-options_file input/indent3d.opts -dm_plex_box_faces 16,16,16 -pc_type cholesky -contact_alpha 10"
  schur_run pen 1 $o -contact_method penalty || return 1
  schur_run none 1 $o || return 1
  schur_run schur 1 $o -contact_shift_accel schur || return 1
  echo "B4 16^3 alpha 10: newton penalty $(sval "$CASE_DIR/pen.txt" newton_iterations) plain $(sval "$CASE_DIR/none.txt" newton_iterations) schur $(sval "$CASE_DIR/schur.txt" newton_iterations)"
  assert_eq converged "$(sval "$CASE_DIR/schur.txt" converged)" yes || rc=1
  assert_le newton "$(sval "$CASE_DIR/schur.txt" newton_iterations)" $(($(sval "$CASE_DIR/pen.txt" newton_iterations) + 3)) || rc=1
  assert_le penetration "$(sval "$CASE_DIR/schur.txt" contact_max_penetration)" "$(sval "$CASE_DIR/schur.txt" contact_gap_tol)" || rc=1
  same_summary "$CASE_DIR/none.txt" "$CASE_DIR/schur.txt" 1e-8 contact_force_z || rc=1
  return $rc
}

# alm: one augmentation on B2 at alpha 10 (the plain augmentation: 7), the same force
test_schur_alm() {
  local rc=0
  schur_run alm 1 -options_file input/hertz2d.opts -contact_method alm -contact_shift_accel schur || return 1
  echo "alm B2: augmentations $(sval "$CASE_DIR/alm.txt" contact_augmentations), newton $(sval "$CASE_DIR/alm.txt" newton_iterations)"
  assert_eq converged "$(sval "$CASE_DIR/alm.txt" converged)" yes || rc=1
  assert_eq augmentations "$(sval "$CASE_DIR/alm.txt" contact_augmentations)" 1 || rc=1
  assert_close force "$(sval "$CASE_DIR/alm.txt" contact_force_y)" 5e-3 1e-8 || rc=1
  return $rc
}

# Without a factorization (GAMG) the update stays the plain one and one line says so: the plain
# update's Newton iterations, no Schur step; with -contact_two_pass it is refused (singular)
test_schur_fallback_and_refusal() {
  local rc=0
  schur_run none 1 -options_file input/hertz2d.opts -pc_type gamg || return 1
  schur_run gamg 1 -options_file input/hertz2d.opts -pc_type gamg -contact_shift_accel schur || return 1
  assert_eq notice "$(grep -c '^shift update: -contact_shift_accel schur back-substitutes with a factorization' "$CASE_DIR/gamg.txt")" 1 || rc=1
  assert_eq steps "$(sval "$CASE_DIR/gamg.txt" contact_shift_accel_steps)" 0 || rc=1
  same_summary "$CASE_DIR/none.txt" "$CASE_DIR/gamg.txt" 0 newton_iterations contact_force_y || rc=1
  bad_input_cases <<'CASES' || rc=1
schur update with two passes|input/patch_4_5.opts|-contact_two_pass -contact_shift_accel schur
CASES
  return $rc
}

# Friction (2D, the factorization from the start): F1a, the block that sticks, keeps its creep
# below 1e-10 h (h = 0.025) within penalty + 3 Newton iterations (measured 8 against 6); F1b, the
# block that slides, the force mu N to 1e-8 in fewer Newton iterations than the plain update
# (measured 35 against 53; penalty 27)
test_schur_friction_block() {
  local rc=0
  schur_run f1a_pen 1 -options_file input/friction_block2d.opts -contact_method penalty || return 1
  schur_run f1a 1 -options_file input/friction_block2d.opts -contact_shift_accel schur || return 1
  schur_run f1b_none 1 -options_file input/friction_slide2d.opts || return 1
  schur_run f1b 1 -options_file input/friction_slide2d.opts -contact_shift_accel schur || return 1
  echo "F1a: newton penalty $(sval "$CASE_DIR/f1a_pen.txt" newton_iterations) schur $(sval "$CASE_DIR/f1a.txt" newton_iterations), creep $(sval "$CASE_DIR/f1a.txt" contact_max_stick_creep); F1b: newton plain $(sval "$CASE_DIR/f1b_none.txt" newton_iterations) schur $(sval "$CASE_DIR/f1b.txt" newton_iterations)"
  assert_eq converged_f1a "$(sval "$CASE_DIR/f1a.txt" converged)" yes || rc=1
  assert_le creep_f1a "$(sval "$CASE_DIR/f1a.txt" contact_max_stick_creep)" 2.5e-12 || rc=1
  assert_le newton_f1a "$(sval "$CASE_DIR/f1a.txt" newton_iterations)" $(($(sval "$CASE_DIR/f1a_pen.txt" newton_iterations) + 3)) || rc=1
  assert_eq stick_f1a "$(sval "$CASE_DIR/f1a.txt" contact_stick_points)" "$(sval "$CASE_DIR/f1a_pen.txt" contact_stick_points)" || rc=1
  assert_eq converged_f1b "$(sval "$CASE_DIR/f1b.txt" converged)" yes || rc=1
  assert_close force_f1b "$(sval "$CASE_DIR/f1b.txt" contact_tangential_force_x)" -0.003 1e-8 || rc=1
  assert_le newton_f1b "$(sval "$CASE_DIR/f1b.txt" newton_iterations)" "$(sval "$CASE_DIR/f1b_none.txt" newton_iterations)" || rc=1
  return $rc
}

# Finite strain (Neo-Hookean B2 at 10x its load, 10 steps, alpha 10): the Schur update
# back-substitutes with each step's finite-strain tangent; within penalty + 2 Newton iterations per
# load step (measured 68 against penalty's 56; the seed's update 111), the peak pressure of the
# plain update (0.1693159124474) to 1e-8
test_schur_neohookean() {
  local rc=0 o="-options_file input/hertz2d.opts -material_model neo_hookean -bc_1_value 0.05 -load_steps 10 -contact_alpha 10"
  schur_run pen 1 $o -contact_method penalty || return 1
  schur_run nh 1 $o -contact_shift_accel schur || return 1
  echo "Neo-Hookean B2 x10: newton penalty $(sval "$CASE_DIR/pen.txt" newton_iterations) schur $(sval "$CASE_DIR/nh.txt" newton_iterations), penetration $(sval "$CASE_DIR/nh.txt" contact_max_penetration)"
  assert_eq converged "$(sval "$CASE_DIR/nh.txt" converged)" yes || rc=1
  assert_le newton "$(sval "$CASE_DIR/nh.txt" newton_iterations)" $(($(sval "$CASE_DIR/pen.txt" newton_iterations) + 20)) || rc=1
  assert_le penetration "$(sval "$CASE_DIR/nh.txt" contact_max_penetration)" "$(sval "$CASE_DIR/nh.txt" contact_gap_tol)" || rc=1
  assert_close peak "$(sval "$CASE_DIR/nh.txt" contact_peak_pressure)" 0.1693159124474 1e-8 || rc=1
  return $rc
}

# 3D friction (F3 in 5 load steps as cattaneo3d_f3_shifted, MUMPS LU): the stuck points'
# tangential shifts and the slipping points' (which follow p and turn towards the slip by
# kappa = mu p/|y| < 1 of the way per plain update) are rows. Within penalty + 3 Newton iterations
# per load step (measured 47 against penalty's 36; with only the stuck points' rows 59), the stick
# radius within one element, creep <= 1e-10 h, Q/F = 0.15 to 1e-8, and the same figures (1e-8) and
# Newton iterations on 2 ranks. About 5 minutes.
test_schur_friction3d() {
  local rc=0 np o="-options_file input/cattaneo3d.opts -load_steps 5 -bc_2_ramp 0,0.2 -bc_3_ramp 0.2,1 -bc_4_ramp 0.2,1 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -output_fields false"
  schur_run pen 1 $o -contact_method penalty || return 1
  for np in 1 2; do
    cm_run f3_np$np $np cm3d $o -contact_shift_accel schur || return 1
    assert_le "newton_np$np" "$(sval "$CASE_DIR/f3_np$np.txt" newton_iterations)" $(($(sval "$CASE_DIR/pen.txt" newton_iterations) + 15)) || rc=1
    assert_le "radius_error_elements_np$np" "$(cmabs f3_np$np radius_error_elements)" 1 || rc=1
    assert_le "stick_creep_np$np" "$(sval "$CASE_DIR/f3_np$np.txt" contact_max_stick_creep)" 1e-12 || rc=1
    assert_close "force_ratio_np$np" "$(awk -v x="$(sval "$CASE_DIR/f3_np$np.txt" contact_force_x)" -v z="$(sval "$CASE_DIR/f3_np$np.txt" contact_force_z)" 'BEGIN{printf "%.12g", x / z}')" -0.15 1e-8 || rc=1
  done
  echo "F3 (5 steps, LU): newton penalty $(sval "$CASE_DIR/pen.txt" newton_iterations) schur $(sval "$CASE_DIR/f3_np1.txt" newton_iterations) ($(sval "$CASE_DIR/f3_np1.txt" contact_shift_accel_solves) back-substitutions)"
  same_summary "$CASE_DIR/f3_np1.txt" "$CASE_DIR/f3_np2.txt" 1e-8 contact_force_x contact_force_z contact_tangential_force_x || rc=1
  same_summary "$CASE_DIR/f3_np1.txt" "$CASE_DIR/f3_np2.txt" 0 newton_iterations contact_stick_points || rc=1
  return $rc
}
