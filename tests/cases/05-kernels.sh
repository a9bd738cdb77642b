# Kernel unit checks (tests/unit/test-kernels.c, built by make as bin/test-kernels): elasticity,
# obstacle geometry, contact law and pair geometry against central finite differences at random
# states; then the ASSEMBLED Jacobian (bulk + contact) against PETSc's finite-difference Jacobian
# (-snes_test_jacobian) for every contact method on small obstacle and pair cases.
# Run: bash tests/run.sh kernels

# The unit driver: every check prints "name dim samples skipped max_rel_err tol ok|FAILED"; the
# driver exits nonzero if any check fails (max relative error > 1e-6) or has no sample.
# run_unit BIN OUT SECONDS PATTERN: a unit driver with its output in OUT (printed); fails unless it
# exits 0 within SECONDS and prints a line matching PATTERN
run_unit() {
  local bin=$1 out=$2 secs=$3 pat=$4 rc=0
  [ -x "$bin" ] || { echo "$bin missing: build it with make (or make check)"; return 1; }
  RERUN="$bin"
  timeout "$secs" "$bin" >"$out" 2>&1 || rc=1
  cat "$out"
  grep -q "$pat" "$out" || { echo "$bin printed no line matching '$pat'"; rc=1; }
  return $rc
}

test_kernels_unit() {
  local out=$CASE_DIR/unit.txt rc=0
  run_unit bin/test-kernels "$out" 300 ' checks, 0 failed$' || rc=1
  # no check may lose samples to the kink/projection guard (see the driver's header)
  awk '/ max_rel_err / && $7 != 0 { print "skipped samples: " $0; bad = 1 } END { exit bad }' "$out" || rc=1
  return $rc
}

# The pair segment choice near a master vertex (tests/unit/test-pairs.c, bin/test-pairs): the
# nearest segment, and the segment of the last Newton iterate kept while within 1e-4 h of the
# nearest (the hysteresis that ends the 2-cycle of F2's halved mesh, README "Contact pairs"), at two
# length scales, and the returns that widen the band after a 2-cycle (25 checks; of the first 14,
# 4 fail without the rule).
test_pairs_keep_facet() {
  run_unit bin/test-pairs "$CASE_DIR/pairs.txt" 60 '^test-pairs: 25 checks, 0 failed$'
}

# kjac_case LABEL METHOD ARGS... : spcontact with the consistent tangent (-contact_tangent full), a
# direct solve (the full tangent is indefinite at deep penetration: CG would stop) and
# -snes_test_jacobian at every Newton iterate of every solve (alm: of every augmentation).
# Per run: the number of Jacobian tests, those at penetrated states (active points > 0), those
# after a shift update (shift != 0: an in-Newton update, or a new alm solve after an augmentation),
# and the largest ||J - Jfd||_F/||J||_F. Asserts: >= 2 tests, >= 1 penetrated, >= 1 after a shift
# update unless penalty, every ratio <= KJAC_BOUND.
# No contact point may sit at the kink g + s = 0 within PETSc's FD step (~1.5e-8 |u|): there the
# FD Jacobian is one-sided (hertz2d.opts at u = 0 touches the plane exactly: ratio 1.5e-2). The
# cases below start penetrated (no point at g = 0 at u = 0).
KJAC_BOUND=1e-6
kjac_case() {
  local label=$1 m=$2 np=1; shift 2
  [ "${1:-}" = -np ] && { np=$2; shift 2; }
  local out=$CASE_DIR/$label-$m.txt
  spc "$out" "$np" "$@" -contact_method "$m" -snes_test_jacobian -contact_tangent full -load_max_cutbacks 0 \
    -ksp_type preonly -pc_type lu -contact_monitor -output_dir "$CASE_DIR" -output_name "$label-$m"
  awk -v label="$label" -v m="$m" -v np="$np" -v bound="$KJAC_BOUND" '
    /^ *contact +[0-9]+ \|F\|/ {
      for (i = 1; i < NF; ++i) if ($i == "active") act = $(i + 1)
      if ($2 == 0 && seen0) shifted = 1                  # a new solve: alm after an augmentation
      if ($2 == 0) seen0 = 1
      if ($NF + 0 > 0) shifted = 1                        # max_shift_change of this iterate
    }
    /\|\|J - Jfd\|\|_F\/\|\|J\|\|_F = / {
      r = $0; sub(/.*\|\|J\|\|_F = /, "", r); sub(/,.*/, "", r); r += 0
      n++; if (act > 0) pen++; if (shifted) sh++; if (r > mx || n == 1) mx = r
      if (!(r <= bound)) bad++
    }
    END {
      printf "%-12s %-18s ranks %d: %2d Jacobian tests, %2d penetrated, %2d after a shift update, max ||J - Jfd||_F/||J||_F %.3e (bound %g)", label, m, np, n, pen, sh, mx, bound
      ok = (n >= 2 && pen >= 1 && (m == "penalty" || sh >= 1) && !bad)
      print ok ? " ok" : " FAILED"; exit !ok }' "$out"
}

