# Cattaneo-Mindlin in 2D (friction.md F2) and its unloading (F5) on the beta = 0 set-up
# (input/cattaneo2d.geo: the B2 disc made whole on its mirror image, one-pass pair, shifted,
# alpha = alpha_T = 10). The stick zone is measured from the run's own _contact.csv (status column)
# by scripts/cattaneo_check.py; "within one element" uses the slave spacing in the stick zone
# (0.00494). Each run takes 30-50 s on one rank.

# cm_run NAME NP MODE OPTS... : run, assert convergence without cut-backs, print the figures
cm_run() {
  local name=$1 np=$2 mode=$3; shift 3
  local out=$CASE_DIR/$name.txt rc=0
  spc "$out" "$np" "$@" -output_dir "$CASE_DIR" -output_name "$name" || return 1
  $PYTHON scripts/cattaneo_check.py "$CASE_DIR/${name}_contact.csv" "$mode" > "$CASE_DIR/$name.check" || { cat "$CASE_DIR/$name.check"; return 1; }
  echo "$name: newton $(sval "$out" newton_iterations) stick $(sval "$out" contact_stick_points) slip $(sval "$out" contact_slip_points) creep $(sval "$out" contact_max_stick_creep) F_x $(sval "$out" contact_force_x) F_y $(sval "$out" contact_force_y)"
  echo "$name: $(tr '\n' ' ' < "$CASE_DIR/$name.check")"
  assert_eq "converged_$name" "$(sval "$out" converged)" yes || rc=1
  assert_eq "cutbacks_$name" "$(sval "$out" cutbacks)" 0 || rc=1
  return $rc
}
cmval() { awk -v k="$2" '$1 == k { print $2 }' "$CASE_DIR/$1.check"; }
cmabs() { awk -v k="$2" '$1 == k { v = $2 + 0; printf "%.10g\n", v < 0 ? -v : v }' "$CASE_DIR/$1.check"; } # |value| (e-notation safe)

# f2_figures NAME CENTRE_BOUND: F2's loads balanced to 1e-8, creep <= 1e-10 h, the stick zone's
# half-width within one element and its centre within CENTRE_BOUND elements
f2_figures() {
  local name=$1 out=$CASE_DIR/$1.txt rc=0
  assert_close "force_balance_x_$name" "$(sval "$out" contact_force_x)" -0.0015 1e-8 || rc=1
  assert_close "force_balance_y_$name" "$(sval "$out" contact_force_y)" 0.01 1e-8 || rc=1
  assert_le "stick_creep_$name" "$(sval "$out" contact_max_stick_creep)" 5e-13 || rc=1
  assert_le "half_width_error_elements_$name" "$(cmabs "$name" half_width_error_elements)" 1 || rc=1
  assert_le "centre_error_elements_$name" "$(cmabs "$name" centre_error_elements)" "$2" || rc=1
  return $rc
}
# f2_same_ranks PREFIX: runs PREFIXnp2 and PREFIXnp3 give PREFIXnp1's figures to 1e-8
f2_same_ranks() {
  local rc=0 np k
  for np in 2 3; do
    same_summary "$CASE_DIR/${1}np1.txt" "$CASE_DIR/${1}np$np.txt" 1e-8 contact_force_x contact_force_y contact_tangential_force_x contact_peak_pressure contact_stick_points contact_slip_points || rc=1
    for k in half_width_error traction_l2_error; do assert_close "${k}_np$np" "$(cmval "${1}np$np" $k)" "$(cmval "${1}np1" $k)" 1e-8 1e-12 || rc=1; done
  done
  return $rc
}

