"""Shared by the scripts that run `arksph run` under the MPI launcher: named checks that print
ok/FAILED and are counted, and one run (on one process, or on several ranks through MPIEXEC) with a
timeout, so that a rank left waiting in a collective call fails the test instead of hanging it."""
import os
import shutil
import subprocess
import sys

TIMEOUT = 300  # seconds per run

failures = []


def check(ok, what):
    print(("ok:     " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)


def launch(arksph, mpiexec, flags, ranks, args, out):
    """Runs `arksph run ARGS --out OUT --quiet` on `ranks` processes; returns (exit code or None on
    timeout, stderr)."""
    cmd = [arksph, "run"] + args + ["--out", out, "--quiet"]
    if ranks > 1:
        cmd = [mpiexec, "-n", str(ranks)] + flags + cmd
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        check(False, " ".join(cmd) + " ended within %d s" % TIMEOUT)
        return None, ""
    print(" ".join(cmd), "->", p.returncode)
    return p.returncode, p.stderr


def fresh(arksph, mpiexec, flags, work, name, ranks, args):
    """Runs `arksph run ARGS` on `ranks` processes into WORK/NAME, emptied first; returns the folder,
    or None when the run did not exit 0 (a failed check)."""
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    code, err = launch(arksph, mpiexec, flags, ranks, args, out)
    check(code == 0, "%s on %d rank(s) exits 0 %s" % (name, ranks, err.strip()[-300:] if code else ""))
    return out if code == 0 else None


def finish(name):
    print("%s: %d failure(s)" % (name, len(failures)))
    sys.exit(1 if failures else 0)
