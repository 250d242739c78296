#!/usr/bin/python3
"""Dam break: the surge front and the column's height against the measurements.

    compare.py OUT.png LABEL=RUN_DIR [LABEL=RUN_DIR ...]

For each run and frame (a = 1, g = 1 as in scene.toml): the front Z = x/a, the largest x of a
particle within 2 dx of the floor, and the height at the left wall, the largest y of a particle
within 2 dx of it, against T = t sqrt(2 g / a). Left panel: Z with Martin & Moyce 1952 (n^2 = 2, both
column sizes) and Koshizuka & Oka 1996; right: the height. Prints a table of Z at the measured T of
Martin & Moyce's larger column (linear interpolation between frames) up to the impact on the right
wall (x = 4a), and, with two runs or more, the largest difference in Z between the runs there.
"""
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python"))
from arksph.readers import read_run  # noqa: E402

HERE = Path(__file__).resolve().parent
A, G, TANK = 1.0, 1.0, 4.0


def measured(name):
    with open(HERE / name) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return rows


def front_and_height(run_dir):
    run = read_run(run_dir)
    first = run.frame(0)["Points"][:, 1]
    dx = np.diff(np.unique(np.round(first, 9)))[0]  # the lattice spacing: the first frame's rows
    T, Z, Hl = [], [], []
    for i in range(len(run)):
        f = run.frame(i)
        x, y = f["Points"][:, 0], f["Points"][:, 1]
        T.append(f["time"] * np.sqrt(2 * G / A))
        Z.append(x[y < 2 * dx].max() / A)
        Hl.append(y[x < 2 * dx].max() / A)
    return np.array(T), np.array(Z), np.array(Hl)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    runs = [arg.split("=", 1) for arg in sys.argv[2:]]
    mm = measured("martin_moyce_1952.csv")
    ko = measured("koshizuka_oka_1996.csv")
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for a_inch, marker in (("1.125", "s"), ("2.25", "o")):
        pts = [(float(r["T"]), float(r["Z"])) for r in mm if r["a_inch"] == a_inch]
        left.plot(*zip(*pts), marker, mfc="none", color="k", label="Martin & Moyce 1952, a = %s in" % a_inch)
    left.plot([float(r["T"]) for r in ko], [float(r["Z"]) for r in ko], "^", mfc="none", color="grey",
              label="Koshizuka & Oka 1996")
    T_mm = np.array([float(r["T"]) for r in mm if r["a_inch"] == "2.25"])
    Z_mm = np.array([float(r["Z"]) for r in mm if r["a_inch"] == "2.25"])
    table = {}
    for label, run_dir in runs:
        T, Z, Hl = front_and_height(run_dir)
        before = np.argmax(Z >= TANK - 0.05) if np.any(Z >= TANK - 0.05) else len(Z)  # up to the impact
        left.plot(T[:before + 1], Z[:before + 1], "-", label=label)
        right.plot(T, Hl, "-", label=label)
        keep = T_mm <= T[max(before - 1, 0)]
        table[label] = np.interp(T_mm[keep], T[:before], Z[:before])
    left.set_xlabel("T = t sqrt(2g/a)")
    left.set_ylabel("front x / a")
    left.set_xlim(0, 4)
    left.set_ylim(1, 4.2)
    left.legend(fontsize=7)
    right.set_xlabel("T = t sqrt(2g/a)")
    right.set_ylabel("height at the left wall / a")
    right.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    n = min(len(v) for v in table.values())
    print("T      M&M    " + "  ".join("%10s" % k for k in table))
    for i in range(n):
        print("%.3f  %.3f  " % (T_mm[i], Z_mm[i]) + "  ".join("%10.3f" % table[k][i] for k in table))
    if len(table) > 1:
        labels = list(table)
        for i in range(len(labels) - 1):
            d = np.abs(table[labels[i]][:n] - table[labels[i + 1]][:n]).max()
            print("largest |Z(%s) - Z(%s)| up to the impact: %.3f a" % (labels[i], labels[i + 1], d))


if __name__ == "__main__":
    main()
