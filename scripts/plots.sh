#!/usr/bin/env bash
# Every README picture by one command: bash scripts/plots.sh [OUTDIR]   (default doc/img)
#  - hertz-profiles.png: contact pressure against Hertz's profile for B2 (hertz2d), B3 (hertz3d,
#    one load step) and B6 (hertz2d_twobody, E* of two bodies), from the runs' <name>_contact.csv
#  - methods-penetration.png: max penetration against Newton iteration for every method at
#    alpha 10, 100, 1000 on B2 (the runs of scripts/compare_methods.sh, their per-iteration CSVs)
#  - b3-pressure-paraview.png: ParaView (pvbatch, default Xdmf3 reader) rendering of B3's pressure
# Runs one spcontact at a time (1 rank for B2/B6 and the methods, 2 for B3).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/env.sh
img=${1:-doc/img}; run=build/plots; mkdir -p "$img" "$run"
$MPIEXEC -n 1 bin/spcontact -options_file input/hertz2d.opts -quiet -output_dir $run -output_name b2 >$run/b2.txt
$MPIEXEC -n 2 bin/spcontact -options_file input/hertz3d.opts -load_steps 1 -quiet -output_dir $run -output_name b3 >$run/b3.txt
$MPIEXEC -n 1 bin/spcontact -options_file input/hertz2d_twobody.opts -quiet -output_dir $run -output_name b6 >$run/b6.txt
bash scripts/compare_methods.sh hertz2d 1 >$run/compare.txt
"$PYTHON" - "$run" "$img" <<'PY'
import csv, math, os, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
run, img = sys.argv[1], sys.argv[2]
estar = 1 / (1 - 0.09)
cases = [("B2: cylinder on a rigid plane", "b2", 2, 0.01, estar),
         ("B3: sphere on a rigid plane", "b3", 3, 0.002, estar),
         ("B6: cylinder on an elastic block", "b6", 2, 0.01, estar / 2)]
fig, axs = plt.subplots(1, 3, figsize=(13, 3.8))
for ax, (title, name, dim, load, es) in zip(axs, cases):
    if dim == 2:
        c = math.sqrt(4 * load / (math.pi * es)); p0 = 2 * load / (math.pi * c)
    else:
        c = (3 * load / (4 * es)) ** (1 / 3); p0 = 3 * load / (2 * math.pi * c * c)
    rows = list(csv.DictReader(open(os.path.join(run, name + "_contact.csv"))))
    r = [abs(float(w["x"])) if dim == 2 else math.hypot(float(w["x"]), float(w["y"])) for w in rows]
    p = [float(w["pressure"]) for w in rows]
    rr = [1.4 * c * k / 200 for k in range(201)]
    ax.plot(rr, [p0 * math.sqrt(max(0, 1 - (x / c) ** 2)) for x in rr], "k-", label="Hertz")
    ax.plot(r, p, "o", ms=3, mfc="none", color="tab:red", label="spcontact (contact points)")
    ax.set_xlim(0, 1.4 * c); ax.set_title(title); ax.set_xlabel("r (x in 2D)"); ax.set_ylabel("pressure")
    ax.legend(fontsize=8)
fig.tight_layout(); fig.savefig(os.path.join(img, "hertz-profiles.png"), dpi=80)
styles = {"penalty": ("k", "-", "x"), "shifted": ("tab:blue", "-", "o"),
          "shifted_regression": ("tab:green", "--", "s"), "alm": ("tab:red", ":", "^")}
fig, axs = plt.subplots(1, 3, figsize=(13, 3.8), sharey=True)
cmp = "build/compare/hertz2d"
for ax, a in zip(axs, (10, 100, 1000)):
    for m, (col, ls, mk) in styles.items():
        f = os.path.join(cmp, "%s_a%d.csv" % (m, a))
        if not os.path.exists(f):
            continue
        pen = [max(float(w["max_penetration"]), 1e-17) for w in csv.DictReader(open(f))]
        wide = m == "penalty"  # drawn first, wide and with large markers: the others run over it
        ax.semilogy(range(1, len(pen) + 1), pen, color=col, ls=ls, marker=mk, ms=10 if wide else 5,
                    lw=5 if wide else 1.5, alpha=0.35 if wide else 1, mfc="none", label=m)
    ax.xaxis.get_major_locator().set_params(integer=True)
    ax.set_title("B2, alpha = %d (penetration 1e-17 = none)" % a); ax.set_xlabel("Newton iteration (all solves of the run)")
    ax.grid(True, which="major", alpha=0.3)
axs[0].set_ylabel("max penetration"); axs[0].legend(fontsize=8)
fig.tight_layout(); fig.savefig(os.path.join(img, "methods-penetration.png"), dpi=80)
print("wrote %s/hertz-profiles.png, %s/methods-penetration.png" % (img, img))
PY
pmax=$(awk '/^=== spcontact summary/{on=1} on && $1=="contact_peak_pressure" {print $2}' $run/b3.txt)
xvfb-run -a -s "-screen 0 1024x768x24" pvbatch scripts/pv_check.py "$PWD/$run/b3.xmf" 1 "$pmax" "$PWD/$img/b3-pressure-paraview.png" \
  displacement:3 contact_pressure:1 >$run/pv.txt 2>&1 || { grep -E '^(ok|FAIL)' $run/pv.txt; exit 1; }
echo "wrote $img/b3-pressure-paraview.png"
