# Materials per region (-material_<k>_label_value/_law/_E/_nu on the "Cell Sets" values): region
# options that repeat one material change nothing, two-body Hertz with dissimilar materials (both
# ways round, 1 and 2 ranks), the two-material patch test, fast operator = PetscFE with two
# materials, the contact eps at a vertex between materials, bad input. Helpers are prefixed mat_ so they cannot collide with other case files.

# Dissimilar Hertz (input/hertz2d_dissimilar.opts): disc E1 = 1, nu1 = 0.3, block E2 = 3, nu2 = 0.25.
# 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 -> E* = 0.817996, b = 0.124761, p0 = 0.0510271 (P = 0.01).
MAT_ESTAR=0.817996
MAT_B=0.124761
MAT_P0=0.0510271
MAT_SWAP="-material_0_E 3 -material_0_nu 0.25 -material_1_E 1 -material_1_nu 0.3"

# mat_hertz OUT FORCE_SIGN: converged, slave/master forces -/+ P/2 to 1e-8, peak within 3 % of p0
# (the B6 bound), no penetration; prints the half-width and the area-weighted profile error
mat_hertz() {
  local out=$1 sign=$2 rc=0
  assert_eq converged "$(sval "$out" converged)" yes || rc=1
  assert_close contact_force "$(sval "$out" contact_force_y)" "${sign}0.005" 1e-8 || rc=1
  assert_close master_force "$(sval "$out" contact_force_master_y)" "$(awk -v s="${sign}1" 'BEGIN{print -0.005 * s}')" 1e-8 || rc=1
  assert_close peak_pressure "$(sval "$out" contact_peak_pressure)" $MAT_P0 0.03 || rc=1
  assert_le max_penetration "$(sval "$out" contact_max_penetration)" 1e-10 || rc=1
  echo "half-width $(sval "$out" contact_radius) (b = $MAT_B)"
  return $rc
}
mat_profile() { $PYTHON scripts/hertz_profile.py "$1" --E $MAT_ESTAR --nu 0 | tr '\n' ' '; echo; }

# Region options that give every cell the default material: the same run as B6, bit for bit (fast
# operator). Region 0 takes -material_E/_nu as defaults, region 1 sets them; -material_E/_nu are
# given explicitly (PETSc's "_%d_" lookup would find them for -material_0_E, -material_0_nu).
test_materials_single_region_identical() {
  local rc=0
  spc "$CASE_DIR/default.txt" 1 -options_file input/hertz2d_twobody.opts -output_dir "$CASE_DIR" -output_name default || return 1
  spc "$CASE_DIR/regions.txt" 1 -options_file input/hertz2d_twobody.opts -material_E 1 -material_nu 0.3 -material_0_label_value 10 -material_1_label_value 20 -material_1_E 1 -material_1_nu 0.3 -output_dir "$CASE_DIR" -output_name regions || return 1
  assert_eq converged "$(sval "$CASE_DIR/regions.txt" converged)" yes || rc=1
  for k in newton_iterations linear_iterations contact_active_points; do
    assert_eq "$k" "$(sval "$CASE_DIR/regions.txt" $k)" "$(sval "$CASE_DIR/default.txt" $k)" || rc=1
  done
  same_summary "$CASE_DIR/default.txt" "$CASE_DIR/regions.txt" 1e-12 displacement_max contact_force_x contact_force_y contact_force_master_y contact_peak_pressure contact_radius contact_max_penetration contact_gap_error contact_eps_min contact_eps_max || rc=1
  if cmp -s "$CASE_DIR/default_contact.csv" "$CASE_DIR/regions_contact.csv"; then echo "contact points CSV: identical ok"; else echo "contact points CSV: differs FAILED"; rc=1; fi
  return $rc
}

