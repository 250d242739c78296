#!/usr/bin/env python3
"""The initial volume fraction of the heavy fluid for run.sh, as the internalField of alpha.heavy.

The heavy fluid fills y > f(x) = 1 - 0.15 sin(2 pi x) (the scene's [[phase]] region). In the cell
[x0, x1] x [y0, y1] its area is the integral over x of clip(y1 - max(y0, f(x)), 0, y1 - y0), taken
by the midpoint rule on 64 sub-columns (f is smooth; the clip's kinks make the rule second order,
an error below 1e-4 of a cell's area). Cells are in blockMesh's order for one block: x fastest.

usage: initial_alpha.py N        (N x 2N cells on the box 1 x 2)
"""
import sys

import numpy as np


def heavy_fraction(n):
    nx, ny = n, 2 * n
    dx, dy = 1.0 / nx, 2.0 / ny
    sub = 64
    # Sub-column midpoints of every cell column: shape (nx, sub).
    xs = (np.arange(nx)[:, None] + (np.arange(sub)[None, :] + 0.5) / sub) * dx
    f = 1.0 - 0.15 * np.sin(2.0 * np.pi * xs)
    y0 = np.arange(ny)[:, None, None] * dy          # (ny, 1, 1)
    y1 = y0 + dy
    filled = np.clip(y1 - np.maximum(y0, f[None, :, :]), 0.0, dy)  # (ny, nx, sub)
    return filled.mean(axis=2) / dy                  # (ny, nx): row j, column i


def main():
    n = int(sys.argv[1])
    alpha = heavy_fraction(n).ravel()  # row-major: x fastest, as blockMesh numbers the cells
    print("internalField nonuniform List<scalar> %d\n(" % alpha.size)
    print("\n".join("%.10g" % a for a in alpha))
    print(");")


if __name__ == "__main__":
    main()
