# Anderson acceleration of the in-Newton shift update (-contact_shift_accel anderson, issue
# "Performance"): on a settled active set the plain update s <- s + g contracts by about
# k/(k + eps) per update; Anderson mixing of the last m updates over all active points (one global
# least-squares problem, reductions only) is GMRES on the shifts for an affine map.
# Counts measured with a direct solver (scripts/compare_accel.sh), so they measure the update.

# B2 at alpha 10, 100, 1000: converged to the gap tolerance, the same contact force as the plain
# update (1e-8), Newton iterations at most the plain update's (measured: 8/5/4 against 9/5/4)
test_accel_b2() {
  local rc=0 a n0 n1
  for a in 10 100 1000; do
    spc "$CASE_DIR/none_$a.txt" 1 -options_file input/hertz2d.opts -contact_alpha $a -pc_type cholesky -output_dir "$CASE_DIR" -output_name none_$a -output_fields false || return 1
    spc "$CASE_DIR/and_$a.txt" 1 -options_file input/hertz2d.opts -contact_alpha $a -pc_type cholesky -contact_shift_accel anderson -output_dir "$CASE_DIR" -output_name and_$a -output_fields false || return 1
    n0=$(sval "$CASE_DIR/none_$a.txt" newton_iterations); n1=$(sval "$CASE_DIR/and_$a.txt" newton_iterations)
    echo "B2 alpha $a: newton plain $n0 anderson $n1, max penetration $(sval "$CASE_DIR/and_$a.txt" contact_max_penetration)"
    assert_eq converged_$a "$(sval "$CASE_DIR/and_$a.txt" converged)" yes || rc=1
    assert_le newton_$a "$n1" "$n0" || rc=1
    assert_le penetration_$a "$(sval "$CASE_DIR/and_$a.txt" contact_max_penetration)" "$(sval "$CASE_DIR/and_$a.txt" contact_gap_tol)" || rc=1
    assert_close force_$a "$(sval "$CASE_DIR/and_$a.txt" contact_force_y)" "$(sval "$CASE_DIR/none_$a.txt" contact_force_y)" 1e-8 || rc=1
  done
  assert_le newton_alpha10 "$(sval "$CASE_DIR/and_10.txt" newton_iterations)" 8 || rc=1
  # the summary names the rule and counts the accelerated updates (alpha 10: 5 of the 6 updates)
  assert_eq accel_key "$(sval "$CASE_DIR/and_10.txt" contact_shift_accel)" anderson || rc=1
  assert_eq accel_steps_alpha10 "$(sval "$CASE_DIR/and_10.txt" contact_shift_accel_steps)" 5 || rc=1
  return $rc
}

# patch2p_alpha10 NAME NP KEY BOUND OPTS...: the two-pass patch test at alpha 10 converges in one
# step (no cut-back) with KEY <= BOUND, pressure deviation <= 1e-6 and the force 0.01 to 1e-8
patch2p_alpha10() {
  local name=$1 np=$2 key=$3 bound=$4 rc=0 dev; shift 4
  local out=$CASE_DIR/$name.txt
  spc "$out" "$np" -options_file input/patch_4_5.opts -contact_two_pass -contact_alpha 10 -output_dir "$CASE_DIR" -output_name "$name" "$@" || return 1
  dev=$(pairs_pressure_dev "$CASE_DIR/${name}_contact.csv" 0.01)
  echo "$name: newton $(sval "$out" newton_iterations) augmentations $(sval "$out" contact_augmentations) cutbacks $(sval "$out" cutbacks) pressure_deviation $dev"
  assert_eq "accel_$name" "$(sval "$out" contact_shift_accel)" anderson || rc=1
  assert_eq "converged_$name" "$(sval "$out" converged)" yes || rc=1
  assert_eq "cutbacks_$name" "$(sval "$out" cutbacks)" 0 || rc=1
  assert_le "${key}_$name" "$(sval "$out" "$key")" "$bound" || rc=1
  assert_le "pressure_deviation_$name" "$dev" 1e-6 || rc=1
  assert_close "contact_force_$name" "$(sval "$out" contact_force_y)" 0.01 1e-8 || rc=1
  return $rc
}

# The two-pass patch test at alpha 10: the plain update needs 11 cut-backs and 2048 load steps without growth
# (about 1e5 Newton iterations); Anderson converges in one step (measured: 10 iterations) and
# passes the patch test (pressure deviation <= 1e-6, force 0.01 to 1e-8)
test_accel_patch_two_pass_alpha10() { patch2p_alpha10 p 1 newton_iterations 12 -contact_shift_accel anderson; }

# alm accelerates its augmentation (s <- s + g after each converged solve) the same way, with a
# history that spans the augmentations of a load step; with -contact_two_pass that is its default
# too. The two-pass patch test at alpha 10: the plain augmentation contracts by about 0.92 and
# did not converge (1375 Newton iterations, 840 augmentations, 13 cut-backs); Anderson converges
# in one step (measured: 23 Newton iterations, 8 augmentations) and passes the patch test, with
# the same figures on 1, 2 and 3 ranks. At the gap rtol 1e-12: with the inexact inner solves
# (-solver_inexact_inner) the ranks' peak pressures spread by 1.6e-8 at the default 1e-10, inside
# what that tolerance allows (eps x gap_tol, about 1e-7 of the pressure), not the 1e-8 compared here.
test_accel_alm_patch_two_pass_alpha10() {
  local rc=0 np
  for np in 1 2 3; do patch2p_alpha10 np$np $np contact_augmentations 12 -contact_method alm -contact_gap_rtol 1e-12 || rc=1; done
  for np in 2 3; do same_summary "$CASE_DIR/np1.txt" "$CASE_DIR/np$np.txt" 1e-8 contact_force_y contact_peak_pressure displacement_max || rc=1; done
  return $rc
}