# F2: stick half-width and centre within one element of c = b sqrt(1 - Q/(mu P)) = 0.076113 and 0
# (Q = 0.5 mu P; measured +0.10 and 1.3e-8 elements, -0.40 and -0.50 before the branch hold); shifted creep <= 1e-10 h (h = 0.005); contact
# forces balance the loads (Q, P) to 1e-8; the same figures on 1, 2 and 3 ranks (1e-8). The traction
# L2 error is 10.1 % against friction.md's 5 %: asserted only as a regression bound (10.5 %), the
# target is missed (doc/friction-benchmarks.md, F2). Before points closing in a step were kept frictionless until the
# commit (contact-friction.c, fresh points) the centre was -2.5 elements and the L2 error 22 %.
test_cattaneo2d_f2_shifted() {
  local rc=0
  for np in 1 2 3; do
    cm_run "np$np" "$np" cm -options_file input/cattaneo2d.opts -contact_method shifted || return 1
    assert_le "half_width_error_elements_np$np" "$(cmabs "np$np" half_width_error_elements)" 1 || rc=1
    assert_le "centre_error_elements_np$np" "$(cmabs "np$np" centre_error_elements)" 1 || rc=1
    assert_le "traction_l2_regression_np$np" "$(cmval "np$np" traction_l2_error)" 0.105 || rc=1
    assert_le "stick_creep_np$np" "$(sval "$CASE_DIR/np$np.txt" contact_max_stick_creep)" 5e-13 || rc=1
    assert_close "force_balance_x_np$np" "$(sval "$CASE_DIR/np$np.txt" contact_force_x)" -0.0015 1e-8 || rc=1
    assert_close "force_balance_y_np$np" "$(sval "$CASE_DIR/np$np.txt" contact_force_y)" 0.01 1e-8 || rc=1
  done
  for np in 2 3; do
    same_summary "$CASE_DIR/np1.txt" "$CASE_DIR/np$np.txt" 1e-8 contact_force_x contact_force_y contact_tangential_force_x contact_peak_pressure displacement_max contact_stick_points contact_slip_points || rc=1
    for k in stick_left stick_right traction_l2_error; do assert_close "${k}_np$np" "$(cmval "np$np" $k)" "$(cmval np1 $k)" 1e-8 1e-12 || rc=1; done
  done
  return $rc
}

# F2 in 3 load steps (the normal load and a third of the shear in step 1): a point that closes in
# step 1 is fresh (no friction until committed) and its anchor facet need not be among the master
# facets its rank holds; the pattern rebuild then read the facet table at -1 (a segfault in step 1
# on 1 and 2 ranks, since fixed). Friction during the normal load moves the stick zone (friction.md's
# table), so only the balance and the creep are asserted, and ranks 1 and 2 agree.
test_cattaneo2d_three_steps_fresh_anchor() {
  local rc=0 np out
  for np in 1 2; do
    out=$CASE_DIR/np$np.txt
    spc "$out" $np -options_file input/cattaneo2d.opts -load_steps 3 -output_dir "$CASE_DIR" -output_name np$np -output_fields false || return 1
    echo "np $np: newton $(sval "$out" newton_iterations) cutbacks $(sval "$out" cutbacks) F_x $(sval "$out" contact_force_x) F_y $(sval "$out" contact_force_y) creep $(sval "$out" contact_max_stick_creep)"
    assert_eq "converged_np$np" "$(sval "$out" converged)" yes || rc=1
    assert_close "force_x_np$np" "$(sval "$out" contact_force_x)" -0.0015 1e-8 || rc=1
    assert_close "force_y_np$np" "$(sval "$out" contact_force_y)" 0.01 1e-8 || rc=1
    assert_le "stick_creep_np$np" "$(sval "$out" contact_max_stick_creep)" 5e-13 || rc=1
  done
  same_summary "$CASE_DIR/np1.txt" "$CASE_DIR/np2.txt" 1e-8 contact_force_x contact_force_y contact_stick_points contact_slip_points || rc=1
  return $rc
}

