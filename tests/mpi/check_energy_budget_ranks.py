#!/usr/bin/env python3
"""The energy budget (metrics.energy_budget, docs/methods/energy-budget.md) of `arksph run`
decomposed over MPI ranks (label mpi), on the vortex tank of tests/scenes/vortex_tank.toml to
t = 0.2 with method.reorder_every = 5 (the particles migrate between the ranks):

  - on 2 and 3 ranks the columns kinetic_energy, potential_energy, compressible_energy,
    viscous_dissipation and total_energy agree with one process within AGREE at every output: the
    ranks sum the energies and the viscous power over their own particles and add them up;
  - a 2-rank run to t = 0.1 restarted on 2 ranks to t = 0.2 continues viscous_dissipation as the
    uninterrupted 2-rank run has it, within AGREE (the checkpoint carries it).

usage: check_energy_budget_ranks.py ARKSPH SOURCE_DIR WORK_DIR MPIEXEC [MPIEXEC FLAGS ...]
"""
import csv
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_checks import check, finish, launch  # noqa: E402

arksph, source, work, mpiexec = sys.argv[1:5]
flags = sys.argv[5:]
# The CSV holds 10 significant digits, and the ranks sum in other orders than one process
# (round-off, ~1e-14): 1e-9 of the column's largest magnitude.
AGREE = 1e-9
COLUMNS = ["kinetic_energy", "potential_energy", "compressible_energy", "viscous_dissipation", "total_energy"]
SCENE = os.path.join(source, "tests", "scenes", "vortex_tank.toml")
ARGS = [SCENE, "--set", "time.end=0.2", "--set", "method.reorder_every=5"]


def run(name, ranks, args):
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    code, err = launch(arksph, mpiexec, flags, ranks, args, out)
    check(code == 0, "%s on %d rank(s) exits 0 %s" % (name, ranks, err.strip()[-200:] if code else ""))
    return out if code == 0 else None


def columns(out):
    with open(os.path.join(out, "timeseries.csv")) as f:
        rows = list(csv.DictReader(f))
    return {c: [float(r[c]) for r in rows] for c in COLUMNS}


def agree(what, out, ref, names):
    if out is None or ref is None:
        return
    a, b = columns(out), columns(ref)
    for c in names:
        scale = max(abs(v) for v in b[c]) or 1.0
        worst = max(abs(x - y) for x, y in zip(a[c], b[c])) / scale if len(a[c]) == len(b[c]) else float("inf")
        check(len(a[c]) == len(b[c]) and worst <= AGREE, "%s: %s within %.3g (%d rows)" % (what, c, worst, len(b[c])))


os.makedirs(work, exist_ok=True)
one = run("one", 1, ARGS)
if one is not None:
    w = columns(one)["viscous_dissipation"]
    check(w[-1] > 0 and all(y > x for x, y in zip(w, w[1:])), "one process: viscous_dissipation > 0 and growing")
for ranks in (2, 3):
    agree("%d ranks against one process" % ranks, run("ranks%d" % ranks, ranks, ARGS), one, COLUMNS)

full = os.path.join(work, "ranks2")
half = run("half", 2, ARGS + ["--set", "time.end=0.1"])
if half is not None:
    code, _ = launch(arksph, mpiexec, flags, 2, ["--restart", os.path.join(half, "checkpoint.h5"), "--set", "time.end=0.2"],
                     half)
    check(code == 0, "restart on 2 ranks exits 0")
    if code == 0:
        agree("2-rank restart against the uninterrupted 2-rank run", half, full, ["viscous_dissipation", "total_energy"])
finish("check_energy_budget_ranks")
