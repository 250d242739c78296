#!/usr/bin/python3
"""Cavity Re = 100, 50 x 50, to t = 10: arksph (wcsph, isph) and PySPH (Debian's python3-pysph, its
cavity example, TVF scheme) in one go on this machine. Prints wall time to t = 10 and Ghia L-infinity
of u and v for each, and the time ratios. Every run's Ghia error is computed here, from its final
particles, by one common interpolation (Shepard-normalised Wendland C2, h = 1.3 dx, the one the
published peer-code cavity figures use), over Ghia's interior centreline points (bench/ghia/*.csv).

Usage: bench/compare_pysph.py [--build build] [--out bench-runs] [--threads 2] [--tf 10]
Needs: build/arksph, python3-numpy, python3-pysph (apt-get install python3-pysph), vtk not needed.
Writes OUT/compare.json and OUT/compare.md.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
import zlib
import base64
import struct

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)


def ghia_points():
    def read(name):
        rows = [l for l in open(os.path.join(HERE, "ghia", name)) if l[0].isdigit()]
        data = np.array([[float(v) for v in r.split(",")] for r in rows])
        return data[1:-1, :2]  # interior points only (first and last rows are boundary values)
    return read("ghia_u_vertical_centerline.csv"), read("ghia_v_horizontal_centerline.csv")


def wendland(r, h):
    q = r / h
    s = np.clip(1.0 - 0.5 * q, 0.0, None)
    return 7.0 / (4.0 * math.pi * h * h) * s**4 * (2.0 * q + 1.0)


def ghia_linf(x, y, u, v, vol, dx):
    """L-infinity error of u on x = 0.5 and v on y = 0.5 against Ghia Re = 100 (lid speed 1)."""
    h = 1.3 * dx
    gu, gv = ghia_points()
    def shepard(px, py, f):
        w = vol * wendland(np.hypot(px - x, py - y), h)
        return np.sum(w * f) / np.sum(w)
    eu = max(abs(shepard(0.5, yy, u) - ref) for yy, ref in gu)
    ev = max(abs(shepard(xx, 0.5, v) - ref) for xx, ref in gv)
    return eu, ev


def read_vtp(path):
    """Positions, velocity, mass and density of an arksph VTP (appended raw/zlib binary)."""
    raw = open(path, "rb").read()
    head, _, tail = raw.partition(b'<AppendedData encoding="raw">')
    appended = tail[tail.index(b"_") + 1:]
    root = ET.fromstring(head.decode() + "</VTKFile>" if b"</VTKFile>" not in head else raw)
    hdr = root.attrib.get("header_type", "UInt32")
    compressed = "compressor" in root.attrib
    isz = 8 if hdr == "UInt64" else 4
    c = "Q" if isz == 8 else "I"
    def block(offset, dtype):
        p = appended[offset:]
        if not compressed:
            n = struct.unpack("<" + c, p[:isz])[0]
            return np.frombuffer(p[isz:isz + n], dtype=dtype)
        nb, bs, last = struct.unpack("<" + c * 3, p[:3 * isz])
        sizes = struct.unpack("<" + c * nb, p[3 * isz:3 * isz + nb * isz])
        pos, out = 3 * isz + nb * isz, b""
        for s in sizes:
            out += zlib.decompress(p[pos:pos + s])
            pos += s
        return np.frombuffer(out, dtype=dtype)
    types = {"Float64": "<f8", "Float32": "<f4", "Int64": "<i8", "Int32": "<i4"}
    arrays = {}
    for da in root.iter("DataArray"):
        name = da.attrib.get("Name", "points")
        arrays[name] = block(int(da.attrib["offset"]), types[da.attrib["type"]]).reshape(
            -1, int(da.attrib.get("NumberOfComponents", "1")))
    pts = arrays["Points"] if "Points" in arrays else arrays["points"]
    return pts[:, 0], pts[:, 1], arrays["velocity"][:, 0], arrays["velocity"][:, 1], \
        arrays["mass"][:, 0], arrays["density"][:, 0]


def run_arksph(args, scheme, extra):
    out = os.path.join(args.out, "arksph_" + scheme)
    cmd = [os.path.join(args.build, "arksph"), "run", os.path.join(REPO, "cases/cavity_re100/scene.toml"),
           "--quiet", "--out", out, "--set", "time.end=%g" % args.tf, "--set", "output.every=0"] + extra
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads))
    t0 = time.time()
    subprocess.run(cmd, check=True, env=env, stdout=subprocess.DEVNULL)
    wall = time.time() - t0
    summary = json.load(open(os.path.join(out, "summary.json")))
    frames = sorted(f for f in os.listdir(out) if f.endswith(".vtp"))
    x, y, u, v, m, rho = read_vtp(os.path.join(out, frames[-1]))
    eu, ev = ghia_linf(x, y, u, v, m / rho, 0.02)
    return {"code": "arksph " + scheme, "wall_s": wall, "steps": summary["steps"],
            "ghia_u_linf": eu, "ghia_v_linf": ev,
            "ghia_u_linf_arksph_summary": summary["metrics"].get("ghia_u_linf")}


def run_pysph(args):
    out = os.path.join(args.out, "pysph_cavity")
    fix = os.path.join(args.out, "pysph-fix")
    os.makedirs(fix, exist_ok=True)
    os.makedirs(os.path.join(args.out, "pysph-home"), exist_ok=True)
    with open(os.path.join(fix, "sitecustomize.py"), "w") as f:
        f.write("from mpi4py import MPI\n")  # works around a PySPH 1.0b1 MPI-init bug (mpi4py imported first)
    # Passive OpenMP waiting as arksph uses by default: fair on a shared machine.
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads), OMP_WAIT_POLICY="PASSIVE", PYTHONPATH=fix,
               HOME=os.path.join(args.out, "pysph-home"))
    cmd = ["/usr/bin/python3", "-m", "pysph.examples.cavity", "--openmp", "--nx", "50", "--re", "100",
           "--tf", "%g" % args.tf, "-d", out]
    # The first call compiles PySPH's generated code (~20 s); it is excluded by a warm-up run.
    subprocess.run(cmd[:-4] + ["--tf", "0.001", "-d", out + "_warmup"], env=env,
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    t0 = time.time()
    subprocess.run(cmd, check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.time() - t0
    from pysph.solver.utils import load, get_files
    data = load(get_files(out)[-1])
    fl = data["arrays"]["fluid"]
    eu, ev = ghia_linf(fl.x, fl.y, fl.u, fl.v, fl.m / fl.rho, 0.02)
    return {"code": "PySPH 1.0b1 (TVF, cavity example)", "wall_s": wall,
            "steps": int(data["solver_data"].get("count", 0)), "ghia_u_linf": eu, "ghia_v_linf": ev}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(REPO, "build"))
    ap.add_argument("--out", default="bench-runs")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--tf", type=float, default=10.0)
    ap.add_argument("--skip-pysph", action="store_true")
    ap.add_argument("--skip-isph", action="store_true", help="leave out the (slow) ISPH run")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    isph = ["--set", "method.scheme=isph", "--set", "method.ppe_pressure_level=zero_min",
            "--set", "method.ppe_divergence=difference", "--set", "time.integrator=ARKSPH_FORWARD_EULER_1_1"]
    rows = [run_arksph(args, "wcsph", []),
            run_arksph(args, "wcsph_cfl05", ["--set", "time.cfl=0.5"]),
            run_arksph(args, "wcsph_cfl06", ["--set", "time.cfl=0.6"]),
            run_arksph(args, "wcsph_bs23_cfl075", ["--set", "time.cfl=0.75",
                                                   "--set", "time.integrator=ARKODE_BOGACKI_SHAMPINE_4_2_3"]),
            None if args.skip_isph else run_arksph(args, "isph", isph + ["--set", "time.dt=0.002"]),
            # dt = 0.25 h / U_lid: the case's CFL number 0.25, with no sound speed in ISPH
            None if args.skip_isph else run_arksph(args, "isph_dt0.01", isph + ["--set", "time.dt=0.01"])]
    rows = [r for r in rows if r is not None]
    if not args.skip_pysph:
        rows.append(run_pysph(args))
    ref = rows[-1]["wall_s"]
    lines = ["| code | wall s to t = %g | steps | Ghia L∞ u / v | time ratio to the last row |" % args.tf,
             "|---|---|---|---|---|"]
    for r in rows:
        r["ratio_to_last"] = ref / r["wall_s"]
        lines.append("| %s | %.1f | %d | %.4f / %.4f | %.2f× faster |" % (
            r["code"], r["wall_s"], r["steps"], r["ghia_u_linf"], r["ghia_v_linf"], r["ratio_to_last"]))
    text = "\n".join(lines)
    print(text)
    open(os.path.join(args.out, "compare.md"), "w").write(text + "\n")
    json.dump(rows, open(os.path.join(args.out, "compare.json"), "w"), indent=1)


if __name__ == "__main__":
    sys.exit(main())
