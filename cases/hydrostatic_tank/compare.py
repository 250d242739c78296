#!/usr/bin/python3
"""Hydrostatic tank: the schemes side by side.

    compare.py OUT.png LABEL=RUN_DIR [LABEL=RUN_DIR ...]

Left: max speed (timeseries.csv) against time, over sqrt(g H) = 1. Right: the pressure of every
particle in the last frame against depth H - y, with rho g (H - y) (the projection schemes' level
is free in a closed box: each run is shifted to the mean of the reference). Prints per run the
largest speed over the outputs, the speed at the last output and the r.m.s. relative deviation of
the pressure from rho g (H - y) (both at zero mean, relative to the reference's r.m.s.).
Reads the VTP frames directly (scripts/vtp_frames.py).
"""
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
from vtp_frames import frames, read_vtp  # noqa: E402

H, G, RHO = 1.0, 1.0, 1.0
def last_frame(run):
    return max(frames(run))


def timeseries(run):
    with open(Path(run) / "timeseries.csv") as f:
        rows = list(csv.DictReader(f))
    return np.array([float(r["t"]) for r in rows]), np.array([float(r["max_speed"]) for r in rows])


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    runs = [a.split("=", 1) for a in sys.argv[2:]]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.6))
    print("| run | max speed at t_end | max over outputs | p r.m.s. rel. deviation |")
    print("|---|---|---|---|")
    for label, run in runs:
        t, s = timeseries(run)
        ax1.semilogy(t[1:], s[1:] / np.sqrt(G * H), label=label, lw=1)
        tf, vtp = last_frame(run)
        d = read_vtp(vtp)
        y, p = d["Points"][:, 1], d["pressure"]
        ref = RHO * G * (H - y)
        dev = (p - p.mean()) - (ref - ref.mean())
        rel = np.sqrt(np.mean(dev ** 2) / np.mean((ref - ref.mean()) ** 2))
        ax2.plot(H - y, p - p.mean() + ref.mean(), ".", ms=1.5, label=label)
        print("| %s | %.2e (t = %g) | %.2e | %.2e |" % (label, s[-1], t[-1], s[1:].max(), rel))
    ax1.axhline(1e-3, color="k", lw=0.6, ls="--")
    ax1.axhline(2e-3, color="k", lw=0.6, ls=":")
    ax1.set_xlabel("t sqrt(g/H)")
    ax1.set_ylabel("max |u| / sqrt(gH)")
    ax1.legend(fontsize=7)
    depth = np.linspace(0, H, 2)
    ax2.plot(depth, RHO * G * depth, "k-", lw=0.8, label="rho g (H - y)")
    ax2.set_xlabel("depth H - y")
    ax2.set_ylabel("p (shifted to the reference's mean)")
    ax2.legend(fontsize=7, markerscale=4)
    fig.tight_layout()
    fig.savefig(out, dpi=80)


if __name__ == "__main__":
    main()
