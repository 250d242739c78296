#!/usr/bin/env python3
"""The initial field and the extraction of run.sh's spin-down case (icoFoam, N x N cells, one block,
cells numbered x fastest, centres at ((i + 1/2) / N, (j + 1/2) / N)).

usage: extract.py initial N                      the internalField of U at t = 0 (rigid rotation)
       extract.py history CASE N HISTORY_CSV T8_CSV
HISTORY_CSV: t, the largest cell speed, kinetic energy 1/2 sum |U|^2 / N^2 (density 1, the mass of
arksph's kinetic_energy), at every time folder. T8_CSV: x, y, u, v at t = 8 as means over blocks of
(N / 50)^2 cells, when 50 divides N.
"""
import csv
import os
import sys

import numpy as np


def centres(n):
    c = (np.arange(n) + 0.5) / n
    x, y = np.meshgrid(c, c)  # row j, column i: x fastest when raveled
    return x.ravel(), y.ravel()


def read_vectors(path, count):
    """The internalField of an ascii volVectorField written by OpenFOAM, shape (count, 3)."""
    text = open(path).read()
    body = text[text.index("internalField"):]
    if "nonuniform" not in body.split("\n", 1)[0]:
        raise SystemExit(f"extract.py: {path}: expected a nonuniform internalField")
    start = body.index("(", body.index("List<vector>"))
    values = body[start + 1:].replace("(", " ").replace(")", " ").split()
    return np.array(values[:3 * count], dtype=float).reshape(count, 3)


def initial(n):
    x, y = centres(n)
    print("internalField nonuniform List<vector> %d\n(" % (n * n))
    print("\n".join("(%.12g %.12g 0)" % (0.25 * (b - 0.5), 0.25 * (0.5 - a)) for a, b in zip(x, y)))
    print(");")


def history(case, n, history_csv, t8_csv):
    times = sorted((float(d), d) for d in os.listdir(case) if d.replace(".", "", 1).isdigit() and float(d) > 0)
    x, y = centres(n)
    u0 = np.stack([0.25 * (y - 0.5), 0.25 * (0.5 - x)], axis=1)
    rows = [(0.0, float(np.linalg.norm(u0, axis=1).max()), 0.5 * float((u0 ** 2).sum()) / n ** 2)]
    at8 = None
    for t, d in times:
        u = read_vectors(os.path.join(case, d, "U"), n * n)[:, :2]
        rows.append((t, float(np.linalg.norm(u, axis=1).max()), 0.5 * float((u ** 2).sum()) / n ** 2))
        if abs(t - 8.0) < 1e-9:
            at8 = u
    with open(history_csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["t", "max_speed", "kinetic_energy"])
        for t, s, k in rows:
            w.writerow([f"{t:g}", f"{s:.8g}", f"{k:.8g}"])
    print(f"extract.py: {history_csv}: max speed {rows[-1][1]:.6g}, kinetic energy {rows[-1][2]:.6g} at t = {rows[-1][0]:g}")
    if at8 is None or n % 50:
        return
    b = n // 50
    grid = at8.reshape(50, b, 50, b, 2).mean(axis=(1, 3))  # (row block, column block, component)
    c = (np.arange(50) + 0.5) / 50
    with open(t8_csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["x", "y", "u", "v"])
        for j in range(50):
            for i in range(50):
                w.writerow([f"{c[i]:.4g}", f"{c[j]:.4g}", f"{grid[j, i, 0]:.6g}", f"{grid[j, i, 1]:.6g}"])


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "initial":
        initial(int(sys.argv[2]))
    elif len(sys.argv) >= 6 and sys.argv[1] == "history":
        history(sys.argv[2], int(sys.argv[3]), sys.argv[4], sys.argv[5])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
