#!/usr/bin/env python3
"""`arksph run` decomposed over MPI ranks (label mpi): short WCSPH runs of a walled cavity (the
published Re = 100 set-up and the embedded default scene, 25 x 25 particles) and of the periodic
Taylor-Green vortex (25 x 25) on 2 and 3 ranks against the one-process run:

  - the same number of steps, and the last frame's velocities, matched by particle id, within
    ROUND_OFF of the one-process run relative to the largest speed;
  - summary.json "mpi": {"ranks": P} (and {"ranks": 1} for one process);
  - with method.reorder_every = 5 the particles migrate (summary mpi.migrations > 0) and the
    results still agree;
  - a scheme or option not run over several ranks (isph-gpps, time.imex) exits 2 on every rank with
    one message from rank 0 (the isph runs and their refusals: check_distributed_isph.py;
    checkpoints and restarts: check_distributed_restart.py);
  - a right-hand side that turns NaN on the particles of one rank (a body force NaN for x > 0.8
    after t = 0.02) ends every rank with exit code 3, as the one-process run, within the timeout
    (no rank left waiting), and the message names the particle as the one-process run's does;
  - so does a state check that fails on one rank only (a body force of 1e9 for x > 0.8: speeds
    beyond the blow-up bound).

usage: check_distributed_run.py ARKSPH SOURCE_DIR WORK_DIR MPIEXEC [MPIEXEC FLAGS ...]
"""
import glob
import json
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_checks import check, finish, launch  # noqa: E402
from vtp_arrays import read_arrays  # noqa: E402

arksph, source, work, mpiexec = sys.argv[1:5]
flags = sys.argv[5:]
# The ranks sum each particle's neighbours and ARKODE's norms in other orders than one process:
# the results differ by round-off, which the flow amplifies over time (a one-process run with its
# particles in another order differs by 3e-15 at t = 0.05, 1.5e-12 at t = 0.1, 1.5e-10 at t = 0.15
# for the vortex). The runs end at t = 0.05 (28 steps), where round-off is still ~1e-14.
ROUND_OFF = 1e-12


def run(name, ranks, args):
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    code, err = launch(arksph, mpiexec, flags, ranks, args, out)
    return out, code, err


def message(err):
    lines = [l for l in err.splitlines() if l.startswith("arksph:")]
    return lines[-1] if lines else ""


def velocities(out):
    frame = sorted(glob.glob(os.path.join(out, "particles_*.vtp")))[-1]
    a = read_arrays(frame)
    v = a["velocity"]
    return {i: (v[3 * k], v[3 * k + 1]) for k, i in enumerate(a["id"])}


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def compare(case, args):
    one, code, _ = run(case + "-1", 1, args)
    check(code == 0, case + ": one process exits 0")
    if code != 0:
        return
    check(summary(one)["mpi"]["ranks"] == 1, case + ": summary mpi.ranks = 1 for one process")
    u1 = velocities(one)
    scale = max(abs(c) for v in u1.values() for c in v)
    for ranks in (2, 3):
        out, code, _ = run("%s-%d" % (case, ranks), ranks, args)
        check(code == 0, "%s on %d ranks exits 0" % (case, ranks))
        if code != 0:
            continue
        s = summary(out)
        check(s["mpi"]["ranks"] == ranks, "%s: summary mpi.ranks = %d" % (case, ranks))
        check(s["steps"] == summary(one)["steps"], "%s: %d ranks take the steps of one process (%d)"
              % (case, ranks, s["steps"]))
        if "reorder_every=5" in " ".join(args):
            check(s["mpi"]["migrations"] > 0, "%s: %d ranks migrated %d times" % (case, ranks, s["mpi"]["migrations"]))
        up = velocities(out)
        check(sorted(up) == sorted(u1), "%s: %d ranks write every particle once" % (case, ranks))
        if sorted(up) != sorted(u1):
            continue
        worst = max(abs(up[i][k] - u1[i][k]) for i in u1 for k in (0, 1)) / scale
        same = sum(up[i] == u1[i] for i in u1)
        check(worst <= ROUND_OFF, "%s: %d ranks vs one process: velocity max |du| / max |u| = %.3g (%d of %d "
              "particles bit-identical)" % (case, ranks, worst, same, len(u1)))


os.makedirs(work, exist_ok=True)
short = ["--set", "time.end=0.05"]
cavity = os.path.join(source, "cases/cavity_re100/scene.toml")
vortex = os.path.join(source, "tests/scenes/taylor_green_vortex_25.toml")
compare("cavity_re100", [cavity, "--set", "fluid.spacing=0.04"] + short)
compare("default_cavity", ["--set", "fluid.spacing=0.04"] + short)
compare("vortex", [vortex] + short)
compare("vortex_migrating", [vortex, "--set", "method.reorder_every=5"] + short)

for what, args in [("scheme isph-gpps", [vortex, "--set", "method.scheme=isph-gpps"]),
                   ("time.imex", [vortex, "--set", "time.imex=true"])]:
    # Every attempt must exit 2. mpirun's output forwarding can lose the one line when all ranks end
    # at once (seen once in a clean build), so the message is looked for in up to three attempts.
    for attempt in range(3):
        _, code, err = run("refused", 2, args)
        lines = [l for l in err.splitlines() if l.startswith("arksph:")]
        if code != 2 or lines:
            break
    check(code == 2 and len(lines) == 1 and "several MPI ranks" in lines[0],
          "%s on 2 ranks: exit %s, one message %s" % (what, code, lines))

nan_force = ["--set", 'fluid.body_force=["t > 0.02 ? (x > 0.8 ? 0/0 : 0) : 0", "0"]']
_, code1, _ = run("nan-1", 1, [vortex] + nan_force + short)
check(code1 == 3, "NaN force on one process: exit 3")
for ranks in (2, 3):
    out, code, err = run("nan-%d" % ranks, ranks, [vortex] + nan_force + short)
    check(code == 3 and "acceleration ax = NaN" in err,
          "NaN force on the particles of one rank of %d: exit %s, %s" % (ranks, code, message(err)))
    if code == 3:
        check(summary(out)["status"] == "failed", "NaN force on %d ranks: summary status failed" % ranks)

blow_up = ["--set", 'fluid.body_force=["t > 0.02 ? (x > 0.8 ? 1e9 : 0) : 0", "0"]']
for ranks in (1, 3):
    out, code, err = run("blow-up-%d" % ranks, ranks, [vortex] + blow_up + short)
    check(code == 3 and "exceeds the blow-up bound" in err,
          "a blow-up on the particles of one rank of %d: exit %s, %s" % (ranks, code, message(err)))

finish("check_distributed_run")
