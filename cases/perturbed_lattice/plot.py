#!/usr/bin/env python3
"""Szewc et al. 2012 Fig. 15 from a run of scene.toml: the summation density of the lattice with one
displaced particle before the correction (first frame) and after the iterated Pozorski-Wawrenczuk
correction (last frame), on one colour scale.

usage: plot.py RUN_DIR OUT.png

Prints the r.m.s. of rho/<rho> - 1 and the range of rho/rho0 of both frames.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from vtp_frames import frames, read_vtp  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    run, out = sys.argv[1], sys.argv[2]
    listed = frames(run)
    (t0, first), (t1, last) = listed[0], listed[-1]
    data = [read_vtp(first), read_vtp(last)]
    rho = [d["summation_density"] for d in data]
    lo, hi = min(r.min() for r in rho), max(r.max() for r in rho)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.6))
    for ax, d, r, title in zip(axes, data, rho, ["initial state", "after the corrected step"]):
        rms = float(np.sqrt(np.mean((r / r.mean() - 1.0) ** 2)))
        p = d["Points"]
        sc = ax.scatter(p[:, 0], p[:, 1], c=r, s=28, cmap="coolwarm", vmin=lo, vmax=hi)
        ax.set_aspect("equal")
        ax.set_title(f"{title}\nr.m.s. {rms:.2e}, range {r.min():.4f}-{r.max():.4f}", fontsize=9)
        print(f"{title}: r.m.s. of rho/<rho> - 1 = {rms:.3e}, rho/rho0 in [{r.min():.5f}, {r.max():.5f}]")
    fig.colorbar(sc, ax=axes, label="summation density / rho0")
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main()
