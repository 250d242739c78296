#!/usr/bin/python3
"""Distances between Rayleigh-Taylor interfaces and an OpenFOAM reference (run.sh), at t = 1, 3, 5.

    compare.py REFERENCE_PREFIX LABEL=SOURCE [LABEL=SOURCE ...]

REFERENCE_PREFIX names the reference files PREFIX_interface_t<T>.csv (bench/openfoam_rt/
openfoam_rt_n200, say). Each SOURCE is an arksph run folder (its particles.pvd and
interface_NNNNNN.csv, the frame nearest T) or another OpenFOAM prefix (a mesh-convergence check).

For each T it prints, per source: the mean distance between the two 0.5 contours (the length-weighted
mean of the distance from each curve to the other, averaged over both directions), the largest
distance (the Hausdorff distance of the two curves), and the differences of the bubble tip (highest
contour point) and the spike tip (lowest) from the reference. Distances are in units of L (the box
is 1 x 2). With --csv FILE the rows are also written to FILE.
"""
import csv
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

TIMES = (1, 3, 5)
STEP = 0.002  # sample spacing along a curve: a quarter of the finest particle spacing compared (1/120)


def read_segments(path):
    if not Path(path).exists():
        raise SystemExit(f"compare.py: {path} does not exist")
    with open(path) as f:
        rows = [[float(r[k]) for k in ("x0", "y0", "x1", "y1")] for r in csv.DictReader(f)]
    if not rows:
        raise SystemExit(f"compare.py: {path} holds no segment")
    return np.array(rows)


def samples(seg):
    """Points along the segments at most STEP apart, each with the curve length it stands for."""
    pts, weights = [], []
    for x0, y0, x1, y1 in seg:
        length = np.hypot(x1 - x0, y1 - y0)
        k = max(1, int(np.ceil(length / STEP)))
        s = (np.arange(k) + 0.5) / k
        pts.append(np.column_stack([x0 + s * (x1 - x0), y0 + s * (y1 - y0)]))
        weights.append(np.full(k, length / k))
    return np.vstack(pts), np.concatenate(weights)


def distance_to(points, seg):
    """Distance from each point to the nearest of the segments (exact point-to-segment distance)."""
    a, b = seg[:, :2], seg[:, 2:]
    d = b - a
    dd = np.maximum((d * d).sum(axis=1), 1e-300)
    out = np.empty(len(points))
    for i in range(0, len(points), 512):
        p = points[i:i + 512, None, :]
        s = np.clip(((p - a) * d).sum(axis=2) / dd, 0.0, 1.0)
        q = a + s[..., None] * d
        out[i:i + 512] = np.sqrt(((p - q) ** 2).sum(axis=2)).min(axis=1)
    return out


def curve_distances(seg_a, seg_b):
    pa, wa = samples(seg_a)
    pb, wb = samples(seg_b)
    da, db = distance_to(pa, seg_b), distance_to(pb, seg_a)
    mean = 0.5 * ((da * wa).sum() / wa.sum() + (db * wb).sum() / wb.sum())
    return mean, max(da.max(), db.max())


def tips(seg):
    ys = np.concatenate([seg[:, 1], seg[:, 3]])
    return ys.max(), ys.min()


def source_interface(source, t):
    """(segments, time) of an arksph run's frame nearest t, or of an OpenFOAM prefix at t."""
    run = Path(source)
    if (run / "particles.pvd").exists():
        root = ET.parse(run / "particles.pvd").getroot()
        times = [float(d.get("timestep")) for d in root.iter("DataSet")]
        k = min(range(len(times)), key=lambda i: abs(times[i] - t))
        return read_segments(run / ("interface_%06d.csv" % k)), times[k]
    return read_segments(f"{source}_interface_t{t}.csv"), float(t)


def main():
    args = sys.argv[1:]
    csv_out = None
    if "--csv" in args:
        i = args.index("--csv")
        csv_out = args[i + 1]
        del args[i:i + 2]
    if len(args) < 2 or any("=" not in a for a in args[1:]):
        sys.exit(__doc__)
    reference = args[0]
    sources = [a.split("=", 1) for a in args[1:]]
    rows = []
    print("| source | t | mean distance | max distance | bubble - ref | spike - ref |")
    print("|---|---|---|---|---|---|")
    for t in TIMES:
        ref = read_segments(f"{reference}_interface_t{t}.csv")
        ref_bubble, ref_spike = tips(ref)
        for label, source in sources:
            seg, t_frame = source_interface(source, t)
            if abs(t_frame - t) > 1e-6:
                print(f"compare.py: {label}: nearest frame to t = {t} is at t = {t_frame:g}", file=sys.stderr)
            mean, worst = curve_distances(seg, ref)
            bubble, spike = tips(seg)
            rows.append((label, t, mean, worst, bubble - ref_bubble, spike - ref_spike))
            print("| %s | %g | %.4f | %.4f | %+.4f | %+.4f |" % rows[-1])
    if csv_out:
        with open(csv_out, "w") as f:
            f.write("source,t,mean_distance,max_distance,bubble_minus_ref,spike_minus_ref\n")
            for r in rows:
                f.write("%s,%g,%.6g,%.6g,%.6g,%.6g\n" % r)


if __name__ == "__main__":
    main()
