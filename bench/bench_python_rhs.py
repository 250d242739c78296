#!/usr/bin/python3
"""The cost of arksph.Model.rhs from Python against the C++ evaluation it wraps, side by side in one
process: for each repeat, R calls of model.rhs(t, y) (NumPy in, NumPy out, particles re-ordered in
and out), R evaluations in C++ on the same state without the copies, and R copies of y (np.copy),
interleaved so that the machine's load hits all three alike. Reports the medians and the ratio
    python / (C++ + one copy of y).

usage: PYTHONPATH=build/python bench/bench_python_rhs.py [--scene S] [--set KEY=VALUE ...] [--repeats 7] [--calls 5]
Default scene: the cavity Re = 1000 at 240 x 240 = 57,600 particles, WCSPH.
"""
import argparse
import statistics
import time
from pathlib import Path

import numpy as np

import arksph

ROOT = Path(__file__).resolve().parents[1]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scene", default=str(ROOT / "cases" / "cavity_re1000" / "scene.toml"))
    p.add_argument("--set", action="append", default=["method.scheme=wcsph", "fluid.spacing=0.004166666666666667"])
    p.add_argument("--repeats", type=int, default=7)
    p.add_argument("--calls", type=int, default=5)
    a = p.parse_args()
    settings = dict(s.split("=", 1) for s in a.set)
    model = arksph.Model(a.scene, set={k: _value(v) for k, v in settings.items()})
    y = model.y0
    model.rhs(0.0, y)  # neighbour lists and storage built once before timing
    py_t, cpp_t, copy_t = [], [], []
    for _ in range(a.repeats):
        start = time.perf_counter()
        for _ in range(a.calls):
            model.rhs(0.0, y)
        py_t.append((time.perf_counter() - start) / a.calls)
        cpp_t.append(model._ode.seconds_per_inside_rhs(0.0, y, a.calls))
        start = time.perf_counter()
        for _ in range(a.calls):
            np.copy(y)
        copy_t.append((time.perf_counter() - start) / a.calls)
    py, cpp, copy = (statistics.median(v) for v in (py_t, cpp_t, copy_t))
    print(f"scene {a.scene} ({', '.join(a.set)}): {model.n} particles, {model.scheme}")
    print(f"model.rhs from Python {py * 1e3:.2f} ms, C++ evaluation {cpp * 1e3:.2f} ms, copy of y {copy * 1e3:.3f} ms "
          f"(medians of {a.repeats} x {a.calls} calls)")
    print(f"ratio python / (C++ + copy) = {py / (cpp + copy):.3f}")


def _value(text):
    try:
        return int(text)
    except ValueError:
        try:
            return float(text)
        except ValueError:
            return text


if __name__ == "__main__":
    main()
