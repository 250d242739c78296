#!/usr/bin/env python3
"""Reads an icoFoam cavity case written by run.sh and writes three CSVs:

  kinetic energy history: t, kinetic_energy = 1/2 int |u|^2 dA over the unit square (volIntegrate of
      |U|^2 from the kineticEnergy function object, divided by 2 and by the mesh depth). With density
      1 this is arksph's kinetic_energy (sum_a m_a |u_a|^2 / 2, total mass 1) in timeseries.csv.
  u on the vertical centreline x = 0.5 versus y at the end time,
  v on the horizontal centreline y = 0.5 versus x at the end time.

Centreline values are linear interpolations between the two cell columns (rows) whose centres
straddle the line (for an even N: the mean of the two), at each cell-centre height, with the wall
values (0 on the walls, 1 for u on the lid) added at both ends.

usage: extract.py CASE END_TIME DEPTH KE_CSV U_CSV V_CSV
"""
import glob
import os
import sys


def read_vectors(path):
    """The internalField of an ascii volVectorField, as a list of (x, y, z)."""
    with open(path) as f:
        text = f.read()
    body = text[text.index("internalField"):]
    count_at = body.index("List<vector>") + len("List<vector>")
    rest = body[count_at:].lstrip()
    count, rest = rest.split(None, 1)
    count = int(count)
    rest = rest[rest.index("(") + 1:]
    out = []
    pos = 0
    for _ in range(count):
        a = rest.index("(", pos)
        b = rest.index(")", a)
        out.append(tuple(float(v) for v in rest[a + 1:b].split()))
        pos = b + 1
    return out


def time_dir(case, end):
    for d in os.listdir(case):
        try:
            if abs(float(d) - float(end)) < 1e-9:
                return os.path.join(case, d)
        except ValueError:
            pass
    raise SystemExit(f"extract.py: no time folder {end} in {case}")


def snap(x):
    """A cell-centre coordinate as a grouping key: writeCellCentres prints centres with round-off in
    their last digits, so one column's cells must not be told apart by them (1e-7 is far below the
    spacing of any mesh used here)."""
    return round(x, 7)


def centreline(cells, values, along, across, component, ends):
    """Profile of values[component] along coordinate `along` on the line across = 0.5."""
    xs = sorted({snap(c[across]) for c in cells})
    lo = max(x for x in xs if x <= 0.5)
    hi = min(x for x in xs if x >= 0.5)
    w = 0.0 if hi == lo else (0.5 - lo) / (hi - lo)
    rows = {}
    for c, v in zip(cells, values):
        key = snap(c[across])
        if key not in (lo, hi):
            continue
        s = snap(c[along])
        weight = (1 - w if key == lo else 0.0) + (w if key == hi else 0.0)
        rows[s] = rows.get(s, 0.0) + weight * v[component]
    profile = [(0.0, ends[0])] + sorted(rows.items()) + [(1.0, ends[1])]
    return profile


def main():
    case, end, depth, ke_csv, u_csv, v_csv = sys.argv[1:7]
    depth = float(depth)
    files = glob.glob(os.path.join(case, "postProcessing", "kineticEnergy", "*", "volFieldValue*.dat"))
    if not files:
        raise SystemExit("extract.py: no postProcessing/kineticEnergy output")
    history = []
    for path in sorted(files):
        with open(path) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                t, value = line.split()[:2]
                history.append((float(t), 0.5 * float(value) / depth))
    history.sort()
    with open(ke_csv, "w") as f:
        f.write("t,kinetic_energy\n")
        if history[0][0] > 0:
            f.write("0,0\n")  # the fluid starts at rest
        for t, ke in history:
            f.write(f"{t:.6g},{ke:.10g}\n")

    tdir = time_dir(case, end)
    cells = read_vectors(os.path.join(tdir, "C"))
    u = read_vectors(os.path.join(tdir, "U"))
    if len(cells) != len(u):
        raise SystemExit("extract.py: C and U differ in length")
    with open(u_csv, "w") as f:
        f.write("y,u\n")
        for y, val in centreline(cells, u, 1, 0, 0, (0.0, 1.0)):
            f.write(f"{y:.10g},{val:.10g}\n")
    with open(v_csv, "w") as f:
        f.write("x,v\n")
        for x, val in centreline(cells, u, 0, 1, 1, (0.0, 0.0)):
            f.write(f"{x:.10g},{val:.10g}\n")


if __name__ == "__main__":
    main()
