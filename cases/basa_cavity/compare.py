#!/usr/bin/env python3
"""Tables and figures of the Basa et al. 2008 cavity runs (arksph batch folders) against the
OpenFOAM solution (bench/openfoam_cavity) and Ghia, Ghia & Shin 1982 (bench/ghia).

usage: compare.py RE RUNS_DIR OUT_DIR

For every run folder in RUNS_DIR (model, correction and pressure reduction read from its
batch_run.txt; a run without the reduction is labelled "<model> (no p_avg)"):
- kinetic energy KE(t) from timeseries.csv against OpenFOAM's, at OpenFOAM's times (every 0.1)
  up to the run's last row: the r.m.s. and largest |KE - KE_FOAM| over those times, and the
  relative difference at the end, all divided by OpenFOAM's KE at the end time;
- centreline u(y) on x = 0.5 and v(x) on y = 0.5 at the run's last output (ghia_u.csv,
  ghia_v.csv: arksph's values at Ghia's 15 interior points of each line): r.m.s. difference from
  Ghia (arksph's own ghia_*_rms) and from OpenFOAM's 200^2 profile interpolated linearly to Ghia's
  points;
- wall time and status from summary.json;
- bursts: the first output time at which KE exceeds BURST_KE (0.06, about 1.4 times OpenFOAM's
  KE at Re = 1000 and 3.4 times at Re = 100, above anything a run near the solution reaches), the
  largest KE with its time, and the largest particle speed of the outputs.
Writes OUT_DIR/re<RE>_results.csv, ke_re<RE>.png, centrelines_re<RE>.png (profiles from the
last frame, interpolated as arksph interpolates for Ghia: Shepard-normalised Wendland C2 at
h = 1.3 dx over the fluid particles) and particles_re<RE>.png (the last frames, coloured by speed).
"""
import csv
import glob
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import vtp_frames  # noqa: E402  (frames and read_vtp; main() has its own `frames`)
FOAM = os.path.join(ROOT, "bench", "openfoam_cavity")
GHIA = os.path.join(ROOT, "bench", "ghia")
LETTER = {"direct": "A", "two_pass": "B", "violeau": "C", "cleary": "D", "morris": "E"}
CORRECTIONS = ["none", "shepard", "bonet_lok"]
COLOUR = {"A": "tab:blue", "B": "tab:orange", "C": "tab:green", "D": "tab:red", "E": "tab:purple",
          "E (no p_avg)": "tab:brown"}
END = {100: 20.0, 1000: 80.0}
SPACING = 0.02  # 50 x 50 particles
INTERP_H = 1.3 * SPACING  # arksph's centreline interpolation (src/diagnostics/ghia.cpp)


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def interpolate(xs, ys, x):
    for i in range(len(xs) - 1):
        if xs[i] <= x <= xs[i + 1]:
            w = (x - xs[i]) / (xs[i + 1] - xs[i]) if xs[i + 1] > xs[i] else 0.0
            return ys[i] + w * (ys[i + 1] - ys[i])
    raise ValueError(f"{x} outside [{xs[0]}, {xs[-1]}]")


def foam_series(re, what):
    rows = read_rows(os.path.join(FOAM, f"openfoam_re{re}_n200_{what}.csv"))
    keys = list(rows[0].keys())
    return [float(r[keys[0]]) for r in rows], [float(r[keys[1]]) for r in rows]


def run_keys(folder):
    with open(os.path.join(folder, "batch_run.txt")) as f:
        args = f.read().split()
    keys = {"method.viscosity_model": "morris", "method.kernel_correction": "none"}
    for a in args:
        if "=" in a:
            k, v = a.split("=", 1)
            keys[k] = v
    # A run without Basa's pressure reduction (the scene's default) is labelled apart: "E (no p_avg)".
    reduced = keys.get("method.pressure_reduction", "true") == "true"
    return keys["method.viscosity_model"], keys["method.kernel_correction"], reduced


BURST_KE = 0.06  # a burst: KE above this (docstring)


