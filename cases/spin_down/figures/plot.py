#!/usr/bin/env python3
"""Cummins & Rudman 1999 Figs. 5-8 for the spin-down runs of sweep.toml, against the OpenFOAM
reference of ../openfoam/run.sh (bench/openfoam_spin_down/).

usage: plot.py RUNS_DIR [OUT_DIR]

    /usr/bin/python3 cases/spin_down/figures/plot.py runs/spin_down_figures

Writes to OUT_DIR (default measured/ beside this script):
- results.csv: per run, the largest speed and the kinetic energy at t = 5, 8 and 10 and their ratio
  to the reference's (N = 200), and CV (C&R eq. 24) at t = 10;
- fig5_streamlines.png: streamlines at t = 8 of the reference and of each run (the particle
  velocities interpolated linearly onto a 50 x 50 grid);
- fig6_particles.png: the particles at t = 10;
- fig7_max_speed.png: the largest speed and the kinetic energy against t, with the reference at
  N = 100 and 200 (its mesh convergence);
- fig8_cv.png: CV against t.
It prints the reference's own mesh convergence (the largest relative difference between N = 100
and 200 over t, of the largest speed and of the kinetic energy) beside the error of the run closest to
the reference (its largest deviation at t = 5, 8, 10), and says so when the mesh difference is not
the smaller.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.interpolate import griddata  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from vtp_frames import frames, read_vtp  # noqa: E402

REFERENCE = os.path.join(ROOT, "bench", "openfoam_spin_down")
REFERENCE_MESHES = (100, 200)
TIMES = (5.0, 8.0, 10.0)


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def label(keys):
    if keys["method.scheme"] == "wcsph":
        walls = "Lennard-Jones walls" if keys["boundary.wall_force"] == "lennard_jones" else "ghost walls"
        return f"WCSPH c = {float(keys['method.sound_speed']):g}, {walls}"
    if keys["method.density_correction"] != "none":
        return "ISPH + P-W (Newton)"
    return "ISPH, zero-mean P (C&R)" if keys["method.ppe_pressure_level"] == "zero_mean" else "ISPH, P >= 0"


def runs_of(folder):
    out = []
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if os.path.exists(os.path.join(path, "batch_run.txt")):
            keys = dict(a.split("=", 1) for a in open(os.path.join(path, "batch_run.txt")).read().split() if "=" in a)
            out.append(dict(label=label(keys), folder=path, series=read_rows(os.path.join(path, "timeseries.csv"))))
    return out


def at(series, t, key):
    row = min(series, key=lambda r: abs(float(r["t"]) - t))
    return float(row[key]) if abs(float(row["t"]) - t) < 1e-6 else float("nan")


def reference(n):
    path = os.path.join(REFERENCE, f"openfoam_n{n}_history.csv")
    return read_rows(path) if os.path.exists(path) else None


def streamlines(ax, x, y, u, v, title):
    g = (np.arange(50) + 0.5) / 50
    ax.streamplot(g, g, u, v, density=1.2, color=np.hypot(u, v), cmap="viridis", linewidth=0.7)
    ax.set_aspect("equal")
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1)
    ax.set_title(title, fontsize=9)


def on_grid(points, values):
    g = (np.arange(50) + 0.5) / 50
    gx, gy = np.meshgrid(g, g)
    out = griddata(points, values, (gx, gy), method="linear")
    near = griddata(points, values, (gx, gy), method="nearest")  # the cells outside the particles' hull
    return np.where(np.isnan(out), near, out)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    runs = runs_of(sys.argv[1])
    if not runs:
        sys.exit(f"plot.py: no runs in {sys.argv[1]}")
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, "measured")
    os.makedirs(out, exist_ok=True)
    ref = {n: reference(n) for n in REFERENCE_MESHES}
    fine = ref[REFERENCE_MESHES[-1]]
    if fine is None:
        sys.exit(f"plot.py: no reference in {REFERENCE}: run cases/spin_down/openfoam/run.sh {REFERENCE_MESHES[-1]}")

    rows = []
    for run in runs:
        row = {"run": run["label"]}
        for t in TIMES:
            for key in ("max_speed", "kinetic_energy"):
                row[f"{key}_t{t:g}"] = at(run["series"], t, key)
                row[f"{key}_t{t:g}_over_reference"] = at(run["series"], t, key) / at(fine, t, key)
        row["cv_t10"] = at(run["series"], 10.0, "cv")
        rows.append(row)
    with open(os.path.join(out, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in r.items()})
            print(" ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}" for k, v in r.items()))

    coarse = ref[REFERENCE_MESHES[0]]
    if coarse:
        for key in ("max_speed", "kinetic_energy"):
            mesh = max(abs(float(a[key]) / float(b[key]) - 1) for a, b in zip(coarse, fine))
            sph = min(max(abs(r[f"{key}_t{t:g}_over_reference"] - 1) for t in TIMES) for r in rows)
            verdict = "below" if mesh < sph else "NOT below"
            print(f"reference {key}: meshes {REFERENCE_MESHES[0]}² and {REFERENCE_MESHES[-1]}² differ by at most "
                  f"{mesh:.2%}, {verdict} the deviation of the closest run from it ({sph:.2%}, its largest at t = 5, 8, 10)")

    fig, ax = plt.subplots(2, 3, figsize=(13, 8.5))
    flat = ax.ravel()
    t8 = read_rows(os.path.join(REFERENCE, f"openfoam_n{REFERENCE_MESHES[-1]}_velocity_t8.csv"))
    streamlines(flat[0], None, None, np.array([float(r["u"]) for r in t8]).reshape(50, 50),
                np.array([float(r["v"]) for r in t8]).reshape(50, 50), f"OpenFOAM {REFERENCE_MESHES[-1]}², t = 8")
    for k, run in enumerate(runs[:5], 1):
        t, vtp = min(frames(run["folder"]), key=lambda f: abs(f[0] - 8.0))
        a = read_vtp(vtp)
        p = a["Points"][:, :2]
        streamlines(flat[k], None, None, on_grid(p, a["velocity"][:, 0]), on_grid(p, a["velocity"][:, 1]),
                    f"{run['label']}, t = {t:g}")
    fig.suptitle("Spin-down, streamlines at t = 8 (C&R Fig. 5)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig5_streamlines.png"), dpi=100)

    fig, ax = plt.subplots(1, len(runs), figsize=(3.6 * len(runs), 3.9), squeeze=False)
    for j, run in enumerate(runs):
        t, vtp = frames(run["folder"])[-1]
        p = read_vtp(vtp)["Points"]
        ax[0][j].plot(p[:, 0], p[:, 1], ".", ms=1.5, color="k")
        ax[0][j].set_aspect("equal")
        ax[0][j].set_xlim(0, 1)
        ax[0][j].set_ylim(0, 1)
        ax[0][j].set_title(f"{run['label']}, t = {t:g}", fontsize=8)
    fig.suptitle("Spin-down, particle positions (C&R Fig. 6)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig6_particles.png"), dpi=110)

    fig, ax = plt.subplots(1, 2, figsize=(12, 4.3))
    for n, series in ref.items():
        if series:
            t = [float(r["t"]) for r in series]
            style = "k-" if n == REFERENCE_MESHES[-1] else "k:"
            ax[0].plot(t, [float(r["max_speed"]) for r in series], style, label=f"OpenFOAM {n}²")
            ax[1].plot(t, [float(r["kinetic_energy"]) for r in series], style, label=f"OpenFOAM {n}²")
    for run in runs:
        t = [float(r["t"]) for r in run["series"]]
        ax[0].plot(t, [float(r["max_speed"]) for r in run["series"]], label=run["label"])
        ax[1].plot(t, [float(r["kinetic_energy"]) for r in run["series"]], label=run["label"])
    ax[0].set_ylabel("largest speed")
    ax[1].set_ylabel("kinetic energy")
    ax[1].set_yscale("log")
    for a in ax:
        a.set_xlabel("t")
        a.legend(fontsize=7)
    fig.suptitle("Spin-down, decay of the largest speed (C&R Fig. 7) and of the kinetic energy")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig7_max_speed.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(6.5, 4.3))
    for run in runs:
        ax.semilogy([float(r["t"]) for r in run["series"]], [max(float(r["cv"]), 1e-6) for r in run["series"]],
                    label=run["label"])
    ax.axhline(0.015, color="grey", ls="--", lw=0.8, label="C&R's CV(10), PSPH")
    ax.set_xlabel("t")
    ax.set_ylabel("CV (C&R eq. 24)")
    ax.legend(fontsize=7)
    ax.set_title("Spin-down, CV against t (C&R Fig. 8)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig8_cv.png"), dpi=110)


if __name__ == "__main__":
    main()
