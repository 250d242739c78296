#!/usr/bin/env python3
"""Reads an interFoam Rayleigh-Taylor case written by run.sh and writes:

  PREFIX_tips.csv              t, bubble_y, spike_y at every written time (and t = 0): the highest
                               and the lowest point of the alpha.heavy = 0.5 contour, as arksph's
                               bubble_y and spike_y in timeseries.csv
  PREFIX_interface_t<T>.csv    x0, y0, x1, y1: the segments of that contour at T = 1, 3, 5, the format
                               of arksph's interface_NNNNNN.csv
  PREFIX_velocity_t5.csv       x, y, u, v at t = 5 as means over blocks of (N / 25)^2 cells, a 25 x 50
                               grid (for streamlines; written when 25 divides N)

The contour is matplotlib's, on the cell centres ((i + 1/2)/N, (j + 1/2)/N) of the N x 2N mesh, whose
cells blockMesh numbers x fastest.

usage: extract.py CASE N PREFIX
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

FRAMES = (1, 3, 5)


def read_scalars(path):
    """The internalField of an ascii volScalarField written as a nonuniform list."""
    with open(path) as f:
        text = f.read()
    body = text[text.index("internalField"):]
    if "List<scalar>" not in body[:body.index(";")]:
        raise SystemExit(f"extract.py: {path}: internalField is not a list of cell values")
    rest = body[body.index("List<scalar>") + len("List<scalar>"):].lstrip()
    count, rest = rest.split(None, 1)
    values = np.array(rest[rest.index("(") + 1:rest.index(")")].split(), dtype=float)
    if values.size != int(count):
        raise SystemExit(f"extract.py: {path}: {values.size} values, header says {count}")
    return values


def read_velocity(path, count):
    """The (u, v) of an ascii volVectorField's nonuniform internalField, shape (count, 2)."""
    with open(path) as f:
        text = f.read()
    body = text[text.index("internalField"):]
    start = body.index("(", body.index("List<vector>"))
    values = body[start + 1:].replace("(", " ").replace(")", " ").split()
    return np.array(values[:3 * count], dtype=float).reshape(count, 3)[:, :2]


def write_velocity(u, n, path):
    b = n // 25
    grid = u.reshape(50, b, 25, b, 2).mean(axis=(1, 3))  # (row block, column block, component)
    with open(path, "w") as f:
        f.write("x,y,u,v\n")
        for j in range(50):
            for i in range(25):
                f.write("%.4g,%.4g,%.6g,%.6g\n" % ((i + 0.5) / 25, (j + 0.5) / 25, grid[j, i, 0], grid[j, i, 1]))


def times(case):
    out = []
    for d in os.listdir(case):
        try:
            out.append((float(d), os.path.join(case, d)))
        except ValueError:
            pass
    return sorted(out)


def contour(alpha, n):
    """The alpha = 0.5 contour as a list of (x0, y0, x1, y1) segments."""
    x = (np.arange(n) + 0.5) / n
    y = (np.arange(2 * n) + 0.5) / n
    fig, ax = plt.subplots()
    cs = ax.contour(x, y, alpha.reshape(2 * n, n), levels=[0.5])
    segments = []
    for line in cs.allsegs[0]:
        for a, b in zip(line[:-1], line[1:]):
            segments.append((a[0], a[1], b[0], b[1]))
    plt.close(fig)
    return segments


def main():
    case, n, prefix = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    rows = []
    for t, folder in times(case):
        path = os.path.join(folder, "alpha.heavy")
        if not os.path.exists(path):
            continue
        alpha = read_scalars(path)
        if alpha.size != 2 * n * n:
            raise SystemExit(f"extract.py: {path} does not hold {2 * n * n} cell values")
        segments = contour(alpha, n)
        if abs(t - 5) < 1e-9 and n % 25 == 0 and os.path.exists(os.path.join(folder, "U")):
            write_velocity(read_velocity(os.path.join(folder, "U"), 2 * n * n), n, f"{prefix}_velocity_t5.csv")
        ys = [s[1] for s in segments] + [s[3] for s in segments]
        rows.append((t, max(ys), min(ys)))
        if any(abs(t - k) < 1e-9 for k in FRAMES):
            with open(f"{prefix}_interface_t{round(t)}.csv", "w") as f:
                f.write("x0,y0,x1,y1\n")
                for s in segments:
                    f.write("%.8g,%.8g,%.8g,%.8g\n" % s)
    with open(f"{prefix}_tips.csv", "w") as f:
        f.write("t,bubble_y,spike_y\n")
        for t, bubble, spike in rows:
            f.write(f"{t:.6g},{bubble:.8g},{spike:.8g}\n")
    last = rows[-1]
    print(f"extract.py: {len(rows)} times to t = {last[0]:g}: bubble {last[1]:.4f}, spike {last[2]:.4f}")


if __name__ == "__main__":
    main()
