#!/usr/bin/env python3
"""Closed-form homogeneous uniaxial loading of the compressible Neo-Hookean law of spcontact
(kernels/neohookean.h: P = mu (F - F^-T) + lambda ln J F^-T), independent of the code.

A unit block (square in plane strain, or cube) with a dead nominal stress -q on its top (axis dim)
and free lateral faces: F = diag(l1, .., l1, l2) (2D: F_33 = 1), P_lateral = 0, P_axial = -q.
Prints l1, l2 and the largest displacement component of a block of side L placed with one corner
fixed laterally (spcontact's summary key displacement_max, the infinity norm): L max(|l1-1|, |l2-1|).

With `follower`, the pressure q acts on the deformed top face (a follower load): the axial
Cauchy stress is -q, i.e. the nominal stress is -q l1^(dim-1) (the top face's area ratio).

usage: neohookean_uniaxial.py DIM E NU Q [L] [follower]
"""
import math
import sys


def residual(dim, lam, mu, q, l1, l2, follower=False):
    J = l1 ** (dim - 1) * l2
    lnJ = math.log(J)
    area = l1 ** (dim - 1) if follower else 1.0
    r1 = mu * (l1 - 1.0 / l1) + lam * lnJ / l1             # lateral nominal stress = 0
    r2 = mu * (l2 - 1.0 / l2) + lam * lnJ / l2 + q * area  # axial nominal stress = -q (x area ratio)
    return r1, r2


def solve(dim, E, nu, q, follower=False):
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    l1, l2 = 1.0, 1.0
    for it in range(100):
        r1, r2 = residual(dim, lam, mu, q, l1, l2, follower)
        if abs(r1) + abs(r2) < 1e-15 * (lam + mu):
            break
        h = 1e-7
        a11 = (residual(dim, lam, mu, q, l1 + h, l2, follower)[0] - residual(dim, lam, mu, q, l1 - h, l2, follower)[0]) / (2 * h)
        a12 = (residual(dim, lam, mu, q, l1, l2 + h, follower)[0] - residual(dim, lam, mu, q, l1, l2 - h, follower)[0]) / (2 * h)
        a21 = (residual(dim, lam, mu, q, l1 + h, l2, follower)[1] - residual(dim, lam, mu, q, l1 - h, l2, follower)[1]) / (2 * h)
        a22 = (residual(dim, lam, mu, q, l1, l2 + h, follower)[1] - residual(dim, lam, mu, q, l1, l2 - h, follower)[1]) / (2 * h)
        det = a11 * a22 - a12 * a21
        d1, d2 = (a22 * r1 - a12 * r2) / det, (-a21 * r1 + a11 * r2) / det
        t = 1.0
        while min(l1 - t * d1, l2 - t * d2) <= 0.0:  # keep the stretches positive (J > 0)
            t *= 0.5
        l1, l2 = l1 - t * d1, l2 - t * d2
    else:
        sys.exit("neohookean_uniaxial.py: Newton did not converge in 100 iterations")
    return l1, l2


if __name__ == "__main__":
    dim, E, nu, q = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
    L = float(sys.argv[5]) if len(sys.argv) > 5 else 1.0
    l1, l2 = solve(dim, E, nu, q, len(sys.argv) > 6 and sys.argv[6] == "follower")
    print("l1 %.15e l2 %.15e displacement_max %.15e" % (l1, l2, L * max(abs(l1 - 1), abs(l2 - 1))))
