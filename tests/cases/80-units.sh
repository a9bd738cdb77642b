# Tolerances and units (README "Tolerances and units"): the same Hertz case in three consistent unit
# systems gives the same Newton counts and relative figures; the two-material patch test meets its
# bound at E ratios 1 and 10 with the default (relative) gap tolerance; the cut-back floor, the
# stagnation test and the wall-time limit each stop a run with one line naming the cause.
# Helpers are prefixed un_ so they cannot collide with other case files.

# B2 (input/hertz2d.opts: R = 1, E = 1, nu = 0.3, pressure 0.005 on the top edge) in unit systems
# "name|options": lengths scaled by L (-dm_plex_scale), stresses by S (E and the pressure); the
# rigid-plane Hertz figures scale as b x L, p0 x S (b = 0.107641, p0 = 0.0591431).
UN_SYSTEMS="base|1|1|
mm-N-MPa (steel, R = 10 mm)|10|210000|-dm_plex_scale 10 -material_E 210000 -bc_1_value 1050
m-N-Pa (steel, R = 0.01 m)|0.01|2.1e11|-dm_plex_scale 0.01 -material_E 2.1e11 -bc_1_value 1.05e9
scaled (L = 1000, S = 1e-3)|1000|1e-3|-dm_plex_scale 1000 -material_E 1e-3 -bc_1_value 5e-6"

# un_rel OUT L S : "penetration/b pressure_error" of a run in a system of length L and stress S
un_rel() {
  awk -v pen="$(sval "$1" contact_max_penetration)" -v pk="$(sval "$1" contact_peak_pressure)" -v L="$2" -v S="$3" \
    'BEGIN { e = pk / (0.0591431 * S) - 1; if (e < 0) e = -e; printf "%.6e %.6e\n", pen / (0.107641 * L), e }'
}

# un_within10 NAME VALUE REF : VALUE within a factor 10 of REF (both > 0; equal zeros pass)
un_within10() {
  awk -v n="$1" -v v="$2" -v r="$3" 'BEGIN { ok = (v == r) || (v > 0 && r > 0 && v <= 10 * r && r <= 10 * v)
    printf "%s: %.4g vs base %.4g (within 10x) %s\n", n, v, r, ok ? "ok" : "FAILED"; exit !ok }'
}

