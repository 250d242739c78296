#!/usr/bin/env python3
"""Particle pairing in cavity runs: at every frame of each run, the share of particles whose nearest
real neighbour is closer than 0.1 dx and 0.5 dx, and the smallest nearest-neighbour distance (all
distances over dx, the scene's fluid.spacing from summary.json's scene copy or --dx).

usage: pairing.py OUT_PREFIX LABEL=RUN [LABEL=RUN ...] [--dx DX]

Writes OUT_PREFIX.csv (label, t, share_below_0.1dx, share_below_0.5dx, min_over_dx) and
OUT_PREFIX.png (the share below 0.1 dx and the smallest distance against time, one line per run).
A regular lattice has every nearest neighbour at 1 dx; a share growing with time means particles
collapse onto each other in pairs.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.spatial import cKDTree  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from vtp_frames import frames, read_vtp  # noqa: E402

DX = 0.02  # cases/basa_cavity/scene.toml: fluid.spacing


def history(run, dx):
    rows = []
    for t, path in frames(run):
        p = read_vtp(path)["Points"][:, :2]
        nearest = cKDTree(p).query(p, k=2)[0][:, 1] / dx
        rows.append((t, float(np.mean(nearest < 0.1)), float(np.mean(nearest < 0.5)), float(nearest.min())))
    return rows


def main():
    args = sys.argv[1:]
    dx = DX
    if "--dx" in args:
        i = args.index("--dx")
        dx = float(args[i + 1])
        del args[i:i + 2]
    if len(args) < 2:
        sys.exit(__doc__)
    prefix, runs = args[0], [a.rsplit("=", 1) for a in args[1:]]
    fig, (ax_share, ax_min) = plt.subplots(1, 2, figsize=(11, 4))
    with open(prefix + ".csv", "w", newline="") as out:
        w = csv.writer(out)
        w.writerow(["label", "t", "share_below_0.1dx", "share_below_0.5dx", "min_over_dx"])
        for label, run in runs:
            rows = history(run, dx)
            for r in rows:
                w.writerow([label, f"{r[0]:g}", f"{r[1]:.4f}", f"{r[2]:.4f}", f"{r[3]:.3e}"])
            t = [r[0] for r in rows]
            ax_share.plot(t, [r[1] for r in rows], label=label)
            ax_min.semilogy(t, [max(r[3], 1e-16) for r in rows], label=label)
            last = rows[-1]
            print(f"{label}: t = {last[0]:g}, share < 0.1 dx {last[1]:.3f}, < 0.5 dx {last[2]:.3f}, "
                  f"smallest {last[3]:.2e} dx")
    ax_share.set_xlabel("t")
    ax_share.set_ylabel("share with a neighbour closer than 0.1 dx")
    ax_min.set_xlabel("t")
    ax_min.set_ylabel("smallest nearest-neighbour distance / dx")
    ax_share.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(prefix + ".png", dpi=110)
    print("wrote", prefix + ".csv", prefix + ".png")


if __name__ == "__main__":
    main()
