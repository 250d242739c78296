#!/usr/bin/python3
"""Standing wave: the work-precision runs against the linear viscous solution.

    viscous_reference.py STUDY_OUTPUT_DIR

The study (work_precision.toml) measures the error against the potential flow times Lamb's decay
exp(-2 nu k^2 t). That field does not satisfy the stress-free condition at the surface: the real
linear flow has a thin vortical layer there (part of Lamb's treatment of the decay), about
sqrt(nu / w) = 0.065 thick, whose velocity is some 14 % of the surface velocity. This script solves
the linear viscous problem of the tank (free-slip walls, no other approximation) in Lamb's
decomposition

    u = grad phi + (psi_y, -psi_x),  phi = a(t) cosh(k y) cos(k x),  psi = Psi(y, t) sin(k x),
    eta = E(t) cos(k x),  Psi_t = nu (Psi_yy - k^2 Psi),  Psi = 0 at y = 0 (free slip there too),
    at y = H: Psi_yy + k^2 Psi = 2 a k^2 sinh(k H)   (no tangential stress),
              E' = a k sinh(k H) - k Psi,             (kinematic)
              a' cosh(k H) + g E + 2 nu (a k^2 cosh(k H) - k Psi_y) = 0   (no normal stress),

starting from a = C / k, Psi = E = 0 (scene.toml's initial state), with second-order finite
differences in y (4000 intervals) and Crank-Nicolson in time (both converged to 4 digits). It prints
the potential reference's own L2 distance from this solution on the dx = 0.0125 lattice, then for
each finished run of the study (last frame) its L2 velocity error against both references.
"""
import csv
import sys
from pathlib import Path

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python"))
from arksph.readers import read_run  # noqa: E402

L, H, G, NU, C = 2.0, 1.0, 1.0, 0.005, 0.0052156
K = np.pi / L
W = np.sqrt(G * K * np.tanh(K * H))


def viscous(t_end, n=4000, dt=2e-4):
    """y, a(t_end), Psi(y, t_end) of the linear viscous solution."""
    y = np.linspace(0.0, H, n + 1)
    dy = y[1] - y[0]
    m = n + 2  # unknowns Psi_1 .. Psi_n, a, E
    ia, ie = n, n + 1
    M = sp.lil_matrix((m, m))
    for j in range(1, n):  # interior: diffusion, Psi_0 = 0
        M[j - 1, j - 1] = NU * (-2 / dy**2 - K * K)
        if j > 1:
            M[j - 1, j - 2] = NU / dy**2
        M[j - 1, j] = NU / dy**2
    # Psi at the surface: Psi_t = nu (Psi_yy - k^2 Psi) with the stress-free Psi_yy
    M[n - 1, n - 1] = -2 * NU * K * K
    M[n - 1, ia] = 2 * NU * K * K * np.sinh(K * H)
    M[ie, ia], M[ie, n - 1] = K * np.sinh(K * H), -K
    ch = np.cosh(K * H)
    M[ia, ie], M[ia, ia] = -G / ch, -2 * NU * K * K
    for col, c in ((n - 1, 3.0), (n - 2, -4.0), (n - 3, 1.0)):  # Psi_y(H), one-sided
        M[ia, col] += 2 * NU * K * c / (2 * dy) / ch
    M = M.tocsc()
    steps = max(1, int(round(t_end / dt)))
    dt = t_end / steps
    eye = sp.identity(m, format="csc")
    lu = spl.splu((eye - 0.5 * dt * M).tocsc())
    rhs = (eye + 0.5 * dt * M).tocsc()
    x = np.zeros(m)
    x[ia] = C / K
    for _ in range(steps):
        x = lu.solve(rhs @ x)
    return y, x[ia], np.concatenate([[0.0], x[:n]])


def viscous_field(px, py, sol):
    y, a, psi = sol
    py_ = np.interp(py, y, np.gradient(psi, y, edge_order=2))
    p = np.interp(py, y, psi)
    return ((-a * K * np.cosh(K * py) + py_) * np.sin(K * px),
            (a * K * np.sinh(K * py) - K * p) * np.cos(K * px))


def potential_field(px, py, t):
    f = np.cos(W * t) * np.exp(-2 * NU * K * K * t)
    return -C * np.cosh(K * py) * np.sin(K * px) * f, C * np.sinh(K * py) * np.cos(K * px) * f


def l2(u, v, ue, ve):
    return np.sqrt(np.mean((u - ue) ** 2 + (v - ve) ** 2))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with open(Path(sys.argv[1]) / "work_precision.csv") as f:
        rows = [r for r in csv.DictReader(f) if r["status"] == "ok"]
    if not rows:
        sys.exit("no finished run in %s" % sys.argv[1])
    solutions = {}
    for r in rows:
        frame = read_run(Path(sys.argv[1]) / Path(r["run"]).name).frame(-1)
        t = round(frame["time"], 9)
        if t not in solutions:
            solutions[t] = viscous(t)
            dx = 0.0125
            gx, gy = np.meshgrid(np.arange(dx / 2, L, dx), np.arange(dx / 2, H, dx))
            gx, gy = gx.ravel(), gy.ravel()
            print("t = %g: potential reference against the viscous solution, dx = %g lattice: L2 %.3e; "
                  "potential amplitude %.4f (Lamb %.4f)"
                  % (t, dx, l2(*viscous_field(gx, gy, solutions[t]), *potential_field(gx, gy, t)),
                     solutions[t][1] * K / C, np.cos(W * t) * np.exp(-2 * NU * K * K * t)))
            print("%-8s %-12s %10s %14s %14s" % ("scheme", "resolution", "wall [s]", "L2 potential", "L2 viscous"))
        p, vel = frame["Points"], frame["velocity"]
        print("%-8s %-12s %10.3f %14.3e %14.3e"
              % (r["scheme"], r["resolution"], float(r["wall_seconds"]),
                 l2(vel[:, 0], vel[:, 1], *potential_field(p[:, 0], p[:, 1], frame["time"])),
                 l2(vel[:, 0], vel[:, 1], *viscous_field(p[:, 0], p[:, 1], solutions[t]))))


if __name__ == "__main__":
    main()
