#!/usr/bin/env python3
"""OpenFOAM's own mesh convergence for the cavity reference: two meshes' CSVs (run.sh) compared by
the measures cases/basa_cavity/compare.py applies to the SPH runs, so that the mesh difference can be
set beside the SPH errors it is meant to judge.

usage: mesh_convergence.py RE N_COARSE N_FINE [OPENFOAM_DIR]     (default: bench/openfoam_cavity)

Prints, for the coarse mesh against the fine one:
- kinetic energy: the r.m.s. and largest |KE_coarse - KE_fine| over the common times (every 0.1),
  and the difference at the end time, each divided by the fine mesh's KE at the end time;
- centrelines: the r.m.s. and largest difference of u(x = 0.5) and v(y = 0.5) at Ghia's interior
  points (both profiles interpolated linearly there), and the same over every row of the coarse
  profile (the fine one interpolated to it), where the steep wall layers weigh in.
"""
import os
import sys

from compare_ghia import interpolate, read_csv

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))


def rms_max(diffs):
    return (sum(d * d for d in diffs) / len(diffs)) ** 0.5, max(abs(d) for d in diffs)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    re, n0, n1 = sys.argv[1:4]
    folder = sys.argv[4] if len(sys.argv) > 4 else os.path.join(ROOT, "bench", "openfoam_cavity")
    name = lambda n, what: os.path.join(folder, f"openfoam_re{re}_n{n}_{what}.csv")  # noqa: E731

    ke0 = {round(r[0], 6): r[1] for r in read_csv(name(n0, "kinetic_energy"))[1]}
    ke1 = {round(r[0], 6): r[1] for r in read_csv(name(n1, "kinetic_energy"))[1]}
    times = sorted(set(ke0) & set(ke1))
    scale = ke1[times[-1]]
    r, m = rms_max([(ke0[t] - ke1[t]) / scale for t in times])
    end = (ke0[times[-1]] - ke1[times[-1]]) / scale
    print(f"Re = {re}, {n0}^2 against {n1}^2, kinetic energy over t = 0-{times[-1]:g}: "
          f"r.m.s. {r:.2e}, max {m:.2e}, end {end:+.2e} (of {scale:.5f})")

    ghia = os.path.join(ROOT, "bench", "ghia")
    for what, ghia_csv in (("u_x0.5", "ghia_u_vertical_centerline.csv"), ("v_y0.5", "ghia_v_horizontal_centerline.csv")):
        p0 = [(a, b) for a, b in read_csv(name(n0, what))[1]]
        p1 = [(a, b) for a, b in read_csv(name(n1, what))[1]]
        points = [row[0] for row in read_csv(os.path.join(ghia, ghia_csv))[1][1:-1]]
        gr, gm = rms_max([interpolate(p0, s) - interpolate(p1, s) for s in points])
        ar, am = rms_max([v - interpolate(p1, s) for s, v in p0])
        print(f"  {what}: at Ghia's points r.m.s. {gr:.4f} max {gm:.4f}; "
              f"over the {len(p0)} rows r.m.s. {ar:.4f} max {am:.4f}")


if __name__ == "__main__":
    main()
