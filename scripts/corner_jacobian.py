#!/usr/bin/env python3
"""det F at the corners of every cell of every written step of an spcontact h5 output, independent
of the code: at a corner the bilinear/trilinear map's derivative is spanned by the cell's edges
from that corner, so J = det[deformed edges] / det[reference edges] (x = X + u). The edges follow
from the XDMF corner order of the cells (the one ParaView draws them with); a cell with a flat
reference corner is refused. Simplices (P1): every other vertex is an edge neighbour, J is the
cell's constant det F. Steps are numbered as the run numbered them (a restarted run's file from
its first_step). From the vertex displacements only:
exact for Q1/P1, and for Q2/P2 where u is linear (a homogeneous state).

Prints one line per written step: `step K min_corner_J J inverted_cells N`, and a last line
`all min_corner_J J inverted_cells N steps K` (N: the largest count of any step).

usage: corner_jacobian.py FILE.h5[.part]
"""
import sys

import h5py
import numpy as np


def corner_edges(n, dim):
    """Per corner of a cell with n corners in dim dimensions, the indices of its edge neighbours,
    from the XDMF corner order the h5 shares with ParaView (a quadrilateral's corners cyclic; a
    hexahedron's bottom face cyclic, then the top face above it), so a skewed cell, whose
    diagonal may be shorter than an edge, still gets its edges"""
    if n == dim + 1:  # simplex: every other vertex
        return [[j for j in range(n) if j != i] for i in range(n)]
    if dim == 2:
        return [[(i + 1) % 4, (i + 3) % 4] for i in range(4)]
    return [[4 * (i // 4) + (i + 1) % 4, 4 * (i // 4) + (i + 3) % 4, (i + 4) % 8] for i in range(8)]


def main():
    f = h5py.File(sys.argv[1], "r")
    X = f["geometry/vertices"][:]
    cells = f["viz/topology/cells"][:]
    U = f["fields/displacement"][:]
    dim = X.shape[1]
    if cells.shape[1] not in (2 ** dim, dim + 1):
        sys.exit("corner_jacobian.py: %d corners per cell in %dD: not a quad/hex or simplex mesh" % (cells.shape[1], dim))
    ref = []  # per cell: (corner, its edge neighbours, reference determinant), evaluated once
    edges = corner_edges(cells.shape[1], dim)
    first = int(np.asarray(f["/"].attrs.get("first_step", 1)).ravel()[0])  # a restarted run's file starts later
    for c in cells:
        Xc = X[c]
        corners = [(i, e, np.linalg.det((Xc[e] - Xc[i]).T)) for i, e in enumerate(edges)]
        if min(abs(d0) for _, _, d0 in corners) <= 1e-12 * np.max(np.abs(Xc - Xc.mean(axis=0))) ** dim:
            sys.exit("corner_jacobian.py: a cell with a flat corner in the reference mesh (not a valid Q1/P1 cell)")
        ref.append(corners)
    worst, most = np.inf, 0
    for k in range(U.shape[0]):
        x = X + U[k]
        jmin, bad = np.inf, 0
        for c, corners in zip(cells, ref):
            xc = x[c]
            j = min(np.linalg.det((xc[e] - xc[i]).T) / d0 for i, e, d0 in corners)
            jmin = min(jmin, j)
            bad += j <= 0.0
        print("step %d min_corner_J %.10g inverted_cells %d" % (first + k, jmin, bad))
        worst, most = min(worst, jmin), max(most, bad)
    print("all min_corner_J %.10g inverted_cells %d steps %d" % (worst, most, U.shape[0]))


if __name__ == "__main__":
    main()
