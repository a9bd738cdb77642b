#!/usr/bin/env python3
"""det F at the corners of every cell of every written step of an spcontact h5 output, independent
of the code: at a corner the bilinear/trilinear map's derivative is spanned by the cell's edges
from that corner, so J = det[deformed edges] / det[reference edges] (x = X + u). The edges are
found from the reference geometry (a Q1 corner's dim nearest vertices of its cell), not from a
vertex ordering; a Q1 cell where they are not unique is refused. Simplices (P1): every other
vertex is an edge neighbour, J is the cell's constant det F. From the vertex displacements only:
exact for Q1/P1, and for Q2/P2 where u is linear (a homogeneous state).

Prints one line per written step: `step K min_corner_J J inverted_cells N`, and a last line
`all min_corner_J J inverted_cells N steps K` (N: the largest count of any step).

usage: corner_jacobian.py FILE.h5[.part]
"""
import sys

import h5py
import numpy as np


def corner_edges(X):
    """Per corner of a cell (X: corners x dim), the indices of its edge neighbours"""
    n, dim = X.shape
    if n == dim + 1:  # simplex
        return [[j for j in range(n) if j != i] for i in range(n)]
    edges = []
    for i in range(n):
        d = np.linalg.norm(X - X[i], axis=1)
        order = np.argsort(d)[1:]  # order[0..] excludes the corner itself (distance 0)
        if d[order[dim - 1]] > (1 - 1e-8) * d[order[dim]]:
            sys.exit("corner_jacobian.py: a cell's edges are not the nearest vertices (not a box-like Q1 cell)")
        edges.append(order[:dim])
    return edges


def main():
    f = h5py.File(sys.argv[1], "r")
    X = f["geometry/vertices"][:]
    cells = f["viz/topology/cells"][:]
    U = f["fields/displacement"][:]
    dim = X.shape[1]
    if cells.shape[1] not in (2 ** dim, dim + 1):
        sys.exit("corner_jacobian.py: %d corners per cell in %dD: not a quad/hex or simplex mesh" % (cells.shape[1], dim))
    ref = []  # per cell: (corner, its edge neighbours, reference determinant), evaluated once
    for c in cells:
        Xc = X[c]
        ref.append([(i, e, np.linalg.det((Xc[e] - Xc[i]).T)) for i, e in enumerate(corner_edges(Xc))])
    worst, most = np.inf, 0
    for k in range(U.shape[0]):
        x = X + U[k]
        jmin, bad = np.inf, 0
        for c, corners in zip(cells, ref):
            xc = x[c]
            j = min(np.linalg.det((xc[e] - xc[i]).T) / d0 for i, e, d0 in corners)
            jmin = min(jmin, j)
            bad += j <= 0.0
        print("step %d min_corner_J %.10g inverted_cells %d" % (k + 1, jmin, bad))
        worst, most = min(worst, jmin), max(most, bad)
    print("all min_corner_J %.10g inverted_cells %d steps %d" % (worst, most, U.shape[0]))


if __name__ == "__main__":
    main()
