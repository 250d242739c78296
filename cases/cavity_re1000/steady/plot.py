#!/usr/bin/env python3
"""Tables and figures of Szewc's steady-state resolution study (sweep.toml) from its batch folder.

usage: plot.py RUNS_DIR[,RUNS_DIR...] [OUT_DIR]      (OUT_DIR defaults to measured/ beside this script)

For every run folder of the RUNS_DIRs (batch folders, comma-separated) (resolution and scheme read from batch_run.txt):
- results.csv: N, scheme, status, end time, the steady-state time (summary.json steady_state),
  steps, wall seconds (of the last launch only for a run continued from a checkpoint: column
  resumed), CPU seconds (summary.json cpu_seconds: every launch of the run, all threads; empty
  for runs made before arksph recorded it), and at the last output the Ghia r.m.s. and largest errors of u on x = 0.5 and of v on
  y = 0.5 and the density r.m.s. (Szewc eq. 56);
- history.png: Ghia u r.m.s. and density r.m.s. against t, one panel per N (Szewc Fig. 12d);
- profiles.png: u(y) on x = 0.5 and v(x) on y = 0.5 at Ghia's points at the last output, per N
  and scheme, against Ghia (Szewc Figs. 9, 16), for the runs that have finished;
- cost.png: CPU time (wall time where not recorded) per scheme against N (Szewc Fig. 10); runs still going are left out.
Runs still going (no summary.json) are reported from their timeseries.csv so far.
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
COLOUR = {"isph": "tab:blue", "isph+pw": "tab:green", "isph+pw-newton": "tab:olive", "isph-gpps": "tab:orange",
          "wcsph": "tab:red"}


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def run_keys(folder):
    keys = {}
    with open(os.path.join(folder, "batch_run.txt")) as f:
        for a in f.read().split():
            if "=" in a:
                k, v = a.split("=", 1)
                keys[k] = v
    n = round(1.0 / float(keys["fluid.spacing"])) ** 2
    scheme = keys.get("method.scheme", "isph")  # the scene's scheme where the sweep does not set one
    if keys.get("method.density_correction", "none") != "none":
        scheme += "+pw"
        if keys.get("method.correction_solver", "fixed_point") == "newton":  # the scene's is the fixed point
            scheme += "-newton"
    return n, scheme


def measure(folder, resumed):
    n, scheme = run_keys(folder)
    ts = read_rows(os.path.join(folder, "timeseries.csv")) if os.path.exists(os.path.join(folder, "timeseries.csv")) else []
    sp = os.path.join(folder, "summary.json")
    summary = json.load(open(sp)) if os.path.exists(sp) else {}
    steady = summary.get("steady_state") or {}
    last = ts[-1] if ts else {}
    row = dict(N=n, scheme=scheme, status=summary.get("status", "running"),
               t_end=float(last.get("t", "nan")), steady_time=steady.get("time") or "",
               steps=summary.get("steps", last.get("steps", "")), wall_seconds=summary.get("wall_seconds", ""),
               cpu_seconds=summary.get("cpu_seconds", ""), resumed=int(resumed))
    for k in ("ghia_u_rms", "ghia_u_linf", "ghia_v_rms", "ghia_v_linf", "density_rms", "kinetic_energy"):
        row[k] = float(last[k]) if k in last else float("nan")
    return row, ts


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, "measured")
    os.makedirs(out, exist_ok=True)
    rows, series = [], {}
    for runs in sys.argv[1].split(","):
        resumed = {}
        if os.path.exists(os.path.join(runs, "batch.csv")):
            for r in read_rows(os.path.join(runs, "batch.csv")):
                resumed[r["run"]] = r.get("resumed", "0") == "1"
        for name in sorted(os.listdir(runs)):
            folder = os.path.join(runs, name)
            if not os.path.exists(os.path.join(folder, "batch_run.txt")):
                continue
            row, ts = measure(folder, resumed.get(name, False))
            rows.append(row)
            series[(row["N"], row["scheme"])] = (ts, folder, row["status"])
    if not rows:
        sys.exit("no runs in " + sys.argv[1])
    with open(os.path.join(out, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in r.items()})

    ns = sorted({r["N"] for r in rows})
    fig, ax = plt.subplots(2, len(ns), figsize=(4 * len(ns), 6), squeeze=False)
    for j, n in enumerate(ns):
        for (nn, scheme), (ts, _, _) in sorted(series.items()):
            if nn != n or not ts:
                continue
            t = [float(r["t"]) for r in ts]
            ax[0][j].plot(t, [float(r["ghia_u_rms"]) for r in ts], color=COLOUR.get(scheme), label=scheme)
            ax[1][j].semilogy(t, [max(float(r["density_rms"]), 1e-6) for r in ts], color=COLOUR.get(scheme), label=scheme)
        ax[0][j].set_title(f"N = {n}")
        ax[0][j].set_ylabel("Ghia u r.m.s.")
        ax[1][j].set_ylabel("density r.m.s.")
        ax[1][j].set_xlabel("t")
        ax[0][j].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "history.png"), dpi=110)

    fig, ax = plt.subplots(2, len(ns), figsize=(4 * len(ns), 7), squeeze=False)
    for j, n in enumerate(ns):
        ghia_drawn = False
        for (nn, scheme), (_, folder, status) in sorted(series.items()):
            if nn != n or status != "ok":  # a run still going or stopped early: not its final profile
                continue
            for i, (line, coord) in enumerate((("u", "y"), ("v", "x"))):
                path = os.path.join(folder, f"ghia_{line}.csv")
                if not os.path.exists(path):
                    continue
                g = sorted(read_rows(path), key=lambda r: float(r[coord]))
                s = [float(r[coord]) for r in g]
                if not ghia_drawn:
                    ax[i][j].plot(s, [float(r[f"{line}_ghia"]) for r in g], "ko", ms=4, label="Ghia")
                ax[i][j].plot(s, [float(r[f"{line}_sph"]) for r in g], "-", color=COLOUR.get(scheme), label=scheme)
            ghia_drawn = True
        ax[0][j].set_title(f"N = {n}")
        ax[0][j].set_xlabel("y (u on x = 0.5)")
        ax[1][j].set_xlabel("x (v on y = 0.5)")
        ax[0][j].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profiles.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(5, 4))
    for scheme in COLOUR:
        # CPU time where the run recorded it (summed over restarts), else its wall time
        cost = lambda r: r["cpu_seconds"] if r["cpu_seconds"] != "" else r["wall_seconds"]
        pts = [(r["N"], cost(r)) for r in rows if r["scheme"] == scheme and r["status"] == "ok" and cost(r) != ""]
        if pts:
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", color=COLOUR[scheme], label=scheme)
    ax.set_xlabel("N")
    ax.set_ylabel("CPU seconds (wall where not recorded), one thread")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "cost.png"), dpi=110)
    for r in rows:
        print(" ".join(f"{k}={v:.4g}" if isinstance(v, float) and not math.isnan(v) else f"{k}={v}" for k, v in r.items()))


if __name__ == "__main__":
    main()
