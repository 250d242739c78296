#!/usr/bin/python3
"""Runs a case with the arksph binary and checks figures of its summary.json against bounds.

usage: check_case.py ARKSPH SCENE OUTDIR KEY<=BOUND [KEY<=BOUND ...]
KEY is a key of summary.json "metrics". Exit 0 when every bound holds, 1 otherwise.
"""
import json
import subprocess
import sys


def main():
    if len(sys.argv) < 5:
        print(__doc__)
        return 2
    binary, scene, out, checks = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    run = subprocess.run([binary, "run", scene, "--quiet", "--out", out])
    if run.returncode != 0:
        print(f"check_case: the run exited {run.returncode}")
        return 1
    with open(f"{out}/summary.json") as f:
        metrics = json.load(f)["metrics"]
    ok = True
    for check in checks:
        key, bound = check.split("<=")
        value = metrics[key]
        passed = value is not None and value <= float(bound)
        print(f"check_case: {key} = {value} (bound {bound}): {'ok' if passed else 'FAIL'}")
        ok &= passed
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
