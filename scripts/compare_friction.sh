#!/usr/bin/env bash
# The seed's friction claim, measured: penalty friction, the shifted penalty (tangential shift) and
# the augmented Lagrangian at alpha = alpha_T = 10, 100, 1000 on a friction benchmark.
# Usage: [ALPHAS="10 100"] [METHODS="penalty shifted shifted:schur alm"] scripts/compare_friction.sh [friction_block2d|friction_patch_4_5|friction_slide2d|friction_slide3d|cattaneo2d|cattaneo3d] [NP] [PETSc options]
# Prints one table (also <outdir>/compare.csv): Newton and linear iterations, cut-backs, max stick
# creep (absolute and in element sizes h), stick-zone error in elements (cattaneo2d: half-width
# against c = 0.076113 and centre; cattaneo3d: stick radius against c from the measured F, and
# centre; by scripts/cattaneo_check.py; '-' elsewhere), tangential force error against the exact T
# (cattaneo3d: F_x/F_z against -Q/F = -0.15, the meshed top disc being a polygon), wall time;
# and a PNG of max stick creep against Newton iteration per method (alpha 100, all curves drawn).
cd "$(dirname "$0")/.." || exit 1
source scripts/env.sh
problem=${1:-friction_block2d}; np=${2:-1}; [ $# -gt 0 ] && shift; [ $# -gt 0 ] && shift
out=build/compare/$problem; mkdir -p "$out"
cm=; [ "$problem" = cattaneo2d ] && cm=cm; [ "$problem" = cattaneo3d ] && cm=cm3d # checker mode
fields=false; [ -n "$cm" ] && fields=true # the stick zone is read from _contact.csv
declare -A T=([friction_block2d]=-0.0015 [friction_patch_4_5]=-0.0015 [friction_slide2d]=-0.003 [friction_slide3d]=-0.002598076211353316 [cattaneo2d]=-0.0015 [cattaneo3d]=-0.15)
declare -A H=([friction_block2d]=0.025 [friction_patch_4_5]=0.2 [friction_slide2d]=0.025 [friction_slide3d]=0.05 [cattaneo2d]=0.005 [cattaneo3d]=0.0104)
echo "method,alpha,newton_iterations,linear_iterations,cutbacks,max_stick_creep,creep_over_h,stick_halfwidth_err_el,stick_centre_err_el,tangential_force_error,wall_time,converged" > "$out/compare.csv"
# METHODS: method names, or method:accel for a shift update rule (-contact_shift_accel accel)
for spec in ${METHODS:-penalty shifted alm}; do
  m=${spec%%:*}; accel=(); [ "$spec" != "$m" ] && accel=(-contact_shift_accel "${spec#*:}")
  for a in ${ALPHAS:-10 100 1000}; do
    name=${spec/:/-}_a$a
    $MPIEXEC -n "$np" bin/spcontact -options_file input/$problem.opts -contact_method $m "${accel[@]}" -contact_alpha $a \
      -output_dir "$out" -output_name "$name" -output_fields $fields "$@" > "$out/$name.txt" 2>&1
    v() { awk -v k="$1" '/^=== spcontact summary/{on=1} on && $1==k {print $2}' "$out/$name.txt" | tail -1; }
    key=contact_tangential_force_x; [ "$problem" = friction_patch_4_5 ] || [ -n "$cm" ] && key=contact_force_x
    t=$(v $key); [ "$problem" = cattaneo3d ] && t=$(awk -v x="$t" -v z="$(v contact_force_z)" 'BEGIN{ if (x != "" && z != "") printf "%.15g", x / z }')
    zw=-; zc=-
    if [ -n "$cm" ] && [ "$(v converged)" = yes ]; then
      $PYTHON scripts/cattaneo_check.py "$out/${name}_contact.csv" $cm > "$out/$name.check" 2>&1
      zw=$(awk '$1 == "half_width_error_elements" || $1 == "radius_error_elements" { printf "%.2f", $2 }' "$out/$name.check")
      zc=$(awk '$1 == "centre_error_elements" { printf "%.2f", $2 }' "$out/$name.check")
    fi
    terr=$(awk -v t="$t" -v r="${T[$problem]}" 'BEGIN{ if (t == "") print "-"; else printf "%.1e", (t-r)/(r<0?-r:r)}')
    creep=$(v contact_max_stick_creep)
    ch=$(awk -v c="$creep" -v h="${H[$problem]}" 'BEGIN{ if (c == "") print "-"; else printf "%.1e", c/h}')
    echo "$spec,$a,$(v newton_iterations),$(v linear_iterations),$(v cutbacks),$creep,$ch,${zw:--},${zc:--},$terr,$(v wall_time),$(v converged)" >> "$out/compare.csv"
  done
done
column -s, -t "$out/compare.csv"
$PYTHON - "$out" <<'PY'
import csv, sys, os
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
out = sys.argv[1]
fig, axs = plt.subplots(1, 3, figsize=(13, 4.2), sharey=True)
for ax, a in zip(axs, (10, 100, 1000)):
    for m, style in [("penalty", "k-"), ("shifted", "b-o"), ("shifted-schur", "g-s"), ("alm", "r--^")]:
        f = os.path.join(out, f"{m}_a{a}.csv")
        if not os.path.exists(f):
            continue
        rows = list(csv.DictReader(open(f)))
        creep = [max(float(r["max_stick_creep"]), 1e-17) for r in rows]
        ax.semilogy(range(len(creep)), creep, style, label=m, ms=3, alpha=0.85)
    ax.set_title(f"alpha = alpha_T = {a}")
    ax.set_xlabel("Newton iteration (cumulative over load steps)")
    ax.grid(True, which="both", alpha=0.3)
axs[0].set_ylabel("max stick creep (accumulated + this step)")
axs[0].legend()
fig.tight_layout()
fig.savefig(os.path.join(out, "creep.png"), dpi=110)
print("plot:", os.path.join(out, "creep.png"))
PY
