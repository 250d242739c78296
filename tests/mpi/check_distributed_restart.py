#!/usr/bin/env python3
"""Checkpoints and restarts of `arksph run` decomposed over MPI ranks (label mpi), on the periodic
Taylor-Green vortex (25 x 25 particles, method.reorder_every = 5: the particles migrate between
the ranks), a checkpoint at t = 0.02 (output.checkpoint_every), the runs ending at t = 0.05:

  - a checkpoint written on 2 ranks, restarted on 2 ranks, ends bit for bit as the uninterrupted
    2-rank run with the same checkpoint schedule (every array of the last frame, the step count);
  - a checkpoint written on 3 ranks, restarted on 2, ends as that uninterrupted 2-rank run within
    ROUND_OFF of the largest speed (velocities matched by particle id): the 3-rank state at the
    checkpoint differs from the 2-rank one by round-off;
  - a one-process checkpoint restarted on 2 ranks agrees with its restart in one process, and a
    2-rank checkpoint restarted in one process with the uninterrupted 2-rank run, within ROUND_OFF;
  - every rank count writes checkpoint.h5 at the end, as one process does; the 3-rank checkpoint
    has the layout of the one-process checkpoint at the same time, its state within ROUND_OFF
    (with h5py; skipped without);
  - a tiny scene (10 x 10 particles, 2 x 2 cells of the kernel support): on 4 ranks (one cell
    each) it agrees with one process within ROUND_OFF, also squeezed into one column of cells so
    that two ranks own no particles; on 5 ranks (more ranks than cells) every rank exits 2 with one
    message, within the timeout;
  - SIGTERM to one rank of a 2-rank run: every rank stops with exit 143 and checkpoint.h5 is
    written; the run continues from it on 3 ranks.

usage: check_distributed_restart.py ARKSPH SOURCE_DIR WORK_DIR MPIEXEC [MPIEXEC FLAGS ...]
"""
import glob
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_checks import TIMEOUT, check, finish, launch  # noqa: E402
from vtp_arrays import read_arrays  # noqa: E402

arksph, source, work, mpiexec = sys.argv[1:5]
flags = sys.argv[5:]
# Runs on other rank counts (or one process) sum neighbours and ARKODE's norms in other orders: the
# results differ by round-off, ~1e-14 of the largest speed at t = 0.05 (docs/parallel.md, the
# same bound as check_distributed_run.py).
ROUND_OFF = 1e-12


def run(ranks, args, out):
    code, err = launch(arksph, mpiexec, flags, ranks, args, out)
    if code not in (0, 2, None):
        print(err)
    return code, err


def fresh(name, ranks, args):
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    code, _ = run(ranks, args, out)
    check(code == 0, "%s on %d rank(s) exits 0" % (name, ranks))
    check(code != 0 or os.path.exists(os.path.join(out, "checkpoint.h5")), "%s writes checkpoint.h5" % name)
    return out if code == 0 else None


def restart(name, ranks, from_dir, args):
    """Restarts from the checkpoint in from_dir, in a copy of that folder (the run's own outputs)."""
    if from_dir is None:
        return None
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    shutil.copytree(from_dir, out)
    code, _ = run(ranks, ["--restart", os.path.join(out, "checkpoint.h5")] + args, out)
    check(code == 0, "%s: restart on %d rank(s) exits 0" % (name, ranks))
    return out if code == 0 else None


def last_frame(out):
    return read_arrays(sorted(glob.glob(os.path.join(out, "particles_*.vtp")))[-1])


def by_id(arrays, name):
    v = arrays[name]
    n = len(arrays["id"])
    c = len(v) // n
    return {i: tuple(v[c * k:c * k + c]) for k, i in enumerate(arrays["id"])}


def steps(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)["steps"]


def compare(what, out, ref, bitwise):
    if out is None or ref is None:
        return
    a, b = last_frame(out), last_frame(ref)
    ua, ub = by_id(a, "velocity"), by_id(b, "velocity")
    check(sorted(ua) == sorted(ub), "%s: every particle once" % what)
    if sorted(ua) != sorted(ub):
        return
    scale = max(abs(c) for v in ub.values() for c in v)
    worst = max(abs(x - y) for i in ub for x, y in zip(ua[i], ub[i])) / scale
    same = sum(ua[i] == ub[i] for i in ub)
    check(steps(out) == steps(ref), "%s: the same step count (%d, %d)" % (what, steps(out), steps(ref)))
    if bitwise:
        differing = [k for k in b if k in a and by_id(a, k) != by_id(b, k)]
        check(not differing and set(a) == set(b),
              "%s: bit-identical (arrays that differ: %s; velocity max |du| / max |u| = %.3g)"
              % (what, differing, worst))
    else:
        check(worst <= ROUND_OFF, "%s: velocity max |du| / max |u| = %.3g (%d of %d particles bit-identical)"
              % (what, worst, same, len(ub)))