# Dissimilar Hertz on 1 and 2 ranks: the analytic figures, and the same figures on both
test_materials_hertz_dissimilar() {
  local rc=0
  for np in 1 2; do spc "$CASE_DIR/np$np.txt" $np -options_file input/hertz2d_dissimilar.opts -output_dir "$CASE_DIR" -output_name np$np || return 1; done
  for np in 1 2; do
    echo "-- $np rank(s)"
    mat_hertz "$CASE_DIR/np$np.txt" "" || rc=1
  done
  mat_profile "$CASE_DIR/np1_contact.csv"
  echo "-- 1 rank vs 2 ranks"
  same_summary "$CASE_DIR/np1.txt" "$CASE_DIR/np2.txt" 1e-8 contact_force_y contact_force_master_y contact_peak_pressure contact_radius contact_active_points displacement_max contact_eps_min contact_eps_max || rc=1
  return $rc
}

# The stiffer body swapped (disc E = 3, nu = 0.25 on a block E = 1, nu = 0.3): same E*, b, p0. The
# slave goes on the softer body (the block's top edge, slave forces change sign). With the stiff
# disc kept as slave, one-pass node-to-segment gives oscillating pressures (a stiff slave against a
# soft, non-matching master): that figure is printed, not bounded (README, "Materials per region").
test_materials_hertz_dissimilar_swapped() {
  local rc=0
  # shellcheck disable=SC2086
  spc "$CASE_DIR/swap.txt" 1 -options_file input/hertz2d_dissimilar.opts $MAT_SWAP -contact_pair_0_slave_values 4 -contact_pair_0_master_values 3 -output_dir "$CASE_DIR" -output_name swap || return 1
  mat_hertz "$CASE_DIR/swap.txt" "-" || rc=1
  mat_profile "$CASE_DIR/swap_contact.csv"
  # shellcheck disable=SC2086
  spc "$CASE_DIR/stiffslave.txt" 1 -options_file input/hertz2d_dissimilar.opts $MAT_SWAP -output_dir "$CASE_DIR" -output_name stiffslave || return 1
  echo "not bounded: stiff disc as slave: converged $(sval "$CASE_DIR/stiffslave.txt" converged) force $(sval "$CASE_DIR/stiffslave.txt" contact_force_y) peak $(sval "$CASE_DIR/stiffslave.txt" contact_peak_pressure)"
  mat_profile "$CASE_DIR/stiffslave_contact.csv"
  assert_close stiff_slave_force "$(sval "$CASE_DIR/stiffslave.txt" contact_force_y)" 0.005 1e-8 || rc=1
  return $rc
}

# Two-material patch test (input/patch_4_5_materials.opts: E = 1 / 10, nu = 0.2 / 0.3, two-pass
# shifted): contact force q x 1 to 1e-8, pressure q at every point to 1e-6
test_materials_patch() {
  local out=$CASE_DIR/run.txt rc=0 dev
  spc "$out" 1 -options_file input/patch_4_5_materials.opts -output_dir "$CASE_DIR" || return 1
  dev=$(awk -F, -v q=0.01 'NR>1 { d = ($8 - q) / q; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.3e\n", m }' "$CASE_DIR/patch_4_5_materials_contact.csv")
  echo "newton $(sval "$out" newton_iterations) gap_error $(sval "$out" contact_gap_error) pressure_deviation $dev"
  assert_eq converged "$(sval "$out" converged)" yes || rc=1
  assert_close contact_force "$(sval "$out" contact_force_y)" 0.01 1e-8 || rc=1
  assert_le pressure_deviation "$dev" 1e-6 || rc=1
  return $rc
}

# Fast operator (per-cell Lame constants) against PetscFE (P0 auxiliary field) with two materials:
# residual and Jacobian to round-off at a random state: triangles on 1 and 2 ranks, quads, and
# quads of one body with a bonded material interface on 2 ranks
mat_check_fast() {
  local np=$1 name=$2 out rc=0 code line; shift 2
  out=$CASE_DIR/$name.txt
  spc "$out" "$np" "$@" -solver_check_fast -snes_max_it 1 -load_max_cutbacks 0 -output_dir "$CASE_DIR" -output_name "$name" -output_fields false; code=$?
  [ $code -eq 0 ] || [ $code -eq 2 ] || { echo "exit code $code"; tail -n 5 "$out"; return 1; }
  line=$(grep '^fast_check' "$out")
  echo "$name ($np rank(s)): $line"
  assert_eq bulk_operator "$(sval "$out" bulk_operator)" fast || rc=1
  assert_le residual_rel_diff "$(echo "$line" | awk '{print $3}')" 1e-12 || rc=1
  assert_le jacobian_rel_diff "$(echo "$line" | awk '{print $5}')" 1e-12 || rc=1
  return $rc
}
test_materials_fast_check() {
  local rc=0
  mat_check_fast 1 hertz_np1 -options_file input/hertz2d_dissimilar.opts || rc=1
  mat_check_fast 2 hertz_np2 -options_file input/hertz2d_dissimilar.opts || rc=1
  mat_check_fast 1 patch -options_file input/patch_4_5_materials.opts || rc=1
  mat_check_fast 2 bimaterial -options_file input/bimaterial2d.opts || rc=1
  return $rc
}

