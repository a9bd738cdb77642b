# The 2D sparse direct solver (src/solver-direct.c): a 2D run with at most -solver_direct_dofs
# dofs (default 1e6) factors its Jacobian (MUMPS: Cholesky where it is symmetric, else LU) from
# the start; a larger one switches once a linear solve of the default iterative solver takes more
# than -solver_direct_switch iterations (default 100), or fails. The switch is tested here on runs made larger than the threshold by
# -solver_direct_dofs 0.

# b2_iterative OUT: the reference of the tests below, B2 started iterative on 1 rank
# (-solver_direct_dofs 0); it never factors (direct_solver_from_step 0)
b2_iterative() {
  spc "$1" 1 -options_file input/hertz2d.opts -solver_direct_dofs 0 -output_dir "$CASE_DIR" -output_name "$(basename "$1" .txt)" -output_fields false || return 1
  assert_eq from_step_iterative "$(sval "$1" direct_solver_from_step)" 0 || return 1
  assert_eq linear_solver_iterative "$(sval "$1" linear_solver)" cg/gamg
}

# The start: B2 on 1, 2 and 3 ranks factors from load step 1 (summary direct_solver_from_step 1,
# one linear iteration per Newton iteration), with the Newton iterations of the iterative run
# (-solver_direct_dofs 0) and its force, peak pressure and active points (1e-8); its penetration
# below the gap tolerance. Frictionless small strain (a symmetric Jacobian) factors with Cholesky
# (summary linear_solver preonly/cholesky), friction (F1b) with LU. Not when the threshold is below
# B2's 9690 dofs, not with -solver_direct_switch 0 (never a direct solver), not in 3D (B1 3D).
test_direct_start_b2() {
  local rc=0 np out ref=$CASE_DIR/iter.txt
  b2_iterative "$ref" || return 1
  for np in 1 2 3; do
    out=$CASE_DIR/np$np.txt
    spc "$out" "$np" -options_file input/hertz2d.opts -output_dir "$CASE_DIR" -output_name "np$np" -output_fields false || return 1
    echo "ranks $np: newton $(sval "$out" newton_iterations) linear $(sval "$out" linear_iterations) (iterative: $(sval "$ref" newton_iterations) / $(sval "$ref" linear_iterations))"
    assert_eq "converged_np$np" "$(sval "$out" converged)" yes || rc=1
    assert_eq "from_step_np$np" "$(sval "$out" direct_solver_from_step)" 1 || rc=1
    assert_eq "linear_solver_np$np" "$(sval "$out" linear_solver)" preonly/cholesky || rc=1
    assert_eq "one_solve_per_newton_np$np" "$(sval "$out" linear_iterations)" "$(sval "$out" newton_iterations)" || rc=1
    assert_le "penetration_np$np" "$(sval "$out" contact_max_penetration)" "$(sval "$out" contact_gap_tol)" || rc=1
    same_summary "$ref" "$out" 0 newton_iterations contact_active_points || rc=1
    same_summary "$ref" "$out" 1e-8 contact_force_y contact_peak_pressure || rc=1
  done
  spc "$CASE_DIR/below.txt" 1 -options_file input/hertz2d.opts -solver_direct_dofs 9000 -output_dir "$CASE_DIR" -output_name below -output_fields false || return 1
  assert_eq from_step_threshold_below "$(sval "$CASE_DIR/below.txt" direct_solver_from_step)" 0 || rc=1
  spc "$CASE_DIR/never.txt" 1 -options_file input/hertz2d.opts -solver_direct_switch 0 -output_dir "$CASE_DIR" -output_name never -output_fields false || return 1
  assert_eq from_step_switch_0 "$(sval "$CASE_DIR/never.txt" direct_solver_from_step)" 0 || rc=1
  same_summary "$ref" "$CASE_DIR/never.txt" 0 linear_iterations || rc=1
  spc "$CASE_DIR/b1_3d.txt" 1 -options_file input/block3d.opts -output_dir "$CASE_DIR" -output_name b1 -output_fields false || return 1
  assert_eq from_step_3d "$(sval "$CASE_DIR/b1_3d.txt" direct_solver_from_step)" 0 || rc=1
  assert_eq linear_solver_3d "$(sval "$CASE_DIR/b1_3d.txt" linear_solver)" cg/gamg || rc=1
  spc "$CASE_DIR/f1b.txt" 1 -options_file input/friction_slide2d.opts -output_dir "$CASE_DIR" -output_name f1b -output_fields false || return 1
  assert_eq linear_solver_friction "$(sval "$CASE_DIR/f1b.txt" linear_solver)" preonly/lu || rc=1
  return $rc
}

