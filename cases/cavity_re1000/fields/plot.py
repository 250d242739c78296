#!/usr/bin/env python3
"""Szewc's figures of the Re = 1000 cavity's fields at N = 3600 (Figs. 2, 3, 13, 17a, 18).

usage: plot.py FREE_SLIP_RUNS FIELDS_RUNS [OUT_DIR]

    /usr/bin/python3 cases/cavity_re1000/fields/plot.py runs/cavity_re1000_free_slip runs/cavity_re1000_fields

FREE_SLIP_RUNS is the batch folder of free_slip.toml, FIELDS_RUNS that of steady_fields.toml. A run
still going is read from its frames and timeseries.csv so far. Writes to OUT_DIR (default measured/
beside this script):
- results.csv: one row per run: the settings, status, end time (and where the run failed, why),
  the largest speed / lid speed over the run, Ghia u and v r.m.s. at the last output, density mean
  and r.m.s. (Szewc eq. 56), the share of particles whose nearest neighbour is closer than dx/2;
- fig3_free_slip.png: WCSPH's first instants with no-slip and free-slip images in the continuity
  equation's divergence: the largest speed against t and the particles coloured by speed at t = 0.03;
- fig2_corner_alpha.png: u on x = 0.5 and v on y = 0.5 against Ghia for alpha = -1, 0, 1, and the
  speed of the particles within 2 h of the two lid corners against t;
- fig13_density.png: the density field at the last output for WCSPH (its continuity density) and
  ISPH and ISPH + P-W (the summation density), each coloured over its 1-99 % range;
- fig17_density.png: density mean and r.m.s. against t for ISPH with and without the correction;
- fig18_nn_histogram.png: nearest-neighbour distance histograms of the same runs.
"""
import csv
import importlib.util
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "scripts"))
from vtp_frames import frames, read_vtp  # noqa: E402

_spec = importlib.util.spec_from_file_location("kernel_study_plot", os.path.join(HERE, "..", "kernels", "plot.py"))
_kernel_study = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_kernel_study)
close_pairs, read_rows = _kernel_study.close_pairs, _kernel_study.read_rows  # the kernel study's readers and writer

DX = 1.0 / 60.0
H = 2.0 * DX
LID_SPEED = 1.0


def runs_of(folder):
    """Settings (batch_run.txt) and folder of every run in a batch folder, in its order."""
    out = []
    for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        path = os.path.join(folder, name)
        if os.path.exists(os.path.join(path, "batch_run.txt")):
            keys = dict(a.split("=", 1) for a in open(os.path.join(path, "batch_run.txt")).read().split() if "=" in a)
            out.append(dict(keys=keys, folder=path))
    return out


def label(run):
    k = run["keys"]
    if "boundary.free_slip_divergence" in k:
        return "free-slip divergence" if k["boundary.free_slip_divergence"] == "true" else "no-slip divergence"
    scheme = k["method.scheme"]
    if k.get("method.density_correction", "none") != "none":
        return f"{scheme} + P-W ({k['method.correction_solver'].replace('_', ' ')})"
    if scheme == "wcsph":
        return f"wcsph, alpha = {float(k['boundary.corner_alpha']):g}"
    return scheme


def measure(run):
    ts = read_rows(os.path.join(run["folder"], "timeseries.csv"))
    sp = os.path.join(run["folder"], "summary.json")
    summary = json.load(open(sp)) if os.path.exists(sp) else {}
    last = ts[-1]
    row = dict(run=label(run), status=summary.get("status", "running"), t_end=float(last["t"]),
               reason=summary.get("failure", ""),
               max_speed_over_lid=max(float(r["max_speed"]) for r in ts) / LID_SPEED)
    for k in ("ghia_u_rms", "ghia_v_rms", "density_mean", "density_rms"):
        row[k] = float(last[k])
    row["nn_below_half_dx"] = close_pairs(run["folder"])[0]
    return row, ts


def scatter(ax, vtp, field, title, vmin=None, vmax=None, ylim=(0, 1), size=2):
    a = read_vtp(vtp)
    x = a["Points"][:, 0]
    y = a["Points"][:, 1]
    if field == "speed":
        c = np.linalg.norm(a["velocity"][:, :2], axis=1)
    else:
        c = a[field]
    keep = (y >= ylim[0]) & (y <= ylim[1])
    sc = ax.scatter(x[keep], y[keep], c=c[keep], s=size, cmap="viridis", vmin=vmin, vmax=vmax)
    ax.set_aspect("equal")
    ax.set_xlim(0, 1)
    ax.set_ylim(*ylim)
    ax.set_title(title, fontsize=9)
    plt.colorbar(sc, ax=ax, fraction=0.046 * (ylim[1] - ylim[0]), label=field)


def frame_at(run, t):
    """The frame nearest to t of a run."""
    return min(frames(run["folder"]), key=lambda f: abs(f[0] - t))


