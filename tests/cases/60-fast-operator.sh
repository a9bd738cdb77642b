# Fast paths: the bulk operator (src/fast-elastic.c, element-level isotropic elasticity on P1/Q1
# cells) must reproduce PetscFE's residual and Jacobian to round-off; the vertex preallocation and
# rigid-body modes (src/matrix.c) must give DMCreateMatrix's pattern and DMPlexCreateRigidBody's
# vectors; contact figures must not change; PetscFE/DMCreateMatrix take over where they do not
# apply. No timings here: scripts/bench.sh measures them.
# Helpers are prefixed fop_ so they cannot collide with other case files.

# fop_check NP ARGS...: -solver_check_fast compares both operators at a random state before the
# first solve; both relative differences must be round-off and the run must have used the fast
# operator. One Newton iteration is enough (exit code 2, "not converged", is expected then).
fop_check() {
  local np=$1 out=$CASE_DIR/run$1.txt rc=0 code; shift
  spc "$out" "$np" "$@" -solver_check_fast -snes_max_it 1 -load_max_cutbacks 0 -output_dir "$CASE_DIR" -output_fields false; code=$?
  [ $code -eq 0 ] || [ $code -eq 2 ] || { echo "exit code $code"; tail -n 5 "$out"; return 1; }
  local line; line=$(grep '^fast_check' "$out")
  echo "$np rank(s): $line"
  assert_eq bulk_operator "$(sval "$out" bulk_operator)" fast || rc=1
  assert_le residual_rel_diff "$(echo "$line" | awk '{print $3}')" 1e-12 || rc=1
  assert_le jacobian_rel_diff "$(echo "$line" | awk '{print $5}')" 1e-12 || rc=1
  line=$(grep '^matrix_check' "$out"); echo "$line"
  local nz alloc bs ref refbs
  read -r _ _ nz _ alloc _ bs _ ref _ refbs <<<"$line"
  assert_eq nonzeros_vs_dmcreatematrix "$nz" "$ref" || rc=1
  assert_eq preallocation_exact "$alloc" "$nz" || rc=1
  assert_eq block_size "$bs" "$refbs" || rc=1
  line=$(grep '^rigid_body_check' "$out"); echo "$line"
  assert_le rigid_body_modes_diff "$(echo "$line" | awk '{print $5}')" 1e-12 || rc=1
  return $rc
}
fop_check_np12() { fop_check 1 "$@" && fop_check 2 "$@"; }

test_fast_operator_q1_quad_2d() { fop_check_np12 -options_file input/block2d.opts; }
test_fast_operator_p1_tri_2d()  { fop_check_np12 -options_file input/hertz2d.opts; }
test_fast_operator_q1_hex_3d()  { fop_check_np12 -options_file input/indent3d.opts -dm_plex_box_faces 6,6,6 -bc_3_type traction -bc_3_values 5 -bc_3_value 0.01,0,0; }
# fully clamped base, no partially constrained vertex: block size 3 (the MatXAIJ block path)
test_fast_operator_blocked_3d() { fop_check_np12 -dm_plex_dim 3 -dm_plex_box_faces 4,4,4 -bc_0_type dirichlet -bc_0_values 1 -bc_1_type traction -bc_1_values 2 -bc_1_value 0,0.1,0; }
test_fast_operator_p1_tet_3d()  { fop_check 1 -options_file input/hertz3d.opts; } # 29k tets: one rank keeps it short

# fop_same NP ARGS...: a full run with the fast paths and with the generic ones (PetscFE operator,
# DMCreateMatrix, DMPlexCreateRigidBody) gives the same summary
fop_same() {
  local np=$1 rc=0; shift
  spc "$CASE_DIR/fast.txt" "$np" "$@" -output_dir "$CASE_DIR" -output_name fast || return 1
  spc "$CASE_DIR/generic.txt" "$np" "$@" -solver_fast_bulk false -solver_fast_prealloc false -output_dir "$CASE_DIR" -output_name generic || return 1
  assert_eq fast_operator "$(sval "$CASE_DIR/fast.txt" bulk_operator)" fast || rc=1
  assert_eq generic_operator "$(sval "$CASE_DIR/generic.txt" bulk_operator)" petscfe || rc=1
  assert_eq converged "$(sval "$CASE_DIR/fast.txt" converged)" yes || rc=1
  for k in newton_iterations linear_iterations contact_active_points; do
    assert_eq "$k" "$(sval "$CASE_DIR/fast.txt" $k)" "$(sval "$CASE_DIR/generic.txt" $k)" || rc=1
  done
  same_summary "$CASE_DIR/generic.txt" "$CASE_DIR/fast.txt" 1e-8 displacement_max contact_force_x contact_force_y contact_force_z contact_peak_pressure contact_radius || rc=1
  return $rc
}
test_fast_operator_same_block3d()          { fop_same 1 -options_file input/block3d.opts; }
test_fast_operator_same_hertz2d()          { fop_same 1 -options_file input/hertz2d.opts; }
test_fast_operator_same_hertz2d_np2()      { fop_same 2 -options_file input/hertz2d.opts -contact_method alm; }
test_fast_operator_same_hertz2d_no_reuse() { fop_same 1 -options_file input/hertz2d.opts -solver_linear_reuse false; }

