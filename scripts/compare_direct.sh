#!/usr/bin/env bash
# 2D runs with the sparse direct solver from the start (the default up to -solver_direct_dofs) against
# the iterative start (-solver_direct_dofs 0: CG or GMRES + GAMG, switching to the factorization only
# once a solve takes more than -solver_direct_switch iterations): B2 (also refined once and twice),
# B6 (two discs), B6 dissimilar, F1b (friction_slide2d), F2 (Cattaneo-Mindlin) and F5 (unloading).
# Usage: [CASES="hertz2d hertz2d_r1 ..."] scripts/compare_direct.sh [NP] [-- options for every run]
# Three runs per case: iterative, direct (the default: Cholesky where the Jacobian is symmetric,
# frictionless; LU with friction) and lu (-solver_direct_cholesky false; the same as direct with
# friction). Prints one table (also build/compare-direct/direct.csv): dofs, Newton and linear iterations, the
# load step of the switch (direct_from: 1 = from the start, 0 = never), max penetration, wall time
# (the summary's wall_time: the solve without process start-up), peak memory per rank.
cd "$(dirname "$0")/.." || exit 1
source scripts/env.sh
np=1; [ $# -gt 0 ] && [ "$1" != "--" ] && { np=$1; shift; }
[ "${1:-}" = "--" ] && shift
out=build/compare-direct; mkdir -p "$out"
cases=(${CASES:-hertz2d hertz2d_r1 hertz2d_r2 hertz2d_twobody hertz2d_dissimilar friction_slide2d cattaneo2d cattaneo2d_unload})
declare -A extra=([hertz2d_r1]="-dm_refine 1" [hertz2d_r2]="-dm_refine 2")
echo "case,start,dofs,newton_iterations,linear_iterations,direct_from,linear_solver,max_penetration,converged,wall_time,memory_mib" > "$out/direct.csv"
for c in "${cases[@]}"; do
  opts=input/${c%_r[0-9]}.opts
  [ -f "$opts" ] || { echo "compare_direct: no $opts (case $c)" >&2; exit 1; }
  for start in iterative direct lu; do
    name=${c}_$start
    sw=""; [ $start = iterative ] && sw="-solver_direct_dofs 0"
    [ $start = lu ] && sw="-solver_direct_cholesky false"
    $MPIEXEC -n "$np" bin/spcontact -options_file "$opts" ${extra[$c]} $sw -output_dir "$out" -output_name "$name" \
      -output_fields false "$@" > "$out/$name.txt" 2>&1
    val() { awk -v k="$1" '/^=== spcontact summary/{on=1} on && $1==k {print $2}' "$out/$name.txt" | tail -1; }
    echo "$c,$start,$(val dofs),$(val newton_iterations),$(val linear_iterations),$(val direct_solver_from_step),$(val linear_solver),$(val contact_max_penetration),$(val converged),$(val wall_time),$(val memory_peak_rank_mib)" >> "$out/direct.csv"
  done
done
column -s, -t "$out/direct.csv"