# B6 (two discs, one-pass pair) at alpha 1000, started iterative (-solver_direct_dofs 0): CG + GAMG
# takes up to about 350 iterations per solve there (10141 for 39 Newton iterations on 1 rank).
# With the switch (the default) the run factors
# from its first load step on, with the same Newton iterations (39 / 41 / 41 measured on 1 / 2 / 3
# ranks, as without it), no cut-back, the step-cap retry as before, the load balanced (1e-8), the
# peak pressure of the iterative run (1e-8) and far fewer linear iterations (about 500): on 1, 2
# and 3 ranks, one message line each.
test_direct_switch_b6_alpha1000() {
  local rc=0 np out ref=$CASE_DIR/gamg.txt
  spc "$ref" 2 -options_file input/hertz2d_twobody.opts -contact_alpha 1000 -solver_direct_switch 0 -output_dir "$CASE_DIR" -output_name gamg -output_fields false || return 1
  assert_eq from_step_off "$(sval "$ref" direct_solver_from_step)" 0 || rc=1
  for np in 1 2 3; do
    out=$CASE_DIR/np$np.txt
    spc "$out" "$np" -options_file input/hertz2d_twobody.opts -contact_alpha 1000 -solver_direct_dofs 0 -output_dir "$CASE_DIR" -output_name "np$np" -output_fields false || return 1
    echo "ranks $np: newton $(sval "$out" newton_iterations) linear $(sval "$out" linear_iterations) (iterative only: $(sval "$ref" newton_iterations) / $(sval "$ref" linear_iterations) on 2 ranks)"
    assert_eq "converged_np$np" "$(sval "$out" converged)" yes || rc=1
    assert_eq "cutbacks_np$np" "$(sval "$out" cutbacks)" 0 || rc=1
    assert_eq "from_step_np$np" "$(sval "$out" direct_solver_from_step)" 1 || rc=1
    assert_eq "message_np$np" "$(grep -c '^linear solver: cg took [0-9]* iterations in one solve (-solver_direct_switch 100) (2D): from here on a sparse direct solver (Cholesky)' "$out")" 1 || rc=1
    assert_le "newton_np$np" "$(sval "$out" newton_iterations)" $(( $(sval "$ref" newton_iterations) + 2 )) || rc=1
    assert_le "linear_np$np" "$(sval "$out" linear_iterations)" $(( $(sval "$ref" linear_iterations) / 10 )) || rc=1
    assert_close "force_np$np" "$(sval "$out" contact_force_y)" 0.005 1e-8 || rc=1
    same_summary "$ref" "$out" 1e-8 contact_peak_pressure contact_active_points || rc=1
  done
  return $rc
}

# A failed linear solve in 2D: B2 started iterative (-solver_direct_dofs 0) with CG capped at 12
# iterations and no inexact acceptance (-solver_linear_accept 0) fails its first Newton solve
# (DIVERGED_LINEAR_SOLVE). The run then factors and solves the load step again: converged without
# a cut-back, the force and peak pressure of the iterative run (1e-8), on 1, 2 and 3 ranks. With
# -solver_direct_switch 0 the same run fails into the cut-back budget (test contact_linear_accept).
test_direct_switch_recovery() {
  local rc=0 np out ref=$CASE_DIR/ref.txt
  b2_iterative "$ref" || return 1
  for np in 1 2 3; do
    out=$CASE_DIR/np$np.txt
    spc "$out" "$np" -options_file input/hertz2d.opts -solver_direct_dofs 0 -ksp_max_it 12 -solver_linear_accept 0 -output_dir "$CASE_DIR" -output_name "np$np" -output_fields false || return 1
    assert_eq "converged_np$np" "$(sval "$out" converged)" yes || rc=1
    assert_eq "cutbacks_np$np" "$(sval "$out" cutbacks)" 0 || rc=1
    assert_eq "from_step_np$np" "$(sval "$out" direct_solver_from_step)" 1 || rc=1
    assert_eq "message_np$np" "$(grep -c '^linear solver: cg failed (DIVERGED_ITS); the load step again (2D): from here on a sparse direct solver (Cholesky)' "$out")" 1 || rc=1
    same_summary "$ref" "$out" 1e-8 contact_force_y contact_peak_pressure || rc=1
  done
  return $rc
}

