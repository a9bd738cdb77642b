#!/usr/bin/env bash
# Benchmark B4 (rigid sphere indenting a box, input/indent3d.opts) and its elasticity floor.
#
# Usage: scripts/bench.sh [--sizes N1,N2,..] [--ranks P1,P2,..] [--methods M1,M2,..] [--no-floor]
#                         [--out DIR] [-- extra spcontact/PETSc options]
#   --sizes    cells per box edge (N^3 Q1 hexes, 3 (N+1)^3 dofs): 32 ~ 1e5, 55 ~ 5e5, 70 ~ 1e6 dofs
#   defaults:  --sizes 12 --ranks 1 --methods penalty,shifted,alm (a smoke run of a minute or so)
#   full:      scripts/bench.sh --sizes 32,55,70 --ranks 1,2 --methods penalty,shifted,alm   (hours)
#
# Per size and rank count: one "floor" row (elasticity only: the same mesh and supports, contact
# dropped, the top face pushed down 0.01 by a Dirichlet condition: one linear solve) and one row per
# contact method. Every phase is read from PETSc's own log (-log_view :file:ascii_csv, max over
# ranks), so -log_view agrees with the table:
#   setup        stages "SP mesh" + "SP setup" (mesh, distribution, FE/problem, contact points,
#                preallocation SPMatCreate, near-null space SPNearNullSpace, SPFastSetUp)
#   bulk_res     event SPBulkResidual      bulk_jac  event SPBulkJacobian
#   c_search     event SPContactSearch (every gap evaluation: obstacle distances, pair projections
#                and the master-facet exchange between ranks)
#   c_assem      events SPContactAssem + SPShiftUpdate minus the search nested in them (contact
#                residual and tangent terms, step control, shift update)
#   pc_setup     event PCSetUp             lin_solve event KSPSolve
#   output       stage "SP output" (HDF5/XDMF per load step, CSV, contact points)
#   total        wall_time of the run's summary; other = total - the phases above
#   it/floor     (solve stage / Newton iterations) / (floor solve stage): cost of a Newton
#                iteration in units of the elasticity solve
#   mem_MiB      peak resident memory of the largest rank (summary memory_peak_rank_mib)
# Output: the table on stdout, DIR/bench.csv, DIR/bench.png (log-log wall time against dofs per
# method and rank count, with the fitted exponents printed; needs two sizes or more), and every
# run's stdout and log in DIR (default build/bench). Timings are never part of `make check`.
cd "$(dirname "$0")/.." || exit 1
source scripts/env.sh
sizes=12; ranks=1; methods=penalty,shifted,alm; floor=1; out=build/bench; extra=()
while [ $# -gt 0 ]; do
  case $1 in
    --sizes) [ $# -ge 2 ] || { echo "bench.sh: --sizes needs a value (see --help)" >&2; exit 1; }; sizes=$2; shift 2 ;;
    --ranks) [ $# -ge 2 ] || { echo "bench.sh: --ranks needs a value (see --help)" >&2; exit 1; }; ranks=$2; shift 2 ;;
    --methods) [ $# -ge 2 ] || { echo "bench.sh: --methods needs a value (see --help)" >&2; exit 1; }; methods=$2; shift 2 ;;
    --no-floor) floor=0; shift ;;
    --out) [ $# -ge 2 ] || { echo "bench.sh: --out needs a value (see --help)" >&2; exit 1; }; out=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    -h|--help) sed -n '2,31p' "$0"; exit 0 ;;
    *) echo "bench.sh: unknown argument $1 (see --help)" >&2; exit 1 ;;
  esac
done
make -s bin/spcontact >/dev/null || exit 1
mkdir -p "$out"
grep -v '^-contact' input/indent3d.opts > "$out/floor.opts"
cat >> "$out/floor.opts" <<'EOF'
# floor: no contact; the top face z = 0 pushed down by 0.01 (one linear solve, to -ksp_rtol)
-solver_inexact false
-bc_3_type dirichlet
-bc_3_values 2
-bc_3_components 2
-bc_3_value -0.01
-output_name floor
EOF
runs=()
run() { # run NAME NP ARGS...
  local name=$1 np=$2; shift 2
  echo "running $name: $MPIEXEC -n $np bin/spcontact $* ${extra[*]}" >&2
  $MPIEXEC -n "$np" bin/spcontact "$@" -output_dir "$out/$name" -log_view ":$out/$name.log.csv:ascii_csv" "${extra[@]}" > "$out/$name.txt" 2>&1 ||
    echo "  $name exited with $? (see $out/$name.txt)" >&2
  runs+=("$name")
}
for n in ${sizes//,/ }; do
  for np in ${ranks//,/ }; do
    [ $floor = 1 ] && run "n${n}_p${np}_floor" "$np" -options_file "$out/floor.opts" -dm_plex_box_faces "$n,$n,$n"
    for m in ${methods//,/ }; do
      run "n${n}_p${np}_$m" "$np" -options_file input/indent3d.opts -dm_plex_box_faces "$n,$n,$n" -contact_method "$m" -output_name "$m"
    done
  done
done
$PYTHON scripts/bench_table.py "$out" "${runs[@]}"
$PYTHON scripts/bench_plot.py "$out/bench.csv" "$out/bench.png"
