#!/usr/bin/env python3
"""Compare a spcontact contact-points CSV with the Hertz pressure profile.

2D (cylinder, line load P per unit length): b = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi b).
3D (sphere, force F):                      a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2).
p(r) = p0 sqrt(1 - r^2/c^2) inside the contact, r the distance from the axis (x in 2D).
The relative L2 error is area-weighted over the contact points:
  sqrt(sum A_i (p_i - p_H(r_i))^2 / sum A_i p_H(r_i)^2).
Defaults are benchmarks B2 (P = 0.01) and B3 (F = 0.002) with R = 1, E = 1, nu = 0.3.

--local (benchmark B4, displacement control, the load is the measured reaction): fit the computed
pressures to the Hertz shape, p^2 = p0^2 (1 - r^2/a^2), by area-weighted least squares over the
points in contact, and check the local Hertz relations on the fitted a_h and p0_h:
  p0_h against 2 E* a_h / (pi R),   P against 4 E* a_h^3 / (3 R)   (3D sphere, P = full force).
"""
import argparse
import csv
import math
import sys


def read_points(path, dim):
    with open(path) as f:
        for row in csv.DictReader(f):
            x, y = float(row["x"]), float(row["y"])
            r = abs(x) if dim == 2 else math.hypot(x, y)
            yield r, float(row["area"]), float(row["pressure"])


def local_relations(a, estar):
    """Area-weighted least-squares fit of p^2 = c0 - c1 r^2 over the points with p > 0."""
    s = [0.0] * 5  # sum w, w r2, w r4, w p2, w r2 p2
    for r, area, p in read_points(a.csv, 3):
        if p <= 0.0:
            continue
        r2, p2 = r * r, p * p
        for k, v in enumerate((1.0, r2, r2 * r2, p2, r2 * p2)):
            s[k] += area * v
    det = s[0] * s[2] - s[1] * s[1]
    if s[0] == 0.0 or det <= 0.0 or a.load is None:
        print("need --load and at least two distinct radii in contact", file=sys.stderr)
        return 1
    c0 = (s[3] * s[2] - s[1] * s[4]) / det
    c1 = -(s[0] * s[4] - s[1] * s[3]) / det
    if c0 <= 0.0 or c1 <= 0.0:
        print("pressure does not fit a Hertz profile", file=sys.stderr)
        return 1
    p0, rad = math.sqrt(c0), math.sqrt(c0 / c1)
    p0_rel = 2 * estar * rad / (math.pi * a.radius)
    load_rel = 4 * estar * rad ** 3 / (3 * a.radius)
    print(f"fit_radius {rad:.6f}\nfit_p0 {p0:.7f}")
    print(f"p0_relation_error {(p0 - p0_rel) / p0_rel:.4e}")
    print(f"load_relation_error {(a.load - load_rel) / load_rel:.4e}")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv", help="<output>_contact.csv written by spcontact")
    ap.add_argument("--dim", type=int, default=2)
    ap.add_argument("--load", type=float, help="P (2D, full cylinder) or F (3D, full sphere)")
    ap.add_argument("--radius", type=float, default=1.0)
    ap.add_argument("--E", type=float, default=1.0)
    ap.add_argument("--nu", type=float, default=0.3)
    ap.add_argument("--local", action="store_true", help="B4: check the local Hertz relations (3D)")
    a = ap.parse_args()
    estar = a.E / (1.0 - a.nu ** 2)
    if a.local:
        return local_relations(a, estar)
    if a.dim == 2:
        load = a.load if a.load else 0.01
        c = math.sqrt(4 * load * a.radius / (math.pi * estar))
        p0 = 2 * load / (math.pi * c)
    else:
        load = a.load if a.load else 0.002
        c = (3 * load * a.radius / (4 * estar)) ** (1.0 / 3.0)
        p0 = 3 * load / (2 * math.pi * c * c)
    num = den = 0.0
    pmax = 0.0
    with open(a.csv) as f:
        for row in csv.DictReader(f):
            x, y, area, p = float(row["x"]), float(row["y"]), float(row["area"]), float(row["pressure"])
            r = abs(x) if a.dim == 2 else math.hypot(x, y)
            ph = p0 * math.sqrt(max(0.0, 1.0 - (r / c) ** 2))
            num += area * (p - ph) ** 2
            den += area * ph ** 2
            pmax = max(pmax, p)
    if den == 0.0:
        print("no contact points inside the Hertz zone", file=sys.stderr)
        return 1
    print(f"hertz_width {c:.6f}\nhertz_p0 {p0:.7f}\npeak_pressure {pmax:.7f}")
    print(f"peak_relative_error {(pmax - p0) / p0:.4e}")
    print(f"l2_relative_error {math.sqrt(num / den):.4e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
