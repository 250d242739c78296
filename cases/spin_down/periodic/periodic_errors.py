#!/usr/bin/python3
"""Doubly periodic spin-down variant: velocity errors against the exact Taylor-Green solution.

usage: periodic_errors.py BATCH_DIR [--label NAME] [--times 1 2 3 4 5] [--U 0.125] [--nu 0.0023809523809523]

BATCH_DIR is the output of `arksph batch` over lattices (coarse to fine) of scene.toml. For every run
and output time t, e_a = |u_a - u_exact(x_a, t)| with
    u = U sin(2 pi x) cos(2 pi y) e^(-8 pi^2 nu t),  v = -U cos(2 pi x) sin(2 pi y) e^(-8 pi^2 nu t),
L1 = mean e_a, L2 = sqrt(mean e_a^2); rates Q = log(E_i / E_{i+1}) / log(dx_i / dx_{i+1}) between
consecutive lattices. A † marks a time at which a run's maximum speed has grown since the previous
output (the exact flow only decays: the run has gone unstable). Writes BATCH_DIR/periodic.md and
periodic.csv. Needs numpy and VTK's Python module (python3-vtk9).
"""
import argparse
import csv
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "convergence"))
from convergence import read_frame, spacing_and_h  # noqa: E402


def exact(x, t, U, nu):
    d = math.exp(-8 * math.pi ** 2 * nu * t)
    sx, cx = np.sin(2 * np.pi * x[:, 0]), np.cos(2 * np.pi * x[:, 0])
    sy, cy = np.sin(2 * np.pi * x[:, 1]), np.cos(2 * np.pi * x[:, 1])
    return np.stack([U * sx * cy * d, -U * cx * sy * d], axis=1)


def grown(run_dir, t):
    """True when the run's max speed at t exceeds that of the previous output (timeseries.csv)."""
    rows = list(csv.DictReader(open(os.path.join(run_dir, "timeseries.csv"))))
    for prev, cur in zip(rows, rows[1:]):
        if abs(float(cur["t"]) - t) < 1e-9:
            return float(cur["max_speed"]) > float(prev["max_speed"])
    return False


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("batch_dir")
    ap.add_argument("--label", default="")
    ap.add_argument("--times", type=float, nargs="+", default=[1, 2, 3, 4, 5])
    ap.add_argument("--U", type=float, default=0.125)
    ap.add_argument("--nu", type=float, default=1 / 420)
    a = ap.parse_args()
    runs = []
    for row in csv.DictReader(open(os.path.join(a.batch_dir, "batch.csv"))):
        d = os.path.join(a.batch_dir, row["run"])
        dx, h = spacing_and_h(d)
        runs.append((dx, h, d))
    runs.sort(reverse=True)
    n = [round(1 / r[0]) for r in runs]
    head = "| t | " + " | ".join("L1 %d² | L2 %d²" % (k, k) for k in n) + " | " + " | ".join(
        "Q L1 %d²–%d² | Q L2" % (n[i], n[i + 1]) for i in range(len(n) - 1)) + " |"
    md = ["### %s" % (a.label or a.batch_dir), "",
          "Lattices %s; h = %s. L1 / L2 of |u − u_exact| (×10⁻³) and rates Q; — where a run did not reach t, "
          "† where a run's maximum speed grew (unstable)." % (", ".join("%d²" % k for k in n),
                                                            ", ".join("%.4g" % r[1] for r in runs)), "",
          head, "|" + "---|" * (1 + 2 * len(n) + 2 * (len(n) - 1))]
    out = open(os.path.join(a.batch_dir, "periodic.csv"), "w")
    out.write("t,lattice,L1,L2,unstable\n")
    for t in a.times:
        errs = []
        for dx, h, d in runs:
            f = read_frame(d, t)
            if f is None:
                errs.append(None)
                continue
            x, u, _ = f
            e = np.linalg.norm(u - exact(x, t, a.U, a.nu), axis=1)
            errs.append((e.mean(), math.sqrt((e ** 2).mean()), grown(d, t)))
            out.write("%g,%d,%.6e,%.6e,%d\n" % (t, round(1 / dx), errs[-1][0], errs[-1][1], errs[-1][2]))
        if all(e is None for e in errs):
            continue
        cells = []
        for e in errs:
            cells += ["—", "—"] if e is None else ["%.3f%s" % (e[0] * 1e3, "†" if e[2] else ""), "%.3f" % (e[1] * 1e3)]
        for i in range(len(runs) - 1):
            if errs[i] is None or errs[i + 1] is None:
                cells += ["—", "—"]
            else:
                r = math.log(runs[i][0] / runs[i + 1][0])
                cells += ["%.2f" % (math.log(errs[i][k] / errs[i + 1][k]) / r) for k in range(2)]
        md.append("| %g | %s |" % (t, " | ".join(cells)))
    text = "\n".join(md) + "\n"
    open(os.path.join(a.batch_dir, "periodic.md"), "w").write(text)
    print(text)


if __name__ == "__main__":
    main()
