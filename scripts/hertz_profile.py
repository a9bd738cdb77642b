#!/usr/bin/env python3
"""Compare a spcontact contact-points CSV with the Hertz pressure profile.

2D (cylinder, line load P per unit length): b = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi b).
3D (sphere, force F):                      a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2).
p(r) = p0 sqrt(1 - r^2/c^2) inside the contact, r the distance from the axis (x in 2D).
The relative L2 error is area-weighted over the contact points:
  sqrt(sum A_i (p_i - p_H(r_i))^2 / sum A_i p_H(r_i)^2).
Defaults are benchmarks B2 (P = 0.01) and B3 (F = 0.002) with R = 1, E = 1, nu = 0.3.
"""
import argparse
import csv
import math
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv", help="<output>_contact.csv written by spcontact")
    ap.add_argument("--dim", type=int, default=2)
    ap.add_argument("--load", type=float, help="P (2D, full cylinder) or F (3D, full sphere)")
    ap.add_argument("--radius", type=float, default=1.0)
    ap.add_argument("--E", type=float, default=1.0)
    ap.add_argument("--nu", type=float, default=0.3)
    a = ap.parse_args()
    estar = a.E / (1.0 - a.nu ** 2)
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