# The whole dissimilar Hertz run with the PetscFE operator (auxiliary field) gives the fast run's figures
test_materials_petscfe_same() {
  local rc=0
  spc "$CASE_DIR/fast.txt" 1 -options_file input/hertz2d_dissimilar.opts -output_dir "$CASE_DIR" -output_name fast || return 1
  spc "$CASE_DIR/petscfe.txt" 1 -options_file input/hertz2d_dissimilar.opts -solver_fast_bulk false -output_dir "$CASE_DIR" -output_name petscfe || return 1
  assert_eq generic_operator "$(sval "$CASE_DIR/petscfe.txt" bulk_operator)" petscfe || rc=1
  assert_eq converged "$(sval "$CASE_DIR/petscfe.txt" converged)" yes || rc=1
  for k in newton_iterations contact_active_points; do
    assert_eq "$k" "$(sval "$CASE_DIR/petscfe.txt" $k)" "$(sval "$CASE_DIR/fast.txt" $k)" || rc=1
  done
  same_summary "$CASE_DIR/fast.txt" "$CASE_DIR/petscfe.txt" 1e-8 displacement_max contact_force_y contact_peak_pressure contact_radius || rc=1
  return $rc
}

# eps = alpha E / h at a slave vertex takes the largest E of the cells around it
# (input/bimaterial2d.opts: one body, halves of E = 1 and 3 bonded at x = 0.5, alpha 10, h = 1/8):
# eps = 80 E_left for x < 0.5, 80 E_right for x > 0.5, 80 max(E) at x = 0.5. With the halves
# swapped on 2 ranks (METIS), the interface vertex is owned by a rank holding only E = 1 cells:
# without the reduction over ranks its eps would be 80 (checked when the test was written).
mat_vertex_eps() { # NP NAME E_LEFT E_RIGHT [ARGS]
  local np=$1 name=$2 el=$3 er=$4 out rc=0; shift 4
  out=$CASE_DIR/$name.txt
  spc "$out" "$np" -options_file input/bimaterial2d.opts "$@" -output_dir "$CASE_DIR" -output_name "$name" || return 1
  assert_eq converged "$(sval "$out" converged)" yes || rc=1
  assert_close reaction "$(sval "$out" contact_force_y)" 0.01 1e-10 || rc=1
  awk -F, -v el="$el" -v er="$er" 'NR>1 { x = $1 + 0; want = 80 * (x < 0.5 - 1e-9 ? el : (x > 0.5 + 1e-9 ? er : (el > er ? el : er)));
      d = ($5 - want) / want; if (d < 0) d = -d; if (d > 1e-9) { bad++; printf "  x %s eps %s want %s\n", $1, $5, want }
      if (x > 0.5 - 1e-9 && x < 0.5 + 1e-9) printf "  interface vertex x = 0.5: eps %s (want %s)\n", $5, want; n++ }
    END { printf "%s: %d points, eps as expected at %d %s\n", "'"$name"'", n, n - bad, bad ? "FAILED" : "ok"; exit bad > 0 }' "$CASE_DIR/${name}_contact.csv" || rc=1
  return $rc
}
test_materials_vertex_eps() {
  local rc=0
  mat_vertex_eps 1 np1 1 3 || rc=1
  mat_vertex_eps 2 np2 1 3 || rc=1
  mat_vertex_eps 2 np2_swapped 3 1 -material_0_E 3 -material_0_nu 0.25 -material_1_E 1 -material_1_nu 0.3 || rc=1
  return $rc
}

