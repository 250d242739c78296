#!/usr/bin/python3
"""Dam break (Zhou et al. 1999): the pressure at a probe on the right wall against Buchner's measurement.

    probe.py OUT.png LABEL=RUN_DIR [LABEL=RUN_DIR ...]

For each run (H = g = rho = 1 as in scene.toml) and each frame, the pressure at the probe on the
right wall, 0.2 H above the floor, interpolated by a Shepard (kernel-normalised) sum over the fluid
particles within the kernel's support of the probe point,

    p(r) = sum_b V_b p_b W(r - r_b, h_b) / sum_b V_b W(r - r_b, h_b),   V_b = m_b / rho_b,

with the Wendland C2 kernel (support 2h) and each particle's h from the frame (the frames carry
"h", "mass", "density" and "pressure"). A probe whose support holds no fluid particle reads 0 (it is
in the air). The frames hold no wall particles, so the support of a point on the wall is half empty
and the sum is a mean over the fluid side only: along the wall it is exact for a linear field on
the lattice, across it it reads the pressure 0.88 dx inside the wall (the kernel-weighted centre of
the particles). The curve is drawn on the wall line (PySPH's probe point); the table also gives the
reading half a spacing inside the wall (the line of the first particles' centres at t = 0), which
reads the pressure 1.07 dx inside. The right wall is the box's max x from summary.json, the
spacing the first frame's row spacing.

Draws p/(rho g H) against t sqrt(g/H) with the measurement (buchner_2002.csv) and prints a table:
the impact time (the first time the pressure reaches IMPACT_LEVEL after t sqrt(g/H) = 1.5), the
largest pressure within 1 of it, the mean over the plateau 3.5-5.0 and the largest pressure of the
second impact (5.3-6.5), for the measurement and each run.
"""
import csv
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "python"))

H, G, RHO = 1.0, 1.0, 1.0
PROBE_Y = 0.2 * H
IMPACT_LEVEL = 0.25          # p / (rho g H): above the measurement's scatter before the impact (|p| <= 0.16)
PLATEAU = (3.5, 5.0)         # t sqrt(g/H): after the impact's peak, before the jet's return
SECOND = (5.3, 6.5)          # t sqrt(g/H): the second impact (the plunging jet's return)


def wendland_c2(r, h):
    """The 2D Wendland C2 kernel W(r, h), support 2h: 7/(4 pi h^2) (1 - q/2)^4 (2q + 1), q = r/h."""
    q = r / h
    s = np.clip(1.0 - 0.5 * q, 0.0, None)
    return 7.0 / (4.0 * np.pi * h * h) * s ** 4 * (2.0 * q + 1.0)


def shepard(points, values, volumes, h, probe):
    """The Shepard interpolation of `values` at `probe` (x, y) over the particles at `points` (n, 2
    or 3; only x and y are read) with volumes V_b and smoothing lengths h_b (arrays, or h a number).
    Returns (value, number of particles within the support); (0, 0) when none is within it."""
    d = np.hypot(points[:, 0] - probe[0], points[:, 1] - probe[1])
    h = np.broadcast_to(np.asarray(h, dtype=float), d.shape)
    near = d < 2.0 * h
    if not np.any(near):
        return 0.0, 0
    w = volumes[near] * wendland_c2(d[near], h[near])
    return float(np.dot(w, values[near]) / w.sum()), int(near.sum())


def lattice_spacing(frame):
    """The spacing of the lattice in a frame at t = 0: the distance between its first two rows."""
    return float(np.diff(np.unique(np.round(frame["Points"][:, 1], 9)))[0])


def probe_series(run_dir):
    """(t sqrt(g/H), p/(rho g H) on the wall line, p/(rho g H) half a spacing inside it, dx)."""
    from arksph.readers import read_run

    run = read_run(run_dir, sort_by_id=False)
    wall = float(run.summary["domain"]["max"][0]) if run.summary and "domain" in run.summary else None
    if wall is None:
        sys.exit("%s: summary.json has no domain.max" % run_dir)
    dx = lattice_spacing(run.frame(0))
    t, on_wall, inside = [], [], []
    for f in run.frames:
        volumes = f["mass"] / f["density"]
        t.append(f["time"] * np.sqrt(G / H))
        inside.append(shepard(f["Points"], f["pressure"], volumes, f["h"], (wall - 0.5 * dx, PROBE_Y))[0])
        on_wall.append(shepard(f["Points"], f["pressure"], volumes, f["h"], (wall, PROBE_Y))[0])
    scale = RHO * G * H
    return np.array(t), np.array(on_wall) / scale, np.array(inside) / scale, dx


def measured():
    with open(HERE / "buchner_2002.csv") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    t = np.array([float(r["t_sqrt_g_H"]) for r in rows])
    p = np.array([float(r["p_rho_g_H"]) for r in rows])
    order = np.argsort(t, kind="stable")
    return t[order], p[order]


def figures(t, p):
    """(impact time, its peak, plateau mean, second peak) of a series; nan where it does not reach."""
    after = (t > 1.5) & (p >= IMPACT_LEVEL)
    impact = t[after][0] if np.any(after) else np.nan
    peak = p[(t >= impact) & (t <= impact + 1.0)].max() if np.isfinite(impact) else np.nan
    plateau = p[(t >= PLATEAU[0]) & (t <= PLATEAU[1])]
    second = p[(t >= SECOND[0]) & (t <= SECOND[1])]
    return (impact, peak, plateau.mean() if plateau.size else np.nan, second.max() if second.size else np.nan)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = Path(sys.argv[1])
    runs = [arg.split("=", 1) for arg in sys.argv[2:]]
    t_exp, p_exp = measured()
    fig, ax = plt.subplots(figsize=(8, 4))
    rows = [("Buchner 2002", figures(t_exp, p_exp), None)]
    for label, run_dir in runs:
        t, on_wall, inside, dx = probe_series(run_dir)
        ax.plot(t, on_wall, "-", lw=0.8, label=label)
        rows.append((label, figures(t, on_wall), figures(t, inside)))
    ax.plot(t_exp, p_exp, "o", mfc="none", color="k", ms=4, label="Buchner 2002 (Zhou et al. 1999)")
    ax.set_xlabel("t sqrt(g/H)")
    ax.set_ylabel("p / (rho g H) at the right wall, y = 0.2 H")
    ax.set_xlim(0, 7.4)
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("%-22s %8s %8s %8s %8s" % ("", "impact", "peak", "plateau", "second"))
    for label, on_wall, inside in rows:
        print("%-22s %8.3f %8.3f %8.3f %8.3f" % ((label,) + on_wall))
        if inside is not None:
            print("%-22s %8.3f %8.3f %8.3f %8.3f" % (("  dx/2 inside",) + inside))


if __name__ == "__main__":
    main()
