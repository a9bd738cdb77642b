"""Log-log plot of total wall time against dofs per method and rank count from scripts/bench.sh's
bench.csv, and the fitted exponent (least squares on log t = a + b log n) of each curve.
Usage: bench_plot.py bench.csv out.png"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def fit(points):
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else float("nan")


def main():
    src, png = sys.argv[1], sys.argv[2]
    curves = {}
    for r in csv.DictReader(open(src)):
        curves.setdefault((r["method"], r["ranks"]), []).append((int(r["dofs"]), float(r["total"])))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    plotted = 0
    for (method, ranks), pts in sorted(curves.items()):
        pts.sort()
        if len(pts) < 2:
            continue
        b = fit(pts)
        print(f"exponent {method:8s} ranks {ranks}: {b:.3f} over {pts[0][0]}..{pts[-1][0]} dofs")
        ax.loglog([n for n, _ in pts], [t for _, t in pts], "o-", label=f"{method}, {ranks} rank(s): t ~ n^{b:.2f}")
        plotted += 1
    if not plotted:
        print("bench_plot: fewer than two sizes per curve, no plot")
        return
    ax.set_xlabel("dofs")
    ax.set_ylabel("total wall time [s]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print("plot:", png)


main()
