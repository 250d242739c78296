#!/usr/bin/env python3
"""Szewc's kernel and smoothing-length studies of the Re = 1000 cavity at N = 3600 (Figs. 5-8, 12a-b).

usage: plot.py WENDLAND_RUNS KERNEL_RUNS SMOOTHING_RUNS [OUT_DIR]
       plot.py --support SUPPORT_RUNS [OUT_DIR]

    /usr/bin/python3 cases/cavity_re1000/kernels/plot.py runs/cavity_re1000_wendland_t120 \\
        runs/cavity_re1000_kernels runs/cavity_re1000_smoothing_length

WENDLAND_RUNS supplies the Wendland, h = 2 dx runs at N = 3600 (those of wendland.toml; the N = 3600
runs of ../steady/sweep.toml without the P-W correction serve too, ended at their steady state); the
other two folders are those of kernels.toml and smoothing_length.toml. A run still going is read
from its timeseries.csv so far. Writes to OUT_DIR (default measured/ beside this script):
- results.csv: study, scheme, kernel, h/dx, status, end time, Ghia u and v r.m.s. and largest
  errors at the last output, density mean and r.m.s. at t = 0 and at the last output (Szewc
  eq. 56), the share of particles whose nearest neighbour is closer than 0.5 dx, steps, wall s;
- profiles_kernels.png, profiles_smoothing_length.png: u on x = 0.5 and v on y = 0.5 against
  Ghia, one column per scheme (Szewc Figs. 5 and 8);
- nn_histogram.png: nearest-neighbour distance histograms per kernel, one panel per scheme
  (Szewc Fig. 7);
- density.png: density mean and r.m.s. against t per kernel and per h/dx for WCSPH (Fig. 12a-b).
With --support, the runs of support.toml (Morris's and Wendland's kernels at equal support radii):
support.csv, with results.csv's columns, and support.png, their nearest-neighbour histograms and u
profiles.
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "steady"))
from plot import read_rows  # noqa: E402  (the steady study's reader of arksph's CSV files)
SCHEMES = ["wcsph", "isph-gpps", "isph"]
N3600_SPACING = 1.0 / 60.0


def runs_of(folder, study):
    """(study, scheme, kernel, h/dx, run folder) of every run in a batch folder."""
    out = []
    if not os.path.isdir(folder):
        return out
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if not os.path.exists(os.path.join(path, "batch_run.txt")):
            continue
        k = dict(a.split("=", 1) for a in open(os.path.join(path, "batch_run.txt")).read().split() if "=" in a)
        if study == "steady":  # only the N = 3600 runs without the P-W correction
            if abs(float(k["fluid.spacing"]) - N3600_SPACING) > 1e-9 or k.get("method.density_correction", "none") != "none":
                continue
        out.append(dict(scheme=k["method.scheme"], kernel=k.get("method.kernel", "wendland_quintic"),
                        h=float(k.get("method.h_over_dx", 2.0)), folder=path))
    return out


def close_pairs(folder, below=0.5):
    path = os.path.join(folder, "nn_histogram.csv")
    if not os.path.exists(path):
        return float("nan"), []
    rows = read_rows(path)
    total = sum(int(r["count"]) for r in rows)
    close = sum(int(r["count"]) for r in rows if float(r["r_over_dx_hi"]) <= below + 1e-12)
    return (close / total if total else float("nan")), rows


def measure(run, study):
    ts = read_rows(os.path.join(run["folder"], "timeseries.csv"))
    sp = os.path.join(run["folder"], "summary.json")
    summary = json.load(open(sp)) if os.path.exists(sp) else {}
    first, last = ts[0], ts[-1]
    share, _ = close_pairs(run["folder"])
    row = dict(study=study, scheme=run["scheme"], kernel=run["kernel"], h_over_dx=run["h"],
               status=summary.get("status", "running"), t_end=float(last["t"]))
    for k in ("ghia_u_rms", "ghia_u_linf", "ghia_v_rms", "ghia_v_linf"):
        row[k] = float(last[k])
    row["density_mean_t0"] = float(first["density_mean"])
    row["density_rms_t0"] = float(first["density_rms"])
    row["density_mean"] = float(last["density_mean"])
    row["density_rms"] = float(last["density_rms"])
    row["nn_below_half_dx"] = share
    row["steps"] = summary.get("steps", last.get("steps", ""))
    row["wall_seconds"] = summary.get("wall_seconds", "")
    return row, ts


def profiles(ax_col, runs, label_of, colours):
    """colours: label -> colour, the same in every panel."""
    ghia_drawn = [False, False]
    for run in sorted(runs, key=label_of):
        for i, (line, coord) in enumerate((("u", "y"), ("v", "x"))):
            path = os.path.join(run["folder"], f"ghia_{line}.csv")
            if not os.path.exists(path):
                continue
            g = sorted(read_rows(path), key=lambda r: float(r[coord]))
            s = [float(r[coord]) for r in g]
            if not ghia_drawn[i]:
                ax_col[i].plot(s, [float(r[f"{line}_ghia"]) for r in g], "ko", ms=3, label="Ghia")
                ghia_drawn[i] = True
            ax_col[i].plot(s, [float(r[f"{line}_sph"]) for r in g], "-", color=colours[label_of(run)],
                           label=label_of(run))


def profile_figure(runs, label_of, title, path):
    fig, ax = plt.subplots(2, len(SCHEMES), figsize=(4 * len(SCHEMES), 7), squeeze=False)
    labels = sorted({label_of(r) for r in runs})
    colours = {label: f"C{k}" for k, label in enumerate(labels)}
    for j, scheme in enumerate(SCHEMES):
        profiles([ax[0][j], ax[1][j]], [r for r in runs if r["scheme"] == scheme], label_of, colours)
        ax[0][j].set_title(scheme)
        ax[0][j].set_xlabel("y (u on x = 0.5)")
        ax[1][j].set_xlabel("x (v on y = 0.5)")
        ax[0][j].legend(fontsize=7)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def support_figure(runs, path):
    """Nearest-neighbour histograms and u on x = 0.5 of each run, labelled kernel and support radius."""
    def label(r):
        radius = r["h"] * (3 if r["kernel"] == "quintic_spline" else 2)
        return f"{r['kernel']}, h/dx = {r['h']:.3g}, support {radius:.3g} dx"
    schemes = [s for s in SCHEMES if any(r["scheme"] == s for r in runs)]
    fig, ax = plt.subplots(2, len(schemes), figsize=(5 * len(schemes), 7), squeeze=False)
    for j, scheme in enumerate(schemes):
        mine = sorted((r for r in runs if r["scheme"] == scheme), key=label)
        for k, run in enumerate(mine):
            _, hist = close_pairs(run["folder"])
            if hist:
                total = sum(int(r["count"]) for r in hist)
                ax[0][j].step([float(r["r_over_dx_lo"]) for r in hist], [int(r["count"]) / total for r in hist],
                              where="post", color=f"C{k}", label=label(run))
        for k, run in enumerate(mine):
            g = sorted(read_rows(os.path.join(run["folder"], "ghia_u.csv")), key=lambda r: float(r["y"]))
            if k == 0:
                ax[1][j].plot([float(r["y"]) for r in g], [float(r["u_ghia"]) for r in g], "ko", ms=3, label="Ghia")
            ax[1][j].plot([float(r["y"]) for r in g], [float(r["u_sph"]) for r in g], "-", color=f"C{k}", label=label(run))
        ax[0][j].set_title(scheme)
        ax[0][j].set_xlabel("nearest-neighbour distance / dx")
        ax[1][j].set_xlabel("y (u on x = 0.5)")
        ax[0][j].legend(fontsize=6)
        ax[1][j].legend(fontsize=6)
    ax[0][0].set_ylabel("share of particles")
    fig.suptitle("Cavity Re = 1000, N = 3600: Morris's and Wendland's kernels at equal support radii")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def write_rows(rows, path):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in r.items()})
    for r in rows:
        print(" ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}" for k, v in r.items()))


def support_study(folder, out):
    runs = runs_of(folder, "support")
    if not runs:
        sys.exit(f"plot.py: no runs in {folder}")
    write_rows([measure(run, "support")[0] for run in runs], os.path.join(out, "support.csv"))
    support_figure(runs, os.path.join(out, "support.png"))


def main():
    args = sys.argv[1:]
    if args and args[0] == "--support":
        if len(args) < 2:
            sys.exit(__doc__)
        out = args[2] if len(args) > 2 else os.path.join(HERE, "measured")
        os.makedirs(out, exist_ok=True)
        support_study(args[1], out)
        return
    if len(args) < 3:
        sys.exit(__doc__)
    steady, kernels, smoothing = args[0:3]
    out = args[3] if len(args) > 3 else os.path.join(HERE, "measured")
    os.makedirs(out, exist_ok=True)
    base = runs_of(steady, "steady")
    kernel_runs = base + runs_of(kernels, "kernels")
    h_runs = base + runs_of(smoothing, "smoothing_length")
    rows, series = [], {}
    for study, runs in (("kernels", kernel_runs), ("smoothing_length", h_runs)):
        for run in runs:
            row, ts = measure(run, study)
            rows.append(row)
            series[(study, run["scheme"], run["kernel"], run["h"])] = ts
    if not rows:
        sys.exit(f"plot.py: no runs in {steady}, {kernels} or {smoothing}")

    profile_figure(kernel_runs, lambda r: r["kernel"], "Cavity Re = 1000, N = 3600, h = 2 dx: kernels (Szewc Fig. 5)",
                   os.path.join(out, "profiles_kernels.png"))
    profile_figure(h_runs, lambda r: f"h/dx = {r['h']:g}", "Cavity Re = 1000, N = 3600, Wendland: h/dx (Szewc Fig. 8)",
                   os.path.join(out, "profiles_smoothing_length.png"))

    fig, ax = plt.subplots(1, len(SCHEMES), figsize=(4 * len(SCHEMES), 3.5), squeeze=False)
    for j, scheme in enumerate(SCHEMES):
        for run in kernel_runs:
            if run["scheme"] != scheme:
                continue
            _, hist = close_pairs(run["folder"])
            if hist:
                lo = [float(r["r_over_dx_lo"]) for r in hist]
                total = sum(int(r["count"]) for r in hist)
                ax[0][j].step(lo, [int(r["count"]) / total for r in hist], where="post", label=run["kernel"])
        ax[0][j].set_title(scheme)
        ax[0][j].set_xlabel("nearest-neighbour distance / dx")
        ax[0][j].legend(fontsize=7)
    ax[0][0].set_ylabel("share of particles")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "nn_histogram.png"), dpi=110)

    fig, ax = plt.subplots(2, 2, figsize=(10, 6), squeeze=False)
    for j, (study, key) in enumerate((("kernels", 2), ("smoothing_length", 3))):
        for (s, scheme, kernel, h), ts in sorted(series.items()):
            if s != study or scheme != "wcsph":
                continue
            label = kernel if study == "kernels" else f"h/dx = {h:g}"
            t = [float(r["t"]) for r in ts]
            ax[0][j].plot(t, [float(r["density_mean"]) for r in ts], label=label)
            ax[1][j].plot(t, [float(r["density_rms"]) for r in ts], label=label)
        ax[0][j].set_title(f"WCSPH, {study.replace('_', ' ')}")
        ax[0][j].set_ylabel("density mean / rho0")
        ax[1][j].set_ylabel("density r.m.s.")
        ax[1][j].set_xlabel("t")
        ax[0][j].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "density.png"), dpi=110)
    write_rows(rows, os.path.join(out, "results.csv"))


if __name__ == "__main__":
    main()