# kjac_methods LABEL ARGS... : kjac_case for every method
kjac_methods() {
  local label=$1 rc=0; shift
  for m in penalty shifted shifted_regression alm; do kjac_case "$label" "$m" "$@" || rc=1; done
  return $rc
}

# Rigid obstacles, all starting inside the body: a tilted plane and a circle on a 6x6 box (2D), the
# B4 sphere on a 4x4x4 box pressed 0.03 (3D), a tilted cylinder on a 3x3x3 box (3D). The curved
# ones carry the curvature term min(0, g + s) A eps d2g/dx2 in the tangent.
kjac_box2d() { echo -dm_plex_dim 2 -dm_plex_simplex 0 -dm_plex_box_faces 6,6 -bc_0_type dirichlet -bc_0_values 1 -contact_values 3; }
test_kernels_jacobian_obstacles() {
  local rc=0
  kjac_methods plane2d $(kjac_box2d) -contact_obstacle_0_type plane -contact_obstacle_0_point 0.5,0.98 -contact_obstacle_0_normal 0.196116135,-0.980580676 || rc=1
  kjac_methods circle2d $(kjac_box2d) -contact_obstacle_0_type sphere -contact_obstacle_0_point 0.5,1.6 -contact_obstacle_0_radius 0.65 || rc=1
  kjac_methods sphere3d -options_file input/indent3d.opts -dm_plex_box_faces 4,4,4 -contact_obstacle_0_motion 0,0,-0.03 || rc=1
  kjac_methods cylinder3d -dm_plex_dim 3 -dm_plex_simplex 0 -dm_plex_box_faces 3,3,3 -bc_0_type dirichlet -bc_0_values 1 -contact_values 2 \
    -contact_obstacle_0_type cylinder -contact_obstacle_0_point 0.5,0.5,1.6 -contact_obstacle_0_normal 1,0.2,0 -contact_obstacle_0_radius 0.65 || rc=1
  return $rc
}

# Contact pairs at penetrated, slid states (one load step: the slave surface starts 0.005 inside and
# slides during the Newton iterations): 2D node-to-segment (slide2d, slid 0.1), 3D node-to-quad
# (slide3d_hex, its diagonal slide); the 3D case again on 2 ranks with shifted (contact elements
# whose master facet lives on the other rank: contact_remote_elements > 0).
test_kernels_jacobian_pairs() {
  local rc=0
  kjac_methods slide2d -options_file input/slide2d.opts -load_steps 1 -bc_1_value 0.1,0 || rc=1
  kjac_methods slide3d_hex -options_file input/slide3d.opts -load_steps 1 || rc=1
  kjac_case slide3d_hex_np2 shifted -np 2 -options_file input/slide3d.opts -load_steps 1 || rc=1
  assert_ge contact_remote_elements_np2 "$(sval "$CASE_DIR/slide3d_hex_np2-shifted.txt" contact_remote_elements)" 1 || rc=1
  return $rc
}
