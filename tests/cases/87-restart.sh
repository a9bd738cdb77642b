# Run lifecycle: the h5 status attribute (complete / failed / interrupted), final names only for
# complete runs, SIGTERM/SIGINT stop at the next converged step, -restart resumes from it.
# Reference for a restart: the same run uninterrupted. Measured: the restarted run reproduces it
# bit for bit (the state it needs is stored exactly); asserted to 1e-10 relative.

# rs_h5 H5 : "status last_step last_load_factor restart_steps" of an output file
rs_h5() {
  "$PYTHON" - "$1" <<'EOF'
import sys
import h5py
with h5py.File(sys.argv[1], "r") as f:
    a = f.attrs
    s = a["status"].decode() if isinstance(a["status"], bytes) else a["status"]
    print(s, int(a["last_step"]), "%.12g" % a["last_load_factor"], int(f["/restart"].attrs["steps"]) if "restart" in f else 0)
EOF
}

# rs_same_field A.h5 B.h5 : max |u_A - u_B| / max |u_A| of the displacement at the last step, the
# vertices matched by their coordinates (the files' vertex orders follow their partitions; vertices
# at the same place, on two bodies, are ordered by their values: equal fields still match)
rs_same_field() {
  "$PYTHON" - "$1" "$2" <<'EOF'
import sys
import h5py
import numpy as np
def field(name):
    with h5py.File(name, "r") as f:
        X = f["/geometry/vertices"][:]
        u = f["/vertex_fields/displacement_Field_0"][-1].reshape(len(X), -1)
    keys = [u[:, k] for k in reversed(range(u.shape[1]))] + [X[:, k] for k in reversed(range(X.shape[1]))]
    return u[np.lexsort(keys)]
ua, ub = field(sys.argv[1]), field(sys.argv[2])
print("%.3e" % (np.abs(ua - ub).max() / np.abs(ua).max()))
EOF
}

