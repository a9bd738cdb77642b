#!/usr/bin/env python3
"""F2/F3/F5 checker (friction.md): stick zone and shear traction of a Cattaneo-Mindlin run.

Usage: cattaneo_check.py CONTACT_CSV MODE [Q_ratio [P]]   (P: the normal force, default 0.01;
       give the measured P and Q/(mu P) for a displacement-controlled run)
  MODE cm3d: F3, the 3D half model y >= 0 (input/cattaneo3d.opts): the normal force F is measured
             (twice the sum of pressure x area), a = (3 F R*/(4 E*))^(1/3), c = a (1 - Q/(mu F))^(1/3),
             q(r) = mu p0 sqrt(1-r^2/a^2) - mu p0 (c/a) sqrt(1-r^2/c^2) [r < c]. The stick radius
             from the stick area (half disc: c = sqrt(2 A_stick/pi)), its centre from the stick points'
             area-weighted mean x against the contact centre (mid x of the points with pressure);
             h = sqrt(mean nodal area / 0.866) (equilateral triangles). Also printed: the smallest
             slip radius and the largest stick radius (the ring where the two mix).
  MODE cm:   loading to Q = Q_ratio mu P (default 0.5): c = b sqrt(1 - Q/(mu P)),
             q(x) = mu p0 sqrt(1-x^2/b^2) - mu p0 (c/b) sqrt(1-x^2/c^2) [|x| < c]
  MODE unload: Q* = Q_ratio mu P, then back to Q = 0: d = b sqrt(1 - Q*/(2 mu P)),
             q(x) = -mu p0 sqrt(1-x^2/b^2) + 2 mu p0 (d/b) sqrt(1-x^2/d^2) - mu p0 (c/b) sqrt(1-x^2/c^2)
The stick zone: the contiguous run of stick points (status 1) around the centre of the contact
(the midpoint of the points carrying pressure), from the slave points (reference x; y < 0.05).
Prints: key value lines (stick_left, stick_right, stick_half_width, stick_centre, c_exact,
half_width_error, half_width_error_elements, centre_error_elements, traction_l2_error, h). 2D also:
traction_l2_stick_part and traction_l2_slip_part (the error of the stick and of the slip points, so
that their squares add up to the whole), traction_l2_of_pressure_error (mu (p - p_Hertz) in the same
norm: what the normal pressure's error alone brings into t = mu p) and pressure_l2_error (against
Hertz, relative to it).
The traction is the recovered tangential traction tx on the slave (opposite to the load on the
upper body, so the sign is flipped), compared on the points with pressure, L2 relative to the
exact profile (trapezoid rule over the slave points)."""
import csv, math, sys

E, nu, mu, R = 1.0, 0.3, 0.3, 1.0
Es = E / (2 * (1 - nu * nu))          # two identical bodies
Rs = R / 2

def main3d(path, ratio):
    rows = [r for r in csv.DictReader(open(path)) if float(r["z"]) < 0.05]
    loaded = [r for r in rows if float(r["pressure"]) > 0.0]
    F = 2 * sum(float(r["pressure"]) * float(r["area"]) for r in loaded)
    a = (3 * F * Rs / (4 * Es)) ** (1.0 / 3.0)
    p0 = 3 * F / (2 * math.pi * a * a)
    c = a * (1 - ratio) ** (1.0 / 3.0)
    xs = [float(r["x"]) for r in loaded]
    xc = 0.5 * (min(xs) + max(xs))
    h = math.sqrt(sum(float(r["area"]) for r in loaded) / len(loaded) / 0.866)
    def rad(r): return math.hypot(float(r["x"]) - xc, float(r["y"]))
    def q(s):
        v = mu * p0 * math.sqrt(max(0.0, 1 - s * s / (a * a)))
        if s < c: v -= mu * p0 * (c / a) * math.sqrt(1 - s * s / (c * c))
        return v
    stick = [r for r in loaded if int(round(float(r["status"]))) == 1]
    slip = [r for r in loaded if int(round(float(r["status"]))) == 2]
    if not stick:
        print("no stick point"); sys.exit(1)
    A = sum(float(r["area"]) for r in stick)
    cs = math.sqrt(2 * A / math.pi)
    xcs = sum(float(r["x"]) * float(r["area"]) for r in stick) / A
    rmin = min((rad(r) for r in slip), default=float("nan"))
    rmax = max(rad(r) for r in stick)
    num = den = 0.0
    for r in rows:
        s = rad(r)
        if s > 1.2 * a: continue
        w = float(r["area"])
        num += w * (-float(r["tx"]) - q(s)) ** 2
        den += w * q(s) ** 2
    out = dict(F=F, a=a, p0=p0, c_exact=c, h=h, stick_radius=cs, radius_error=cs - c,
               radius_error_elements=(cs - c) / h, stick_centre_x=xcs - xc,
               centre_error_elements=(xcs - xc) / h,
               min_slip_radius=rmin, max_stick_radius=rmax, min_slip_error_elements=(rmin - c) / h,
               max_stick_error_elements=(rmax - c) / h, traction_l2_error=math.sqrt(num / den),
               stick_points=len(stick), slip_points=len(slip))
    for k, v in out.items():
        print(k, "%.10g" % v if isinstance(v, float) else v)

def main():
    path, mode = sys.argv[1], sys.argv[2]
    if mode == "cm3d":
        main3d(path, float(sys.argv[3]) if len(sys.argv) > 3 else 0.5)
        return
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
    part = dict(stick=0.0, slip=0.0, pressure=0.0)  # squared parts of num; pressure: mu (p - p_Hertz)
    pnum = pden = 0.0
    for i in range(len(x) - 1):
        w = x[i + 1] - x[i]
        for j in (i, i + 1):
            if abs(x[j]) > 1.2 * b: continue
            e2 = 0.5 * w * (tx[j] - q(x[j])) ** 2
            ph = p0 * math.sqrt(max(0.0, 1 - x[j] * x[j] / (b * b)))
            num += e2
            den += 0.5 * w * q(x[j]) ** 2
            if st[j] == 1: part["stick"] += e2
            if st[j] == 2: part["slip"] += e2
            part["pressure"] += 0.5 * w * (mu * (pr[j] - ph)) ** 2
            pnum += 0.5 * w * (pr[j] - ph) ** 2
            pden += 0.5 * w * ph * ph
    out = dict(b=b, p0=p0, stick_left=left, stick_right=right, stick_half_width=half,
               stick_centre=0.5 * (left + right), ref_half_width=ref_half, h=h,
               half_width_error=half - ref_half, half_width_error_elements=(half - ref_half) / h,
               centre_error_elements=0.5 * (left + right) / h, traction_l2_error=math.sqrt(num / den),
               traction_l2_stick_part=math.sqrt(part["stick"] / den),
               traction_l2_slip_part=math.sqrt(part["slip"] / den),
               traction_l2_of_pressure_error=math.sqrt(part["pressure"] / den),
               pressure_l2_error=math.sqrt(pnum / pden), stick_points=hi - lo + 1)
    for k, v in out.items():
        print(k, "%.10g" % v if isinstance(v, float) else v)

main()
