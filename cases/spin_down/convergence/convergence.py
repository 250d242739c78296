#!/usr/bin/python3
"""Spatial convergence of the spin-down (Cummins & Rudman 1999 §3.4, Tables I-III).

usage: convergence.py BATCH_DIR [--label NAME] [--paper table1|table3|table2|none] [--times 1 2 3 4 5]
                      [--periodic 1.0]   (doubly periodic box of that period: minimum-image interpolation)

BATCH_DIR is the output of `arksph batch` over three lattices (coarse to fine). For each pair of
consecutive lattices, the velocities of the finer run are interpolated onto the coarser run's
particles with the quartic spline (C&R eq. 6) at the finer run's h, Shepard-normalised
(sum_b V_b u_b W_ab / sum_b V_b W_ab, V_b = m_b / rho_b; the normalisation stands in for the wall
images C&R do not describe), and
    L1 = mean_a |u_a - u~(x_a)|,   L2 = sqrt(mean_a |u_a - u~(x_a)|^2)
over the coarse particles. The rate is Q = log(E_coarse / E_fine) / log(dx_coarse / dx_middle)
... with E_coarse the (coarse, middle) error and E_fine the (middle, fine) error, as C&R's Table I
reads (t = 1: L1 1.043e-3 and 3.885e-4 give Q = 1.46 with dx ratio 53/27).
Writes BATCH_DIR/convergence.md (markdown, beside the paper's numbers) and convergence.csv.
Needs numpy and scipy; the frames are read by scripts/vtp_frames.py (no VTK).
"""
import argparse
import csv
import json
import math
import os
import re
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "scripts"))
import vtp_frames  # noqa: E402  (frames and read_vtp; main() has its own `frames`)

# C&R Tables I-III: t -> (L1 coarse, L2 coarse, L1 fine, L2 fine, Q L1, Q L2); scales in the headers.
PAPER = {
    "table1": {"pairs": ("27^2-53^2", "53^2-105^2"), "scale": (1e-3, 1e-4), "rows": {
        1: (1.043, 1.758, 3.885, 6.866, 1.46, 1.39), 2: (1.050, 1.761, 3.837, 6.201, 1.49, 1.55),
        3: (0.916, 1.547, 3.993, 6.586, 1.23, 1.27), 4: (0.866, 1.413, 4.112, 6.566, 1.11, 1.14),
        5: (0.807, 1.342, 4.183, 6.397, 0.97, 1.10)}},
    "table2": {"pairs": ("32^2-64^2", "64^2-128^2"), "scale": (1e-3, 1e-3), "rows": {
        1: (6.991, 8.762, 2.956, 3.824, 1.24, 1.20), 2: (5.694, 7.332, 2.541, 3.301, 1.16, 1.15),
        3: (4.397, 5.902, 2.126, 2.778, 1.05, 1.09), 4: (3.100, 4.472, 1.711, 2.255, 0.86, 0.99),
        5: (1.863, 3.042, 1.296, 1.732, 0.52, 0.81)}},
    "table3": {"pairs": ("27^2-50^2", "50^2-88^2"), "scale": (1e-3, 1e-4), "rows": {
        1: (0.723, 1.286, 2.670, 5.050, 1.72, 1.61), 2: (0.768, 1.285, 2.520, 4.500, 1.92, 1.81),
        3: (0.803, 1.338, 2.913, 4.771, 1.75, 1.78), 4: (0.930, 1.534, 3.350, 5.162, 1.76, 1.89),
        5: (0.983, 1.600, 3.631, 5.490, 1.72, 1.84)}},
}


def quartic(q):
    """C&R eq. 6 without the constant (Shepard normalisation cancels it)."""
    f = np.where(q < 2.5, (2.5 - q) ** 4, 0.0)
    f -= np.where(q < 1.5, 5 * (1.5 - q) ** 4, 0.0)
    f += np.where(q < 0.5, 10 * (0.5 - q) ** 4, 0.0)
    return f


def read_frame(run_dir, t):
    """Positions, velocities, volumes of the frame at time t (from particles.pvd)."""
    for ts, path in vtp_frames.frames(run_dir):
        if abs(ts - t) < 1e-9:
            a = vtp_frames.read_vtp(path)
            return a["Points"][:, :2], a["velocity"][:, :2], a["mass"] / a["density"]
    return None


def run_info(run_dir):
    s = json.load(open(os.path.join(run_dir, "summary.json")))
    scene = s.get("scene_resolved") or {}
    return s


def spacing_and_h(run_dir):
    """dx and h from the resolved scene written in the run header (run.log) or summary.json."""
    log = open(os.path.join(run_dir, "run.log")).read()
    m = re.search(r"dx ([0-9.eE+-]+), h ([0-9.eE+-]+)", log)
    return float(m.group(1)), float(m.group(2))


def interp_error(coarse, fine, h_fine, period=0.0):
    """period > 0: a doubly periodic box [0, period)^2 (minimum-image distances)."""
    xc, uc, _ = coarse
    xf, uf, vf = fine
    if period > 0:
        xc, xf = np.mod(xc, period), np.mod(xf, period)
    tree = cKDTree(xf, boxsize=period if period > 0 else None)
    err = np.empty(len(xc))
    for a, nbrs in enumerate(tree.query_ball_point(xc, 2.5 * h_fine)):
        nbrs = np.asarray(nbrs, dtype=int)
        if len(nbrs) == 0:  # no finer particle within reach (a run gone unstable): the error is |u|
            err[a] = np.linalg.norm(uc[a])
            continue
        d = xf[nbrs] - xc[a]
        if period > 0:
            d -= period * np.round(d / period)
        w = vf[nbrs] * quartic(np.linalg.norm(d, axis=1) / h_fine)
        ui = (w[:, None] * uf[nbrs]).sum(axis=0) / w.sum()
        err[a] = np.linalg.norm(uc[a] - ui)
    return err.mean(), math.sqrt((err ** 2).mean())


