#!/usr/bin/python3
"""Table of the Rayleigh-Taylor figures per run: status, wall time, steps, CV and upper-phase
density r.m.s. at the end, bubble and spike tips at t = 3 and t = 5, and the spread of the tips
across runs.   summarise.py ROOT RUN [RUN ...]   (writes ROOT/summary.csv and prints it)"""
import csv
import json
import sys
from pathlib import Path


def at(rows, t, key):
    r = min(rows, key=lambda r: abs(float(r["t"]) - t))
    return float(r[key]) if abs(float(r["t"]) - t) < 1e-6 else float("nan")


root = Path(sys.argv[1])
table = []
for name in sys.argv[2:]:
    d = root / name
    try:
        s = json.loads((d / "summary.json").read_text())
        rows = list(csv.DictReader(open(d / "timeseries.csv")))
    except (OSError, ValueError):
        table.append({"run": name, "status": "missing"})
        continue
    table.append({"run": name, "status": s["status"], "final_time": s["final_time"], "wall_seconds": round(s["wall_seconds"], 1),
                  "steps": s["steps"], "ppe_seconds": round(s["timing"]["ppe"], 1), "cv_end": s["metrics"]["cv"],
                  "upper_density_rms_end": s["metrics"].get("upper_density_rms"),
                  "bubble_t3": at(rows, 3, "bubble_y"), "spike_t3": at(rows, 3, "spike_y"),
                  "bubble_t5": at(rows, 5, "bubble_y"), "spike_t5": at(rows, 5, "spike_y")})
keys = ["run", "status", "final_time", "wall_seconds", "steps", "ppe_seconds", "cv_end", "upper_density_rms_end",
        "bubble_t3", "spike_t3", "bubble_t5", "spike_t5"]
with open(root / "summary.csv", "w", newline="") as f:
    w = csv.DictWriter(f, keys, restval="")
    w.writeheader()
    w.writerows(table)
print(open(root / "summary.csv").read())
for k in ["bubble_t3", "spike_t3", "bubble_t5", "spike_t5"]:
    v = [r[k] for r in table if k in r and r[k] == r[k]]
    if v:
        print("%s spread (max - min) across runs: %.4f" % (k, max(v) - min(v)))