def measure(re, folder):
    model, corr, reduced = run_keys(folder)
    letter = LETTER.get(model, model) + ("" if reduced else " (no p_avg)")
    row = dict(model=letter, viscosity_model=model, correction=corr)
    ts = read_rows(os.path.join(folder, "timeseries.csv")) if os.path.exists(os.path.join(folder, "timeseries.csv")) else []
    summary_path = os.path.join(folder, "summary.json")
    summary = json.load(open(summary_path)) if os.path.exists(summary_path) else {}
    row["status"] = summary.get("status", "running")
    row["final_time"] = float(summary.get("final_time", ts[-1]["t"] if ts else 0.0))
    row["wall_seconds"] = summary.get("wall_seconds", float("nan"))
    row["steps"] = summary.get("steps", 0)
    row["wall_reflections"] = summary.get("wall_reflections", 0)
    t_sph = [float(r["t"]) for r in ts]
    ke_sph = [float(r["kinetic_energy"]) for r in ts]
    t_foam, ke_foam = foam_series(re, "kinetic_energy")
    ke_end_foam = interpolate(t_foam, ke_foam, END[re])
    diffs = []
    for t, ke in zip(t_sph, ke_sph):
        if t <= t_foam[-1] and math.isfinite(ke):
            diffs.append(ke - interpolate(t_foam, ke_foam, t))
    row["ke_end"] = ke_sph[-1] if ke_sph else float("nan")
    row["ke_end_rel_err"] = (ke_sph[-1] - interpolate(t_foam, ke_foam, t_sph[-1])) / ke_end_foam if ke_sph else float("nan")
    row["ke_rms_rel"] = (sum(d * d for d in diffs) / len(diffs)) ** 0.5 / ke_end_foam if diffs else float("nan")
    row["ke_max_rel"] = max(abs(d) for d in diffs) / ke_end_foam if diffs else float("nan")
    above = [t for t, ke in zip(t_sph, ke_sph) if ke > BURST_KE]
    row["first_ke_above_burst_t"] = above[0] if above else float("nan")
    finite = [(ke, t) for t, ke in zip(t_sph, ke_sph) if math.isfinite(ke)]
    row["ke_largest"], row["ke_largest_t"] = max(finite) if finite else (float("nan"), float("nan"))
    speeds = [float(r["max_speed"]) for r in ts if math.isfinite(float(r["max_speed"]))]
    row["speed_largest"] = max(speeds) if speeds else float("nan")
    for line, coord in (("u", "y"), ("v", "x")):
        path = os.path.join(folder, f"ghia_{line}.csv")
        if not os.path.exists(path) or row["status"] != "ok":
            row[f"{line}_rms_ghia"] = row[f"{line}_rms_foam"] = float("nan")
            continue
        g = read_rows(path)
        fx, fv = foam_series(re, f"{line}_{'x' if line == 'u' else 'y'}0.5")
        d_ghia = [float(r[f"{line}_sph"]) - float(r[f"{line}_ghia"]) for r in g]
        d_foam = [float(r[f"{line}_sph"]) - interpolate(fx, fv, float(r[coord])) for r in g]
        row[f"{line}_rms_ghia"] = (sum(d * d for d in d_ghia) / len(d_ghia)) ** 0.5
        row[f"{line}_rms_foam"] = (sum(d * d for d in d_foam) / len(d_foam)) ** 0.5
    return row, (t_sph, ke_sph)


def wendland_c2(q):
    return (1 - q / 2) ** 4 * (2 * q + 1) if q < 2 else 0.0


def last_frame(folder):
    """Positions and velocities of the last frame particles.pvd lists (None without frames)."""
    if not os.path.exists(os.path.join(folder, "particles.pvd")):
        return None
    listed = vtp_frames.frames(folder)
    if not listed:
        return None
    data = vtp_frames.read_vtp(listed[-1][1])
    return data["Points"], data["velocity"]


def last_frame_profiles(folder, n=101):
    """u(y) on x = 0.5 and v(x) on y = 0.5 from the last frame (None without frames)."""
    frame = last_frame(folder)
    if frame is None:
        return None
    pos, vel = frame
    out = {}
    for line in ("u", "v"):
        s_list, v_list = [], []
        for i in range(n):
            s = i / (n - 1)
            px, py = (0.5, s) if line == "u" else (s, 0.5)
            num = den = 0.0
            for (x, y, _), w3 in zip(pos, vel):
                q = math.hypot(x - px, y - py) / INTERP_H
                if q < 2:
                    w = wendland_c2(q)
                    num += w * (w3[0] if line == "u" else w3[1])
                    den += w
            if den > 0:
                s_list.append(s)
                v_list.append(num / den)
        out[line] = (s_list, v_list)
    return out


