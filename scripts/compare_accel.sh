#!/usr/bin/env bash
# The shifted method's update rules side by side: penalty (reference), shifted with the plain update
# (-contact_shift_accel none), with Anderson acceleration (anderson) and with the Schur update
# (schur; not with two passes, where it is refused), at alpha = 10, 100, 1000 on B2, B3, B4
# (indent3d at 16^3 cells), B6 and the two-pass patch test (B5).
# Usage: [CASES="hertz2d indent3d ..."] scripts/compare_accel.sh [NP] [-- PETSc/spcontact options for every run]
# (CASES: a subset of the benchmarks, by options-file name; default all five)
# Prints one table (also build/compare-accel/accel.csv): Newton and linear iterations, max
# penetration, converged, and the Schur update's back-substitutions. Direct Cholesky throughout
# (B4 too), so that Newton counts measure the contact algorithm, not the preconditioner, and the
# Schur update has its factorization.
cd "$(dirname "$0")/.." || exit 1
source scripts/env.sh
np=1; [ $# -gt 0 ] && [ "$1" != "--" ] && { np=$1; shift; }
[ "${1:-}" = "--" ] && shift
out=build/compare-accel; mkdir -p "$out"
cases=(${CASES:-hertz2d hertz3d indent3d hertz2d_twobody patch_4_5})
declare -A label=([hertz2d]=B2 [hertz3d]=B3 [indent3d]=B4-16 [hertz2d_twobody]=B6 [patch_4_5]=B5-2pass)
declare -A extra=([indent3d]="-dm_plex_box_faces 16,16,16" [patch_4_5]="-contact_two_pass -load_grow_after 0")
echo "case,alpha,variant,newton_iterations,linear_iterations,max_penetration,gap_tol,converged,back_substitutions,wall_time" > "$out/accel.csv"
for c in "${cases[@]}"; do
  solver="-pc_type cholesky"
  for a in 10 100 1000; do
    for v in penalty none anderson schur; do
      [ $v = schur ] && [ "$c" = patch_4_5 ] && continue
      if [ $v = penalty ]; then m="-contact_method penalty"; else m="-contact_method shifted -contact_shift_accel $v"; fi
      name=${c}_a${a}_$v
      $MPIEXEC -n "$np" bin/spcontact -options_file input/$c.opts ${extra[$c]} $m -contact_alpha $a \
        -output_dir "$out" -output_name "$name" -output_fields false $solver "$@" > "$out/$name.txt" 2>&1
      val() { awk -v k="$1" '/^=== spcontact summary/{on=1} on && $1==k {print $2}' "$out/$name.txt" | tail -1; }
      echo "${label[$c]},$a,$v,$(val newton_iterations),$(val linear_iterations),$(val contact_max_penetration),$(val contact_gap_tol),$(val converged),$(val contact_shift_accel_solves),$(val wall_time)" >> "$out/accel.csv"
    done
  done
done
column -s, -t "$out/accel.csv"