# rs_case NP OPTIONS... : 10 load steps uninterrupted; the same interrupted after step 5 (rank 0
# raises SIGTERM: the others stop with it); restarted from its file on RS_NP ranks (default NP);
# figures and field compared
rs_case() {
  local np=$1 rc=0 code; shift
  local np2=${RS_NP:-$np}
  local o=("$@" -load_steps 10 -output_dir "$CASE_DIR")
  spc "$CASE_DIR/full.txt" "$np" "${o[@]}" -output_name full || return 1
  spc "$CASE_DIR/half.txt" "$np" "${o[@]}" -output_name half -debug_interrupt_after_step 5; code=$?
  [ "$code" -ne 0 ] || { echo "interrupted run exited 0 FAILED"; rc=1; }
  assert_eq "restart line" "$(grep -c "^spcontact: interrupted by signal 15 after load step 5 (load factor 0.5); restart with -restart $CASE_DIR/half.h5.part and another -output_name$" "$CASE_DIR/half.txt")" 1 || rc=1
  assert_eq "interrupted file: status, last step, load factor, restart steps" "$(rs_h5 "$CASE_DIR/half.h5.part")" "interrupted 5 0.5 5" || rc=1
  assert_eq "interrupted run: no final-named file" "$(ls "$CASE_DIR" | grep -c '^half[._a-z]*\(h5\|xmf\|csv\)$')" 0 || rc=1
  assert_eq "complete file: status, last step, load factor" "$(rs_h5 "$CASE_DIR/full.h5" | cut -d' ' -f1-2)" "complete 10" || rc=1
  spc "$CASE_DIR/rest.txt" "$np2" "${o[@]}" -output_name rest -restart "$CASE_DIR/half.h5.part" || return 1
  assert_eq "restarted on" "$(sval "$CASE_DIR/rest.txt" ranks) ranks" "$np2 ranks" || rc=1
  assert_eq "restarted run status" "$(sval "$CASE_DIR/rest.txt" status) $(rs_h5 "$CASE_DIR/rest.h5" | cut -d' ' -f1-2)" "complete complete 10" || rc=1
  assert_eq "restarted file: first step, slabs" "$("$PYTHON" -c "import h5py; f = h5py.File('$CASE_DIR/rest.h5', 'r'); print(f.attrs['first_step'], f['/vertex_fields/displacement_Field_0'].shape[0])")" "6 5" || rc=1
  # the Newton count is the same on the same rank count; on another one the partition changes the
  # rounding of reductions and a solve near its tolerance may take one iteration more or less
  # (two-pass F4 3 -> 1 with the Anderson update: 83 to 86)
  # the work counters carry over the restart (restart format 9): the same on the same rank count,
  # but the restarted process assembles the Jacobian and builds the preconditioner it had no copy
  # of (one reuse or keep fewer, at most) and the pairs' pattern of its new matrix (one more)
  if [ "$np2" = "$np" ]; then
    same_summary "$CASE_DIR/full.txt" "$CASE_DIR/rest.txt" 0 newton_iterations linear_iterations refined_steps refinement_linear_iterations linear_solves_accepted contact_evaluations contact_shift_updates contact_shift_accel_steps || rc=1
    if [ -n "$(sval "$CASE_DIR/full.txt" contact_shift_accel_solves)" ]; then same_summary "$CASE_DIR/full.txt" "$CASE_DIR/rest.txt" 0 contact_shift_accel_solves || rc=1; fi
    local jf jr pf pr key
    for key in jacobian_reuses preconditioner_kept; do
      jf=$(sval "$CASE_DIR/full.txt" $key) jr=$(sval "$CASE_DIR/rest.txt" $key)
      assert_le "$key, restarted <= uninterrupted" "$jr" "$jf" || rc=1
      assert_ge "$key, restarted >= uninterrupted - 1" "$jr" "$((jf - 1))" || rc=1
    done
    pf=$(sval "$CASE_DIR/full.txt" contact_pattern_rebuilds) pr=$(sval "$CASE_DIR/rest.txt" contact_pattern_rebuilds)
    assert_ge "contact_pattern_rebuilds, restarted >= uninterrupted" "$pr" "$pf" || rc=1
    assert_le "contact_pattern_rebuilds, restarted <= uninterrupted + 1" "$pr" "$((pf + 1))" || rc=1
  else assert_close "newton_iterations (another rank count: +-1)" "$(sval "$CASE_DIR/rest.txt" newton_iterations)" "$(sval "$CASE_DIR/full.txt" newton_iterations)" 0 1 || rc=1; fi
  same_summary "$CASE_DIR/full.txt" "$CASE_DIR/rest.txt" 1e-10 load_factor load_steps displacement_max \
    contact_active_points contact_max_penetration contact_gap_error contact_force_x contact_force_y contact_peak_pressure contact_radius contact_retries_step_cap || rc=1
  if [ "$(sval "$CASE_DIR/full.txt" contact_friction)" = yes ]; then
    same_summary "$CASE_DIR/full.txt" "$CASE_DIR/rest.txt" 1e-10 contact_stick_points contact_slip_points contact_tangential_force_x || rc=1
    # the creep is what the converged iterate left (F4: about its bound creep_rtol h = 2e-11); on
    # another rank count the partition rounds it differently (F4 3 -> 1: 3.1e-14 apart)
    local catol=1e-14; [ "$np2" = "$np" ] || catol=1e-13
    SAME_ATOL=$catol same_summary "$CASE_DIR/full.txt" "$CASE_DIR/rest.txt" 1e-10 contact_max_stick_creep || rc=1
  fi
  assert_le "displacement field at load 1, restarted vs uninterrupted (relative)" "$(rs_same_field "$CASE_DIR/full.h5" "$CASE_DIR/rest.h5")" 1e-10 || rc=1
  return $rc
}

