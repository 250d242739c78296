#!/usr/bin/python3
"""Plot of `arksph study work-precision`: L2 velocity error against wall time, one curve per scheme.

usage: plot_work_precision.py work_precision.csv OUT.png [--target E] [--title TEXT]

Points are labelled with their resolution name; the dashed line marks the target error of the
study's "soonest" line. Needs matplotlib (Debian: python3-matplotlib).
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("png")
    ap.add_argument("--target", type=float, default=0.0)
    ap.add_argument("--title", default="work-precision")
    a = ap.parse_args()
    curves = {}
    for r in csv.DictReader(open(a.csv)):
        if r["status"] != "ok":
            continue
        w, e = float(r["wall_seconds"]), float(r["error_l2"])
        if w > 0 and e > 0 and math.isfinite(e):
            curves.setdefault(r["scheme"], []).append((w, e, r["resolution"]))
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    for name, pts in curves.items():
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=name)
        for w, e, res in pts:
            ax.annotate(res, (w, e), fontsize=7, textcoords="offset points", xytext=(3, 3))
    if a.target > 0:
        ax.axhline(a.target, color="grey", ls="--", lw=0.8, label="target %.2g" % a.target)
    ax.set_xlabel("wall time of the run [s]")
    ax.set_ylabel("L2 velocity error at the end time")
    ax.set_title(a.title, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.png, dpi=80)


if __name__ == "__main__":
    main()
