#!/usr/bin/python3
"""Rayleigh-Taylor pictures (Szewc et al. 2012 Fig. 11, Cummins & Rudman 1999 Figs. 10-11).

    plot.py OUT_DIR LABEL=RUN_DIR [LABEL=RUN_DIR ...]

Writes into OUT_DIR:
  rt_particles.png  particles coloured by phase at t = 1, 3, 5 (rows), one column per run, with the
                    0.5 contour of the smoothed phase indicator (interface_NNNNNN.csv) on top, and
                    in green the OpenFOAM interface of bench/openfoam_rt (200 x 400) at t = 1, 3, 5;
  rt_tips.png       bubble and spike tip heights (timeseries.csv) against time;
  rt_density.png    mean and r.m.s. of the heavy (upper) phase's density over its initial density
                    against time (timeseries.csv upper_density_mean, upper_density_rms: Szewc eqs.
                    55-56), Szewc et al. 2012 Fig. 14.
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

# The OpenFOAM interface (bench/openfoam_rt), drawn in green where it exists for a panel's time.
REFERENCE = Path(__file__).resolve().parents[2] / "bench" / "openfoam_rt" / "openfoam_rt_n200"
TIMES = tuple(float(t) for t in __import__('os').environ.get('RT_TIMES', '1 3 5').split())


def nearest(run, t):
    fr = frames(run)
    k = min(range(len(fr)), key=lambda i: abs(fr[i][0] - t))
    return k, fr[k]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    runs = [a.split("=", 1) for a in sys.argv[2:]]
    fig, axes = plt.subplots(len(TIMES), len(runs), figsize=(2.2 * len(runs), 4.2 * len(TIMES)), squeeze=False)
    for c, (label, run) in enumerate(runs):
        for r, t in enumerate(TIMES):
            ax = axes[r][c]
            k, (tf, vtp) = nearest(run, t)
            d = read_vtp(vtp)
            p = d["Points"]
            ax.scatter(p[:, 0], p[:, 1], c=d["phase"], cmap="coolwarm", s=0.6, linewidths=0, vmin=0, vmax=1)
            icsv = Path(run) / ("interface_%06d.csv" % k)
            if icsv.exists():
                with open(icsv) as f:
                    for row in csv.DictReader(f):
                        ax.plot([float(row["x0"]), float(row["x1"])], [float(row["y0"]), float(row["y1"])], "k-", lw=0.8)
            ref = REFERENCE.parent / ("%s_interface_t%g.csv" % (REFERENCE.name, t))
            if ref.exists():
                with open(ref) as f:
                    for row in csv.DictReader(f):
                        ax.plot([float(row["x0"]), float(row["x1"])], [float(row["y0"]), float(row["y1"])], "-",
                                color="lime", lw=0.6)
            ax.set_xlim(0, 1)
            ax.set_ylim(0, 2)
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            ax.set_title("%s, t = %g" % (label, tf), fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "rt_particles.png", dpi=150)

    fig, ax = plt.subplots(figsize=(6, 4))
    for label, run in runs:
        with open(Path(run) / "timeseries.csv") as f:
            rows = list(csv.DictReader(f))
        t = [float(r["t"]) for r in rows]
        line, = ax.plot(t, [float(r["bubble_y"]) for r in rows], "-", label=label + " bubble")
        ax.plot(t, [float(r["spike_y"]) for r in rows], "--", color=line.get_color(), label=label + " spike")
    ax.set_xlabel("t / sqrt(L/g)")
    ax.set_ylabel("tip height y / L")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "rt_tips.png", dpi=150)

    fig, (ax_mean, ax_rms) = plt.subplots(1, 2, figsize=(10, 4))
    for label, run in runs:
        with open(Path(run) / "timeseries.csv") as f:
            rows = list(csv.DictReader(f))
        t = [float(r["t"]) for r in rows]
        ax_mean.plot(t, [float(r["upper_density_mean"]) for r in rows], label=label)
        ax_rms.plot(t, [100.0 * float(r["upper_density_rms"]) for r in rows], label=label)
    ax_mean.set_ylabel("upper phase: mean density / rho0 (1.8 at t = 0)")
    ax_rms.set_ylabel("upper phase: density r.m.s. (%)")
    for ax in (ax_mean, ax_rms):
        ax.set_xlabel("t / sqrt(L/g)")
        ax.grid(alpha=0.3)
    ax_rms.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "rt_density.png", dpi=150)


if __name__ == "__main__":
    main()
