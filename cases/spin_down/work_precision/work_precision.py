#!/usr/bin/python3
"""Work-precision of the spin-down (C&R Fig. 15 setting): velocity error at t = 0.5 against wall time.

usage: work_precision.py REFERENCE_BATCH_DIR BATCH_DIR [BATCH_DIR ...] [--out DIR] [--t 0.5]

Each run of the batch folders (arksph batch) is compared with the single run of the reference
batch (a finer lattice): the reference velocities are interpolated onto the run's particles with
the quartic spline at the reference h, Shepard-normalised (as in ../convergence/convergence.py),
and L1 / L2 are the mean and r.m.s. of |u_a - u_ref(x_a)|. Work is the run's wall_seconds from
summary.json (the whole run: set-up, steps, output). Writes DIR/work_precision.csv and .png and
prints, for a few error levels, the scheme that reaches the level in the least wall time
(log-log interpolation along each scheme's curve).
"""
import argparse
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "convergence"))
from convergence import interp_error, read_frame, spacing_and_h  # noqa: E402


def scheme_label(run_dir):
    s = json.load(open(os.path.join(run_dir, "summary.json")))
    scheme = s.get("scheme", "?")
    terms = " ".join(s.get("terms", []))
    if "pozorski" in terms or "density_correction" in terms:
        scheme += "+PW"
    return scheme


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("reference")
    ap.add_argument("batches", nargs="+")
    ap.add_argument("--out", default=".")
    ap.add_argument("--t", type=float, default=0.5)
    a = ap.parse_args()
    ref_rows = list(csv.DictReader(open(os.path.join(a.reference, "batch.csv"))))
    ref_dir = os.path.join(a.reference, ref_rows[0]["run"])
    _, h_ref = spacing_and_h(ref_dir)
    ref = read_frame(ref_dir, a.t)
    rows = []
    for b in a.batches:
        for r in csv.DictReader(open(os.path.join(b, "batch.csv"))):
            d = os.path.join(b, r["run"])
            if r["status"] != "ok":
                rows.append((scheme_label(d) if os.path.exists(os.path.join(d, "summary.json")) else "?", 0, 0,
                             float("nan"), float("nan"), r["status"], d))
                continue
            dx, _ = spacing_and_h(d)
            l1, l2 = interp_error(read_frame(d, a.t), ref, h_ref)
            rows.append((scheme_label(d), round(1 / dx), float(r["wall_seconds"]), l1, l2, "ok", d))
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "work_precision.csv"), "w") as f:
        f.write("scheme,lattice,wall_seconds,L1,L2,status,run\n")
        for s, n, w, l1, l2, st, d in rows:
            f.write("%s,%d,%.3f,%.6e,%.6e,%s,%s\n" % (s, n, w, l1, l2, st, d))
    curves = {}
    for s, n, w, l1, l2, st, d in rows:
        if st == "ok":
            curves.setdefault(s, []).append((w, l2, n))
    for c in curves.values():
        c.sort(key=lambda p: p[2])
    print("scheme     lattice  wall[s]   L2 error")
    for s, c in curves.items():
        for w, l2, n in c:
            print("%-10s %4d^2  %8.2f  %.3e" % (s, n, w, l2))

    def time_to(curve, target):  # log-log interpolation of wall time at a target error
        for (w0, e0, _), (w1, e1, _) in zip(curve, curve[1:]):
            if (e0 - target) * (e1 - target) <= 0 and e0 != e1:
                f = math.log(target / e0) / math.log(e1 / e0)
                return math.exp(math.log(w0) + f * (math.log(w1) - math.log(w0)))
        return None
    all_err = sorted(e for c in curves.values() for _, e, _ in c)
    if all_err:
        for target in sorted({float("%.1e" % math.sqrt(all_err[0] * all_err[-1])), float("%.1e" % (all_err[-1] * 0.7)),
                              float("%.1e" % (all_err[0] * 1.3))}):
            times = {s: time_to(c, target) for s, c in curves.items()}
            reached = {s: t for s, t in times.items() if t is not None}
            if reached:
                best = min(reached, key=reached.get)
                print("L2 = %.1e: soonest %s (%.2f s); %s" % (target, best, reached[best], ", ".join(
                    "%s %.2f s" % (s, t) for s, t in sorted(reached.items(), key=lambda kv: kv[1]))))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not available: no plot", file=sys.stderr)
        return
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for s, c in curves.items():
        ax.loglog([p[0] for p in c], [p[1] for p in c], "o-", label=s)
        for w, e, n in c:
            ax.annotate("%d²" % n, (w, e), fontsize=7, textcoords="offset points", xytext=(3, 3))
    ax.set_xlabel("wall time of the run [s]")
    ax.set_ylabel("L2 velocity error at t = %g" % a.t)
    ax.set_title("spin-down, Re = 420: work-precision")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "work_precision.png"), dpi=120)


if __name__ == "__main__":
    main()
