#!/usr/bin/python3
"""Standing wave: period and decay of the run's kinetic energy against linear theory.

    measure.py RUN_DIR [RUN_DIR ...]

The kinetic energy of the mode is largest twice a period and decays at twice the amplitude's rate:
its local maxima in timeseries.csv (each refined by a parabola through three outputs) give the
period (twice their mean spacing; the start, a maximum too, is an end point and not used) and the decay rate (a straight
line through log KE at the maxima, halved). Theory: w^2 = g k tanh(k H), the amplitude's rate
2 nu k^2 (Lamb 1932 §348). L, H and g are the scene's; nu is read from the run's summary.json.
"""
import csv
import re
import sys
from pathlib import Path

import numpy as np

L, H, G = 2.0, 1.0, 1.0


def maxima(t, e):
    out = []
    for i in range(1, len(e) - 1):
        if e[i] > e[i - 1] and e[i] >= e[i + 1]:
            a = (e[i - 1] - 2 * e[i] + e[i + 1]) / 2
            b = (e[i + 1] - e[i - 1]) / 2
            x = -b / (2 * a)
            out.append((t[i] + x * (t[1] - t[0]), e[i] - b * b / (4 * a)))
    return np.array(out)


def theory_period():
    k = np.pi / L
    return 2 * np.pi / np.sqrt(G * k * np.tanh(k * H))


def measure(run):
    """(period, amplitude decay rate, Lamb's rate) of the run in directory `run`."""
    k = np.pi / L
    with open(Path(run) / "timeseries.csv") as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["t"]) for r in rows])
    e = np.array([float(r["kinetic_energy"]) for r in rows])
    # the viscosity as the run resolved it (summary.json's resolved_scene, TOML text)
    summary = (Path(run) / "summary.json").read_text()
    nu = float(re.search(r"viscosity = ([0-9.eE+-]+)", summary).group(1))
    m = maxima(t, e)
    measured = 2 * np.diff(m[:, 0]).mean()
    rate = -np.polyfit(m[:, 0], np.log(m[:, 1]), 1)[0] / 2
    return measured, rate, 2 * nu * k * k


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    period = theory_period()
    print("theory: period %.4f" % period)
    for run in sys.argv[1:]:
        measured, rate, lamb = measure(run)
        print("%s: period %.4f (%+.2f %%), amplitude decay rate %.5f, Lamb's %.5f (ratio %.2f)"
              % (run, measured, 100 * (measured / period - 1), rate, lamb, rate / lamb))


if __name__ == "__main__":
    main()
