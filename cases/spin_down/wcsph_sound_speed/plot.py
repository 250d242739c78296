#!/usr/bin/env python3
"""C&R 1999 Figs. 3 and 4 from the runs of sweep.toml: the maximum speed, normalised by its value at
t = 0, and the CV (C&R eq. 24) against time, for c = 1.25, 2.5 and 5, with mirror ghosts (Fig. 3) and
with Lennard-Jones boundary particles (Fig. 4).

    /usr/bin/python3 cases/spin_down/wcsph_sound_speed/plot.py runs/spin_down_wcsph_sound_speed

Writes measured/sound_speed.png and measured/sound_speed.csv next to this script.
"""
import csv
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

HERE = pathlib.Path(__file__).resolve().parent
TIMES = [2, 5, 8.5, 10, 12, 16, 20]


def read_run(folder):
    rows = list(csv.DictReader(open(folder / "timeseries.csv")))
    t = [float(r["t"]) for r in rows]
    speed = [float(r["max_speed"]) for r in rows]
    cv = [float(r["cv"]) for r in rows]
    summary = json.load(open(folder / "summary.json")) if (folder / "summary.json").exists() else {}
    return t, speed, cv, summary


def value_at(t, values, when):
    for ti, v in zip(t, values):
        if abs(ti - when) < 1e-9:
            return v
    return float("nan")


def main():
    runs = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "runs/spin_down_wcsph_sound_speed")
    fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
    table = []
    for folder in sorted(p for p in runs.iterdir() if (p / "timeseries.csv").exists()):
        name = folder.name
        c = float(name.split("sound_speed-")[1].split("_")[0])
        lj = "lennard_jones" in name
        t, speed, cv, summary = read_run(folder)
        col = 1 if lj else 0
        label = f"c = {c:g}"
        axes[0][col].plot(t, [s / speed[0] for s in speed], label=label)
        axes[1][col].semilogy(t, [max(x, 1e-6) for x in cv], label=label)
        row = {"sound_speed": c, "walls": "lennard_jones" if lj else "ghosts",
               "end_time": t[-1], "status": summary.get("status", "")}
        for when in TIMES:
            row[f"speed_ratio_t{when:g}"] = value_at(t, [s / speed[0] for s in speed], when)
            row[f"cv_t{when:g}"] = value_at(t, cv, when)
        table.append(row)
    axes[0][0].set_title("mirror ghosts (C&R Fig. 3)")
    axes[0][1].set_title("Lennard-Jones boundary particles (C&R Fig. 4)")
    for ax in axes[0]:
        ax.set_ylabel("max |u| / max |u|(0)")
        ax.legend()
    for ax in axes[1]:
        ax.set_ylabel("CV (C&R eq. 24)")
        ax.set_xlabel("t")
        ax.legend()
    fig.suptitle("Spin-down, WCSPH (quartic spline, h = 1.3 dx, 50 x 50): sound speed and wall model")
    fig.tight_layout()
    out = HERE / "measured"
    out.mkdir(exist_ok=True)
    fig.savefig(out / "sound_speed.png", dpi=110)
    with open(out / "sound_speed.csv", "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(table[0].keys()))
        w.writeheader()
        for r in table:
            w.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in r.items()})
    print((out / "sound_speed.csv").read_text())


if __name__ == "__main__":
    main()
