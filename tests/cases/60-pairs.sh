# Contact pairs (deformable-deformable, 2D node-to-segment; 3D: 61-pairs3d.sh): B5 patch test
# one-pass/two-pass with every method, B6 two-body Hertz, frictionless sliding across segment junctions, the tangent at a
# penetrated and slid state, parallel invariance with the interface cut by the partition, bad input.

# max |p - q| / q over all contact points, from the contact-points CSV
pairs_pressure_dev() { awk -F, -v q="$2" 'NR>1 { d = ($8 - q) / q; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.3e\n", m }' "$1"; }

# b5_case MESH METHOD TWO_PASS [bound]: converged, contact force q x 1 to 1e-8; with a bound, the
# max relative pressure deviation must stay below it (two-pass shifted-type methods: 1e-6)
b5_case() {
  local mesh=$1 m=$2 tp=$3 bound=${4:-} out=$CASE_DIR/$1_$2_$3.txt rc=0
  spc "$out" 1 -options_file input/patch_$mesh.opts -contact_method "$m" -contact_two_pass "$tp" -output_dir "$CASE_DIR" -output_name "p_${mesh}_${m}_$tp" || return 1
  local dev; dev=$(pairs_pressure_dev "$CASE_DIR/p_${mesh}_${m}_${tp}_contact.csv" 0.01)
  echo "B5 $mesh method $m two_pass $tp: newton $(sval "$out" newton_iterations) max_penetration $(sval "$out" contact_max_penetration) pressure_deviation $dev"
  assert_eq converged "$(sval "$out" converged)" yes || rc=1
  assert_close contact_force "$(sval "$out" contact_force_y)" 0.01 1e-8 || rc=1
  [ -n "$bound" ] && { assert_le pressure_deviation "$dev" "$bound" || rc=1; }
  return $rc
}
b5_all() { # one-pass is known to fail the patch test: its deviation is reported, not bounded
  local mesh=$1 rc=0
  for m in penalty shifted shifted_regression alm; do b5_case "$mesh" "$m" false || rc=1; done
  b5_case "$mesh" penalty true || rc=1
  for m in shifted shifted_regression alm; do b5_case "$mesh" "$m" true 1e-6 || rc=1; done
  return $rc
}
test_pairs_b5_4_5() { b5_all 4_5; }
test_pairs_b5_7_4() { b5_all 7_4; }

# B6: E* = 0.549451, b = 0.152227, p0 = 0.0418205 (finite block: 3 %)
test_pairs_b6_shifted() {
  local out=$CASE_DIR/run.txt rc=0
  spc "$out" 1 -options_file input/hertz2d_twobody.opts -output_dir "$CASE_DIR" || return 1
  assert_eq converged "$(sval "$out" converged)" yes || rc=1
  assert_close contact_force "$(sval "$out" contact_force_y)" 0.005 1e-8 || rc=1
  assert_close master_force "$(sval "$out" contact_force_master_y)" -0.005 1e-8 || rc=1
  assert_close peak_pressure "$(sval "$out" contact_peak_pressure)" 0.0418205 0.03 || rc=1
  assert_le max_penetration "$(sval "$out" contact_max_penetration)" 1e-10 || rc=1
  echo "half-width $(sval "$out" contact_radius) (b = 0.152227)"
  assert_close jacobian_mallocs "$(sval "$out" contact_jacobian_mallocs)" 0 0 0 || rc=1
  return $rc
}

# slide_figures OUT : from the per-step contact lines of a sliding run, the worst slave/master force
# balance, tangential/normal force ratio, normal force variation against step 1, max penetration
slide_figures() {
  awk '/^contact_step/ { fx = $6; fy = $7; mx = $9; my = $10; pen = $12;
         if (!f0) f0 = fy;
         bal = (fy + my) / fy; if (bal < 0) bal = -bal; if (bal > mb) mb = bal;
         t = fx / fy; if (t < 0) t = -t; if (t > mt) mt = t;
         d = (fy - f0) / f0; if (d < 0) d = -d; if (d > md) md = d;
         if (pen > mp) mp = pen }
       END { printf "force_balance %.3e\ntangential_ratio %.3e\nnormal_force_variation %.3e\nmax_penetration_converged %.3e\n", mb, mt, md, mp }' "$1"
}