def plot_ke(re, series, out):
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2), sharey=True)
    t_foam, ke_foam = foam_series(re, "kinetic_energy")
    for ax, corr in zip(axes, CORRECTIONS):
        ax.plot(t_foam, ke_foam, "k-", lw=2, label="OpenFOAM 200²")
        for (letter, c), (t, ke) in sorted(series.items()):
            if c == corr:
                ax.plot(t, ke, lw=1, color=COLOUR.get(letter), label=f"model {letter}")
        ax.set_title(f"Re = {re}, correction {corr}", fontsize=10)
        ax.set_xlabel("t")
        ax.set_ylim(0, 1.6 * max(ke_foam))
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("kinetic energy")
    for ax in axes:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_particles(re, frames, out):
    """The particles of each run's last frame coloured by speed (Basa Fig. 8 shows velocity vectors):
    one panel per run, by correction (rows of the full matrix) and model."""
    keys = sorted(frames, key=lambda k: (CORRECTIONS.index(k[1]), k[0]))
    ncols = min(5, len(keys))
    nrows = (len(keys) + ncols - 1) // ncols
    fig, axes = plt.subplots(nrows, ncols, figsize=(2.9 * ncols, 2.9 * nrows + 0.4), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for ax, (letter, corr) in zip(axes.flat, keys):
        (pos, vel), status, t = frames[(letter, corr)]
        speed = (vel[:, 0] ** 2 + vel[:, 1] ** 2) ** 0.5
        ax.axis("on")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_aspect("equal")
        ax.scatter(pos[:, 0], pos[:, 1], c=speed, s=1.2, cmap="viridis", vmin=0, vmax=1)
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.set_title(f"{letter}, {corr}: {status}, t = {t:.3g}", fontsize=8)
    fig.suptitle(f"Re = {re}: particles at the last output, coloured by speed (0-1)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=60)
    plt.close(fig)


def plot_centrelines(re, profiles, out):
    fig, axes = plt.subplots(2, 3, figsize=(14, 8.5), sharey="row")
    ghia_u = read_rows(os.path.join(GHIA, "ghia_u_vertical_centerline.csv"))
    ghia_v = read_rows(os.path.join(GHIA, "ghia_v_horizontal_centerline.csv"))
    fu = foam_series(re, "u_x0.5")
    fv = foam_series(re, "v_y0.5")
    for j, corr in enumerate(CORRECTIONS):
        ax_u, ax_v = axes[0][j], axes[1][j]
        ax_u.plot(fu[1], fu[0], "k-", lw=2, label="OpenFOAM 200²")
        ax_u.plot([float(r[f"Re{re}"]) for r in ghia_u], [float(r["y"]) for r in ghia_u], "ks", mfc="none", label="Ghia")
        ax_v.plot(fv[0], fv[1], "k-", lw=2, label="OpenFOAM 200²")
        ax_v.plot([float(r["x"]) for r in ghia_v], [float(r[f"Re{re}"]) for r in ghia_v], "ks", mfc="none", label="Ghia")
        for (letter, c), p in sorted(profiles.items()):
            if c != corr or p is None:
                continue
            ax_u.plot(p["u"][1], p["u"][0], lw=1, color=COLOUR.get(letter), label=f"model {letter}")
            ax_v.plot(p["v"][0], p["v"][1], lw=1, color=COLOUR.get(letter), label=f"model {letter}")
        ax_u.set_title(f"u(y) on x = 0.5, Re = {re}, {corr}", fontsize=10)
        ax_v.set_title(f"v(x) on y = 0.5, Re = {re}, {corr}", fontsize=10)
        ax_u.set_xlabel("u")
        ax_v.set_xlabel("x")
        for ax in (ax_u, ax_v):
            ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("y")
    axes[1][0].set_ylabel("v")
    for ax in axes[0]:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


FIELDS = ["model", "viscosity_model", "correction", "status", "final_time", "ke_end", "ke_end_rel_err", "ke_rms_rel",
          "ke_max_rel", "u_rms_foam", "v_rms_foam", "u_rms_ghia", "v_rms_ghia", "steps", "wall_reflections",
          "wall_seconds", "first_ke_above_burst_t", "ke_largest", "ke_largest_t", "speed_largest"]


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    re, runs, out = int(sys.argv[1]), sys.argv[2], sys.argv[3]
    os.makedirs(out, exist_ok=True)
    rows, series, profiles, frames = [], {}, {}, {}
    for folder in sorted(glob.glob(os.path.join(runs, "*", "batch_run.txt"))):
        folder = os.path.dirname(folder)
        row, s = measure(re, folder)
        rows.append(row)
        series[(row["model"], row["correction"])] = s
        profiles[(row["model"], row["correction"])] = last_frame_profiles(folder) if row["status"] == "ok" else None
        frame = last_frame(folder)
        if frame is not None:
            frames[(row["model"], row["correction"])] = (frame, row["status"], row["final_time"])
    rows.sort(key=lambda r: (r["model"], CORRECTIONS.index(r["correction"])))
    with open(os.path.join(out, f"re{re}_results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in r.items()})
    plot_ke(re, series, os.path.join(out, f"ke_re{re}.png"))
    plot_centrelines(re, profiles, os.path.join(out, f"centrelines_re{re}.png"))
    if frames:
        plot_particles(re, frames, os.path.join(out, f"particles_re{re}.png"))
    print("| model | correction | status (t reached) | KE end rel. err | KE r.m.s. / max | u r.m.s. FOAM / Ghia "
          "| v r.m.s. FOAM / Ghia | reflections | first KE > 0.06 (t) | largest KE (t), largest speed | wall s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['model']} | {r['correction']} | {r['status']} ({r['final_time']:.4g}) | {r['ke_end_rel_err']:+.3f} "
              f"| {r['ke_rms_rel']:.3f} / {r['ke_max_rel']:.3g} | {r['u_rms_foam']:.4f} / {r['u_rms_ghia']:.4f} "
              f"| {r['v_rms_foam']:.4f} / {r['v_rms_ghia']:.4f} | {r['wall_reflections']} "
              f"| {'never' if math.isnan(r['first_ke_above_burst_t']) else format(r['first_ke_above_burst_t'], '.3g')} "
              f"| {r['ke_largest']:.3g} ({r['ke_largest_t']:.3g}), {r['speed_largest']:.3g} "
              f"| {r['wall_seconds']:.0f} |")


if __name__ == "__main__":
    main()
