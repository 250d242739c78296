#!/usr/bin/env python3
"""`arksph batch` under an MPI launcher (label mpi): a five-run sweep of the small Taylor-Green
scene run by one process, by `mpiexec -n 2` and by `mpiexec -n 3` must give the same batch.csv:
every run once, in sweep order, with the same values, status, steps and metrics (only wall_seconds
may differ). Then: `-n 3` over the `-n 2` folder skips every run (resume), and a folder whose lock
is held by another process is refused (nonzero exit, no batch.csv written).

usage: check_batch_ranks.py ARKSPH SOURCE_DIR WORK_DIR MPIEXEC [MPIEXEC FLAGS ...]
"""
import csv
import fcntl
import os
import shutil
import subprocess
import sys

arksph, source, work, mpiexec = sys.argv[1:5]
flags = sys.argv[5:]
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAILED:", what)


def batch(out, ranks):
    cmd = [arksph, "batch", os.path.join(work, "sweep.toml"), "--out", out, "--jobs", "1"]
    if ranks:
        cmd = [mpiexec, "-n", str(ranks)] + flags + cmd
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    print(" ".join(cmd), "->", p.returncode)
    if p.returncode:
        print(p.stdout, p.stderr)
    return p.returncode


def table(out):
    path = os.path.join(out, "batch.csv")
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows


def without_wall(rows):
    i = rows[0].index("wall_seconds")
    return [r[:i] + r[i + 1:] for r in rows]


shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
values = ["0.01", "0.02", "0.03", "0.04", "0.05"]
with open(os.path.join(work, "sweep.toml"), "w") as f:
    f.write('[sweep]\nscene = "%s/cases/sweeps/taylor_green_small.toml"\nset = ["output.every=0.1"]\n'
            '[[vary]]\nkey = "time.end"\nvalues = [%s]\n' % (source, ", ".join(values)))

one = os.path.join(work, "one")
check(batch(one, 0) == 0, "one process: exit 0")
reference = table(one)
check(reference is not None and len(reference) == 1 + len(values), "one process: a row per run")
if reference is None:
    sys.exit(1)
names = [r[0] for r in reference[1:]]
check(names == ["%d_end-%s" % (i, v) for i, v in enumerate(values)], "one process: runs in sweep order")

for ranks in (2, 3):
    out = os.path.join(work, "np%d" % ranks)
    check(batch(out, ranks) == 0, "-n %d: exit 0" % ranks)
    rows = table(out)
    check(rows is not None, "-n %d: rank 0 wrote batch.csv" % ranks)
    if rows is None:
        continue
    check([r[0] for r in rows[1:]] == names, "-n %d: every run once, in sweep order" % ranks)
    check(without_wall(rows) == without_wall(reference), "-n %d: the same table as one process" % ranks)
    leftovers = [n for n in os.listdir(out) if n.startswith(".arksph.batch_")]
    check(leftovers == [], "-n %d: rank files removed after the merge (%s)" % (ranks, leftovers))

# Resume: three ranks over the folder of the two-rank batch run nothing.
out = os.path.join(work, "np2")
check(batch(out, 3) == 0, "resume -n 3: exit 0")
rows = table(out)
if rows is not None:
    skipped = rows[0].index("skipped")
    check(all(r[skipped] == "1" for r in rows[1:]) and len(rows) == 1 + len(values), "resume -n 3: every run skipped")
    resumed = [r[:skipped] + r[skipped + 1:] for r in without_wall(rows)]
    first = [r[:skipped] + r[skipped + 1:] for r in without_wall(reference)]
    check(resumed == first, "resume -n 3: the same values and metrics")

# Another batch holds the folder's lock: the launch is refused and writes nothing.
busy = os.path.join(work, "busy")
os.makedirs(busy)
with open(os.path.join(busy, ".arksph.lock"), "w") as lock:
    fcntl.flock(lock, fcntl.LOCK_EX)
    check(batch(busy, 2) != 0, "locked folder: refused")
check(table(busy) is None, "locked folder: no batch.csv")

print("%d check(s) failed" % len(failures) if failures else "all checks passed")
sys.exit(1 if failures else 0)
