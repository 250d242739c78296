#!/usr/bin/python3
"""Runs cases/standing_wave with the arksph binary and checks its period and decay against linear theory.

usage: check_standing_wave.py ARKSPH OUTDIR [--set KEY=VALUE ...]

The period within 2 % of w^2 = g k tanh(k H) and the amplitude's decay rate within 20 % of Lamb's
2 nu k^2: the acceptance of a free-surface scheme on this wave (the case's README). The figures come
from cases/standing_wave/measure.py. Exit 0 when both hold, 1 otherwise.
"""
import importlib.util
import subprocess
import sys
from pathlib import Path

CASE = Path(__file__).resolve().parents[2] / "cases" / "standing_wave"
PERIOD_BOUND = 0.02  # relative error of the period
DECAY_BOUND = 0.2    # relative error of the decay rate


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    binary, out, sets = sys.argv[1], sys.argv[2], sys.argv[3:]
    run = subprocess.run([binary, "run", str(CASE / "scene.toml"), "--quiet", "--out", out] + sets)
    if run.returncode != 0:
        print(f"check_standing_wave: the run exited {run.returncode}")
        return 1
    spec = importlib.util.spec_from_file_location("measure", CASE / "measure.py")
    measure = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(measure)
    period, rate, lamb = measure.measure(out)
    period_error = period / measure.theory_period() - 1
    decay_error = rate / lamb - 1
    ok = abs(period_error) <= PERIOD_BOUND and abs(decay_error) <= DECAY_BOUND
    print(f"check_standing_wave: period {100 * period_error:+.2f} % (bound {100 * PERIOD_BOUND:.0f} %), "
          f"decay {rate / lamb:.2f} x Lamb's (bound {DECAY_BOUND}): {'ok' if ok else 'FAIL'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
