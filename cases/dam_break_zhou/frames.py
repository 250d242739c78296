#!/usr/bin/python3
"""Dam break (Zhou et al. 1999): the particles coloured by pressure at a few times, the probe marked.

    frames.py RUN_DIR OUT.png T [T ...]

T in units of sqrt(H / g) (H = g = 1 in scene.toml): the frame nearest each is drawn, four to a
row; the tank's right part (x > 2.5 H, the whole height) where the surge, the impact and the jet
are; pressure over rho g H, clipped to [0, 1.5]. The cross is the probe (the right wall, 0.2 H
above the floor).
"""
import sys
import tomllib
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python"))
from arksph.readers import read_run  # noqa: E402


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    run = read_run(sys.argv[1])
    box = tomllib.loads(run.summary["resolved_scene"])["domain"]["max"]
    times = [float(t) for t in sys.argv[3:]]
    rows = (len(times) + 3) // 4
    fig, axes = plt.subplots(rows, 4, figsize=(12, 3.3 * rows), squeeze=False, constrained_layout=True)
    for ax in axes.flat[len(times):]:
        ax.axis("off")
    for ax, t in zip(axes.flat, times):
        f = run.frame(int(np.argmin(np.abs(run.times - t))))
        sc = ax.scatter(f["Points"][:, 0], f["Points"][:, 1], c=f["pressure"], s=0.6, cmap="viridis", vmin=0, vmax=1.5)
        ax.plot([box[0]], [0.2], "x", color="r", ms=6)
        ax.set_aspect("equal")
        ax.set_xlim(2.5, box[0])
        ax.set_ylim(0, box[1])
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title("t sqrt(g/H) = %.2f" % f["time"], fontsize=8)
    fig.colorbar(sc, ax=axes.ravel().tolist(), shrink=0.6, label="p / (rho g H)")
    fig.savefig(sys.argv[2], dpi=70)


if __name__ == "__main__":
    main()