test_restart_b2_shifted()         { rs_case 1 -options_file input/hertz2d.opts -contact_method shifted; }
# A run whose first step failed (two-pass B6 at alpha 1000 in 10 steps, without the chatter hold:
# step 1 takes 23 Newton iterations, -snes_max_it 20 stops it) and was solved again with the step
# cap at 0.1 for that step: the restart carries the retry count and the remaining steps are the same
test_restart_after_step_cap_recovery() {
  rs_case 1 -options_file input/hertz2d_twobody.opts -contact_two_pass -contact_alpha 1000 -contact_chatter_flips 0 -snes_max_it 20 || return 1
  assert_eq recovery_in_first_half "$(grep -c '^Newton did not converge: the load step again' "$CASE_DIR/half.txt")" 1 || return 1
  assert_eq no_recovery_after_restart "$(grep -c '^Newton did not converge' "$CASE_DIR/rest.txt")" 0
}
# A 2D run started iterative (-solver_direct_dofs 0) that switched to the sparse direct solver
# (-solver_direct_switch 1: at its first solve)
# resumes with it: one line names the interrupted run's step, the summary key keeps it, and the
# restarted steps take the Newton iterations of the uninterrupted run (they are LU solves there
# too); on 1 rank, and interrupted on 2 ranks and resumed on 3 (MUMPS)
test_restart_direct_solver()     { rs_direct 1; }
test_restart_direct_solver_2to3() { RS_NP=3 rs_direct 2; }
rs_direct() {
  rs_case "$1" -options_file input/hertz2d.opts -solver_direct_dofs 0 -solver_direct_switch 1 || return 1
  local rc=0
  assert_eq switched_in_first_half "$(grep -c '^linear solver: cg took' "$CASE_DIR/half.txt")" 1 || rc=1
  assert_eq resumed_line "$(grep -c '^linear solver: the sparse direct solver (Cholesky) of the interrupted run, from its load step 1;' "$CASE_DIR/rest.txt")" 1 || rc=1
  assert_eq "direct_solver_from_step (full, restarted)" "$(sval "$CASE_DIR/full.txt" direct_solver_from_step) $(sval "$CASE_DIR/rest.txt" direct_solver_from_step)" "1 1" || rc=1
  return $rc
}
test_restart_b2_shifted_np2()     { rs_case 2 -options_file input/hertz2d.opts -contact_method shifted; }
test_restart_friction_alm()       { rs_case 1 -options_file input/friction_block2d.opts -contact_method alm; }
test_restart_friction_predicted()  { rs_case 2 -options_file input/friction_block2d.opts -contact_method shifted; } # every shear step starts from predicted shifts
# F1b full slip: slipping points with moving anchors and tangential shifts
test_restart_friction_slide_shifted_np2() { rs_case 2 -options_file input/friction_slide2d.opts -contact_method shifted; }
# Another rank count: the restart data is stored by serial mesh point number (restart-natural.c),
# the friction anchors on master facets by the facets' serial numbers. B2 interrupted on 1 rank,
# resumed on 2; the frictional two-pass patch F4 (anchors on pair facets) 1 -> 3 and 3 -> 1.
test_restart_b2_shifted_1to2()    { RS_NP=2 rs_case 1 -options_file input/hertz2d.opts -contact_method shifted; }
# The plain shift update here: on 3 ranks the assembly adds off-rank contributions in message
# arrival order, so a run differs from the next at round-off (forces at 1e-11), and with the
# two-pass default (Anderson) F4 in 10 steps then takes 83 to 85 Newton iterations from run to run.
test_restart_friction_patch_1to3() { RS_NP=3 rs_case 1 -options_file input/friction_patch_4_5.opts -contact_shift_accel none; }
test_restart_friction_patch_3to1() { RS_NP=1 rs_case 3 -options_file input/friction_patch_4_5.opts -contact_shift_accel none; }
# Friction on a sliding pair, 2 ranks -> 1: the points' flag that refreshes the committed tangent
# basis at the next solve's start is in the file (without it the restarted run kept the stale
# basis: forces 1e-6 off the uninterrupted run's)
# the work counters over a restart: the preconditioner kept and the refined steps (B4 at 8^3, CG +
# GAMG), the accelerated shift updates (the two-pass patch test, Anderson) are those of the
# uninterrupted run (before, the restarted run counted them from 0)
test_restart_counters_iterative() { rs_case 1 -options_file input/indent3d.opts -dm_plex_box_faces 8,8,8; }
test_restart_counters_anderson()  { rs_case 2 -options_file input/patch_4_5.opts -contact_two_pass; }
# and the Schur update's steps and back-substitutions (restart format 10; B6 in 10 steps, 2 ranks)
test_restart_counters_schur()     { rs_case 2 -options_file input/hertz2d_twobody.opts -contact_shift_accel schur; }
test_restart_friction_pair_slide_2to1() { RS_NP=1 rs_case 2 -options_file input/slide2d.opts -contact_friction_mu 0.3; }