os.makedirs(work, exist_ok=True)
vortex = os.path.join(source, "tests/scenes/taylor_green_vortex_25.toml")
scene = [vortex, "--set", "method.reorder_every=5", "--set", "output.checkpoint_every=0.02",
         "--set", "output.every=0.01"]
longer = ["--set", "time.end=0.05"]
a2 = fresh("uninterrupted-2", 2, scene + longer)
c3 = fresh("checkpoint-3", 3, scene + ["--set", "time.end=0.02"])
c2 = fresh("checkpoint-2", 2, scene + ["--set", "time.end=0.02"])
c1 = fresh("checkpoint-1", 1, scene + ["--set", "time.end=0.02"])



def same_layout(rank_file, one_file):
    """The checkpoint of a decomposed run against the one-process one at the same time (h5py): the
    same attributes, the same values of those that do not depend on the integrator's history, the
    same datasets, types, shapes and storage filters; the same ids; the state matched by id within
    ROUND_OFF of each dataset's largest value."""
    try:
        import h5py
    except ImportError:
        print("skipped: the checkpoint layout comparison needs h5py (/usr/bin/python3: python3-h5py)")
        return
    with h5py.File(rank_file, "r") as a, h5py.File(one_file, "r") as b:
        check(sorted(a.attrs) == sorted(b.attrs), "3-rank checkpoint: the root attributes of one process %s"
              % sorted(b.attrs))
        # The integrator's evaluations, attempts and step sizes differ: a decomposed run re-initialises
        # ARKODE at every migration, one process only when a re-sort changed the order.
        exact = ["format", "format_version", "dimension", "has_density", "particles", "time", "steps",
                 "output_frame", "checkpoint_index", "wall_reflections"]
        differ = [k for k in exact if k not in a.attrs or a.attrs[k] != b.attrs[k]]
        check(not differ, "3-rank checkpoint: %s equal one process's (differ: %s)" % (", ".join(exact), differ))
        names = []
        b.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
        for n in names:
            x, y = a.get(n), b[n]
            check(x is not None and (x.dtype, x.shape, x.chunks, x.compression, x.shuffle, x.fletcher32) ==
                  (y.dtype, y.shape, y.chunks, y.compression, y.shuffle, y.fletcher32),
                  "3-rank checkpoint: dataset %s stored as one process stores it" % n)
        ia, ib = list(a["particles/id"][:]), list(b["particles/id"][:])
        check(sorted(ia) == sorted(ib), "3-rank checkpoint: the ids of one process")
        if sorted(ia) != sorted(ib):
            return
        where = {i: k for k, i in enumerate(ia)}
        worst = 0.0
        for n in names:
            if n.startswith("state/"):
                x, y = a[n][:], b[n][:]
                scale = max(abs(v) for v in y) or 1.0
                worst = max(worst, max(abs(x[where[i]] - y[k]) for k, i in enumerate(ib)) / scale)
        check(worst <= ROUND_OFF, "3-rank checkpoint: state by id within %.3g of one process's (relative)" % worst)


if c3 and c1:
    same_layout(os.path.join(c3, "checkpoint.h5"), os.path.join(c1, "checkpoint.h5"))
compare("2-rank checkpoint restarted on 2 ranks vs the uninterrupted 2-rank run",
        restart("restart-2-on-2", 2, c2, longer), a2, bitwise=True)
compare("3-rank checkpoint restarted on 2 ranks vs the uninterrupted 2-rank run",
        restart("restart-3-on-2", 2, c3, longer), a2, bitwise=False)
compare("2-rank checkpoint restarted in one process vs the uninterrupted 2-rank run",
        restart("restart-2-on-1", 1, c2, longer), a2, bitwise=False)
compare("one-process checkpoint restarted on 2 ranks vs restarted in one process",
        restart("restart-1-on-2", 2, c1, longer), restart("restart-1-on-1", 1, c1, longer), bitwise=False)

# Tiny: spacing 0.1 in the unit box, support R = 4 dx = 0.4: 2 x 2 cells.
tiny = [vortex, "--set", "fluid.spacing=0.1", "--set", "time.end=0.02"]
compare("tiny scene on 4 ranks (one cell each) vs one process",
        fresh("tiny-4", 4, tiny), fresh("tiny-1", 1, tiny), bitwise=False)