un_hertz() {
  local np=$1 rc=0 m name L S args out k=0 base_n base_pen base_err rel n
  for m in penalty shifted alm; do
    k=0
    while IFS='|' read -r name L S args; do
      k=$((k + 1)); out=$CASE_DIR/${m}_${k}_np$np.txt
      # shellcheck disable=SC2086
      spc "$out" "$np" -options_file input/hertz2d.opts -contact_method $m -output_dir "$CASE_DIR" -output_name "${m}_$k" -output_fields false $args </dev/null || { echo "$m $name: run failed"; rc=1; continue; }
      n=$(sval "$out" newton_iterations); rel=$(un_rel "$out" "$L" "$S")
      echo "np $np $m $name: newton $n penetration/b ${rel% *} pressure_error ${rel#* } gap_tol $(sval "$out" contact_gap_tol)"
      if [ $k -eq 1 ]; then base_n=$n; base_pen=${rel% *}; base_err=${rel#* }; continue; fi
      assert_close "newton_${m}_$k" "$n" "$base_n" 0 1 || rc=1
      un_within10 "penetration_over_b_${m}_$k" "${rel% *}" "$base_pen" || rc=1
      un_within10 "pressure_error_${m}_$k" "${rel#* }" "$base_err" || rc=1
    done <<<"$UN_SYSTEMS"
  done
  return $rc
}

test_units_hertz_np1() { un_hertz 1; }
test_units_hertz_np2() { un_hertz 2; }

# Two-material patch test (input/patch_4_5_materials.opts, no gap tolerance given): stiff block
# E = 1 and 10 against the soft one (E = 1): force q to 1e-8, pressure q at every point to 1e-6
test_units_patch_materials() {
  local rc=0 np E out dev
  for np in 1 2; do
    for E in 1 10; do
      out=$CASE_DIR/E${E}_np$np.txt
      spc "$out" "$np" -options_file input/patch_4_5_materials.opts -material_1_E "$E" -output_dir "$CASE_DIR" -output_name "E${E}_np$np" || { echo "E $E np $np: run failed"; rc=1; continue; }
      dev=$(awk -F, -v q=0.01 'NR>1 { d = ($8 - q) / q; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.3e\n", m }' "$CASE_DIR/E${E}_np${np}_contact.csv")
      echo "E ratio $E np $np: newton $(sval "$out" newton_iterations) gap_rtol $(sval "$out" contact_gap_rtol) gap_tol $(sval "$out" contact_gap_tol) pressure_deviation $dev"
      assert_ge "gap_rtol_in_use_E$E" "$(sval "$out" contact_gap_rtol)" 1e-300 || rc=1
      assert_close "contact_force_E${E}_np$np" "$(sval "$out" contact_force_y)" 0.01 1e-8 || rc=1
      assert_le "pressure_deviation_E${E}_np$np" "$dev" 1e-6 || rc=1
    done
  done
  return $rc
}

# Cut-back floor: B2 with 2 Newton iterations per solve never converges; increments 1, 0.5, 0.25
# fail, halving 0.25 would go below -load_min_increment 0.2: exactly 2 cut-backs, one stop line
test_units_cutback_floor() {
  local out=$CASE_DIR/run.txt code rc=0
  spc "$out" 1 -options_file input/hertz2d.opts -output_dir "$CASE_DIR" -snes_max_it 2 -load_min_increment 0.2; code=$?
  grep -E "^(stopping|cutting)" "$out"
  assert_eq exit_code "$code" 2 || rc=1
  assert_eq cutbacks "$(sval "$out" cutbacks)" 2 || rc=1
  assert_eq stop_lines "$(grep -c '^stopping: load factor 0.25 not reached: halving the increment 0.25 would go below -load_min_increment 0.2' "$out")" 1 || rc=1
  # the budget: -load_max_cutbacks 1 stops after one cut-back whatever the floor
  spc "$CASE_DIR/budget.txt" 1 -options_file input/hertz2d.opts -output_dir "$CASE_DIR" -output_name budget -snes_max_it 2 -load_max_cutbacks 1; code=$?
  assert_eq exit_code_budget "$code" 2 || rc=1
  assert_eq cutbacks_budget "$(sval "$CASE_DIR/budget.txt" cutbacks)" 1 || rc=1
  assert_eq budget_line "$(grep -c '^stopping: .*cut-back budget spent (1 cut-backs, -load_max_cutbacks)' "$CASE_DIR/budget.txt")" 1 || rc=1
  return $rc
}

# The two-pass curved stall (issue 12): two-pass shifted on the two-body Hertz case. alpha 100
# converges. At alpha 1000 the semismooth Newton iteration cycles between two active sets (period
# 2, ~19 points flip, the shift never updates): the stagnation test stops the solve after
# -solver_stall_its iterations without progress with one line naming the stall and one naming its
# cause (the active set changed at every one of them) and what to use instead. Why it cycles: on a
# curved non-matching interface the two passes cannot close every gap of both surfaces at once,
# the shifts of the two sides compete for the same points, and one h of new penetration per
# Newton step (the default -contact_step_cap 1) is far more than the penetration at this penalty.
# The recovery then solves the step again with the cap at 0.1 (once per step, one line) and it
# converges without a cut-back: the force to 1e-8, 51 Newton iterations (15 of them stalled).
# Without the step control (-contact_step_cap 0: no recovery either) both solves stall, the
# cut-back budget ends the run, exit 2, before -snes_max_it (50) each. All of this without the
# chatter hold (-contact_chatter_flips 0); with it (the default) the first solve stalls too and the
# recovery converges in 56 Newton iterations, and without the step control the hold alone breaks
# the cycle (37 Newton iterations, no cut-back).
test_units_twopass_stall() {
  local out rc=0 code n
  out=$CASE_DIR/a100.txt
  spc "$out" 1 -options_file input/hertz2d_twobody.opts -contact_two_pass -contact_alpha 100 -output_dir "$CASE_DIR" -output_name a100 -output_fields false; code=$?
  echo "alpha 100: exit $code converged $(sval "$out" converged) newton $(sval "$out" newton_iterations)"
  assert_eq converged_alpha100 "$(sval "$out" converged)" yes || rc=1
  assert_close force_alpha100 "$(sval "$out" contact_force_y)" 0.005 1e-8 || rc=1
  out=$CASE_DIR/a1000.txt
  spc "$out" 1 -options_file input/hertz2d_twobody.opts -contact_two_pass -contact_alpha 1000 -contact_chatter_flips 0 -load_max_cutbacks 1 -output_dir "$CASE_DIR" -output_name a1000 -output_fields false; code=$?
  grep -E "^(solve stalled|stopping|load step|Newton did not)" "$out"
  assert_eq exit_code_alpha1000 "$code" 0 || rc=1
  assert_eq stall_lines_alpha1000 "$(grep -c '^solve stalled: neither the residual .* nor the gap error .* decreased in 15 Newton iterations (-solver_stall_its)' "$out")" 1 || rc=1
  assert_eq recovery_line "$(grep -c '^Newton did not converge: the load step again with -contact_step_cap 0.1 until a load step converges$' "$out")" 1 || rc=1
  assert_eq step_cap_retries "$(sval "$out" contact_retries_step_cap)" 1 || rc=1
  assert_eq cutbacks_alpha1000 "$(sval "$out" cutbacks)" 0 || rc=1
  assert_close force_alpha1000 "$(sval "$out" contact_force_y)" 0.005 1e-8 || rc=1
  assert_le gap_error_alpha1000 "$(sval "$out" contact_gap_error)" "$(sval "$out" contact_gap_tol)" || rc=1
  assert_le newton_alpha1000 "$(sval "$out" newton_iterations)" 60 || rc=1
  out=$CASE_DIR/nocap.txt
  spc "$out" 1 -options_file input/hertz2d_twobody.opts -contact_two_pass -contact_alpha 1000 -contact_chatter_flips 0 -contact_step_cap 0 -load_max_cutbacks 1 -output_dir "$CASE_DIR" -output_name nocap -output_fields false; code=$?
  grep -E "^(solve stalled|stopping|load step|Newton did not)" "$out"
  n=$(sval "$out" newton_iterations)
  assert_eq exit_code_nocap "$code" 2 || rc=1
  assert_eq stall_lines "$(grep -c '^solve stalled: neither the residual .* nor the gap error .* decreased in 15 Newton iterations (-solver_stall_its)' "$out")" 2 || rc=1
  assert_eq stalled_reason "$(grep -c 'solve did not converge (STALLED)' "$out")" 2 || rc=1
  # the stall names its cause (an active-set cycle) and what to use instead
  assert_eq cycle_lines "$(grep -c '^solve stalled: the active set changed in 15 of those iterations (an active-set cycle): with -contact_two_pass use one pass' "$out")" 2 || rc=1
  assert_eq no_recovery "$(grep -c '^Newton did not converge' "$out")" 0 || rc=1
  assert_eq cutbacks "$(sval "$out" cutbacks)" 1 || rc=1
  assert_le newton_bounded "$n" 98 || rc=1
  return $rc
}

# Two-pass at alpha 10 (issue 12): the two passes' redundant constraints make the plain shift
# update contract by about 0.92 per iteration, so the plain rule reaches -snes_max_it in every
# solve (unbounded before the cut-back budget: 3029 Newton iterations and 20 cut-backs, exit 2).
# With -contact_two_pass the shifted method defaults to Anderson acceleration, which converges in
# one step: 44 Newton iterations, the force to 1e-8, the same on 1 and 2 ranks. The plain rule,
# asked for, still ends within the budget (-load_max_cutbacks 1: 4 solves of -snes_max_it 50).
# alm (Anderson across its augmentations) needs 40 augmentations, 58 Newton iterations: with the
# old budget of 30 it took 515 and 3 cut-backs.
# twopass_a10 TAG NEWTON_MAX [options]: two-pass B6 at alpha 10 on 1 and 2 ranks: converged in one
# step (no cut-back, no step-cap retry), at most NEWTON_MAX Newton iterations, the force to 1e-8,
# the gap tolerance met, the same figures on both rank counts
twopass_a10() {
  local tag=$1 nmax=$2 rc=0 np out; shift 2
  for np in 1 2; do
    out=$CASE_DIR/$tag$np.txt
    spc "$out" $np -options_file input/hertz2d_twobody.opts -contact_two_pass -contact_alpha 10 "$@" -output_dir "$CASE_DIR" -output_name $tag$np -output_fields false || return 1
    echo "$tag np $np: newton $(sval "$out" newton_iterations) accel $(sval "$out" contact_shift_accel) steps $(sval "$out" contact_shift_accel_steps) augmentations $(sval "$out" contact_augmentations) force $(sval "$out" contact_force_y)"
    assert_eq "${tag}_converged_np$np" "$(sval "$out" converged)" yes || rc=1
    assert_eq "${tag}_cutbacks_np$np" "$(sval "$out" cutbacks)" 0 || rc=1
    assert_eq "${tag}_retries_np$np" "$(sval "$out" contact_retries_step_cap)" 0 || rc=1
    assert_le "${tag}_newton_np$np" "$(sval "$out" newton_iterations)" "$nmax" || rc=1
    assert_close "${tag}_force_np$np" "$(sval "$out" contact_force_y)" 0.005 1e-8 || rc=1
    assert_le "${tag}_gap_error_np$np" "$(sval "$out" contact_gap_error)" "$(sval "$out" contact_gap_tol)" || rc=1
  done
  SAME_ATOL=1e-12 same_summary "$CASE_DIR/${tag}1.txt" "$CASE_DIR/${tag}2.txt" 1e-8 contact_force_y contact_peak_pressure || rc=1
  return $rc
}

test_units_twopass_alpha10() {
  local rc=0 np out code
  twopass_a10 np 50 || rc=1
  for np in 1 2; do assert_eq "accel_default_np$np" "$(sval "$CASE_DIR/np$np.txt" contact_shift_accel)" anderson || rc=1; done
  twopass_a10 alm 70 -contact_method alm || rc=1 # alm's default budget (-contact_alm_max 50) holds its 40 augmentations
  out=$CASE_DIR/plain.txt
  spc "$out" 1 -options_file input/hertz2d_twobody.opts -contact_two_pass -contact_alpha 10 -contact_shift_accel none -load_max_cutbacks 1 -output_dir "$CASE_DIR" -output_name plain -output_fields false; code=$?
  grep -E "^(stopping|load step)" "$out"
  assert_eq exit_code_plain "$code" 2 || rc=1
  assert_eq accel_plain "$(sval "$out" contact_shift_accel)" none || rc=1
  assert_le newton_plain_bounded "$(sval "$out" newton_iterations)" 200 || rc=1
  assert_eq budget_line_plain "$(grep -c '^stopping: .*cut-back budget spent (1 cut-backs, -load_max_cutbacks)' "$out")" 1 || rc=1
  return $rc
}

# The chatter hold is off by default with -contact_two_pass (contact-enforce.c): on the curved
# two-pass pairs it held points that open, shifted at alpha 10 and 100. Neo-Hookean two-pass B6
# (alpha 10): 326 Newton iterations, 2 step-cap retries and 159 holds with it, 47 and none without;
# the dissimilar pair (linear, alpha 100) 196 and 1 cut-back -> 26. Asserted: both converge in
# one step without a retry, the force to 1e-8, the same on 1 and 2 ranks.
test_units_twopass_neohookean_alpha10() { twopass_a10 nh 60 -material_model neo_hookean; }
test_units_twopass_dissimilar_alpha100() {
  local rc=0 np out
  for np in 1 2; do
    out=$CASE_DIR/dis$np.txt
    spc "$out" $np -options_file input/hertz2d_dissimilar.opts -contact_two_pass -contact_alpha 100 -output_dir "$CASE_DIR" -output_name dis$np -output_fields false || return 1
    echo "dissimilar two-pass np $np: newton $(sval "$out" newton_iterations) holds $(sval "$out" contact_chatter_holds) force $(sval "$out" contact_force_y)"
    assert_eq "converged_np$np" "$(sval "$out" converged)" yes || rc=1
    assert_eq "cutbacks_np$np" "$(sval "$out" cutbacks)" 0 || rc=1
    assert_eq "retries_np$np" "$(sval "$out" contact_retries_step_cap)" 0 || rc=1
    assert_le "newton_np$np" "$(sval "$out" newton_iterations)" 40 || rc=1
    assert_close "force_np$np" "$(sval "$out" contact_force_y)" 0.005 1e-8 || rc=1 # the top pressure 0.005 on a unit width
    assert_le "gap_error_np$np" "$(sval "$out" contact_gap_error)" "$(sval "$out" contact_gap_tol)" || rc=1
  done
  SAME_ATOL=1e-12 same_summary "$CASE_DIR/dis1.txt" "$CASE_DIR/dis2.txt" 1e-8 contact_force_y contact_peak_pressure || rc=1
  return $rc
}

# The step-cap retry on 1, 2 and 3 ranks: B6 (one pass) at alpha 1000 without the chatter hold
# (-contact_chatter_flips 0) stalls in its first Newton solve (an active-set cycle) and converges
# when the step is solved again with the cap at 0.1: one retry, no cut-back, the force to 1e-8, the
# same figures on every rank count (41 Newton iterations each; 146 and 3 cut-backs before the
# retry existed). With the hold (the default) see test_units_chatter_hold_ranks.
test_units_step_cap_retry_ranks() { b6_alpha1000_ranks 1 50 -contact_chatter_flips 0; }
# b6_alpha1000_ranks RETRIES NEWTON_MAX [options]: B6 at alpha 1000 on 1, 2 and 3 ranks converges
# with RETRIES step-cap retries, no cut-back, at most NEWTON_MAX Newton iterations, the force to
# 1e-8, the same figures on every rank count
b6_alpha1000_ranks() {
  local retries=$1 newton_max=$2 rc=0 np out; shift 2
  for np in 1 2 3; do
    out=$CASE_DIR/np$np.txt
    spc "$out" "$np" -options_file input/hertz2d_twobody.opts -contact_alpha 1000 "$@" -output_dir "$CASE_DIR" -output_name "np$np" -output_fields false || return 1
    assert_eq "converged_np$np" "$(sval "$out" converged)" yes || rc=1
    assert_eq "cutbacks_np$np" "$(sval "$out" cutbacks)" 0 || rc=1
    assert_eq "retries_np$np" "$(sval "$out" contact_retries_step_cap)" "$retries" || rc=1
    assert_close "force_np$np" "$(sval "$out" contact_force_y)" 0.005 1e-8 || rc=1
    assert_le "newton_np$np" "$(sval "$out" newton_iterations)" "$newton_max" || rc=1
  done
  for np in 2 3; do
    same_summary "$CASE_DIR/np1.txt" "$CASE_DIR/np$np.txt" 1e-8 contact_force_y contact_peak_pressure contact_active_points displacement_max || rc=1
  done
  return $rc
}

# The chatter hold (default -contact_chatter_flips 3, contact-enforce.c) on B6 at alpha 1000, 1, 2
# and 3 ranks: the points of its first solve that plunge in, bounce out and come back stay closed,
# so the solve does not stall: no retry, no cut-back, 19 Newton iterations (41 with the retry
# above), the force to 1e-8, the same figures on every rank count
test_units_chatter_hold_ranks() {
  local rc=0 np
  b6_alpha1000_ranks 0 25 || rc=1
  for np in 1 2 3; do
    assert_ge "chatter_holds_np$np" "$(sval "$CASE_DIR/np$np.txt" contact_chatter_holds)" 1 || rc=1
  done
  return $rc
}

# Wall time: a limit already passed when the first load step would start stops the run there with
# one line, exit 3 (a planned stop, not a failed step's 2), no step done, status stopped and a line on how to go on (no timing is asserted:
# any setup takes longer than 1 microsecond)
test_units_wall_time() {
  local out=$CASE_DIR/run.txt code rc=0
  spc "$out" 1 -options_file input/hertz2d.opts -output_dir "$CASE_DIR" -load_steps 3 -max_wall_time 1e-6; code=$?
  grep "^stopping" "$out"
  assert_eq exit_code "$code" 3 || rc=1
  assert_eq load_steps "$(sval "$out" load_steps)" 0 || rc=1
  assert_eq stop_lines "$(grep -c '^stopping: load factor 0.333333 not reached: wall time .* s exceeds -max_wall_time 1e-06; last converged load factor 0' "$out")" 1 || rc=1
  # a planned stop, not a failure (QA helper 27: it said failed, and nothing about a restart)
  assert_eq status "$(sval "$out" status)" stopped || rc=1
  assert_eq hint "$(grep -c '^spcontact: stopped by -max_wall_time before any load step converged: nothing to restart from; raise -max_wall_time$' "$out")" 1 || rc=1
  # a restarted run stopped before a step of its own points back to the file it restarted from
  spc "$CASE_DIR/a.txt" 1 -options_file input/hertz2d.opts -output_dir "$CASE_DIR" -output_name a -load_steps 3 -debug_interrupt_after_step 1
  spc "$CASE_DIR/b.txt" 1 -options_file input/hertz2d.opts -output_dir "$CASE_DIR" -output_name b -load_steps 3 -restart "$CASE_DIR/a.h5.part" -max_wall_time 1e-6; code=$?
  assert_eq restarted_exit_code "$code" 3 || rc=1
  assert_eq restarted_status "$(sval "$CASE_DIR/b.txt" status)" stopped || rc=1
  assert_eq restarted_hint "$(grep -c "^spcontact: stopped by -max_wall_time before a load step converged after the restart (load step 1, load factor 0.333333); restart with -restart $CASE_DIR/a.h5.part again" "$CASE_DIR/b.txt")" 1 || rc=1
  # a run with contact pairs stopped before its first solve has no Jacobian yet: its summary
  # crashed (SEGV in MatGetInfo, exit 59; QA helper 29); now the stop, with the pairs' keys
  local np
  for np in 1 2; do
    spc "$CASE_DIR/pair$np.txt" $np -options_file input/patch_4_5.opts -output_dir "$CASE_DIR" -output_name pair$np -max_wall_time 1e-6; code=$?
    assert_eq "pair_exit_code_np$np" "$code" 3 || rc=1
    assert_eq "pair_status_np$np" "$(sval "$CASE_DIR/pair$np.txt" status)" stopped || rc=1
    assert_eq "pair_mallocs_np$np" "$(sval "$CASE_DIR/pair$np.txt" contact_jacobian_mallocs)" 0. || rc=1
    assert_eq "pair_summary_end_np$np" "$(grep -c '^=== end summary ===' "$CASE_DIR/pair$np.txt")" 1 || rc=1
  done
  return $rc
}

# The residual's round-off floor: F1a (friction block, all points stick) at alpha 1000 sits at
# |F| 2e-13 to 3e-13 against the relative target 1.6e-13; every method stalled into the cut-back
# floor (10 cut-backs) before the floor test. Now each converges without a cut-back: penalty
# creeps tau/eps_T = 3.75e-8 (friction.md), shifted and alm below 1e-10 h (h = 0.025), the
# tangential force 0.0015 to 1e-8; on 1, 2 and 3 ranks with the same figures
test_units_roundoff_floor_f1a_alpha1000() {
  local rc=0 m np out
  for m in penalty shifted alm; do
    for np in 1 2 3; do
      out=$CASE_DIR/${m}_np$np.txt
      spc "$out" "$np" -options_file input/friction_block2d.opts -contact_method $m -contact_alpha 1000 -output_dir "$CASE_DIR" -output_name "${m}_np$np" -output_fields false || { echo "$m np $np: run failed"; rc=1; continue; }
      assert_eq "converged_${m}_np$np" "$(sval "$out" converged)" yes || rc=1
      assert_eq "cutbacks_${m}_np$np" "$(sval "$out" cutbacks)" 0 || rc=1
      assert_close "tangential_force_${m}_np$np" "$(sval "$out" contact_tangential_force_x)" -0.0015 1e-8 || rc=1
      if [ $m = penalty ]; then assert_close "creep_${m}_np$np" "$(sval "$out" contact_max_stick_creep)" 3.75e-8 1e-6 || rc=1
      else assert_le "creep_${m}_np$np" "$(sval "$out" contact_max_stick_creep)" 2.5e-12 || rc=1; fi
      assert_le "newton_${m}_np$np" "$(sval "$out" newton_iterations)" 24 || rc=1
    done
    for np in 2 3; do
      same_summary "$CASE_DIR/${m}_np1.txt" "$CASE_DIR/${m}_np$np.txt" 1e-8 contact_tangential_force_x contact_force_y displacement_max || rc=1
    done
  done
  return $rc
}

# A load small against E: F1b (friction_slide2d, full slip: T = mu N) at 1e-4 of its load (strain
# about 1e-6, steel under 0.2 MPa). The relative residual target (1e-10 of the first residual,
# 1.6e-17) lies below what the coordinates' round-off leaves in the contact forces (|F| ~ 2e-15),
# so every step stalled into the cut-back floor (QA helper 23, with every method). The round-off
# floor now counts that residual: converged without a cut-back, T = -mu N and N to 1e-8, the same
# figures on 2 and 3 ranks
test_units_small_load_friction() {
  local rc=0 m np out
  for m in penalty shifted alm; do
    for np in 1 2 3; do
      out=$CASE_DIR/${m}_np$np.txt
      spc "$out" "$np" -options_file input/friction_slide2d.opts -bc_0_value 1e-6 -bc_1_value 2e-6 -contact_method $m -output_dir "$CASE_DIR" -output_name "${m}_np$np" -output_fields false || { echo "$m np $np: run failed"; rc=1; continue; }
      assert_eq "converged_${m}_np$np" "$(sval "$out" converged)" yes || rc=1
      assert_eq "cutbacks_${m}_np$np" "$(sval "$out" cutbacks)" 0 || rc=1
      assert_close "normal_force_${m}_np$np" "$(sval "$out" contact_force_y)" 1e-6 1e-8 || rc=1
      assert_close "tangential_force_${m}_np$np" "$(sval "$out" contact_force_x)" -3e-7 1e-8 || rc=1
    done
    same_summary "$CASE_DIR/${m}_np1.txt" "$CASE_DIR/${m}_np2.txt" 1e-8 contact_force_x contact_force_y || rc=1
    same_summary "$CASE_DIR/${m}_np1.txt" "$CASE_DIR/${m}_np3.txt" 1e-8 contact_force_x contact_force_y || rc=1
  done
  return $rc
}

# A mesh far from the origin: a slip was the current position minus the reference one, which lost
# machine epsilon x |X| (1e-13 at x = 1000, above the slip test's 7.5e-14): F1b moved to x = 1000
# stopped after 9 cut-backs, at 1e6 at load 0 (QA helper 23). Slips now come from the displacements:
# at 1000 and 1e6 the same Newton iterations and T = -mu N, N to 1e-8 as at the origin, 1, 2 and 3 ranks
test_units_friction_far_from_origin() {
  local rc=0 x np out base
  base=$CASE_DIR/x0_np1.txt
  for x in 0 1000 1000000; do
    for np in 1 2 3; do
      [ $x = 0 ] && [ $np != 1 ] && continue
      out=$CASE_DIR/x${x}_np$np.txt
      spc "$out" "$np" -options_file input/friction_slide2d.opts -dm_plex_box_lower $x,0 -dm_plex_box_upper $((x + 1)),0.5 -output_dir "$CASE_DIR" -output_name "x${x}_np$np" -output_fields false || { echo "x $x np $np: run failed"; rc=1; continue; }
      assert_eq "cutbacks_x${x}_np$np" "$(sval "$out" cutbacks)" 0 || rc=1
      assert_close "normal_force_x${x}_np$np" "$(sval "$out" contact_force_y)" 0.01 1e-8 || rc=1
      assert_close "tangential_force_x${x}_np$np" "$(sval "$out" contact_force_x)" -0.003 1e-8 || rc=1
      assert_eq "newton_x${x}_np$np" "$(sval "$out" newton_iterations)" "$(sval "$base" newton_iterations)" || rc=1
    done
  done
  return $rc
}

# A stall with the gaps closed says so and names the residual tolerances and rigid motion, not
# the shift update (QA helper 23: the advice to use Anderson came with Anderson on and the gaps
# closed): B2 asked for a residual below its round-off (-snes_atol 1e-30 -snes_rtol 1e-30)
test_units_stall_gaps_closed() {
  local out=$CASE_DIR/out.txt rc=0
  spc "$out" 1 -options_file input/hertz2d.opts -snes_atol 1e-30 -snes_rtol 1e-30 -snes_stol 0 -load_max_cutbacks 0 -output_dir "$CASE_DIR" -output_fields false && { echo "an unreachable residual tolerance converged"; rc=1; }
  grep -E "^solve stalled" "$out"
  assert_ge gaps_closed_lines "$(grep -c '^solve stalled with the gaps closed (gap error .* <= its tolerance .*): the residual does not fall below .*; either the residual tolerances ask for less than its round-off (loosen -snes_atol / -snes_rtol) or a body is not held against rigid motion' "$out")" 1 || rc=1
  assert_eq no_anderson_advice "$(grep -c 'shift_accel anderson' "$out")" 0 || rc=1
  return $rc
}

# An alm re-solve after an augmentation takes at least one Newton step: with -contact_gap_rtol
# 1e-13 on B2 the augmentation's force change falls below the residual target, and a re-solve
# that stopped at once left the gap where it was (13 cut-backs, 593 Newton iterations, not
# converged). Now: converged without a cut-back, the gap error below 1e-13 h_c, the force to 1e-8,
# the same figures on 1, 2 and 3 ranks
test_units_alm_resolve_takes_a_step() {
  local rc=0 np out
  for np in 1 2 3; do
    out=$CASE_DIR/np$np.txt
    spc "$out" "$np" -options_file input/hertz2d.opts -contact_method alm -contact_gap_rtol 1e-13 -output_dir "$CASE_DIR" -output_name "np$np" -output_fields false || { echo "np $np: run failed"; rc=1; continue; }
    assert_eq "converged_np$np" "$(sval "$out" converged)" yes || rc=1
    assert_eq "cutbacks_np$np" "$(sval "$out" cutbacks)" 0 || rc=1
    assert_le "gap_error_np$np" "$(sval "$out" contact_gap_error)" "$(sval "$out" contact_gap_tol)" || rc=1
    assert_close "force_np$np" "$(sval "$out" contact_force_y)" 0.005 1e-8 || rc=1
  done
  for np in 2 3; do
    same_summary "$CASE_DIR/np1.txt" "$CASE_DIR/np$np.txt" 1e-8 contact_force_y contact_peak_pressure displacement_max || rc=1
  done
  return $rc
}

test_units_bad_input() {
  bad_input_cases <<'CASES'
gap rtol 0|input/hertz2d.opts|-contact_gap_rtol 0
gap rtol >= 1|input/hertz2d.opts|-contact_gap_rtol 2
gap tol <= 0|input/hertz2d.opts|-contact_gap_tol -1
min increment 0|input/hertz2d.opts|-load_min_increment 0
min increment > 1|input/hertz2d.opts|-load_min_increment 1.5
wall time < 0|input/hertz2d.opts|-max_wall_time -1
atol rel < 0|input/hertz2d.opts|-solver_atol_rel -1
stall its < 0|input/hertz2d.opts|-solver_stall_its -2
CASES
}
