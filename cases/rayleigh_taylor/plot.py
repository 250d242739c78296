#!/usr/bin/python3
"""Rayleigh-Taylor pictures (Szewc et al. 2012 Fig. 11, Cummins & Rudman 1999 Figs. 10-11).

    plot.py OUT_DIR LABEL=RUN_DIR [LABEL=RUN_DIR ...]

Writes into OUT_DIR:
  rt_particles.png  particles coloured by phase at t = 1, 3, 5 (rows), one column per run, with the
                    0.5 contour of the smoothed phase indicator (interface_NNNNNN.csv) on top, and
                    in green the OpenFOAM interface of bench/openfoam_rt (200 x 400) at t = 1, 3, 5;
  rt_tips.png       bubble and spike tip heights (timeseries.csv) against time.
Reads the VTP frames directly (appended raw binary, zlib, UInt64 headers, as arksph writes them).
"""
import csv
import re
import struct
import sys
import xml.etree.ElementTree as ET
import zlib
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# The OpenFOAM interface (bench/openfoam_rt), drawn in green where it exists for a panel's time.
REFERENCE = Path(__file__).resolve().parents[2] / "bench" / "openfoam_rt" / "openfoam_rt_n200"
TIMES = tuple(float(t) for t in __import__('os').environ.get('RT_TIMES', '1 3 5').split())
DTYPES = {"Float64": "<f8", "Int64": "<i8", "Int32": "<i4", "Float32": "<f4", "UInt8": "u1"}


def read_vtp(path):
    raw = Path(path).read_bytes()
    marker = raw.index(b"<AppendedData")
    start = raw.index(b"_", marker) + 1
    head = raw[:marker].decode()
    arrays = {}
    for tag in re.findall(r"<DataArray[^>]*>", head):
        da = dict(re.findall(r'(\w+)="([^"]*)"', tag))
        off = start + int(da.get("offset"))
        nblocks, _, _ = struct.unpack_from("<QQQ", raw, off)
        sizes = struct.unpack_from("<%dQ" % nblocks, raw, off + 24)
        pos = off + 24 + 8 * nblocks
        data = b""
        for s in sizes:
            data += zlib.decompress(raw[pos:pos + s])
            pos += s
        a = np.frombuffer(data, dtype=DTYPES[da.get("type")])
        nc = int(da.get("NumberOfComponents", "1"))
        arrays[da.get("Name")] = a.reshape(-1, nc) if nc > 1 else a
    return arrays


def frames(run):
    """(time, vtp file) from particles.pvd."""
    root = ET.parse(Path(run) / "particles.pvd").getroot()
    return [(float(d.get("timestep")), Path(run) / d.get("file")) for d in root.iter("DataSet")]


def nearest(run, t):
    fr = frames(run)
    k = min(range(len(fr)), key=lambda i: abs(fr[i][0] - t))
    return k, fr[k]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    runs = [a.split("=", 1) for a in sys.argv[2:]]
    fig, axes = plt.subplots(len(TIMES), len(runs), figsize=(2.2 * len(runs), 4.2 * len(TIMES)), squeeze=False)
    for c, (label, run) in enumerate(runs):
        for r, t in enumerate(TIMES):
            ax = axes[r][c]
            k, (tf, vtp) = nearest(run, t)
            d = read_vtp(vtp)
            p = d["Points"]
            ax.scatter(p[:, 0], p[:, 1], c=d["phase"], cmap="coolwarm", s=0.6, linewidths=0, vmin=0, vmax=1)
            icsv = Path(run) / ("interface_%06d.csv" % k)
            if icsv.exists():
                with open(icsv) as f:
                    for row in csv.DictReader(f):
                        ax.plot([float(row["x0"]), float(row["x1"])], [float(row["y0"]), float(row["y1"])], "k-", lw=0.8)
            ref = REFERENCE.parent / ("%s_interface_t%g.csv" % (REFERENCE.name, t))
            if ref.exists():
                with open(ref) as f:
                    for row in csv.DictReader(f):
                        ax.plot([float(row["x0"]), float(row["x1"])], [float(row["y0"]), float(row["y1"])], "-",
                                color="lime", lw=0.6)
            ax.set_xlim(0, 1)
            ax.set_ylim(0, 2)
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            ax.set_title("%s, t = %g" % (label, tf), fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "rt_particles.png", dpi=150)

    fig, ax = plt.subplots(figsize=(6, 4))
    for label, run in runs:
        with open(Path(run) / "timeseries.csv") as f:
            rows = list(csv.DictReader(f))
        t = [float(r["t"]) for r in rows]
        line, = ax.plot(t, [float(r["bubble_y"]) for r in rows], "-", label=label + " bubble")
        ax.plot(t, [float(r["spike_y"]) for r in rows], "--", color=line.get_color(), label=label + " spike")
    ax.set_xlabel("t / sqrt(L/g)")
    ax.set_ylabel("tip height y / L")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "rt_tips.png", dpi=150)


if __name__ == "__main__":
    main()