# Where the switch does not apply: a 3D run (B1 3D with a threshold of 1 iteration), and a 2D run
# whose solver the user chose (-pc_type gamg given): no direct solver, the figures of the
# iterative run. With a threshold of 1 an iterative 2D run switches at its first solve and still
# gives B2's figures.
test_direct_switch_scope() {
  local rc=0
  spc "$CASE_DIR/b1_3d.txt" 1 -options_file input/block3d.opts -solver_direct_switch 1 -output_dir "$CASE_DIR" -output_name b1 -output_fields false || return 1
  assert_eq from_step_3d "$(sval "$CASE_DIR/b1_3d.txt" direct_solver_from_step)" 0 || rc=1
  # ... and the 2D option given to a 3D run is reported unused (QA helper 24), the 3D ones to a 2D run
  assert_eq unused_2d_option_in_3d "$(grep -c '^spcontact: warning: option -solver_direct_switch was not used' "$CASE_DIR/b1_3d.txt")" 1 || rc=1
  spc "$CASE_DIR/b1_2d.txt" 1 -options_file input/block2d.opts -solver_direct_switch_3d 300 -solver_direct_dofs_3d 10 -output_dir "$CASE_DIR" -output_name b1_2d -output_fields false || return 1
  assert_eq unused_3d_options_in_2d "$(grep -c '^spcontact: warning: option -solver_direct_\(switch\|dofs\)_3d was not used' "$CASE_DIR/b1_2d.txt")" 2 || rc=1
  b2_iterative "$CASE_DIR/ref.txt" || return 1
  spc "$CASE_DIR/user.txt" 1 -options_file input/hertz2d.opts -solver_direct_switch 1 -pc_type gamg -output_dir "$CASE_DIR" -output_name user -output_fields false || return 1
  assert_eq from_step_user_solver "$(sval "$CASE_DIR/user.txt" direct_solver_from_step)" 0 || rc=1
  same_summary "$CASE_DIR/ref.txt" "$CASE_DIR/user.txt" 0 newton_iterations linear_iterations || rc=1
  spc "$CASE_DIR/one.txt" 1 -options_file input/hertz2d.opts -solver_direct_dofs 0 -solver_direct_switch 1 -output_dir "$CASE_DIR" -output_name one -output_fields false || return 1
  assert_eq from_step_threshold_1 "$(sval "$CASE_DIR/one.txt" direct_solver_from_step)" 1 || rc=1
  assert_eq converged_threshold_1 "$(sval "$CASE_DIR/one.txt" converged)" yes || rc=1
  same_summary "$CASE_DIR/ref.txt" "$CASE_DIR/one.txt" 1e-8 contact_force_y contact_peak_pressure || rc=1
  return $rc
}

# The 3D switch (-solver_direct_switch_3d, 500 by default; for F3 at alpha 1000, where GMRES +
# GAMG took up to 2000 iterations per solve: README): F1c (friction_slide3d, GMRES, 13671 dofs)
# with the threshold at 20 iterations switches to LU in its first step, with one line, and gives
# F1c's figures, |T| = mu N = 0.003 at 30 degrees (1e-8), on 1 and 2 ranks. Above
# -solver_direct_dofs_3d it may not switch (the run line names no switch). Frictionless 3D (CG)
# never switches (direct_switch_scope).
test_direct_switch_3d() {
  local rc=0 np out
  for np in 1 2; do
    out=$CASE_DIR/np$np.txt
    spc "$out" "$np" -options_file input/friction_slide3d.opts -solver_direct_switch_3d 20 -output_dir "$CASE_DIR" -output_name "np$np" -output_fields false || return 1
    assert_eq "converged_np$np" "$(sval "$out" converged) $(sval "$out" cutbacks)" "yes 0" || rc=1
    assert_eq "from_step_np$np" "$(sval "$out" direct_solver_from_step)" 1 || rc=1
    assert_eq "message_np$np" "$(grep -c '^linear solver: gmres took [0-9]* iterations in one solve (-solver_direct_switch_3d 20) (3D): from here on a sparse direct solver (LU); -solver_direct_switch_3d 0 keeps the iterative one$' "$out")" 1 || rc=1
    assert_close "T_x_np$np" "$(sval "$out" contact_tangential_force_x)" -2.598076211353316e-03 1e-8 || rc=1
    assert_close "T_y_np$np" "$(sval "$out" contact_tangential_force_y)" -1.5e-03 1e-8 || rc=1
    assert_close "N_np$np" "$(sval "$out" contact_force_z)" 1e-02 1e-8 || rc=1
  done
  out=$CASE_DIR/cap.txt
  spc "$out" 1 -options_file input/friction_slide3d.opts -solver_direct_switch_3d 20 -solver_direct_dofs_3d 10000 -load_steps 1 -snes_max_it 1 -load_max_cutbacks 0 -output_dir "$CASE_DIR" -output_name cap -output_fields false
  assert_eq "run line above the cap" "$(grep -c '^run: 3D, 13671 dofs.*linear solver gmres/gamg$' "$out")" 1 || rc=1
  return $rc
}