# 1, 2 and 3 ranks give the same figures (global reductions only), B4 16^3 at alpha 10 (GAMG)
test_accel_ranks() {
  local rc=0 np
  for np in 1 2 3; do
    spc "$CASE_DIR/np$np.txt" $np -options_file input/indent3d.opts -dm_plex_box_faces 16,16,16 -contact_alpha 10 -contact_shift_accel anderson -output_dir "$CASE_DIR" -output_name np$np -output_fields false || return 1
    echo "ranks $np: newton $(sval "$CASE_DIR/np$np.txt" newton_iterations) force_z $(sval "$CASE_DIR/np$np.txt" contact_force_z)"
  done
  for np in 2 3; do
    assert_eq converged_np$np "$(sval "$CASE_DIR/np$np.txt" converged)" yes || rc=1
    same_summary "$CASE_DIR/np1.txt" "$CASE_DIR/np$np.txt" 1e-8 contact_force_z contact_peak_pressure contact_active_points || rc=1
    assert_le penetration_np$np "$(sval "$CASE_DIR/np$np.txt" contact_max_penetration)" "$(sval "$CASE_DIR/np$np.txt" contact_gap_tol)" || rc=1
  done
  return $rc
}

# The default is the seed's plain update: no option and -contact_shift_accel none agree exactly;
# a bad depth is one line
test_accel_default_unchanged() {
  local rc=0
  spc "$CASE_DIR/def.txt" 1 -options_file input/hertz2d.opts -output_dir "$CASE_DIR" -output_name def -output_fields false || return 1
  spc "$CASE_DIR/none.txt" 1 -options_file input/hertz2d.opts -contact_shift_accel none -output_dir "$CASE_DIR" -output_name none -output_fields false || return 1
  same_summary "$CASE_DIR/def.txt" "$CASE_DIR/none.txt" 0 newton_iterations linear_iterations contact_force_y contact_max_penetration || rc=1
  assert_eq accel_key "$(sval "$CASE_DIR/def.txt" contact_shift_accel)" none || rc=1
  assert_eq accel_steps "$(sval "$CASE_DIR/def.txt" contact_shift_accel_steps)" 0 || rc=1
  bad_input_cases <<'CASES' || rc=1
accel depth zero|input/hertz2d.opts|-contact_shift_accel anderson -contact_shift_accel_depth 0
accel type unknown|input/hertz2d.opts|-contact_shift_accel aitken
accel with a method that has no plain shift update|input/hertz2d.opts|-contact_method penalty -contact_shift_accel anderson
CASES
  return $rc
}

# With friction Anderson also steps the stuck points' tangential shifts (s_T <- s_T + Dg_T, the
# same affine fixed point). F4, the frictional two-pass patch at alpha 100: the plain update takes
# 136 Newton iterations, Anderson 37 (measured; 177 and 50 before -contact_friction_stick_hold);
# both pass the patch (pressure and tangential traction at every point within 1e-6, creep <=
# 1e-10 h, force Q to 1e-8); 1, 2 and 3 ranks agree (figures to 1e-8, Newton iterations within
# one).
test_accel_friction_patch() {
  local rc=0 np
  for np in 1 2 3; do
    local out=$CASE_DIR/np$np.txt dev
    spc "$out" $np -options_file input/friction_patch_4_5.opts -contact_shift_accel anderson -output_dir "$CASE_DIR" -output_name np$np || return 1
    dev=$(awk -F, 'NR>1{ d = ($8 - 0.01) / 0.01; if (d < 0) d = -d; if (d > p) p = d; t = $10 < 0 ? -$10 : $10; e = (t - 0.0015) / 0.0015; if (e < 0) e = -e; if (e > q) q = e } END { printf "%.3e %.3e\n", p, q }' "$CASE_DIR/np${np}_contact.csv")
    echo "np$np: newton $(sval "$out" newton_iterations) accel_steps $(sval "$out" contact_shift_accel_steps) pressure deviation ${dev% *} traction deviation ${dev#* }"
    assert_eq "converged_np$np" "$(sval "$out" converged)" yes || rc=1
    assert_le "newton_np$np" "$(sval "$out" newton_iterations)" 60 || rc=1
    assert_le "pressure_deviation_np$np" "${dev% *}" 1e-6 || rc=1
    assert_le "traction_deviation_np$np" "${dev#* }" 1e-6 || rc=1
    assert_le "stick_creep_np$np" "$(sval "$out" contact_max_stick_creep)" 2e-11 || rc=1
    assert_close "force_x_np$np" "$(sval "$out" contact_force_x)" -0.0015 1e-8 || rc=1
  done
  for np in 2 3; do
    same_summary "$CASE_DIR/np1.txt" "$CASE_DIR/np$np.txt" 1e-8 contact_force_x contact_force_y contact_peak_pressure displacement_max contact_stick_points || rc=1
    # 3 ranks add off-rank contributions in message arrival order: round-off that can move the
    # last Newton iteration of a step (49 against 50 in one of five 3-rank runs)
    assert_close "newton_np${np}_vs_np1" "$(sval "$CASE_DIR/np$np.txt" newton_iterations)" "$(sval "$CASE_DIR/np1.txt" newton_iterations)" 0 1 || rc=1
  done
  return $rc
}