# F2 on the rigid-top-edge set-up (input/cattaneo2d_rigid.opts: point-symmetric, the normal phase
# in 30 steps, then the slide in 10), against CM at the measured P and Q (Q/(mu P) = 0.524): stick
# zone centred (1e-8 elements) and its half-width within one element of c; 1 and 2 ranks identical
# to 1e-8. The traction L2 error is 6.1 %, against friction.md's 5 %: asserted only as a regression
# bound (6.5 %), the 5 % target is missed (doc/friction-benchmarks.md, F2).
# F2's rigid-edge set-up without friction and with the top edge held in x (-contact_friction_mu 0
# -bc_2_value 0: a frictionless Hertz contact of the two curved, non-matching contact meshes, in
# 40 steps): converges without a cut-back, pressure within 3 % of Hertz in L2 and its peak within
# 2 % of p0 at the measured P, tangential force below 1e-3 P; 1 and 2 ranks identical to 1e-8.
# Before a point's segment-keeping band widened after two returns (src/contact-pairs.c) this run
# stalled at load 0.145 in a 2-cycle of a point either side of a master vertex (7 cut-backs, exit 2)
test_cattaneo2d_rigid_frictionless() {
  local rc=0 np
  for np in 1 2; do
    local name=fl_np$np out=$CASE_DIR/fl_np$np.txt P
    spc "$out" "$np" -options_file input/cattaneo2d_rigid.opts -contact_friction_mu 0 -bc_2_value 0 -quiet -output_dir "$CASE_DIR" -output_name "$name" || rc=1
    P=$(sval "$out" contact_force_y)
    $PYTHON scripts/cattaneo_check.py "$CASE_DIR/${name}_contact.csv" cm 0.5 "$P" > "$CASE_DIR/$name.check" || { cat "$CASE_DIR/$name.check"; return 1; }
    echo "$name: newton $(sval "$out" newton_iterations) P $P peak $(sval "$out" contact_peak_pressure) p0 $(cmval "$name" p0) pressure_l2 $(cmval "$name" pressure_l2_error)"
    assert_eq "converged_$name" "$(sval "$out" converged)" yes || rc=1
    assert_eq "cutbacks_$name" "$(sval "$out" cutbacks)" 0 || rc=1
    assert_le "pressure_l2_against_hertz_$name" "$(cmval "$name" pressure_l2_error)" 0.03 || rc=1
    assert_close "peak_pressure_against_p0_$name" "$(sval "$out" contact_peak_pressure)" "$(cmval "$name" p0)" 0.02 || rc=1
    assert_le "tangential_force_over_P_$name" "$(awk -v x="$(sval "$out" contact_force_x)" -v p="$P" 'BEGIN { printf "%.6e", (x < 0 ? -x : x) / p }')" 1e-3 || rc=1
  done
  same_summary "$CASE_DIR/fl_np1.txt" "$CASE_DIR/fl_np2.txt" 1e-8 contact_force_x contact_force_y contact_peak_pressure contact_radius || rc=1
  return $rc
}

test_cattaneo2d_f2_rigid_edge() {
  local rc=0 np
  for np in 1 2; do
    local name=rigid_np$np out=$CASE_DIR/rigid_np$np.txt P Q
    spc "$out" "$np" -options_file input/cattaneo2d_rigid.opts -output_dir "$CASE_DIR" -output_name "$name" || return 1
    P=$(sval "$out" contact_force_y); Q=$(sval "$out" contact_force_x)
    $PYTHON scripts/cattaneo_check.py "$CASE_DIR/${name}_contact.csv" cm "$(awk -v q="$Q" -v p="$P" 'BEGIN{printf "%.12g", -q / (0.3 * p)}')" "$P" > "$CASE_DIR/$name.check" || { cat "$CASE_DIR/$name.check"; return 1; }
    echo "$name: newton $(sval "$out" newton_iterations) P $P Q $Q: $(tr '\n' ' ' < "$CASE_DIR/$name.check")"
    assert_eq "converged_$name" "$(sval "$out" converged)" yes || rc=1
    assert_le "centre_error_elements_$name" "$(cmabs "$name" centre_error_elements)" 1 || rc=1
    assert_le "half_width_error_elements_$name" "$(cmabs "$name" half_width_error_elements)" 1 || rc=1
    assert_le "traction_l2_regression_$name" "$(cmval "$name" traction_l2_error)" 0.065 || rc=1
    assert_le "stick_creep_$name" "$(sval "$out" contact_max_stick_creep)" 5e-13 || rc=1
    # at every converged step too (the history's last row per step): the update takes the committed
    # creep back (before, the steps' leftovers added up to 6.2e-13 to 7.4e-13 from step 21 on)
    assert_le "stick_creep_every_step_$name" "$(awk -F, 'NR > 1 { last[$1] = $11 } END { for (k in last) if (last[k] > m) m = last[k]; printf "%.6e", m }' "$CASE_DIR/$name.csv")" 5e-13 || rc=1
  done
  same_summary "$CASE_DIR/rigid_np1.txt" "$CASE_DIR/rigid_np2.txt" 1e-8 contact_force_x contact_force_y contact_tangential_force_x contact_stick_points contact_slip_points || rc=1
  for k in stick_left stick_right traction_l2_error; do assert_close "${k}_np2" "$(cmval rigid_np2 $k)" "$(cmval rigid_np1 $k)" 1e-8 1e-12 || rc=1; done
  return $rc
}

