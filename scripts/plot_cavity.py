#!/usr/bin/env python3
"""Picture of lid-driven cavity runs against Ghia, Ghia & Shin 1982: u on x = 0.5 and v on y = 0.5
(each run's ghia_u.csv / ghia_v.csv, Ghia's interior points of the scene's metrics.ghia_re), and
the particles of each run's last frame coloured by speed.

usage: plot_cavity.py OUT.png RUN_DIR [RUN_DIR ...]

Each run folder needs ghia_u.csv, ghia_v.csv, summary.json and particles.pvd (a finished or
stopped `arksph run` of a scene with metrics.ghia_re). The legend names each run by its scheme (with its
regularisation and P-W correction) and N, with its Ghia r.m.s. errors of u and v and its end time. Needs matplotlib and numpy.
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtp_frames import frames, read_vtp  # noqa: E402


def columns(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def method(s):
    """The scheme with its regularisation and P-W correction, from summary.json's terms."""
    parts = [s["scheme"]]
    for term in s.get("terms", []):
        if term.startswith("regularisation:"):
            parts.append(term.split(":", 1)[1].replace("_", " "))
        elif term.startswith("correction:"):
            parts.append("P-W")
    return " + ".join(parts)


def label(run):
    s = json.load(open(os.path.join(run, "summary.json")))
    m = s.get("metrics", {})
    return (f"{method(s)}, N = {s['particles']}, t = {s['final_time']:g}: "
            f"r.m.s. u {m.get('ghia_u_rms', float('nan')):.3f}, v {m.get('ghia_v_rms', float('nan')):.3f}")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, runs = sys.argv[1], sys.argv[2:]
    fig, ax = plt.subplots(1, 2 + len(runs), figsize=(4.2 * (2 + len(runs)), 4.2))
    for k, run in enumerate(runs):
        u, v = columns(os.path.join(run, "ghia_u.csv")), columns(os.path.join(run, "ghia_v.csv"))
        if k == 0:
            ax[0].plot(u["u_ghia"], u["y"], "ko", ms=4, label="Ghia et al. 1982")
            ax[1].plot(v["x"], v["v_ghia"], "ko", ms=4, label="Ghia et al. 1982")
        ax[0].plot(u["u_sph"], u["y"], "-", label=label(run))
        ax[1].plot(v["x"], v["v_sph"], "-", label=label(run))
        t, vtp = frames(run)[-1]
        p = read_vtp(vtp)
        speed = (p["velocity"][:, :2] ** 2).sum(axis=1) ** 0.5
        sc = ax[2 + k].scatter(p["Points"][:, 0], p["Points"][:, 1], c=speed, s=2, cmap="viridis", vmin=0, vmax=1)
        ax[2 + k].set_aspect("equal")
        scheme = method(json.load(open(os.path.join(run, "summary.json"))))
        ax[2 + k].set_title(f"{scheme}, particles at t = {t:g}", fontsize=9)
        fig.colorbar(sc, ax=ax[2 + k], fraction=0.046, label="|u|")
    ax[0].set_xlabel("u on x = 0.5")
    ax[0].set_ylabel("y")
    ax[1].set_xlabel("x")
    ax[1].set_ylabel("v on y = 0.5")
    ax[1].legend(fontsize=6, loc="lower left")
    fig.tight_layout()
    if os.path.dirname(out):
        os.makedirs(os.path.dirname(out), exist_ok=True)
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
