#!/usr/bin/env python3
"""free_surface and output.walls over MPI ranks (label mpi): the coarse column at rest of
tests/python/test_surface_frames.py (10 x 10 particles below a free surface, to t = 0.05, frames at
t = 0 and at the end) on one process and on 2 ranks, frames joined on rank 0 and in pieces:

  - the free_surface array of every frame equals one process's, particle by particle (by id);
  - the wall points (walls_NNNNNN.vtp, or the pieces that walls_NNNNNN.pvtp names) are one
    process's: the same number, the same ids in the same order when joined, positions within
    ROUND_OFF (each rank's fields come from its own evaluator over its halo).

usage: check_surface_frames.py ARKSPH SOURCE_DIR WORK_DIR MPIEXEC [MPIEXEC FLAGS ...]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_checks  # noqa: E402
from run_checks import check, finish  # noqa: E402

arksph, source, work, mpiexec = sys.argv[1:5]
flags = sys.argv[5:]
sys.path.insert(0, os.path.join(source, "python"))
sys.path.insert(0, os.path.join(source, "tests", "python"))
import numpy as np  # noqa: E402
import test_surface_frames  # noqa: E402  (its COLUMN)
from arksph.readers import read_run  # noqa: E402

# Positions summed in another order on a rank (its halo) than on one process: a few ulp.
ROUND_OFF = 1e-12


def fresh(name, ranks, args):
    out = run_checks.fresh(arksph, mpiexec, flags, work, name, ranks, args)
    return read_run(out) if out else None


os.makedirs(work, exist_ok=True)
scene = os.path.join(work, "column.toml")
with open(scene, "w") as f:
    f.write(test_surface_frames.COLUMN)
args = [scene, "--set", "output.walls=true"]
one = fresh("surface-1", 1, args)
joined = fresh("surface-2", 2, args)
pieces = fresh("surface-pieces-2", 2, args + ["--set", "output.pieces=true"])
if one:
    check(len(one) == 2 and len(one.wall_paths) == 2, "one process: 2 frames and 2 wall files")
for name, other in (("joined", joined), ("pieces", pieces)):
    if not (one and other):
        continue
    check(len(other) == len(one) and len(other.wall_paths) == len(one.wall_paths),
          "%s: as many frames and wall files as one process (%d, %d)" % (name, len(other), len(other.wall_paths)))
    for i in range(min(len(one), len(other))):
        a, b = one.frame(i), other.frame(i)
        same = np.array_equal(a["id"], b["id"]) and np.array_equal(a["free_surface"], b["free_surface"])
        check(same, "%s frame %d: free_surface equals one process's (%d surface particles of %d)"
              % (name, i, int(a["free_surface"].sum()), len(a["id"])))
        wa, wb = one.walls(i), other.walls(i)
        check(len(wa["id"]) == len(wb["id"]), "%s frame %d: %d wall points, one process %d"
              % (name, i, len(wb["id"]), len(wa["id"])))
        if len(wa["id"]) != len(wb["id"]):
            continue
        if name == "pieces":  # each rank's own order: compare as sorted (id, x, y)
            key = lambda w: np.lexsort((w["Points"][:, 1], w["Points"][:, 0], w["id"]))  # noqa: E731
            wa = {k: v[key(wa)] for k, v in wa.items() if k != "time"}
            wb = {k: v[key(wb)] for k, v in wb.items() if k != "time"}
        check(np.array_equal(wa["id"], wb["id"]), "%s frame %d: the wall points' ids in one process's order" % (name, i))
        gap = np.abs(wa["Points"] - wb["Points"]).max() if len(wa["id"]) else 0.0
        check(gap <= ROUND_OFF, "%s frame %d: wall positions within %g of one process's (%.3g)" % (name, i, ROUND_OFF, gap))
finish("check_surface_frames")
