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
                    55-56), Szewc et al. 2012 Fig. 14;
  rt_streamlines.png  streamlines at t = 5 per run (particle velocities interpolated onto a 25 x 50
                    grid) and of the OpenFOAM reference where bench/openfoam_rt holds its velocity
                    (openfoam_rt_n100_velocity_t5.csv), C&R Fig. 12;
  rt_interface_t3.png, rt_interface_t3.csv  the particles within 0.06 of the interface at t = 3
                    (C&R Fig. 13) and, for them and for the rest, the mean nearest-neighbour distance
                    and the share of particles whose nearest neighbour is closer than 0.6 dx (dx from
                    the particle count on the 1 x 2 box): the clumping at the interface.
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


def box_axes(ax):
    """The 1 x 2 box, to scale, without ticks."""
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 2)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])


def nearest(run, t):
    fr = frames(run)
    k = min(range(len(fr)), key=lambda i: abs(fr[i][0] - t))
    return k, fr[k]


def grid_velocity(points, velocity):
    from scipy.interpolate import griddata
    gx, gy = np.meshgrid((np.arange(25) + 0.5) / 25, (np.arange(50) + 0.5) / 25)
    out = []
    for k in range(2):
        v = griddata(points, velocity[:, k], (gx, gy), method="linear")
        out.append(np.where(np.isnan(v), griddata(points, velocity[:, k], (gx, gy), method="nearest"), v))
    return out


def streamline_panel(ax, u, v, title):
    g = (np.arange(25) + 0.5) / 25
    ax.streamplot(g, (np.arange(50) + 0.5) / 25, u, v, density=(0.8, 1.6), color="k", linewidth=0.5, arrowsize=0.5)
    box_axes(ax)
    ax.set_title(title, fontsize=8)


def streamlines_figure(runs, out):
    ref = REFERENCE.parent / "openfoam_rt_n100_velocity_t5.csv"
    panels = []
    if ref.exists():
        with open(ref) as f:
            rows = list(csv.DictReader(f))
        panels.append(("OpenFOAM 100 x 200, t = 5", np.array([float(r["u"]) for r in rows]).reshape(50, 25),
                       np.array([float(r["v"]) for r in rows]).reshape(50, 25)))
    for label, run in runs:
        _, (tf, vtp) = nearest(run, 5.0)
        d = read_vtp(vtp)
        u, v = grid_velocity(d["Points"][:, :2], d["velocity"])
        panels.append(("%s, t = %g" % (label, tf), u, v))
    fig, axes = plt.subplots(1, len(panels), figsize=(2.2 * len(panels), 4.4), squeeze=False)
    for ax, (title, u, v) in zip(axes[0], panels):
        streamline_panel(ax, u, v, title)
    fig.tight_layout()
    fig.savefig(out / "rt_streamlines.png", dpi=100)


def interface_clumping(runs, out, t=3.0, band=0.06):
    from scipy.spatial import cKDTree
    fig, axes = plt.subplots(1, len(runs), figsize=(2.2 * len(runs), 4.4), squeeze=False)
    rows = []
    for ax, (label, run) in zip(axes[0], runs):
        k, (tf, vtp) = nearest(run, t)
        d = read_vtp(vtp)
        p = d["Points"][:, :2]
        dx = np.sqrt(2.0 / len(p))
        icsv = Path(run) / ("interface_%06d.csv" % k)
        if not icsv.exists():
            continue
        with open(icsv) as f:
            seg = np.array([[float(r["x0"]), float(r["y0"]), float(r["x1"]), float(r["y1"])] for r in csv.DictReader(f)])
        s = np.linspace(0, 1, 8)[:, None, None]
        samples = (seg[None, :, :2] * (1 - s) + seg[None, :, 2:] * s).reshape(-1, 2)
        near = cKDTree(samples).query(p)[0] < band
        nn = cKDTree(p).query(p, k=2)[0][:, 1] / dx
        for where, mask in (("interface", near), ("rest", ~near)):
            rows.append(dict(run=label, t=tf, region=where, particles=int(mask.sum()),
                             mean_nn_over_dx=float(nn[mask].mean()), share_nn_below_0_6dx=float((nn[mask] < 0.6).mean())))
        ax.scatter(p[near, 0], p[near, 1], c=d["phase"][near], cmap="coolwarm", s=1.2, linewidths=0, vmin=0, vmax=1)
        box_axes(ax)
        ax.set_title("%s, t = %g" % (label, tf), fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "rt_interface_t3.png", dpi=130)
    with open(out / "rt_interface_t3.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in r.items()})
            print(" ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}" for k, v in r.items()))


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
            box_axes(ax)
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
    streamlines_figure(runs, out)
    interface_clumping(runs, out)


if __name__ == "__main__":
    main()
