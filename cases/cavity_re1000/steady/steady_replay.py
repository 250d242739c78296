#!/usr/bin/env python3
"""Replays the steady-state stop (time.steady_measure = "window_means") on the frames of finished runs.

    steady_replay.py RUN_DIR [RUN_DIR ...] [--window W] [--tolerances T1,T2,...]

For each run folder (the frames its particles.pvd lists, at output times 0, 1, 2, ...) it takes, per
frame, the sample that arksph's monitor takes (src/diagnostics/steady_state.hpp): the kinetic energy and the velocities
at Ghia's interior centreline points, interpolated as src/diagnostics/ghia.cpp does (Shepard-normalised
Wendland C2 with h = 1.3 dx over the fluid particles; velocities over the lid speed 1). It prints the
first output time at which the change of the means of the two latest windows of W outputs is below
each tolerance, and the rate every 10 outputs. dx is read from the run's summary.json (derived h / 2).
Needs python3 with numpy; the frames are read by scripts/vtp_frames.py (no VTK).
"""
import argparse
import csv
import json
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "scripts"))
from vtp_frames import frames, read_vtp  # noqa: E402

GHIA = os.path.join(HERE, "..", "..", "..", "bench", "ghia")


def interior_coords(name):
    with open(os.path.join(GHIA, name)) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    return [float(r[0]) for r in rows[1:] if 0 < float(r[0]) < 1]


def samples(run, dx):
    uy = interior_coords("ghia_u_vertical_centerline.csv")
    vx = interior_coords("ghia_v_horizontal_centerline.csv")
    h = 1.3 * dx

    def weight(r):
        q = r / h
        return np.where(q < 2, (1 - q / 2) ** 4 * (2 * q + 1), 0.0)

    out = []
    for _, path in frames(run):
        data = read_vtp(path)
        x, vel, mass = data["Points"], data["velocity"], data["mass"]
        vol = mass / data["density"]
        ke = 0.5 * np.sum(mass * (vel[:, 0] ** 2 + vel[:, 1] ** 2))
        c = []
        for y in uy:
            w = vol * weight(np.hypot(x[:, 0] - 0.5, x[:, 1] - y))
            c.append(np.sum(w * vel[:, 0]) / np.sum(w) if np.sum(w) > 0 else 0.0)
        for xx in vx:
            w = vol * weight(np.hypot(x[:, 0] - xx, x[:, 1] - 0.5))
            c.append(np.sum(w * vel[:, 1]) / np.sum(w) if np.sum(w) > 0 else 0.0)
        out.append(np.concatenate([[ke], c]))
    return np.array(out)


def means_rate(a, k, w):
    """Rate of the window means at output k, windows of w outputs (outputs one time unit apart)."""
    earlier = a[k - 2 * w + 1:k - w + 1].mean(0)
    later = a[k - w + 1:k + 1].mean(0)
    ke_rate = abs(later[0] - earlier[0]) / (later[0] * w) if later[0] else 0.0
    return max(ke_rate, np.max(np.abs(later[1:] - earlier[1:])) / w)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("runs", nargs="+")
    p.add_argument("--window", type=int, default=10)
    p.add_argument("--tolerances", default="0.002,0.001,0.0005")
    args = p.parse_args()
    tolerances = [float(t) for t in args.tolerances.split(",")]
    for run in args.runs:
        with open(os.path.join(run, "summary.json")) as f:
            dx = json.load(f)["derived"]["h"] / 2
        a = samples(run, dx)
        rates = [(k, means_rate(a, k, args.window)) for k in range(2 * args.window, len(a))]
        first = {t: next((k for k, r in rates if r < t), None) for t in tolerances}
        print(f"{os.path.basename(run.rstrip('/'))}: first stop {first}")
        print("   " + " ".join(f"{k}:{r:.4f}" for k, r in rates if k % 10 == 0))


if __name__ == "__main__":
    main()