# Sliding: a block pressed 0.005 into a longer one, then slid 0.6 in 12 steps (slave vertices every
# 0.12 cross master vertices every 0.2; no crossing happens exactly at a converged state). Per step: slave/master forces balance, no penetration,
# normal force within 3 % of the first step's, tangential force tiny (frictionless).
test_pairs_slide() {
  local out=$CASE_DIR/run.txt rc=0
  spc "$out" 1 -options_file input/slide2d.opts -output_dir "$CASE_DIR" || return 1
  assert_eq converged "$(sval "$out" converged)" yes || rc=1
  grep '^contact_step' "$out"
  [ "$(grep -c '^contact_step' "$out")" -eq 12 ] || { echo "expected 12 load steps"; rc=1; }
  slide_figures "$out" > "$CASE_DIR/figs.txt"
  cat "$CASE_DIR/figs.txt"
  # Newton iterates (not converged states) of steps 2..12: bounded by 0.05 h, the same at crossings
  awk -F, 'NR>1 { if ($6 > m[$1]) m[$1] = $6 } END { for (k in m) printf "step %d max penetration over its Newton iterates %.3e\n", k, m[k] }' "$CASE_DIR/slide2d.csv" | sort -k2 -n
  local iter_pen; iter_pen=$(awk -F, 'NR>1 && $1 > 1 && $6 > m { m = $6 } END { printf "%.3e", m }' "$CASE_DIR/slide2d.csv")
  assert_le force_balance "$(awk '$1=="force_balance"{print $2}' "$CASE_DIR/figs.txt")" 1e-10 || rc=1
  assert_le tangential_ratio "$(awk '$1=="tangential_ratio"{print $2}' "$CASE_DIR/figs.txt")" 1e-3 || rc=1
  assert_le normal_force_variation "$(awk '$1=="normal_force_variation"{print $2}' "$CASE_DIR/figs.txt")" 0.03 || rc=1
  assert_le max_penetration_every_step "$(awk '$1=="max_penetration_converged"{print $2}' "$CASE_DIR/figs.txt")" 1e-10 || rc=1
  assert_le max_penetration_iterates_steps_2_12 "$iter_pen" 0.006 || rc=1
  return $rc
}

# Consistent finite-sliding tangent (projection and normal variations): penalty, the whole slide
# in one step, so the Newton iterates are penetrated and slid; full geometric tangent.
test_pairs_jacobian_slid() {
  local out=$CASE_DIR/run.txt rc=0
  spc "$out" 1 -options_file input/slide2d.opts -load_steps 1 -contact_method penalty -contact_tangent full \
    -snes_test_jacobian -snes_max_it 3 -contact_step_cap 0 -load_max_cutbacks 0 -ksp_type preonly -pc_type lu -contact_monitor -output_dir "$CASE_DIR"
  grep -E '\|\|J - Jfd\|\|_F/\|\|J\|\|_F|contact +[0-9]' "$out"
  grep '||J - Jfd||_F/||J||_F =' "$out" | sed 's/.*||J||_F = \([^,]*\),.*/\1/' > "$CASE_DIR/ratios.txt"
  [ "$(wc -l < "$CASE_DIR/ratios.txt")" -ge 3 ] || { echo "expected 3 Jacobian tests"; return 1; }
  while read -r r; do assert_le jacobian_ratio "$r" 1e-6 || rc=1; done < "$CASE_DIR/ratios.txt"
  return $rc
}

# 1, 2, 3 ranks; METIS puts the bodies on different ranks, so contact elements have master
# facets owned elsewhere (contact_remote_elements > 0)
pairs_invariance() { # pairs_invariance OPTS [extra]
  local opts=$1 rc=0; shift
  for np in 1 2 3; do spc "$CASE_DIR/np$np.txt" $np -options_file "$opts" -output_dir "$CASE_DIR" -output_name np$np "$@" || return 1; done
  for np in 2 3; do
    echo "-- 1 rank vs $np ranks (remote elements $(sval "$CASE_DIR/np$np.txt" contact_remote_elements), mallocs $(sval "$CASE_DIR/np$np.txt" contact_jacobian_mallocs), exchange time $(sval "$CASE_DIR/np$np.txt" contact_exchange_time) s)"
    assert_eq converged "$(sval "$CASE_DIR/np$np.txt" converged)" yes || rc=1
    same_summary "$CASE_DIR/np1.txt" "$CASE_DIR/np$np.txt" 1e-8 contact_peak_pressure contact_radius contact_active_points displacement_max contact_points || rc=1
    # a force component that vanishes (3D: y) is round-off of the converged residual: absolute
    # tolerance 1e-10 x the load (the residual target is 1e-10 x the initial residual)
    SAME_ATOL=$(awk -v y="$(sval "$CASE_DIR/np1.txt" contact_force_y)" -v z="$(sval "$CASE_DIR/np1.txt" contact_force_z)" 'BEGIN{y=y<0?-y:y; z=z<0?-z:z; print 1e-10*(y>z?y:z)}') \
      same_summary "$CASE_DIR/np1.txt" "$CASE_DIR/np$np.txt" 1e-8 contact_force_y contact_force_z || rc=1
    assert_ge remote_elements "$(sval "$CASE_DIR/np$np.txt" contact_remote_elements)" 1 || rc=1
    assert_close jacobian_mallocs "$(sval "$CASE_DIR/np$np.txt" contact_jacobian_mallocs)" 0 0 0 || rc=1
  done
  return $rc
}
test_pairs_b6_parallel_invariance() { pairs_invariance input/hertz2d_twobody.opts; }