def fig3(runs, path):
    fig = plt.figure(figsize=(12, 9))
    grid = fig.add_gridspec(3, 1, height_ratios=[1.3, 1, 1])
    ax = fig.add_subplot(grid[0])
    for run in runs:
        ts = read_rows(os.path.join(run["folder"], "timeseries.csv"))
        ax.plot([float(r["t"]) for r in ts], [float(r["max_speed"]) for r in ts], label=label(run))
    ax.set_xlabel("t")
    ax.set_ylabel("largest particle speed / lid speed")
    ax.legend(fontsize=8)
    for j, run in enumerate(runs[:2], 1):
        t, vtp = frame_at(run, 0.03)
        scatter(fig.add_subplot(grid[j]), vtp, "speed", f"{label(run)}, t = {t:g}: the top of the cavity", 0.0, 1.5,
                ylim=(0.8, 1.0), size=12)
    fig.suptitle("Cavity Re = 1000, WCSPH, N = 3600: the velocity divergence at the corners (Szewc Fig. 3)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def corner_speed(run):
    """(t, largest speed of the particles within 2 h of the lid's corners) over a run's frames."""
    out = []
    for t, vtp in frames(run["folder"]):
        a = read_vtp(vtp)
        p = a["Points"]
        near = ((p[:, 0] < 2 * H) | (p[:, 0] > 1 - 2 * H)) & (p[:, 1] > 1 - 2 * H)
        out.append((t, float(np.linalg.norm(a["velocity"][near, :2], axis=1).max()) if near.any() else 0.0))
    return out


def fig2(runs, path):
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    for k, run in enumerate(runs):
        for i, (line, coord) in enumerate((("u", "y"), ("v", "x"))):
            g = sorted(read_rows(os.path.join(run["folder"], f"ghia_{line}.csv")), key=lambda r: float(r[coord]))
            s = [float(r[coord]) for r in g]
            if k == 0:
                ax[i].plot(s, [float(r[f"{line}_ghia"]) for r in g], "ko", ms=3, label="Ghia")
            ax[i].plot(s, [float(r[f"{line}_sph"]) for r in g], "-", color=f"C{k}", label=label(run))
        cs = corner_speed(run)
        ax[2].plot([c[0] for c in cs], [c[1] for c in cs], color=f"C{k}", label=label(run))
    ax[0].set_xlabel("y (u on x = 0.5)")
    ax[1].set_xlabel("x (v on y = 0.5)")
    ax[2].set_xlabel("t")
    ax[2].set_ylabel("largest speed within 2 h of a lid corner")
    for a in ax:
        a.legend(fontsize=7)
    fig.suptitle("Cavity Re = 1000, WCSPH, N = 3600: the corner ghosts' weighting alpha (Szewc eq. 48, Fig. 2)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def fig13(runs, path):
    fig, ax = plt.subplots(1, len(runs), figsize=(5 * len(runs), 4.5), squeeze=False)
    for j, run in enumerate(runs):
        t, vtp = frames(run["folder"])[-1]
        # WCSPH carries its density (the continuity equation); ISPH's is the summation density.
        field = "density" if run["keys"]["method.scheme"] == "wcsph" else "summation_density"
        rho = read_vtp(vtp)[field]
        scatter(ax[0][j], vtp, field, f"{label(run)}, t = {t:g}", float(np.percentile(rho, 1)),
                float(np.percentile(rho, 99)))
    fig.suptitle("Cavity Re = 1000, N = 3600: the density field at the steady state (Szewc Fig. 13)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def fig17_18(series, runs, path17, path18):
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    for run in runs:
        ts = series[run["folder"]]
        t = [float(r["t"]) for r in ts]
        ax[0].plot(t, [float(r["density_mean"]) for r in ts], label=label(run))
        ax[1].semilogy(t[1:], [float(r["density_rms"]) for r in ts[1:]], label=label(run))  # t = 0: a lattice
    ax[0].set_ylabel("density mean / rho0")
    ax[1].set_ylabel("density r.m.s. (Szewc eq. 56)")
    for a in ax:
        a.set_xlabel("t")
        a.legend(fontsize=8)
    fig.suptitle("Cavity Re = 1000, N = 3600: ISPH with and without the P-W correction (Szewc Fig. 17a)")
    fig.tight_layout()
    fig.savefig(path17, dpi=110)
    fig, ax = plt.subplots(figsize=(6, 4))
    for run in runs:
        _, hist = close_pairs(run["folder"])
        if hist:
            total = sum(int(r["count"]) for r in hist)
            ax.step([float(r["r_over_dx_lo"]) for r in hist], [int(r["count"]) / total for r in hist], where="post",
                    label=label(run))
    ax.set_xlabel("nearest-neighbour distance / dx")
    ax.set_ylabel("share of particles")
    ax.legend(fontsize=8)
    ax.set_title("ISPH with and without the P-W correction (Szewc Fig. 18)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path18, dpi=110)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    free_slip, fields = runs_of(sys.argv[1]), runs_of(sys.argv[2])
    out = sys.argv[3] if len(sys.argv) > 3 else os.path.join(HERE, "measured")
    if not free_slip and not fields:
        sys.exit(f"plot.py: no runs in {sys.argv[1]} or {sys.argv[2]}")
    os.makedirs(out, exist_ok=True)
    rows, series = [], {}
    for run in free_slip + fields:
        row, ts = measure(run)
        rows.append(row)
        series[run["folder"]] = ts
    _kernel_study.write_rows(rows, os.path.join(out, "results.csv"))
    if free_slip:
        fig3(free_slip, os.path.join(out, "fig3_free_slip.png"))
    wcsph = [r for r in fields if r["keys"]["method.scheme"] == "wcsph"]
    isph = [r for r in fields if r["keys"]["method.scheme"] == "isph"]
    if wcsph:
        fig2(wcsph, os.path.join(out, "fig2_corner_alpha.png"))
    alpha0 = [r for r in wcsph if float(r["keys"]["boundary.corner_alpha"]) == 0.0]
    if alpha0 + isph:
        fig13(alpha0 + isph, os.path.join(out, "fig13_density.png"))
    if isph:
        fig17_18(series, isph, os.path.join(out, "fig17_density.png"), os.path.join(out, "fig18_nn_histogram.png"))


if __name__ == "__main__":
    main()
