#!/usr/bin/env python3
"""The dam break over MPI ranks (label mpi): cases/dam_break/scene.toml at dx = a/20 (800
particles, WCSPH with its defaults and the adaptive step), to t = 0.06 (about 50 steps), frames
every 0.02, on one process and on 2 and 3 ranks:

  - the same number of steps and the same frame times;
  - every frame's positions, velocities and densities equal one process's by particle id within
    ROUND_OFF (relative to the frame's largest value of the field): the ranks sum each particle's
    neighbours in another order (their halo), so the runs part by a few ulp per step;
  - the free_surface array equals one process's in every frame.

Then isph (C&R's projection; hypre on the ranks, KLU on one process, method.ppe_tolerance = 1e-10)
the same way, its positions and velocities within POISSON of one process's: each solve's pressure
is within a fraction of the tolerance of the exact one, and the differences of the steps add up
(the bound of check_distributed_isph.py, 100 x the tolerance); the same surface particles.

usage: check_dam_break_ranks.py ARKSPH SOURCE_DIR WORK_DIR MPIEXEC [MPIEXEC FLAGS ...]
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_checks  # noqa: E402
from run_checks import check, finish  # noqa: E402

arksph, source, work, mpiexec = sys.argv[1:5]
flags = sys.argv[5:]
sys.path.insert(0, os.path.join(source, "python"))
import numpy as np  # noqa: E402
from arksph.readers import read_run  # noqa: E402

# Measured: 3.2e-14 (2 ranks) and 2.5e-14 (3 ranks) relative over the 52 steps; bound 1e-12.
ROUND_OFF = 1e-12

os.makedirs(work, exist_ok=True)
args = [os.path.join(source, "cases", "dam_break", "scene.toml"), "--set", "fluid.spacing=0.05",
        "--set", "time.end=0.06", "--set", "output.every=0.02"]
runs = {}
for ranks in (1, 2, 3):
    out = run_checks.fresh(arksph, mpiexec, flags, work, "dam-%d" % ranks, ranks, args)
    runs[ranks] = read_run(out) if out else None
one = runs[1]
check(one is not None, "one process runs the dam break")
if one:
    steps = json.loads((one.path / "summary.json").read_text())["steps"]
    check(40 <= steps <= 80, "one process: %d steps to t = 0.06 (about 50)" % steps)
for ranks in (2, 3):
    other = runs[ranks]
    if not (one and other):
        check(False, "%d ranks run the dam break" % ranks)
        continue
    s = json.loads((other.path / "summary.json").read_text())["steps"]
    check(s == steps, "%d ranks: %d steps, one process %d" % (ranks, s, steps))
    check(np.array_equal(one.times, other.times), "%d ranks: the frame times of one process" % ranks)
    worst = 0.0
    for i in range(min(len(one), len(other))):
        a, b = one.frame(i), other.frame(i)
        if not np.array_equal(a["id"], b["id"]):
            check(False, "%d ranks frame %d: the particle ids of one process" % (ranks, i))
            continue
        for field in ("Points", "velocity", "density"):
            scale = max(np.abs(a[field]).max(), 1e-300)
            worst = max(worst, np.abs(a[field] - b[field]).max() / scale)
        check(np.array_equal(a["free_surface"], b["free_surface"]),
              "%d ranks frame %d: free_surface equals one process's (%d surface particles)"
              % (ranks, i, int(a["free_surface"].sum())))
    check(worst <= ROUND_OFF, "%d ranks: positions, velocities, densities within %.0e of one process's "
          "over the %d steps (largest relative difference %.2e)" % (ranks, ROUND_OFF, steps, worst))

# isph: measured 4.7e-12 (2 ranks) and 9.3e-13 (3 ranks) to t = 0.06.
POISSON = 1e-8
isph = {}
for ranks in (1, 2, 3):
    extra = ["--set", "method.scheme=isph", "--set", "method.ppe_tolerance=1e-10"]
    if ranks == 1:
        extra += ["--set", "method.ppe_solver=klu"]
    out = run_checks.fresh(arksph, mpiexec, flags, work, "dam-isph-%d" % ranks, ranks, args + extra)
    isph[ranks] = read_run(out) if out else None
check(isph[1] is not None, "one process runs the dam break under isph")
for ranks in (2, 3):
    a_run, b_run = isph[1], isph[ranks]
    if not (a_run and b_run):
        check(False, "%d ranks run the dam break under isph" % ranks)
        continue
    check(np.array_equal(a_run.times, b_run.times), "isph %d ranks: the frame times of one process" % ranks)
    worst = 0.0
    for i in range(min(len(a_run), len(b_run))):
        a, b = a_run.frame(i), b_run.frame(i)
        if not np.array_equal(a["id"], b["id"]):
            check(False, "isph %d ranks frame %d: the particle ids of one process" % (ranks, i))
            continue
        for field in ("Points", "velocity"):
            scale = max(np.abs(a[field]).max(), 1e-300)
            worst = max(worst, np.abs(a[field] - b[field]).max() / scale)
        check(np.array_equal(a["free_surface"], b["free_surface"]),
              "isph %d ranks frame %d: free_surface equals one process's" % (ranks, i))
    check(worst <= POISSON, "isph %d ranks: positions and velocities within %.0e of one process's "
          "(largest relative difference %.2e)" % (ranks, POISSON, worst))
finish("check_dam_break_ranks")
