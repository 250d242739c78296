#!/usr/bin/python3
"""Transverse drift of particle rows in a Poiseuille run (Basa et al. 2008 section 6.1.4, Fig. 7).

    drift.py RUN_DIR U0          prints t, kinetic energy / steady value, and the drifts below

Basa separate two transverse motions of the particles that start in one lattice row: the row
moving as a whole (an oscillation that stays below 0.1-0.5 % of the spacing), and a relative drift
of neighbours out of the row, which grows exponentially and announces the failure. From the frames
of a run (particles.pvd; every frame must hold the particle ids) this measures, in units of the
initial spacing dx:
  pair_drift      |y_a - y_b| of one representative pair: the first two neighbours (in x) of the
                  row nearest y = 1/4 of the channel (between wall and centreline), as Basa's
                  single pair;
  max_pair_drift  the largest |y_a - y_b| over every pair of neighbours in every row (the last and
                  first particle of a row are neighbours across the periodic sides);
  rms_pair_drift  the r.m.s. of |y_a - y_b| over those pairs;
  max_row_shift   the largest |mean y of a row - its initial y|: the motion of rows as a whole.
and the kinetic energy (timeseries.csv) over the steady value of the parabolic profile with
centreline speed U0 on the unit channel of density 1: (1/2) (8/15) U0^2.
"""
import csv
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
from vtp_frames import frames, read_vtp  # noqa: E402

COLUMNS = ["t", "ke_ratio", "pair_drift", "max_pair_drift", "rms_pair_drift", "max_row_shift"]


def rows_and_pairs(points, ids):
    """The rows of the first frame (particles whose y agree to 1e-9) as id arrays, each sorted in x,
    and their neighbour pairs (periodic in x), as two aligned id arrays."""
    y = np.round(points[:, 1], 9)
    rows = []
    for level in np.unique(y):
        members = np.where(y == level)[0]
        rows.append(ids[members[np.argsort(points[members, 0])]])
    a = np.concatenate([r for r in rows if len(r) > 1])
    b = np.concatenate([np.roll(r, -1) for r in rows if len(r) > 1])
    return rows, a, b


def drift_series(run, u0):
    """Rows of COLUMNS, one per frame of the run folder."""
    fr = frames(run)
    first = read_vtp(fr[0][1])
    p0, ids0 = first["Points"], first["id"]
    rows, pa, pb = rows_and_pairs(p0, ids0)
    y0_by_id = dict(zip(ids0.tolist(), p0[:, 1]))
    levels = np.array([y0_by_id[int(r[0])] for r in rows])
    dx = float(np.min(np.diff(np.sort(levels))))
    quarter = rows[int(np.argmin(np.abs(levels - 0.25)))]
    with open(Path(run) / "timeseries.csv") as f:
        series = [(float(r["t"]), float(r["kinetic_energy"])) for r in csv.DictReader(f)]
    ts = np.array([t for t, _ in series])
    ke_steady = 0.5 * (8.0 / 15.0) * u0 * u0
    out = []
    for t, path in fr:
        d = read_vtp(path)
        order = np.argsort(d["id"])
        sorted_ids = d["id"][order]
        y_of = lambda ids: d["Points"][order[np.searchsorted(sorted_ids, ids)], 1]  # noqa: E731
        gaps = np.abs(y_of(pa) - y_of(pb)) / dx
        shift = max(abs(float(np.mean(y_of(r))) - lvl) for r, lvl in zip(rows, levels)) / dx
        pair = abs(float(y_of(quarter[:1])[0] - y_of(quarter[1:2])[0])) / dx
        ke = series[int(np.argmin(np.abs(ts - t)))][1]  # the output row of this frame
        out.append([t, ke / ke_steady, pair, float(gaps.max()),
                    float(np.sqrt(np.mean(gaps ** 2))), shift])
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    w = csv.writer(sys.stdout)
    w.writerow(COLUMNS)
    for row in drift_series(sys.argv[1], float(sys.argv[2])):
        w.writerow(["%.6g" % v for v in row])


if __name__ == "__main__":
    main()