# Where they do not apply, PetscFE assembles (second order, manufactured solutions) and
# DMCreateMatrix preallocates (second order)
test_fast_operator_fallback() {
  local rc=0
  spc "$CASE_DIR/p2.txt" 1 -options_file input/elastic2d.opts -petscspace_degree 2 -solver_check_fast -output_dir "$CASE_DIR" -output_name p2 || return 1
  assert_eq degree2_operator "$(sval "$CASE_DIR/p2.txt" bulk_operator)" petscfe || rc=1
  grep -q '^fast_check not_applicable' "$CASE_DIR/p2.txt" || { echo "no not_applicable line"; rc=1; }
  spc "$CASE_DIR/mms.txt" 1 -dm_plex_dim 2 -dm_plex_box_faces 4,4 -bc_0_type dirichlet -bc_0_values 1,2,3,4 -material_mms 0.01 -output_dir "$CASE_DIR" -output_name mms || return 1
  assert_eq mms_operator "$(sval "$CASE_DIR/mms.txt" bulk_operator)" petscfe || rc=1
  return $rc
}

# GAMG's graph (src/matrix-graph.c): on a frictionless small-strain run GAMG aggregates on the
# system matrix itself instead of PETSc's copy; the aggregates, hence every iteration count and
# figure, are the same as with the copy (-solver_gamg_shared_graph false), on 1, 2 and 3 ranks.
# -info names the path taken; with friction (a non-symmetric matrix) PETSc's copy is used.
fop_graph() {
  local np=$1 rc=0; shift
  spc "$CASE_DIR/shared$np.txt" "$np" "$@" -info :mat -output_dir "$CASE_DIR" -output_name shared || return 1
  spc "$CASE_DIR/copy$np.txt" "$np" "$@" -info :mat -solver_gamg_shared_graph false -output_dir "$CASE_DIR" -output_name copy || return 1
  grep -q 'GAMG graph: the system matrix itself' "$CASE_DIR/shared$np.txt" || { echo "$np rank(s): the shared graph was not used"; rc=1; }
  ! grep -q 'GAMG graph: the system matrix itself' "$CASE_DIR/copy$np.txt" || { echo "$np rank(s): the shared graph was used with false"; rc=1; }
  assert_eq converged "$(sval "$CASE_DIR/shared$np.txt" converged)" yes || rc=1
  for k in newton_iterations linear_iterations contact_active_points; do
    assert_eq "$k" "$(sval "$CASE_DIR/shared$np.txt" $k)" "$(sval "$CASE_DIR/copy$np.txt" $k)" || rc=1
  done
  same_summary "$CASE_DIR/copy$np.txt" "$CASE_DIR/shared$np.txt" 1e-12 displacement_max contact_force_x contact_force_y contact_force_z contact_max_penetration || rc=1
  return $rc
}
test_gamg_shared_graph_b4() {
  local rc=0
  for np in 1 2 3; do fop_graph $np -options_file input/indent3d.opts -dm_plex_box_faces 16,16,16 || rc=1; done
  same_summary "$CASE_DIR/shared1.txt" "$CASE_DIR/shared2.txt" 1e-8 contact_force_z displacement_max || rc=1
  same_summary "$CASE_DIR/shared1.txt" "$CASE_DIR/shared3.txt" 1e-8 contact_force_z displacement_max || rc=1
  return $rc
}
test_gamg_shared_graph_friction_copies() {
  spc "$CASE_DIR/fric.txt" 1 -options_file input/friction_block2d.opts -solver_direct_dofs 0 -info :mat -output_dir "$CASE_DIR" -output_name fric || return 1
  ! grep -q 'GAMG graph: the system matrix itself' "$CASE_DIR/fric.txt" || { echo "friction run used the shared graph"; return 1; }
  grep -q 'MatCoarsenApply_MISK_private' "$CASE_DIR/fric.txt" || { echo "no GAMG coarsening in the friction run"; return 1; }
}

# Jacobian reuse against rigid planes (SPContactTangentFixed): without friction, a plane's contact
# tangent depends on the active set alone, so the assembled Jacobian (and its factorization) is
# kept for as long as the active set does not change, past -solver_jacobian_reuse's cap of 5 for
# curved obstacles. B2's active set changes once (1 -> 28 points, at the first Newton iteration):
# 2 assemblies, so jacobian_reuses = newton - 2, with the Newton and linear iterations of
# assembling at every iteration (-solver_jacobian_reuse 0) and its figures to 1e-10; 1, 2 and 3 ranks.
test_jacobian_reuse_plane() {
  local rc=0 np every kept
  for np in 1 2 3; do
    every=$CASE_DIR/every_np$np.txt kept=$CASE_DIR/kept_np$np.txt
    spc "$every" "$np" -options_file input/hertz2d.opts -solver_jacobian_reuse 0 -output_dir "$CASE_DIR" -output_name "every_np$np" -output_fields false || return 1
    spc "$kept" "$np" -options_file input/hertz2d.opts -output_dir "$CASE_DIR" -output_name "kept_np$np" -output_fields false || return 1
    assert_eq "reuses_every_np$np" "$(sval "$every" jacobian_reuses)" 0 || rc=1
    assert_eq "reuses_np$np" "$(sval "$kept" jacobian_reuses)" $(( $(sval "$kept" newton_iterations) - 2 )) || rc=1
    same_summary "$every" "$kept" 0 newton_iterations linear_iterations contact_active_points || rc=1
    same_summary "$every" "$kept" 1e-10 contact_force_y contact_peak_pressure displacement_max || rc=1
  done
  return $rc
}