# F5: Q up to Q* = 0.5 mu P, then back to 0: stick half-width within one element of
# d = b sqrt(1 - Q*/(2 mu P)) = 0.866025 b = 0.0932194 (measured -0.37) and centred (1e-8 elements);
# the tangential force back to 0
test_cattaneo2d_f5_unload_shifted() {
  local rc=0
  cm_run unload 1 unload -options_file input/cattaneo2d_unload.opts -contact_method shifted || return 1
  assert_le half_width_error_elements "$(cmabs unload half_width_error_elements)" 1 || rc=1
  assert_le centre_error_elements "$(cmabs unload centre_error_elements)" 1 || rc=1
  assert_le stick_creep "$(sval "$CASE_DIR/unload.txt" contact_max_stick_creep)" 5e-13 || rc=1
  assert_close tangential_force_zero "$(sval "$CASE_DIR/unload.txt" contact_force_x)" 0 0 1.5e-11 || rc=1 # 1e-8 Q
  assert_close normal_force "$(sval "$CASE_DIR/unload.txt" contact_force_y)" 0.01 1e-8 || rc=1
  return $rc
}

# F3 (3D, input/cattaneo3d.opts, half model y >= 0 of two hemispheres, 28k dofs) in 5 load steps
# (1 normal, 4 shear to Q = 0.5 mu F): stick radius (from the stick area) and centre within one
# element of c = a (1 - Q/(mu F))^(1/3) (a from the measured F; measured -0.48 and -0.13 elements);
# no slip point inside c - h and no stick point beyond c + h (measured -0.61 and -0.10 elements);
# shifted creep <= 1e-10 h (h = 0.0104); the contact forces in the ratio of the loads (Q/F = 0.15 to
# 1e-8) and F within 0.5 % of 1e-3 (the meshed top half disc is a polygon); the same figures on 1, 2
# and 3 ranks (1e-8). friction.md gives no traction bound for F3 (q is approximate for nu != 0): the
# L2 error (26 %; the pressure's against Hertz is 9.5 %) is a regression bound only. 2-3 min a run.
test_cattaneo3d_f3_shifted() {
  local rc=0 np
  for np in 1 2 3; do
    local name=f3_np$np out=$CASE_DIR/f3_np$np.txt
    cm_run "$name" "$np" cm3d -options_file input/cattaneo3d.opts -load_steps 5 -bc_2_ramp 0,0.2 -bc_3_ramp 0.2,1 -bc_4_ramp 0.2,1 || return 1
    assert_le "radius_error_elements_$name" "$(cmabs "$name" radius_error_elements)" 1 || rc=1
    assert_le "centre_error_elements_$name" "$(cmabs "$name" centre_error_elements)" 1 || rc=1
    assert_le "min_slip_error_elements_$name" "$(cmabs "$name" min_slip_error_elements)" 1 || rc=1
    assert_le "max_stick_error_elements_$name" "$(cmabs "$name" max_stick_error_elements)" 1 || rc=1
    assert_le "traction_l2_regression_$name" "$(cmval "$name" traction_l2_error)" 0.28 || rc=1
    assert_le "stick_creep_$name" "$(sval "$out" contact_max_stick_creep)" 1e-12 || rc=1
    assert_close "force_ratio_$name" "$(awk -v x="$(sval "$out" contact_force_x)" -v z="$(sval "$out" contact_force_z)" 'BEGIN{printf "%.12g", x / z}')" -0.15 1e-8 || rc=1
    assert_close "normal_force_$name" "$(sval "$out" contact_force_z)" 1e-3 5e-3 || rc=1
  done
  for np in 2 3; do
    same_summary "$CASE_DIR/f3_np1.txt" "$CASE_DIR/f3_np$np.txt" 1e-8 contact_force_x contact_force_z contact_tangential_force_x contact_peak_pressure displacement_max contact_stick_points contact_slip_points || rc=1
    for k in stick_radius stick_centre_x traction_l2_error; do assert_close "${k}_np$np" "$(cmval "f3_np$np" $k)" "$(cmval f3_np1 $k)" 1e-8 1e-12 || rc=1; done
  done
  return $rc
}

test_cattaneo2d_bad_input() {
  bad_input_cases <<'CASES'
gradient on a traction condition|input/cattaneo2d.opts|-bc_2_gradient 1,0
gradient with the wrong number of components|input/cattaneo2d.opts|-bc_3_gradient 1,0,0
CASES
}

