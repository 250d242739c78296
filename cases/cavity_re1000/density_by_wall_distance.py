#!/usr/bin/python3
"""Where the density error of a frame sits: r.m.s. of the summation density (Szewc eq. 56) by
distance from the nearest wall and per wall, from a VTP frame's `summation_density` array.

usage: density_by_wall_distance.py FRAME.vtp [--dx DX] [--box XMIN YMIN XMAX YMAX]
FRAME may also be a .pvtp index of pieces; read by scripts/vtp_frames.py (no VTK).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from vtp_frames import read_vtp  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("frame")
    ap.add_argument("--dx", type=float, default=1 / 60, help="particle spacing (default 1/60)")
    ap.add_argument("--box", type=float, nargs=4, default=[0, 0, 1, 1], metavar=("XMIN", "YMIN", "XMAX", "YMAX"))
    a = ap.parse_args()
    try:
        data = read_vtp(a.frame)
    except (OSError, ValueError) as e:
        sys.exit("density_by_wall_distance.py: %s" % e)
    if "summation_density" not in data:
        sys.exit("density_by_wall_distance.py: %s: no summation_density array" % a.frame)
    xy = data["Points"][:, :2]
    rho = data["summation_density"]
    dev = rho - rho.mean()
    x0, y0, x1, y1 = a.box
    dist = {"bottom": xy[:, 1] - y0, "top": y1 - xy[:, 1], "left": xy[:, 0] - x0, "right": x1 - xy[:, 0]}
    near = np.min(np.stack(list(dist.values())), axis=0) / a.dx
    rms = lambda m: 100 * np.sqrt(np.mean(dev[m] ** 2)) if m.any() else float("nan")
    print("%s: N %d, mean %.6f, r.m.s. %.4f %%" % (a.frame, len(rho), rho.mean(), rms(np.ones_like(near, bool))))
    print("distance to the nearest wall / dx   particles   r.m.s. %")
    for lo, hi in [(0, 1), (1, 2), (2, 3), (3, 4), (4, np.inf)]:
        m = (near >= lo) & (near < hi)
        print("  %3g - %-4g %20d   %8.4f" % (lo, hi, m.sum(), rms(m)))
    print("first row (within dx) by wall: particles, closest distance / dx, r.m.s. %")
    for name, d in dist.items():
        m = d < a.dx
        if m.any():
            print("  %-6s %5d   %6.3f   %8.4f" % (name, m.sum(), d[m].min() / a.dx, rms(m)))


if __name__ == "__main__":
    main()
