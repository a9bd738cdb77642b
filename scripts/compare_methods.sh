#!/usr/bin/env bash
# The seed's claim, measured: every contact method at alpha = 10, 100, 1000 on one benchmark.
# Usage: scripts/compare_methods.sh [hertz2d|block2d|block3d|hertz3d|indent3d] [NP] [PETSc options]
# indent3d (B4) has no a-priori peak pressure: its reference is Hertz's p0 for the computed force,
# p0 = (6 P E*^2 / (pi^3 R^2))^(1/3) with P = 4 |F_z| (quarter model), E* = 1/(1 - 0.3^2), R = 1.
# Prints one table (also <outdir>/compare.csv) and a PNG of max penetration vs Newton iteration.
# The linear solver is a direct Cholesky for the small cases, so Newton counts measure the contact
# algorithm, not the preconditioner (add PETSc options after NP to change that).
cd "$(dirname "$0")/.." || exit 1
source scripts/env.sh
# The peak-pressure error is against the shipped input's load: options after NP that change the
# load or the geometry leave that column meaningless ("-" where no reference exists).
problem=${1:-hertz2d}; np=${2:-1}; shift 2 2>/dev/null
[ -f "input/$problem.opts" ] || { echo "compare_methods.sh: no input/$problem.opts (give one of the names of input/*.opts, e.g. hertz2d, block2d, block3d, hertz3d, indent3d)" >&2; exit 1; }
[[ $np =~ ^[1-9][0-9]*$ ]] || { echo "compare_methods.sh: NP '$np' is not a rank count (usage: scripts/compare_methods.sh PROBLEM NP [options])" >&2; exit 1; }
out=build/compare/$problem; mkdir -p "$out"
# direct Cholesky for the small 2D/3D cases; B4 is too large for it: GAMG (the default)
solver="-pc_type cholesky"; [ "$problem" = indent3d ] && solver=""
declare -A p0=([hertz2d]=0.0591431 [hertz3d]=0.0776038 [block2d]=0.01 [block3d]=0.01)
echo "method,alpha,newton_iterations,linear_iterations,cutbacks,max_penetration,peak_pressure_error,wall_time,converged" > "$out/compare.csv"
for m in penalty shifted shifted_regression alm; do
  for a in 10 100 1000; do
    name=${m}_a$a
    $MPIEXEC -n "$np" bin/spcontact -options_file input/$problem.opts -contact_method $m -contact_alpha $a \
      -output_dir "$out" -output_name "$name" -output_fields false $solver "$@" > "$out/$name.txt" 2>&1; code=$?
    if [ $code -ne 0 ] && [ $code -ne 2 ]; then # 2: not converged (a row); anything else: no run at all
      echo "compare_methods.sh: $name failed (exit $code): $(grep -m1 'error' "$out/$name.txt")" >&2; exit 1
    fi
    v() { awk -v k="$1" '/^=== spcontact summary/{on=1} on && $1==k {print $2}' "$out/$name.txt" | tail -1; }
    ref=${p0[$problem]:-}
    [ -z "$ref" ] && [ "$problem" = indent3d ] && ref=$(awk -v f="$(v contact_force_z)" 'BEGIN{e=1/(1-0.09); pi=atan2(0,-1); P=4*(f<0?-f:f); print (6*P*e*e/(pi*pi*pi))^(1/3)}')
    err=-; [ -n "$ref" ] && err=$(awk -v p="$(v contact_peak_pressure)" -v r="$ref" 'BEGIN{printf "%.2e", (p-r)/r}')
    echo "$m,$a,$(v newton_iterations),$(v linear_iterations),$(v cutbacks),$(v contact_max_penetration),$err,$(v wall_time),$(v converged)" >> "$out/compare.csv"
  done
done
column -s, -t "$out/compare.csv"
$PYTHON - "$out" <<'PY'
import csv, sys, os
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
out = sys.argv[1]
fig, ax = plt.subplots(figsize=(7, 4.5))
for m, style in [("penalty", "k-"), ("shifted", "b-o"), ("shifted_regression", "g-s"), ("alm", "r-^")]:
    f = os.path.join(out, f"{m}_a100.csv")
    if not os.path.exists(f):
        continue
    pen = [max(float(r["max_penetration"]), 1e-17) for r in csv.DictReader(open(f))]
    ax.semilogy(range(len(pen)), pen, style, label=f"{m} (alpha 100)", ms=4)
ax.set_xlabel("Newton iteration (cumulative, including the initial state of each solve)")
ax.set_ylabel("max penetration")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(os.path.join(out, "penetration.png"), dpi=120)
print("plot:", os.path.join(out, "penetration.png"))
PY