# GAMG's graph without the matrix's zero entries (-pc_gamg_threshold 0, spcontact's default with
# pairs or friction) against PETSc's graph that keeps them (-1): B6 (CG) on 1, 2 and 3 ranks, the
# same active points, force and peak pressure to 1e-8, Newton iterations within one (the loose later
# search steps, -solver_inexact_rtol_search_later, end where each preconditioner leaves them:
# measured 11 and 12 either way round), at most 3/4 of the CG
# iterations (1 rank: 863 -> 400); the default is the option given (-pc_gamg_threshold 0
# explicitly: the same run to the digit). GAMG throughout (-solver_direct_switch 0): with zero
# entries kept a solve takes up to 122 CG iterations, and the 2D switch to LU would end the test.
test_pairs_gamg_graph() {
  local rc=0 on off
  for np in 1 2 3; do
    for v in default:'' kept:'-pc_gamg_threshold -1' given:'-pc_gamg_threshold 0'; do
      # shellcheck disable=SC2086
      spc "$CASE_DIR/${v%%:*}$np.txt" $np -options_file input/hertz2d_twobody.opts ${v#*:} -solver_direct_switch 0 -output_dir "$CASE_DIR" -output_name "${v%%:*}$np" || return 1
    done
    assert_eq "converged_np$np" "$(sval "$CASE_DIR/default$np.txt" converged)" yes || rc=1
    same_summary "$CASE_DIR/kept$np.txt" "$CASE_DIR/default$np.txt" 1e-8 contact_active_points contact_force_y contact_peak_pressure || rc=1
    assert_close "newton_iterations_np$np" "$(sval "$CASE_DIR/default$np.txt" newton_iterations)" "$(sval "$CASE_DIR/kept$np.txt" newton_iterations)" 0 1 || rc=1
    # the explicit 0 is the default; on 3 ranks two runs of the same command differ by round-off
    # (262 or 263 CG iterations, the peak pressure by 3e-14; also before 2026-11-28's change, 1 run in 4)
    same_summary "$CASE_DIR/given$np.txt" "$CASE_DIR/default$np.txt" 1e-10 contact_force_y contact_peak_pressure || rc=1
    assert_eq "newton_iterations_given_np$np" "$(sval "$CASE_DIR/given$np.txt" newton_iterations)" "$(sval "$CASE_DIR/default$np.txt" newton_iterations)" || rc=1
    assert_close "linear_iterations_given_np$np" "$(sval "$CASE_DIR/given$np.txt" linear_iterations)" "$(sval "$CASE_DIR/default$np.txt" linear_iterations)" 0 1 || rc=1
    on=$(sval "$CASE_DIR/default$np.txt" linear_iterations); off=$(sval "$CASE_DIR/kept$np.txt" linear_iterations)
    echo "np $np: CG iterations $off (zero entries kept) -> $on (default)"
    assert_le "linear_iterations_np${np}_fewer" "$on" $((off * 3 / 4)) || rc=1
  done
  return $rc
}
test_pairs_b5_two_pass_parallel_invariance() { pairs_invariance input/patch_7_4.opts -contact_two_pass; }

test_pairs_bad_input() {
  bad_input_cases <<'CASES'
pair without master|input/patch_4_5.opts|-contact_pair_1_slave_values 3
pair without slave|input/patch_4_5.opts|-contact_pair_1_master_values 2
empty master values|input/patch_4_5.opts|-contact_pair_0_master_values
slave = master|input/patch_4_5.opts|-contact_pair_0_master_values 3
unknown master value|input/patch_4_5.opts|-contact_pair_0_master_values 42
unknown pair label|input/patch_4_5.opts|-contact_pair_0_label nosuch
unknown tangent|input/patch_4_5.opts|-contact_tangent nosuch
two-pass without pair|input/block2d.opts|-contact_two_pass
CASES
}

# A body drifting over its master surface: F2's set-up without friction (-contact_friction_mu 0)
# leaves the upper disc without tangential support. It used to stall and cut back while the disc
# slid sideways (the master facets it met outside the exchange's bounding box once ended in PETSc's
# "New nonzero ... caused a malloc"; SPContactMarkRows marks every owned master facet's rows, and a
# failed solve's Jacobian is not reused). The body check now refuses the set-up before the solve:
# with the block held still, the disc turns about its centre on its frictionless pair. One error
# line, exit 1, no output file, on 1 and 2 ranks. (With mu = 0.001 it still drifts and ends as a
# failed solve, exit 2, but takes 86 s with 6 cut-backs: not a test.)
test_pairs_drift_pattern() {
  local rc=0 np out
  for np in 1 2; do
    out=$CASE_DIR/np$np.txt
    spc "$out" "$np" -options_file input/cattaneo2d.opts -contact_friction_mu 0 -output_dir "$CASE_DIR" -output_name "np$np"
    assert_eq "exit_np$np" $? 1 || rc=1
    assert_eq "error_lines_np$np" "$(grep -c '^spcontact: error' "$out")" 1 || rc=1
    assert_eq "refused as free to turn, np$np" "$(grep -c '^spcontact: error: nothing holds the body in the box (-1, 0)..(1, 1) (9997 cells) against the bodies it touches: .* to turn about the point (0, 1.00138)' "$out")" 1 || rc=1
    assert_eq "no PETSc line np$np" "$(grep -c 'caused a malloc\|PETSC ERROR' "$out")" 0 || rc=1
    [ -z "$(ls "$CASE_DIR" | grep -E "^np$np\.(h5|xmf|csv)$")" ] || { echo "np$np output written FAILED"; rc=1; }
  done
  return $rc
}

# Two-pass pairs: a vertex that overhangs the other surface's end has no projection of its own but
# carries force as a master (QA helper 27). Its pressure is its force along its own surface's
# normal: the upper block slid 0.4 past the lower block's end, the slave surface's sum of p A is
# the slave force to 1e-4 (the normals' tilt; 12 % of it was missing, at pressure 0), on 1 and 2
# ranks; its gap is nan in _contact.csv, as in the h5. In 3D with friction the normal force at
# such points is no longer counted as tangential: contact_tangential_force_z 6.0e-5 (one pass:
# 6e-5) against 2.34e-3 of contact_force_z 2.35e-2 before.
test_pairs_two_pass_overhang_pressure() {
  local rc=0 np out sum
  for np in 1 2; do
    out=$CASE_DIR/o$np.txt
    spc "$out" $np -options_file input/slide2d.opts -contact_two_pass -bc_1_value -0.4,0 -load_steps 8 -output_dir "$CASE_DIR" -output_name o$np || rc=1
    sum=$(awk -F, 'NR > 1 && $2 < 0.4975 { s += $8 * $4 } END { printf "%.12e", s }' "$CASE_DIR/o${np}_contact.csv")
    assert_close "slave surface's sum of p A against the slave force on $np rank(s)" "$sum" "$(sval "$out" contact_force_y)" 1e-4 || rc=1
    assert_ge "points with no projection (nan gap) on $np rank(s)" "$(awk -F, 'NR > 1 && $6 == "nan"' "$CASE_DIR/o${np}_contact.csv" | wc -l)" 1 || rc=1
  done
  spc "$CASE_DIR/f3.txt" 1 -options_file input/slide3d.opts -contact_friction_mu 0.2 -load_steps 3 -contact_two_pass -output_dir "$CASE_DIR" -output_name f3 -output_fields false || rc=1
  assert_le "3D: tangential force along the normal, relative to the normal force" "$(awk -v t="$(sval "$CASE_DIR/f3.txt" contact_tangential_force_z)" -v f="$(sval "$CASE_DIR/f3.txt" contact_force_z)" 'BEGIN { if (t < 0) t = -t; printf "%.3e", t / f }')" 1e-2 || rc=1
  return $rc
}