# every case: one line "spcontact: error: ..."; the first must name the uncovered value and the option
test_materials_bad_input() {
  local rc=0
  bad_input_cases <<'CASES' || rc=1
cell without material|input/hertz2d_twobody.opts|-material_0_label_value 10
unknown law|input/hertz2d_dissimilar.opts|-material_1_law nosuch
E zero|input/hertz2d_dissimilar.opts|-material_1_E 0
E negative|input/hertz2d_dissimilar.opts|-material_0_E -3
nu 0.5|input/hertz2d_dissimilar.opts|-material_1_nu 0.5
nu -1|input/hertz2d_dissimilar.opts|-material_0_nu -1
label value with no cells|input/hertz2d_dissimilar.opts|-material_2_label_value 30
same label value twice|input/hertz2d_dissimilar.opts|-material_1_label_value 10
options without label value|input/hertz2d_dissimilar.opts|-material_2_E 5
unknown material label|input/hertz2d_dissimilar.opts|-material_label nosuch
region materials with mms|input/hertz2d_dissimilar.opts|-material_mms 0.01
material index 8|input/hertz2d_dissimilar.opts|-material_8_label_value 30
material index 12, E only|input/hertz2d_dissimilar.opts|-material_12_E 3
region E without label value, -material_E set|input/hertz2d_twobody.opts|-material_E 2 -material_1_E 3
unknown default model|input/hertz2d_twobody.opts|-material_model nosuch
CASES
  grep -q 'value(s) 20 .*-material_<k>_label_value' "$CASE_DIR/e1.txt" && echo "cell without material: names value 20 and -material_<k>_label_value ok" || { echo "cell without material: message does not name value 20 and the option FAILED"; rc=1; }
  return $rc
}

# Set-up warnings for materials that a contact run handles badly (QA helper 28), each with its
# cure checked: a Poisson's ratio near 0.5 (B2 at 0.4999 with the defaults: 20 cut-backs; with the
# advised -contact_shift_accel schur it converges without a cut-back), and a pair whose slave is
# 1e6 times stiffer than its master (20 cut-backs in 100 s; swapped: no warning), on 1 and 2 ranks
test_materials_contact_warnings() {
  local rc=0 np
  for np in 1 2; do
    spc "$CASE_DIR/nu$np.txt" $np -options_file input/hertz2d.opts -material_nu 0.4999 -contact_shift_accel schur -output_dir "$CASE_DIR" -output_name nu$np || rc=1
    assert_eq "nu warning on $np rank(s)" "$(grep -c '^spcontact: warning: -material_nu 0.4999 is near 0.5: P1/Q1 elements lock there' "$CASE_DIR/nu$np.txt")" 1 || rc=1
    assert_eq "the advised schur update converges without a cut-back on $np rank(s)" "$(sval "$CASE_DIR/nu$np.txt" cutbacks)" 0 || rc=1
    spc "$CASE_DIR/st$np.txt" $np -options_file input/hertz2d_dissimilar.opts -material_0_E 1e6 -material_1_E 1 -snes_max_it 2 -load_max_cutbacks 0 -output_dir "$CASE_DIR" -output_name st$np
    assert_eq "stiff slave warning on $np rank(s)" "$(grep -c '^spcontact: warning: contact pair 0: its slave surface is 1e+06 times stiffer than its master (E 1e+06 against 1)' "$CASE_DIR/st$np.txt")" 1 || rc=1
  done
  spc "$CASE_DIR/sw.txt" 1 -options_file input/hertz2d_dissimilar.opts -material_0_E 1 -material_1_E 1e6 -output_dir "$CASE_DIR" -output_name sw || rc=1
  assert_eq "no warning with the slave on the soft body" "$(grep -c 'times stiffer' "$CASE_DIR/sw.txt")" 0 || rc=1
  assert_eq "nor for nu 0.3" "$(grep -c 'near 0.5' "$CASE_DIR/sw.txt")" 0 || rc=1
  return $rc
}
