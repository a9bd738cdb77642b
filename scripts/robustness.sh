#!/usr/bin/env bash
# Robustness of the default solver strategy (inexact Newton + Jacobian reuse, see README
# "Performance"): B2, B3, B4 (24^3), B6 and the two-pass patch test (without increment growth, as measured before it existed) at alpha 10, 100, 1000 for
# penalty, shifted and alm, with the default iterative solver (CG or GMRES + GAMG), against the
# same runs with exact linear solves and a fresh Jacobian and preconditioner every Newton iteration
# (-solver_inexact false -solver_jacobian_reuse 0 -solver_pc_lag 0).
# Usage: scripts/robustness.sh [NP] [--cases c1,c2] [--methods m1,m2] [-- extra options]
# Prints one table (also build/robustness/robustness.csv): Newton iterations with the default and
# with exact solves, their difference, linear iterations per Newton iteration for both, Jacobian
# reuses and Jacobians that kept the preconditioner (defaults), converged.
cd "$(dirname "$0")/.." || exit 1
source scripts/env.sh
np=1; cases=B2,B3,B4,B6,patch2p; methods=penalty,shifted,alm; extra=()
[[ ${1:-} =~ ^[0-9]+$ ]] && { np=$1; shift; }
while [ $# -gt 0 ]; do
  case $1 in
    --cases) [ $# -ge 2 ] || { echo "robustness.sh: --cases needs a value (see --help)" >&2; exit 1; }; cases=$2; shift 2 ;;
    --methods) [ $# -ge 2 ] || { echo "robustness.sh: --methods needs a value (see --help)" >&2; exit 1; }; methods=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "robustness.sh: unknown argument $1 (see --help)" >&2; exit 1 ;;
  esac
done
make -s bin/spcontact >/dev/null || exit 1
declare -A opts=(
  [B2]="-options_file input/hertz2d.opts"
  [B3]="-options_file input/hertz3d.opts"
  [B4]="-options_file input/indent3d.opts -dm_plex_box_faces 24,24,24"
  [B6]="-options_file input/hertz2d_twobody.opts"
  [patch2p]="-options_file input/patch_4_5.opts -contact_two_pass -load_grow_after 0"
)
out=build/robustness; mkdir -p "$out"
csv=$out/robustness.csv
echo "case,method,alpha,newton,newton_exact,extra_newton,lin_per_newton,lin_per_newton_exact,jacobian_reuses,preconditioner_kept,converged,converged_exact" > "$csv"
v() { awk -v k="$2" '/^=== spcontact summary/{on=1} on && $1==k {print $2}' "$1" | tail -1; }
for c in ${cases//,/ }; do
  for m in ${methods//,/ }; do
    for a in 10 100 1000; do
      base="$out/${c}_${m}_a$a"
      # shellcheck disable=SC2086
      $MPIEXEC -n "$np" bin/spcontact ${opts[$c]} -contact_method "$m" -contact_alpha "$a" -output_dir "$out" -output_name "${c}_${m}_a$a" -output_fields false -quiet "${extra[@]}" > "$base.txt" 2>&1
      # shellcheck disable=SC2086
      $MPIEXEC -n "$np" bin/spcontact ${opts[$c]} -contact_method "$m" -contact_alpha "$a" -output_dir "$out" -output_name "${c}_${m}_a${a}_exact" -output_fields false -quiet -solver_inexact false -solver_jacobian_reuse 0 -solver_pc_lag 0 "${extra[@]}" > "$base.exact.txt" 2>&1
      n=$(v "$base.txt" newton_iterations); ne=$(v "$base.exact.txt" newton_iterations)
      l=$(v "$base.txt" linear_iterations); le=$(v "$base.exact.txt" linear_iterations)
      echo "$c,$m,$a,$n,$ne,$((n - ne)),$(awk -v l="$l" -v n="$n" 'BEGIN{printf "%.1f", l/(n>0?n:1)}'),$(awk -v l="$le" -v n="$ne" 'BEGIN{printf "%.1f", l/(n>0?n:1)}'),$(v "$base.txt" jacobian_reuses),$(v "$base.txt" preconditioner_kept),$(v "$base.txt" converged),$(v "$base.exact.txt" converged)" >> "$csv"
      tail -1 "$csv" >&2
    done
  done
done
column -s, -t "$csv"
