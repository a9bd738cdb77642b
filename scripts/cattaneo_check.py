#!/usr/bin/env python3
"""F2/F5 checker (friction.md): stick zone and shear traction of a 2D Cattaneo-Mindlin run.

Usage: cattaneo_check.py CONTACT_CSV MODE [Q_ratio [P]]   (P: the normal force, default 0.01;
       give the measured P and Q/(mu P) for a displacement-controlled run)
  MODE cm:   loading to Q = Q_ratio mu P (default 0.5): c = b sqrt(1 - Q/(mu P)),
             q(x) = mu p0 sqrt(1-x^2/b^2) - mu p0 (c/b) sqrt(1-x^2/c^2) [|x| < c]
  MODE unload: Q* = Q_ratio mu P, then back to Q = 0: d = b sqrt(1 - Q*/(2 mu P)),
             q(x) = -mu p0 sqrt(1-x^2/b^2) + 2 mu p0 (d/b) sqrt(1-x^2/d^2) - mu p0 (c/b) sqrt(1-x^2/c^2)
The stick zone: the contiguous run of stick points (status 1) around the centre of the contact
(the midpoint of the points carrying pressure), from the slave points (reference x; y < 0.05).
Prints: key value lines (stick_left, stick_right, stick_half_width, stick_centre, c_exact,
half_width_error, half_width_error_elements, centre_error_elements, traction_l2_error, h).
The traction is the recovered tangential traction tx on the slave (opposite to the load on the
upper body, so the sign is flipped), compared on the points with pressure, L2 relative to the
exact profile (trapezoid rule over the slave points)."""
import csv, math, sys

E, nu, mu, R = 1.0, 0.3, 0.3, 1.0
Es = E / (2 * (1 - nu * nu))          # two identical bodies
Rs = R / 2

def main():
    path, mode = sys.argv[1], sys.argv[2]
    ratio = float(sys.argv[3]) if len(sys.argv) > 3 else 0.5
    P = float(sys.argv[4]) if len(sys.argv) > 4 else 0.01
    b = math.sqrt(4 * P * Rs / (math.pi * Es))
    p0 = 2 * P / (math.pi * b)
    rows = [r for r in csv.DictReader(open(path)) if float(r["y"]) < 0.05 and float(r["y"]) >= -1e-12]
    rows.sort(key=lambda r: float(r["x"]))
    x = [float(r["x"]) for r in rows]
    st = [int(round(float(r["status"]))) for r in rows]
    pr = [float(r["pressure"]) for r in rows]
    tx = [-float(r["tx"]) for r in rows]
    loaded = [i for i in range(len(x)) if pr[i] > 0.0]
    centre = 0.5 * (x[loaded[0]] + x[loaded[-1]])
    i0 = min(range(len(x)), key=lambda i: abs(x[i] - centre))
    if st[i0] != 1:
        print("no stick point at the centre"); sys.exit(1)
    lo = hi = i0
    while lo > 0 and st[lo - 1] == 1: lo -= 1
    while hi < len(x) - 1 and st[hi + 1] == 1: hi += 1
    # the stick zone edge: halfway between the last stick point and the first slip point
    left = 0.5 * (x[lo] + x[lo - 1]) if lo > 0 else x[lo]
    right = 0.5 * (x[hi] + x[hi + 1]) if hi < len(x) - 1 else x[hi]
    h = sum(x[i + 1] - x[i] for i in range(lo, hi)) / max(1, hi - lo)
    c = b * math.sqrt(1 - ratio)
    if mode == "cm":
        ref_half = c
        def q(s):
            v = mu * p0 * math.sqrt(max(0.0, 1 - s * s / (b * b)))
            if abs(s) < c: v -= mu * p0 * (c / b) * math.sqrt(1 - s * s / (c * c))
            return v
    else:
        d = b * math.sqrt(1 - ratio / 2)
        ref_half = d
        def q(s):
            v = -mu * p0 * math.sqrt(max(0.0, 1 - s * s / (b * b)))
            if abs(s) < d: v += 2 * mu * p0 * (d / b) * math.sqrt(1 - s * s / (d * d))
            if abs(s) < c: v -= mu * p0 * (c / b) * math.sqrt(1 - s * s / (c * c))
            return v
    half = 0.5 * (right - left)
    num = den = 0.0
    for i in range(len(x) - 1):
        w = x[i + 1] - x[i]
        for j in (i, i + 1):
            if abs(x[j]) > 1.2 * b: continue
            num += 0.5 * w * (tx[j] - q(x[j])) ** 2
            den += 0.5 * w * q(x[j]) ** 2
    out = dict(b=b, p0=p0, stick_left=left, stick_right=right, stick_half_width=half,
               stick_centre=0.5 * (left + right), ref_half_width=ref_half, h=h,
               half_width_error=half - ref_half, half_width_error_elements=(half - ref_half) / h,
               centre_error_elements=0.5 * (left + right) / h, traction_l2_error=math.sqrt(num / den),
               stick_points=hi - lo + 1)
    for k, v in out.items():
        print(k, "%.10g" % v if isinstance(v, float) else v)

main()
