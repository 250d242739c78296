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
the lattice, across it it reads the pressure 0.88 dx inside the wall at h = 2 dx (the
kernel-weighted centre of the particles). The curve is drawn on the wall line (PySPH's probe point); the table also gives the
reading half a spacing inside the wall (the line of the first particles' centres at t = 0), which
reads the pressure 1.07 dx inside. The right wall is the box's max x (summary.json's resolved
scene), the spacing the first frame's row spacing.

Draws p/(rho g H) against t sqrt(g/H) with the measurement (buchner_2002.csv): the whole run with
the pressure axis cut at YLIM, and the impact at full scale. Prints a table for the measurement
and each run: the first frame's time at which a particle is within dx of the right wall (the
surge's arrival; not measured in the experiment), the impact time (the first time the probe reads
IMPACT_LEVEL or more after t sqrt(g/H) = 1.5), the largest pressure within 1 of it, the means over
the RISE after the impact, the PLATEAU and the measurement's SECOND rise (the plunging jet's
return), and the largest pressure over SECOND_MAX. The measurement's figures are from its
digitised points (sorted by time); the means are by the trapezoidal rule on the samples.
"""
import csv
import sys
import tomllib
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "python"))

H, G, RHO = 1.0, 1.0, 1.0
PROBE_Y = 0.2 * H
IMPACT_LEVEL = 0.25          # p / (rho g H): above the measurement's scatter before the impact (|p| <= 0.16)
RISE = (2.6, 3.5)            # t sqrt(g/H): the measured rise and peak after the impact
PLATEAU = (3.5, 5.0)         # t sqrt(g/H): after the impact's peak, before the jet's return
SECOND = (5.5, 6.2)          # t sqrt(g/H): the measured second rise (the plunging jet's return)
SECOND_MAX = (5.3, 6.5)      # t sqrt(g/H): where the largest pressure of the second rise is sought
YLIM = (-0.5, 1.5)           # p / (rho g H): the whole-run panel


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
    """The probe's readings of a run folder: {"t": t sqrt(g/H), "wall": p/(rho g H) on the wall line,
    "inside": p/(rho g H) half a spacing inside it, "dx": the spacing, "arrival": the first frame's
    t sqrt(g/H) at which a particle is within dx of the right wall (nan if none)}."""
    from arksph.readers import read_run

    run = read_run(run_dir, sort_by_id=False)
    if not run.summary or "resolved_scene" not in run.summary:
        sys.exit("%s: no summary.json with the resolved scene" % run_dir)
    wall = float(tomllib.loads(run.summary["resolved_scene"])["domain"]["max"][0])
    dx = lattice_spacing(run.frame(0))
    t, on_wall, inside, arrival = [], [], [], np.nan
    for f in run.frames:
        volumes = f["mass"] / f["density"]
        t.append(f["time"] * np.sqrt(G / H))
        on_wall.append(shepard(f["Points"], f["pressure"], volumes, f["h"], (wall, PROBE_Y))[0])
        inside.append(shepard(f["Points"], f["pressure"], volumes, f["h"], (wall - 0.5 * dx, PROBE_Y))[0])
        if np.isnan(arrival) and f["Points"][:, 0].max() >= wall - dx:
            arrival = t[-1]
    scale = RHO * G * H
    return {"t": np.array(t), "wall": np.array(on_wall) / scale, "inside": np.array(inside) / scale,
            "dx": dx, "arrival": arrival}


def measured():
    with open(HERE / "buchner_2002.csv") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    t = np.array([float(r["t_sqrt_g_H"]) for r in rows])
    p = np.array([float(r["p_rho_g_H"]) for r in rows])
    order = np.argsort(t, kind="stable")
    return t[order], p[order]


def window_mean(t, p, a, b):
    """The mean of p over [a, b] by the trapezoidal rule on the samples (linear between them)."""
    grid = np.linspace(a, b, 1001)
    trapezoid = getattr(np, "trapezoid", None) or np.trapz  # NumPy 2 renamed it
    return float(trapezoid(np.interp(grid, t, p), grid) / (b - a))


def figures(t, p):
    """(impact time, its peak, RISE mean, PLATEAU mean, SECOND mean, SECOND_MAX peak) of a series
    sorted by time; nan where it does not reach."""
    after = (t > 1.5) & (p >= IMPACT_LEVEL)
    impact = t[after][0] if np.any(after) else np.nan
    peak = p[(t >= impact) & (t <= impact + 1.0)].max() if np.any(after) else np.nan
    means = [window_mean(t, p, *w) if t[-1] >= w[1] else np.nan for w in (RISE, PLATEAU, SECOND)]
    second = p[(t >= SECOND_MAX[0]) & (t <= SECOND_MAX[1])].max() if t[-1] >= SECOND_MAX[1] else np.nan
    return (impact, peak, *means, second)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = Path(sys.argv[1])
    runs = [arg.split("=", 1) for arg in sys.argv[2:]]
    t_exp, p_exp = measured()
    fig, (whole, impact) = plt.subplots(1, 2, figsize=(12, 4.2), gridspec_kw={"width_ratios": [2, 1]})
    rows = [("Buchner 2002", np.nan, figures(t_exp, p_exp), None)]
    for label, run_dir in runs:
        r = probe_series(run_dir)
        for ax in (whole, impact):
            ax.plot(r["t"], r["wall"], "-", lw=0.7, label=label)
        rows.append((label, r["arrival"], figures(r["t"], r["wall"]), figures(r["t"], r["inside"])))
    for ax in (whole, impact):
        ax.plot(t_exp, p_exp, "o", mfc="none", color="k", ms=4, label="Buchner 2002 (Zhou et al. 1999)")
        ax.set_xlabel("t sqrt(g/H)")
    whole.set_ylabel("p / (rho g H) at the right wall, y = 0.2 H")
    whole.set_xlim(0, 7.4)
    whole.set_ylim(*YLIM)
    whole.set_title("cut at p = %g rho g H" % YLIM[1], fontsize=8)
    impact.set_xlim(2.3, 3.3)
    impact.set_title("the impact, full scale", fontsize=8)
    whole.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    names = ("arrival", "impact", "peak", "rise", "plateau", "second", "2nd max")
    print("%-16s" % "" + "".join("%9s" % n for n in names))
    for label, arrival, on_wall, inside in rows:
        print("%-16s" % label + "%9.3f" % arrival + "".join("%9.3f" % v for v in on_wall))
        if inside is not None:
            print("%-16s" % "  dx/2 inside" + "%9s" % "" + "".join("%9.3f" % v for v in inside))

if __name__ == "__main__":
    main()