# alpha 1000 with GMRES + GAMG: the Arnoldi basis loses its orthogonality (KSP_DIVERGED_BREAKDOWN
# in the second step, on 1 and 2 ranks), which used to end in cut-backs until the run stopped. The
# solver re-orthogonalises from then on and solves the step again: no cut-back, the loads balanced
# to 1e-8, creep <= 1e-10 h. F2 shortened to its normal step and two shear steps of 0.1 Q each
# (Q = 0.2 x 0.5 mu P at the end), -contact_step_cap 0.1 (at alpha 1000 the default cap of one h
# lets the first normal step stall). About 20 s on 1 rank. Run without the branch hold
# (-contact_branch_hold false): with it, the 2-rank run's Newton steps differ and its basis no
# longer breaks down, and this case is here for the recovery. With PETSc's GAMG graph
# (-pc_gamg_threshold -1, zero entries kept): spcontact's default drops the zeros with pairs and
# friction, and with it this case no longer breaks down either. -solver_linear_accept 0: a breakdown
# whose residual had already fallen 1e-3 would otherwise be accepted as an inexact step, and this
# case is here for the recovery of the ones that cannot be.
test_cattaneo2d_alpha1000_breakdown() {
  local rc=0 r=0.3333333333333333
  for np in 1 2; do
    local out=$CASE_DIR/np$np.txt
    spc "$out" "$np" -options_file input/cattaneo2d.opts -contact_method shifted -contact_alpha 1000 -contact_step_cap 0.1 -contact_branch_hold false -pc_gamg_threshold -1 -solver_linear_accept 0 -solver_direct_switch 0 \
      -load_steps 3 -bc_1_ramp 0,$r -bc_2_ramp $r,1 -bc_3_ramp $r,1 -bc_2_value 0.00015,0 -bc_3_gradient -0.00045,0 \
      -output_dir "$CASE_DIR" -output_name "np$np" || return 1
    assert_eq "converged_np$np" "$(sval "$out" converged)" yes || rc=1
    assert_eq "cutbacks_np$np" "$(sval "$out" cutbacks)" 0 || rc=1
    assert_eq "reorthogonalised_np$np" "$(sval "$out" krylov_reorthogonalised)" yes || rc=1
    grep -q "^linear solve broke down" "$out" || { echo "np$np: no breakdown message FAILED"; rc=1; }
    assert_close "force_balance_x_np$np" "$(sval "$out" contact_force_x)" -0.0003 1e-8 || rc=1
    assert_close "force_balance_y_np$np" "$(sval "$out" contact_force_y)" 0.01 1e-8 || rc=1
    assert_le "stick_creep_np$np" "$(sval "$out" contact_max_stick_creep)" 5e-13 || rc=1
  done
  return $rc
}

# The jump wait (-contact_friction_jump_wait, default 10) on the full F2 at alpha 1000. Near the
# end of the shear, a Newton step that changed stick/slip statuses left a penetration of ~1e-7
# (eps = 2e5: a pressure of a third of p0); the in-Newton update took it into the shifts, the
# statuses moved again and the steps stalled: 209 Newton iterations and 3 cut-backs with
# -contact_friction_jump_wait 0, 164 and 2 (both in the normal step) with the wait (GMRES + GAMG
# throughout, -solver_direct_switch 0). With the 2D switch to LU (the default; GMRES takes 259
# iterations in the second solve) 163 and 2 on 1, 2 and 3 ranks, 5 or 6 waits.
# Asserted: at most 170 Newton iterations and 2 cut-backs, the wait used, the loads balanced to
# 1e-8, creep <= 1e-10 h, the stick zone within one element (-0.40 and +0.50 elements, as every
# method at this alpha), the same figures on 1, 2 and 3 ranks. About 20 s per run (3 to 4 min
# each with GMRES throughout). Without the chatter hold (-contact_chatter_flips 0), whose default
# takes this run to 75 Newton iterations and no cut-back (test_cattaneo2d_alpha1000_chatter_hold).
test_cattaneo2d_alpha1000_jump_wait() {
  local rc=0 np
  for np in 1 2 3; do
    local name=jw_np$np out=$CASE_DIR/jw_np$np.txt
    spc "$out" "$np" -options_file input/cattaneo2d.opts -contact_method shifted -contact_alpha 1000 -contact_chatter_flips 0 -output_dir "$CASE_DIR" -output_name "$name" || return 1
    $PYTHON scripts/cattaneo_check.py "$CASE_DIR/${name}_contact.csv" cm > "$CASE_DIR/$name.check" || { cat "$CASE_DIR/$name.check"; return 1; }
    echo "$name: newton $(sval "$out" newton_iterations) cutbacks $(sval "$out" cutbacks) waits $(sval "$out" contact_friction_jump_waits) $(tr '\n' ' ' < "$CASE_DIR/$name.check")"
    assert_eq "converged_$name" "$(sval "$out" converged)" yes || rc=1
    assert_le "newton_$name" "$(sval "$out" newton_iterations)" 170 || rc=1
    assert_le "cutbacks_$name" "$(sval "$out" cutbacks)" 2 || rc=1
    assert_ge "jump_waits_used_$name" "$(sval "$out" contact_friction_jump_waits)" 1 || rc=1
    f2_figures "$name" 1 || rc=1
  done
  f2_same_ranks jw_ || rc=1
  return $rc
}