# rs_kill SIG CODE: a real signal from outside (1 rank, no launcher): the run stops after the step
# it is in, exits with CODE (128 + signal), the file says interrupted and holds that many steps
rs_kill() {
  local sig=$1 want=$2 rc=0 pid code n
  RERUN="$SPC -options_file input/hertz2d.opts -load_steps 10 -contact_monitor -output_dir $CASE_DIR -output_name k & kill -$sig \$!"
  $SPC -options_file input/hertz2d.opts -load_steps 10 -contact_monitor -output_dir "$CASE_DIR" -output_name k >"$CASE_DIR/k.txt" 2>&1 &
  pid=$!
  for _ in $(seq 1 1200); do # until step 2 has started (its first Newton line), at most 120 s
    n=$(grep -c "contact   0 " "$CASE_DIR/k.txt"); [ "$n" -ge 2 ] && break; sleep 0.1
  done
  kill -"$sig" "$pid"; wait "$pid"; code=$?
  assert_eq "exit code after SIG$sig" "$code" "$want" || rc=1
  local st; st=$(rs_h5 "$CASE_DIR/k.h5.part") || rc=1
  assert_eq "status" "${st%% *}" interrupted || rc=1
  n=$(echo "$st" | cut -d' ' -f2)
  assert_ge "converged steps kept" "$n" 2 || rc=1
  assert_le "stopped early" "$n" 9 || rc=1
  assert_eq "readable steps in the h5 = last_step" "$("$PYTHON" -c "import h5py; print(h5py.File('$CASE_DIR/k.h5.part','r')['/vertex_fields/displacement_Field_0'].shape[0])")" "$n" || rc=1
  return $rc
}

test_restart_kill_term() { rs_kill TERM 143; }
test_restart_kill_int()  { rs_kill INT 130; }

# Final names all or none: the h5's final name is taken by a directory, so its rename fails; the
# renames before it (csv, contact csv, xmf) are undone, one error line, exit 1
test_restart_rename_all_or_none() {
  local rc=0 code
  mkdir -p "$CASE_DIR/d.h5"
  RERUN="mkdir $CASE_DIR/d.h5; $SPC -options_file input/hertz2d.opts -output_dir $CASE_DIR -output_name d"
  $SPC -options_file input/hertz2d.opts -output_dir "$CASE_DIR" -output_name d >"$CASE_DIR/o.txt" 2>"$CASE_DIR/e.txt"; code=$?
  assert_eq "exit code" "$code" 1 || rc=1
  assert_eq "stderr" "$(cat "$CASE_DIR/e.txt")" "spcontact: error: cannot rename $CASE_DIR/d.h5.part to $CASE_DIR/d.h5 (Is a directory); the complete results stay under their .part names" || rc=1
  assert_eq "files" "$(cd "$CASE_DIR" && ls -d d.* d_* | tr '\n' ' ')" "d.csv.part d.h5 d.h5.part d.xmf.part d_contact.csv.part " || rc=1
  return $rc
}

# A failed run (the step cannot converge in 2 Newton iterations, no cut-back): status failed,
# exit 2, every file keeps its .part name (no step converged: no .xmf at all)
test_restart_failed_status() {
  local rc=0 code
  spc "$CASE_DIR/f.txt" 1 -options_file input/hertz2d.opts -load_steps 2 -snes_max_it 2 -load_max_cutbacks 0 -output_dir "$CASE_DIR" -output_name f; code=$?
  assert_eq "exit code" "$code" 2 || rc=1
  assert_eq "status" "$(rs_h5 "$CASE_DIR/f.h5.part" | cut -d' ' -f1-2)" "failed 0" || rc=1
  assert_eq "files, all .part" "$(cd "$CASE_DIR" && ls f.* f_* | tr '\n' ' ')" "f.csv.part f.h5.part f.txt f_contact.csv.part " || rc=1
  # the summary reports the last converged state (here u = 0: nothing penetrates), as its closing
  # line says, and counts the active points as the contact-points CSV does (before: the active
  # points, penetration and gap error of the failed iterate, 3.99e-05 deep)
  assert_eq "summary at u = 0: penetration, gap error" "$(sval "$CASE_DIR/f.txt" contact_max_penetration) $(sval "$CASE_DIR/f.txt" contact_gap_error)" "0.0000000000e+00 0.0000000000e+00" || rc=1
  assert_eq "active points: summary = CSV" "$(sval "$CASE_DIR/f.txt" contact_active_points)" "$(awk -F, 'NR > 1 {a += $9} END {print a}' "$CASE_DIR/f_contact.csv.part")" || rc=1
  return $rc
}

