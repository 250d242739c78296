"""One row of results.csv: the errors at t = 1 and t = 2 from a run's timeseries.csv (the amplitude
error is empty for runs written before arksph had it)."""
import csv
import json
import sys

out, scheme, reg, re, n, code = sys.argv[1:7]


def at(rows, t):
    best = min(rows, key=lambda r: abs(float(r["t"]) - t))
    if abs(float(best["t"]) - t) > 1e-6:
        return "nan", "nan", "nan"
    return best["velocity_l1_relative"], best["peak_speed_error"], best.get("amplitude_error", "")


try:
    rows = list(csv.DictReader(open(out + "/timeseries.csv")))
    wall = json.load(open(out + "/summary.json"))["wall_seconds"]
except (OSError, ValueError, KeyError):
    rows, wall = [], "nan"
l1_1, pk_1, amp_1 = at(rows, 1.0) if rows else ("nan", "nan", "nan")
l1_2, pk_2, amp_2 = at(rows, 2.0) if rows else ("nan", "nan", "nan")
print(",".join(str(v) for v in [scheme, reg, re, n, l1_1, pk_1, l1_2, pk_2, wall, code, amp_1, amp_2]))