# The chatter hold (-contact_chatter_flips, 3 by default; contact-enforce.c) on the full F2 and F5
# at alpha 1000, shifted. Without it a contact-edge point opens and closes at every Newton
# iteration near the end of the shear (|F| 1e-5 and 3e-2 in turn): F2 163 Newton iterations and
# 2 cut-backs, F5 205 and 3. With the default 75 and 92, no cut-back, the F2 zone -0.40 and -0.50
# elements off (as without it); with N = 2 73 and no cut-back, the zone centred (+0.10 and 1e-8
# elements, as at alpha 10 and 100). Asserted: no cut-back, at most 85 / 105 Newton iterations,
# the hold used, the loads balanced to 1e-8, creep <= 1e-10 h, the stick zones within one element
# (F2's centred to 0.1 element with N = 2); F2 with the default the same on 1, 2 and 3 ranks (1e-8).
# About 10 s per run.
test_cattaneo2d_alpha1000_chatter_hold() {
  local rc=0 np name
  for np in 1 2 3; do
    name=ch_np$np
    cm_run "$name" "$np" cm -options_file input/cattaneo2d.opts -contact_method shifted -contact_alpha 1000 || return 1
    f2_chatter_figures "$name" 1 || rc=1
  done
  f2_same_ranks ch_ || rc=1
  cm_run ch2 1 cm -options_file input/cattaneo2d.opts -contact_method shifted -contact_alpha 1000 -contact_chatter_flips 2 || return 1
  f2_chatter_figures ch2 0.1 || rc=1
  cm_run f5 1 unload -options_file input/cattaneo2d_unload.opts -contact_method shifted -contact_alpha 1000 || return 1
  assert_le newton_f5 "$(sval "$CASE_DIR/f5.txt" newton_iterations)" 105 || rc=1
  assert_ge chatter_holds_f5 "$(sval "$CASE_DIR/f5.txt" contact_chatter_holds)" 1 || rc=1
  assert_close force_balance_y_f5 "$(sval "$CASE_DIR/f5.txt" contact_force_y)" 0.01 1e-8 || rc=1
  assert_le stick_creep_f5 "$(sval "$CASE_DIR/f5.txt" contact_max_stick_creep)" 5e-13 || rc=1
  assert_le half_width_error_elements_f5 "$(cmabs f5 half_width_error_elements)" 1 || rc=1
  assert_le centre_error_elements_f5 "$(cmabs f5 centre_error_elements)" 1 || rc=1
  return $rc
}
# f2_chatter_figures NAME CENTRE_BOUND: at most 85 Newton iterations, the hold used, F2's figures
f2_chatter_figures() {
  local rc=0
  assert_le "newton_$1" "$(sval "$CASE_DIR/$1.txt" newton_iterations)" 85 || rc=1
  assert_ge "chatter_holds_$1" "$(sval "$CASE_DIR/$1.txt" contact_chatter_holds)" 1 || rc=1
  f2_figures "$1" "$2" || rc=1
  return $rc
}

