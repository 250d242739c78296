"""The wall probe of cases/dam_break_zhou/probe.py: its Shepard interpolation on synthetic frames.

A lattice of spacing dx filling a tank 5.35 long up to y = H = 1 (the particles at (i + 1/2) dx, as
arksph places them), volumes dx^2, h = 2 dx:

  - the hydrostatic field p = rho g (H - y) read at the right wall 0.2 H above the floor, and half a
    spacing inside it, at dx = H/20, H/40, H/60, and 0.01 H higher (a point off the lattice's
    symmetry);
  - p = x read at the wall: the reading is the pressure WALL_DEPTH inside the wall (the support is
    half empty; probe.py's docstring and the case's README state this depth);
  - a probe whose support holds no particle reads 0.

No binary needed: probe.py's functions are called on arrays.

    python3 -m unittest -v tests/python/test_wall_probe.py
"""
import importlib.util
import unittest
from pathlib import Path

import numpy as np

PROBE_PY = Path(__file__).resolve().parents[2] / "cases" / "dam_break_zhou" / "probe.py"
_spec = importlib.util.spec_from_file_location("dam_break_zhou_probe", PROBE_PY)
probe = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(probe)

LENGTH, H = 5.35, 1.0
# Shepard's sum reproduces a constant exactly and a linear field up to grad p . (c - r), c the
# kernel-weighted centre of the particles in the support. Along the wall, c - r is below 4e-4 dx on
# the lattice (measured 2.1e-5 rho g H at dx = H/20, y = 0.21): 1e-4 rho g H is 5 times that, and a
# sum that is not normalised (half the weight missing at the wall) or a support cut short misses by
# far more.
HYDROSTATIC_TOL = 1e-4
# Across the wall the reading of p = x is that at c, 0.883 dx inside the wall line (1.07 dx from the
# point dx/2 inside): the same at every dx on the lattice. 0.01 dx: the third digit.
WALL_DEPTH, INSIDE_DEPTH, DEPTH_TOL = 0.883, 1.072, 0.01


def lattice(dx):
    nx, ny = int(round(LENGTH / dx)), int(round(H / dx))
    x, y = np.meshgrid((np.arange(nx) + 0.5) * dx, (np.arange(ny) + 0.5) * dx)
    points = np.c_[x.ravel(), y.ravel(), np.zeros(x.size)]
    return points, np.full(x.size, dx * dx), np.full(x.size, 2.0 * dx)


class WallProbe(unittest.TestCase):
    def test_hydrostatic_pressure_at_the_wall(self):
        for dx in (H / 20, H / 40, H / 60):
            points, volumes, h = lattice(dx)
            p = 1.0 * 1.0 * (H - points[:, 1])  # rho = g = 1
            for x in (LENGTH, LENGTH - 0.5 * dx):
                for y in (0.2 * H, 0.21 * H):
                    value, n = probe.shepard(points, p, volumes, h, (x, y))
                    with self.subTest(dx=dx, x=x, y=y):
                        self.assertGreater(n, 20)  # half a support of 4 dx radius: 25-28 particles
                        self.assertLess(abs(value - (H - y)), HYDROSTATIC_TOL)

    def test_reading_across_the_wall_is_from_inside(self):
        for dx in (H / 20, H / 40):
            points, volumes, h = lattice(dx)
            on_wall, _ = probe.shepard(points, points[:, 0], volumes, h, (LENGTH, 0.2))
            inside, _ = probe.shepard(points, points[:, 0], volumes, h, (LENGTH - 0.5 * dx, 0.2))
            with self.subTest(dx=dx):
                self.assertAlmostEqual((LENGTH - on_wall) / dx, WALL_DEPTH, delta=DEPTH_TOL)
                self.assertAlmostEqual((LENGTH - inside) / dx, INSIDE_DEPTH, delta=DEPTH_TOL)

    def test_probe_in_the_air_reads_zero(self):
        dx = H / 20
        points, volumes, h = lattice(dx)
        p = H - points[:, 1]
        # Right above the top row's last particle, at 2h = 4 dx from it: no particle within the
        # support; a thousandth of dx lower: that particle alone.
        x, top = LENGTH - 0.5 * dx, H - 0.5 * dx
        value, n = probe.shepard(points, p, volumes, h, (x, top + 4.0 * dx + 1e-6 * dx))
        self.assertEqual((value, n), (0.0, 0))
        value, n = probe.shepard(points, p, volumes, h, (x, top + 4.0 * dx - 1e-3 * dx))
        self.assertEqual(n, 1)
        self.assertAlmostEqual(value, H - top, places=12)


if __name__ == "__main__":
    unittest.main()