# Restart errors: one line each, nonzero exit, nothing written
test_restart_bad_input() {
  local rc=0
  spc "$CASE_DIR/h.txt" 1 -options_file input/hertz2d.opts -load_steps 4 -debug_interrupt_after_step 1 -output_dir "$CASE_DIR" -output_name h
  spc "$CASE_DIR/c.txt" 1 -options_file input/hertz2d.opts -load_steps 1 -output_dir "$CASE_DIR" -output_name c || rc=1
  spc "$CASE_DIR/f.txt" 1 -options_file input/friction_block2d.opts -debug_interrupt_after_step 2 -output_dir "$CASE_DIR" -output_name f
  spc "$CASE_DIR/p.txt" 1 -options_file input/hertz2d.opts -contact_method penalty -load_steps 4 -debug_interrupt_after_step 1 -output_dir "$CASE_DIR" -output_name p
  "$PYTHON" -c "import h5py; h5py.File('$CASE_DIR/empty.h5','w')"
  echo "not hdf5" > "$CASE_DIR/text.h5"
  "$PYTHON" -c "import h5py; h5py.File('$CASE_DIR/old.h5','w').create_group('restart').attrs['steps'] = 1"
  bad_input_cases <<EOF || rc=1
restart file missing|input/hertz2d.opts|-load_steps 4 -output_name x -restart $CASE_DIR/none.h5
restart file not HDF5|input/hertz2d.opts|-load_steps 4 -output_name x -restart $CASE_DIR/text.h5
restart file without restart data|input/hertz2d.opts|-load_steps 4 -output_name x -restart $CASE_DIR/empty.h5
restart data of an older version (partition order)|input/hertz2d.opts|-load_steps 4 -output_name x -restart $CASE_DIR/old.h5
restart of a complete run|input/hertz2d.opts|-load_steps 1 -output_name x -restart $CASE_DIR/c.h5
restart over its own file|input/hertz2d.opts|-load_steps 4 -output_name h -restart $CASE_DIR/h.h5.part
restart with another method|input/hertz2d.opts|-load_steps 4 -output_name x -contact_method alm -restart $CASE_DIR/h.h5.part
restart with another mesh|input/hertz2d.opts|-load_steps 4 -output_name x -dm_refine 1 -restart $CASE_DIR/h.h5.part
restart with friction added|input/hertz2d.opts|-load_steps 4 -output_name x -contact_friction_mu 0.2 -restart $CASE_DIR/h.h5.part
restart with the obstacle moved|input/hertz2d.opts|-load_steps 4 -output_name x -contact_obstacle_0_point 0,-0.001 -restart $CASE_DIR/h.h5.part
restart with another load|input/hertz2d.opts|-load_steps 4 -output_name x -bc_1_value 0.006 -restart $CASE_DIR/h.h5.part
restart with another Poisson ratio (an option not given there)|input/hertz2d.opts|-load_steps 4 -output_name x -material_nu 0.25 -restart $CASE_DIR/h.h5.part
restart with another friction coefficient|input/friction_block2d.opts|-output_name x -contact_friction_mu 0.2 -restart $CASE_DIR/f.h5.part
restart with another obstacle friction coefficient|input/friction_block2d.opts|-output_name x -contact_obstacle_0_mu 0.2 -restart $CASE_DIR/f.h5.part
restart of penalty with another penalty factor|input/hertz2d.opts|-load_steps 4 -output_name x -contact_method penalty -contact_alpha 100 -restart $CASE_DIR/p.h5.part
restart with the box taller (the same counts; QA helper 25)|input/friction_block2d.opts|-output_name x -dm_plex_box_upper 1,0.6 -restart $CASE_DIR/f.h5.part
restart with the mesh scaled|input/friction_block2d.opts|-output_name x -dm_plex_scale 3 -restart $CASE_DIR/f.h5.part
EOF
  assert_eq "no x.* output written" "$(ls "$CASE_DIR" | grep -c '^x[._]')" 0 || rc=1
  # what may change: the same values written otherwise, solver options, and alpha where the
  # solution does not depend on it (shifted)
  spc "$CASE_DIR/r.txt" 1 -options_file input/friction_block2d.opts -contact_friction_mu 3e-1 -material_nu 0.0 -bc_1_value "0.0015, 0" -contact_alpha 100 -ksp_rtol 1e-9 -output_dir "$CASE_DIR" -output_name r -restart "$CASE_DIR/f.h5.part" || rc=1
  assert_eq "restart with mu 3e-1 for 0.3, nu 0.0 for 0, a value with a space, another alpha and ksp_rtol: status" "$(sval "$CASE_DIR/r.txt" status)" complete || rc=1
  # an option the run does not use (a plane's radius) is not compared: reported unused instead
  spc "$CASE_DIR/r3.txt" 1 -options_file input/friction_block2d.opts -contact_obstacle_0_radius 2 -output_dir "$CASE_DIR" -output_name r3 -restart "$CASE_DIR/f.h5.part" || rc=1
  assert_eq "restart with a plane's radius added: status" "$(sval "$CASE_DIR/r3.txt" status)" complete || rc=1
  assert_eq "the radius reported unused" "$(grep -c '^spcontact: warning: option -contact_obstacle_0_radius was not used' "$CASE_DIR/r3.txt")" 1 || rc=1
  # a value with a space is compared whole (QA helper 25: only its first word was)
  spc "$CASE_DIR/r2.txt" 1 -options_file input/friction_block2d.opts -bc_1_value "0.0015, 0.001" -output_dir "$CASE_DIR" -output_name r2 -restart "$CASE_DIR/f.h5.part"
  assert_eq "restart with a changed second word of a value: refused" "$(grep -c '^spcontact: error: -restart .*-bc_1_value is 0.0015,0 there and 0.0015, 0.001 here' "$CASE_DIR/r2.txt")" 1 || rc=1
  # an option on one side only is refused even at its default (the file holds the options given,
  # not the defaults taken), and the line says which side and what to do
  sed '/^-material_nu/d' input/friction_block2d.opts >"$CASE_DIR/nomu.opts"
  spc "$CASE_DIR/r4.txt" 1 -options_file "$CASE_DIR/nomu.opts" -output_dir "$CASE_DIR" -output_name r4 -restart "$CASE_DIR/f.h5.part"
  assert_eq "option given there only: refused, give it here" "$(grep -c "^spcontact: error: -restart $CASE_DIR/f.h5.part: -material_nu 0 was given to the interrupted run and is not given here; give it here too (the problem would change)$" "$CASE_DIR/r4.txt")" 1 || rc=1
  spc "$CASE_DIR/r5.txt" 1 -options_file input/friction_block2d.opts -contact_two_pass 0 -output_dir "$CASE_DIR" -output_name r5 -restart "$CASE_DIR/f.h5.part"
  assert_eq "option given here only: refused, leave it out if at its default" "$(grep -c "^spcontact: error: -restart $CASE_DIR/f.h5.part: -contact_two_pass 0 is given here and was not given to the interrupted run, which took its default; leave it out if 0 is the default (-help shows it), else restart with the interrupted run's options (the problem would change)$" "$CASE_DIR/r5.txt")" 1 || rc=1
  return $rc
}

# 3 ranks (the partition cuts the contact surface of the sliding block)
test_restart_friction_slide_shifted_np3() { rs_case 3 -options_file input/friction_slide2d.opts -contact_method shifted; }
