#!/usr/bin/python3
"""Picture of the spin-down convergence tables: L1 error of each lattice pair at time t against the
coarse lattice's dx, ours (solid) beside Cummins & Rudman's Tables I-III (dashed), and the doubly
periodic variant against the exact solution (dotted, per lattice).

usage: plot_convergence.py OUT.png [--t 1] [--table1 DIR] [--table2 DIR] [--table3 DIR] [--periodic DIR ...]

DIR: a batch folder after convergence.py (convergence.csv) or periodic_errors.py (periodic.csv);
--periodic DIR=LABEL names the curve.
"""
import argparse
import csv
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from convergence import PAPER  # noqa: E402

LABEL = {"table1": "I: ISPH h = 1.3 dx", "table2": "II: WCSPH h = 1.3 dx", "table3": "III: ISPH h = 0.23 dx^0.5"}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("png")
    ap.add_argument("--t", type=float, default=1.0)
    for k in ("table1", "table2", "table3"):
        ap.add_argument("--" + k)
    ap.add_argument("--periodic", nargs="*", default=[])
    a = ap.parse_args()
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    for i, k in enumerate(("table1", "table2", "table3")):
        d = getattr(a, k)
        if not d:
            continue
        colour = "C%d" % i
        rows = list(csv.DictReader(open(os.path.join(d, "convergence.csv"))))
        cols = list(rows[0].keys())
        pairs = [tuple(int(v) for v in re.findall(r"\d+", c[3:])) for c in cols if c.startswith("L1_")]
        for r in rows:
            if abs(float(r["t"]) - a.t) < 1e-9:
                xs = [1.0 / p[0] for p in pairs if r["L1_%d_%d" % p]]
                ys = [float(r["L1_%d_%d" % p]) for p in pairs if r["L1_%d_%d" % p]]
                ax.loglog(xs, ys, "o-", color=colour, label="ours, " + LABEL[k])
        paper = PAPER[k]["rows"].get(int(round(a.t)))
        if paper:
            sc = PAPER[k]["scale"]
            ax.loglog([1.0 / p[0] for p in pairs], [paper[0] * sc[0], paper[2] * sc[1]], "s--", color=colour,
                      alpha=0.6, label="C&R, " + LABEL[k])
    for j, arg in enumerate(a.periodic):
        d, _, name = arg.partition("=")
        pts = [(1.0 / int(r["lattice"]), float(r["L1"])) for r in csv.DictReader(open(os.path.join(d, "periodic.csv")))
               if abs(float(r["t"]) - a.t) < 1e-9]
        if pts:
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], "^:", color="C%d" % (3 + j),
                      label="periodic vs exact, " + (name or os.path.basename(d.rstrip("/"))))
    ax.set_xlabel("dx (coarse lattice of the pair)")
    ax.set_ylabel("L1 velocity error at t = %g" % a.t)
    ax.set_title("spin-down spatial convergence (C&R 1999 Tables I-III)", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=6.5)
    fig.tight_layout()
    fig.savefig(a.png, dpi=80)


if __name__ == "__main__":
    main()