# Empty ranks: the lattice squeezed into x < 0.4 (initial.offset), so the bisection's one cell per
# rank leaves the two ranks of the cells at x > 0.5 without particles (summary mpi.fewest_particles
# = 0), with a checkpoint (a deal) at t = 0.01; the run agrees with one process. With migrations
# (method.reorder_every = 2) it agrees with the 2-rank run: a decomposed run re-initialises its
# integrator at every migration, one process only when the re-sort changed the order
# (docs/parallel.md), which changes the step sizes of this squeezed start.
squeezed = tiny + ["--set", 'initial.offset=["-0.6*x", "0"]', "--set", "output.checkpoint_every=0.01"]


def fewest_particles(out):
    if out:
        with open(os.path.join(out, "summary.json")) as f:
            fewest = json.load(f)["mpi"]["fewest_particles"]
        check(fewest == 0, "%s: a rank without particles (mpi.fewest_particles = %s)" % (os.path.basename(out), fewest))
    return out


compare("squeezed tiny scene with empty ranks on 4 ranks vs one process",
        fewest_particles(fresh("empty-4", 4, squeezed)), fresh("empty-1", 1, squeezed), bitwise=False)
migrating = squeezed + ["--set", "method.reorder_every=2"]
compare("squeezed tiny scene, migrating, with empty ranks on 4 ranks vs 2 ranks",
        fewest_particles(fresh("empty-migrating-4", 4, migrating)), fresh("empty-migrating-2", 2, migrating),
        bitwise=False)
for attempt in range(3):  # mpirun's output forwarding can lose the line when all ranks end at once
    code, err = run(5, tiny, os.path.join(work, "tiny-5"))
    lines = [l for l in err.splitlines() if l.startswith("arksph:")]
    if code != 2 or lines:
        break
check(code == 2 and len(lines) == 1 and "cannot be split" in lines[0],
      "tiny scene on 5 ranks (4 cells): exit %s, one message %s" % (code, lines))


def is_arksph(pid):
    try:
        return os.path.realpath("/proc/%s/exe" % pid) == os.path.realpath(arksph)
    except OSError:
        return False


def interrupted(name):
    """A 2-rank run stopped by SIGTERM to one rank once its second frame is written."""
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    cmd = [mpiexec, "-n", "2"] + flags + [arksph, "run", vortex, "--set", "time.end=100", "--set",
                                          "output.every=0.01", "--out", out, "--quiet"]
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + TIMEOUT
    while not os.path.exists(os.path.join(out, "particles_000002.vtp")) and p.poll() is None and time.time() < deadline:
        time.sleep(0.1)
    ranks = [pid for pid in subprocess.run(["pgrep", "-f", out], capture_output=True, text=True).stdout.split()
             if is_arksph(pid)]  # the rank processes (not the launcher or its proxies)
    if ranks:
        os.kill(int(ranks[-1]), signal.SIGTERM)
    try:
        _, err = p.communicate(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        p.kill()
        p.communicate()
        check(False, "SIGTERM to one rank: the run ends within %d s" % TIMEOUT)
        return None
    lines = [l for l in err.splitlines() if l.startswith("arksph:")]
    check(p.returncode == 143 and any("interrupted by SIGTERM" in l and "checkpoint written" in l for l in lines)
          and os.path.exists(os.path.join(out, "checkpoint.h5")),
          "SIGTERM to one of 2 ranks: exit %s, %s, checkpoint.h5 written" % (p.returncode, lines))
    if p.returncode != 143:
        return None, None
    # The time the run stopped at: the signal can arrive some frames after the second (a fast
    # machine), so the continuation's end time is taken after it.
    stopped_at = [float(m.group(1)) for l in lines for m in [re.search(r"at t = ([-+0-9.eE]+)", l)] if m]
    return out, (stopped_at[0] if stopped_at else None)


stopped, stopped_at = interrupted("interrupted-2")
check(stopped is None or stopped_at is not None, "SIGTERM to one of 2 ranks: the message names the time it stopped at")
if stopped and stopped_at is not None:
    code, _ = run(3, ["--restart", os.path.join(stopped, "checkpoint.h5"), "--set", "time.end=%.17g" % (stopped_at + 0.05)],
                  stopped)
    check(code == 0, "the interrupted 2-rank run (stopped at t = %g) continues on 3 ranks to t = %g: exit %s"
          % (stopped_at, stopped_at + 0.05, code))

finish("check_distributed_restart")