# F3 at alpha 1000 with the defaults, 1 rank: GMRES + GAMG needs more than 500 iterations in a
# normal-step solve, so the run factors from there on (-solver_direct_switch_3d; before: GMRES to
# its 2000 iterations, 95 Newton iterations, 3 cut-backs, 35 minutes). Converged without a
# cut-back (56 Newton iterations), the stick zone of alpha 10 (radius -0.44, centre -0.14
# elements), creep <= 1e-12 (1e-10 h), Q/F = 0.15 to 1e-8. About 2-5 minutes.
test_cattaneo3d_alpha1000_direct() {
  local rc=0 name=f3_a1000 out=$CASE_DIR/f3_a1000.txt
  cm_run "$name" 1 cm3d -options_file input/cattaneo3d.opts -load_steps 5 -bc_2_ramp 0,0.2 -bc_3_ramp 0.2,1 -bc_4_ramp 0.2,1 -contact_alpha 1000 -output_fields false || return 1
  assert_eq "switched in step 1" "$(sval "$out" direct_solver_from_step) $(grep -c '^linear solver: gmres took [0-9]* iterations in one solve (-solver_direct_switch_3d 500) (3D)' "$out")" "1 1" || rc=1
  assert_le "newton_iterations" "$(sval "$out" newton_iterations)" 60 || rc=1
  assert_le "radius_error_elements_$name" "$(cmabs "$name" radius_error_elements)" 1 || rc=1
  assert_le "centre_error_elements_$name" "$(cmabs "$name" centre_error_elements)" 1 || rc=1
  assert_le "stick_creep_$name" "$(sval "$out" contact_max_stick_creep)" 1e-12 || rc=1
  assert_close "force_ratio_$name" "$(awk -v x="$(sval "$out" contact_force_x)" -v z="$(sval "$out" contact_force_z)" 'BEGIN{printf "%.12g", x / z}')" -0.15 1e-8 || rc=1
  return $rc
}

# F3 at alpha 1000 without the chatter hold (-contact_chatter_flips 0): the normal step cycles
# between active sets (doc/friction-benchmarks.md, F3). Without the hold a frictional load step is
# not solved again with a tighter cap, so the stall message names -contact_step_cap (F3 converges
# with 0.1); the run stops with exit 2 and leaves only .part files. One step, no cut-back, the stall
# after 8 iterations: about 40 s on 2 ranks. With the hold (the default) the normal step converges
# (22 Newton iterations) and this run stops in its last step on GMRES's iteration limit.
test_cattaneo3d_alpha1000_cycle_message() {
  local out=$CASE_DIR/f3_cycle.txt rc=0 code=0
  spc "$out" 2 -options_file input/cattaneo3d.opts -load_steps 5 -bc_2_ramp 0,0.2 -bc_3_ramp 0.2,1 -bc_4_ramp 0.2,1 \
    -contact_alpha 1000 -contact_chatter_flips 0 -load_max_cutbacks 0 -solver_stall_its 8 -output_dir "$CASE_DIR" -output_name f3_cycle || code=$?
  assert_eq exit_code "$code" 2 || rc=1
  assert_eq cycle_message "$(grep -c '^solve stalled: .*(an active-set cycle).*, a tighter -contact_step_cap or' "$out")" 1 || rc=1
  assert_eq status "$(sval "$out" status)" failed || rc=1
  assert_eq final_files "$(ls "$CASE_DIR" | grep -c '^f3_cycle\(\.h5\|\.xdmf\|\.csv\|_contact\.csv\)$')" 0 || rc=1
  return $rc
}

# F2 with the Schur shift update (-contact_shift_accel schur: normal rows of the active points,
# tangential rows of the stuck and slipping ones, back-substitutions with the 2D factorization): the F2 figures,
# the plain update's traction L2 error to 1e-4, on 1 and 2 ranks with the same figures; Newton
# iterations measured 62 against the plain update's 109 and penalty's 46, asserted <= 70
test_cattaneo2d_schur() {
  local rc=0 np
  for np in 1 2; do
    cm_run schur_np$np $np cm -options_file input/cattaneo2d.opts -contact_shift_accel schur || return 1
    f2_figures schur_np$np 1 || rc=1
    assert_le "newton_np$np" "$(sval "$CASE_DIR/schur_np$np.txt" newton_iterations)" 70 || rc=1
    assert_close "traction_l2_np$np" "$(cmval schur_np$np traction_l2_error)" 0.10046 1e-3 || rc=1
  done
  same_summary "$CASE_DIR/schur_np1.txt" "$CASE_DIR/schur_np2.txt" 1e-8 contact_force_x contact_force_y contact_tangential_force_x contact_peak_pressure contact_stick_points contact_slip_points || rc=1
  return $rc
}
