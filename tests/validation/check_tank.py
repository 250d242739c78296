#!/usr/bin/python3
"""Runs cases/hydrostatic_tank with one scheme and checks that the tank stays at rest.

usage: check_tank.py ARKSPH OUTDIR SCHEME [--pressure-bound B] [--set KEY=VALUE ...]
Bounds (sqrt(g H) = 1): max speed <= 1e-3 at the last output and <= 2e-3 at every output; r.m.s.
relative deviation of the last frame's pressure from rho g (H - y) (both at zero mean) <= B, 1e-2
unless given. WCSPH's pressure is that of a weakly compressible fluid: its deviation falls with the
sound speed c (8.7e-3, 2.4e-3, 1.2e-3 at c = 10, 20, 40, H = g = 1; the exact weakly compressible
profile's is 5.1e-3, 1.3e-3, 3.2e-4), so its tests give B for their c.
Exit 0 when every bound holds, 1 otherwise.
"""
import subprocess
import sys
from pathlib import Path

CASE = Path(__file__).resolve().parents[2] / "cases" / "hydrostatic_tank"
sys.path.insert(0, str(CASE))
import compare  # noqa: E402  (the case's own reader of timeseries.csv and the VTP frames)
import numpy as np  # noqa: E402


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    binary, out, scheme, extra = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    pressure_bound = 1e-2
    if extra[:1] == ["--pressure-bound"] and len(extra) >= 2:
        pressure_bound, extra = float(extra[1]), extra[2:]
    run = subprocess.run([binary, "run", str(CASE / "scene.toml"), "--quiet", "--out", out,
                          "--set", "method.scheme=" + scheme] + extra)
    if run.returncode != 0:
        print(f"check_tank: the run exited {run.returncode}")
        return 1
    t, s = compare.timeseries(out)
    _, vtp = compare.last_frame(out)
    d = compare.read_vtp(vtp)
    y, p = d["Points"][:, 1], d["pressure"]
    ref = 1.0 - y
    dev = (p - p.mean()) - (ref - ref.mean())
    rel = float(np.sqrt(np.mean(dev ** 2) / np.mean((ref - ref.mean()) ** 2)))
    checks = [("max speed at t = %g" % t[-1], s[-1], 1e-3), ("max speed over the outputs", s.max(), 2e-3),
              ("pressure r.m.s. relative deviation", rel, pressure_bound)]
    ok = True
    for name, value, bound in checks:
        passed = value <= bound
        print(f"check_tank: {scheme} {' '.join(extra)}: {name} = {value:.3e} (bound {bound:g}): {'ok' if passed else 'FAIL'}")
        ok &= passed
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
