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


def run_all(label, extra_one, extra_ranks):
    """The dam break on 1, 2 and 3 ranks (label in the folder names), each read back (None if it failed)."""
    runs = {}
    for ranks in (1, 2, 3):
        extra = extra_one if ranks == 1 else extra_ranks
        out = run_checks.fresh(arksph, mpiexec, flags, work, "%s-%d" % (label, ranks), ranks, args + extra)
        runs[ranks] = read_run(out) if out else None
    return runs


def compare(name, one, other, ranks, fields, bound):
    """Every frame of `other` against one process's by particle id: the same ids and surface
    particles, and each field within `bound` of one process's (relative to the frame's largest)."""
    check(np.array_equal(one.times, other.times), "%s %d ranks: the frame times of one process" % (name, ranks))
    worst = 0.0
    for i in range(min(len(one), len(other))):
        a, b = one.frame(i), other.frame(i)
        if not np.array_equal(a["id"], b["id"]):
            check(False, "%s %d ranks frame %d: the particle ids of one process" % (name, ranks, i))
            continue
        for field in fields:
            scale = max(np.abs(a[field]).max(), 1e-300)
            worst = max(worst, np.abs(a[field] - b[field]).max() / scale)
        check(np.array_equal(a["free_surface"], b["free_surface"]),
              "%s %d ranks frame %d: free_surface equals one process's (%d surface particles)"
              % (name, ranks, i, int(a["free_surface"].sum())))
    check(worst <= bound, "%s %d ranks: %s within %.0e of one process's (largest relative difference %.2e)"
          % (name, ranks, ", ".join(fields), bound, worst))


runs = run_all("dam", [], [])
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
    compare("wcsph", one, other, ranks, ("Points", "velocity", "density"), ROUND_OFF)

# isph: measured 4.7e-12 (2 ranks) and 9.3e-13 (3 ranks) to t = 0.06.
POISSON = 1e-8
isph_sets = ["--set", "method.scheme=isph", "--set", "method.ppe_tolerance=1e-10"]
isph = run_all("dam-isph", isph_sets + ["--set", "method.ppe_solver=klu"], isph_sets)
check(isph[1] is not None, "one process runs the dam break under isph")
for ranks in (2, 3):
    if not (isph[1] and isph[ranks]):
        check(False, "%d ranks run the dam break under isph" % ranks)
        continue
    compare("isph", isph[1], isph[ranks], ranks, ("Points", "velocity"), POISSON)
finish("check_dam_break_ranks")
