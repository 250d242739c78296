#!/usr/bin/env python3
"""Differences between centreline profiles (CSV: coordinate, value) and Ghia, Ghia & Shin 1982
Tables I and II (bench/ghia), over Ghia's interior points (wall and lid rows left out, as in
src/diagnostics/ghia.cpp); the profile is interpolated linearly to Ghia's coordinates.

usage: compare_ghia.py RE U_CSV V_CSV GHIA_DIR
"""
import os
import sys


def read_csv(path):
    rows = []
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#") and l.strip()]
    header = lines[0].strip().split(",")
    for l in lines[1:]:
        rows.append([float(v) for v in l.strip().split(",")])
    return header, rows


def interpolate(profile, s):
    for (s0, v0), (s1, v1) in zip(profile, profile[1:]):
        if s0 <= s <= s1:
            return v0 + (v1 - v0) * (s - s0) / (s1 - s0) if s1 > s0 else v0
    raise ValueError(f"{s} outside the profile")


def errors(profile_csv, ghia_csv, re):
    _, prof = read_csv(profile_csv)
    prof = [(r[0], r[1]) for r in prof]
    header, ghia = read_csv(ghia_csv)
    col = header.index(f"Re{re}")
    interior = ghia[1:-1]  # first and last rows are boundary values
    diffs = [interpolate(prof, r[0]) - r[col] for r in interior]
    rms = (sum(d * d for d in diffs) / len(diffs)) ** 0.5
    return rms, max(abs(d) for d in diffs)


def main():
    re, u_csv, v_csv, ghia_dir = sys.argv[1:5]
    ur, ui = errors(u_csv, os.path.join(ghia_dir, "ghia_u_vertical_centerline.csv"), re)
    vr, vi = errors(v_csv, os.path.join(ghia_dir, "ghia_v_horizontal_centerline.csv"), re)
    print(f"Ghia Re = {re}: u(x=0.5) rms {ur:.4f} max {ui:.4f}; v(y=0.5) rms {vr:.4f} max {vi:.4f}")


if __name__ == "__main__":
    main()