def grown(run_dir, t):
    """True when the run's max speed at t exceeds that of the previous output (timeseries.csv): the
    spin-down only decays, so the run has gone unstable by t."""
    path = os.path.join(run_dir, "timeseries.csv")
    if not os.path.exists(path):
        return False
    rows = list(csv.DictReader(open(path)))
    for prev, cur in zip(rows, rows[1:]):
        if abs(float(cur["t"]) - t) < 1e-9:
            return float(cur["max_speed"]) > float(prev["max_speed"])
    return False


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("batch_dir")
    ap.add_argument("--label", default="")
    ap.add_argument("--paper", default="table1", choices=["table1", "table2", "table3", "none"])
    ap.add_argument("--times", type=float, nargs="+", default=[1, 2, 3, 4, 5])
    ap.add_argument("--periodic", type=float, default=0.0, help="period of a doubly periodic box (0: walls)")
    a = ap.parse_args()
    runs = []
    with open(os.path.join(a.batch_dir, "batch.csv")) as f:
        for row in csv.DictReader(f):
            d = os.path.join(a.batch_dir, row["run"])
            dx, h = spacing_and_h(d)
            if os.path.exists(os.path.join(d, "particles.pvd")):
                runs.append((dx, h, d, row["status"]))
    runs.sort(reverse=True)  # coarse to fine
    if len(runs) < 2:
        sys.exit("convergence.py: expected two or three runs, found %d" % len(runs))
    n = [round(1 / r[0]) for r in runs]
    rows = []  # (t, e1, e2 or None, q or None); a run that stopped early (e.g. interrupted) leaves gaps
    for t in a.times:
        frames = [read_frame(r[2], t) for r in runs]
        if frames[1] is None:
            continue
        e1 = interp_error(frames[0], frames[1], runs[1][1], a.periodic) if frames[0] is not None else None
        e2 = q = None
        if len(runs) > 2 and frames[2] is not None:
            e2 = interp_error(frames[1], frames[2], runs[2][1], a.periodic)
            ratio = math.log(runs[0][0] / runs[1][0])
            q = [math.log(e1[k] / e2[k]) / ratio for k in range(2)] if e1 else None
        if e1 is None and e2 is None:
            continue
        rows.append((t, e1, e2, q))
    n3 = n[2] if len(n) > 2 else 0
    out_csv = os.path.join(a.batch_dir, "convergence.csv")
    with open(out_csv, "w") as f:
        f.write("t,L1_%d_%d,L2_%d_%d,L1_%d_%d,L2_%d_%d,Q_L1,Q_L2\n" % (n[0], n[1], n[0], n[1], n[1], n3, n[1], n3))
        for t, e1, e2, q in rows:
            f.write("%g,%s,%s,%s,%s,%s,%s\n" % (t, *(("%.6e" % e1[0], "%.6e" % e1[1]) if e1 else ("", "")),
                                               *(("%.6e" % e2[0], "%.6e" % e2[1]) if e2 else ("", "")),
                                                   *(("%.4f" % q[0], "%.4f" % q[1]) if q else ("", ""))))
    md = ["### %s" % (a.label or a.batch_dir), "",
          "Lattices %s; h = %s. L1 / L2 velocity errors (×10⁻³), rates Q%s; "
          "— where a run did not reach t; † after t where a run of the pair has gone unstable (its maximum speed "
          "grew since the previous output)." % (", ".join("%d²" % k for k in n), ", ".join("%.4g" % r[1] for r in runs),
                                              "; C&R's values in brackets" if a.paper != "none" else ""), "",
          "| t | L1 (%d²–%d²) | L2 | L1 (%d²–%d²) | L2 | Q L1 | Q L2 |" % (n[0], n[1], n[1], n3),
          "|---|---|---|---|---|---|---|"]
    paper = PAPER.get(a.paper)
    for t, e1, e2, q in rows:
        p = paper["rows"].get(int(round(t))) if paper and abs(t - round(t)) < 1e-9 else None
        sc1, sc2 = (paper["scale"] if paper else (1, 1))

        def cell(e, k, scale):
            if e is None:
                return "—" + (" [%.3f]" % (p[k] * scale * 1e3) if p else "")
            return "%.3f" % (e[k % 2] * 1e3) + (" [%.3f]" % (p[k] * scale * 1e3) if p else "")

        def rate(k):
            return ("%.2f" % q[k] if q else "—") + (" [%.2f]" % p[4 + k] if p else "")
        bad = [grown(r[2], t) for r in runs]
        mark = "†" if any(bad) else ""
        md.append("| %g%s | %s | %s | %s | %s | %s | %s |" % (
            t, mark, cell(e1, 0, sc1), cell(e1, 1, sc1), cell(e2, 2, sc2), cell(e2, 3, sc2), rate(0), rate(1)))
    text = "\n".join(md) + "\n"
    open(os.path.join(a.batch_dir, "convergence.md"), "w").write(text)
    print(text)


if __name__ == "__main__":
    main()
