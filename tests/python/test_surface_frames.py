"""What the frames carry beside the particles' fields: the free_surface array of a scene with
fluid.region, and the wall points of output.walls (walls_NNNNNN.vtp, walls.pvd). A coarse column
at rest (10 x 10 particles in a walled box 1 x 1.5) to t = 0.05, frames at t = 0 and at the end;
the counts and positions are checked against brute force over the frame's particles.

Run by ctest (label python) with PYTHONPATH=build/python and ARKSPH_BINARY=build/arksph.
"""
import os
import subprocess
import tempfile
import unittest
from pathlib import Path

import numpy as np

import test_free_surface
from arksph.readers import read_run

BINARY = os.environ.get("ARKSPH_BINARY", str(Path(__file__).resolve().parents[2] / "build" / "arksph"))

DX = 0.1
BOX = ((0.0, 0.0), (1.0, 1.5))
# test_free_surface.py's column H = 1 deep in a walled box 1 x 1.5, g = rho = 1, coarser and shorter.
COLUMN = (test_free_surface.COLUMN.replace("spacing = 0.05", "spacing = 0.1").replace("end = 5.0", "end = 0.05")
          .replace("[output]\nevery = 0.5\n", ""))
assert "spacing = 0.1" in COLUMN and "end = 0.05" in COLUMN and "every" not in COLUMN
# The same box filled with fluid (no region): no free surface.
TANK = COLUMN.replace('region = "y < 1"\n', "")


def run(scene_text, *settings):
    """Runs the scene in a temporary folder; returns (Run, the folder's file names, TemporaryDirectory)."""
    tmp = tempfile.TemporaryDirectory()
    scene = Path(tmp.name) / "scene.toml"
    scene.write_text(scene_text)
    out = Path(tmp.name) / "out"
    command = [BINARY, "run", str(scene), "--quiet", "--out", str(out)]
    for s in settings:
        command += ["--set", s]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        tmp.cleanup()
        raise AssertionError("%s -> %d: %s" % (" ".join(command), done.returncode, done.stderr))
    return read_run(out), sorted(p.name for p in out.iterdir()), tmp


def support_radius(frame):
    # The default kernel, Wendland's quintic, reaches 2 h (docs/user-guide.md, the "h" array).
    return 2.0 * frame["h"][0]


class FreeSurfaceField(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.column, cls.files, cls.tmp = run(COLUMN)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_the_top_row_is_marked_and_the_fluid_below_its_neighbours_is_not(self):
        """Brute force per lattice column: the particles within half a spacing of the column's
        highest particle (its top row) are on the surface; those more than 1.5 spacings below it
        (below the top row's neighbours) are not. The row in between may be either."""
        self.assertEqual(len(self.column), 2)
        for frame in self.column.frames:
            self.assertIn("free_surface", frame)
            self.assertEqual(frame["free_surface"].dtype, np.uint8)
            surface = frame["free_surface"]
            self.assertTrue(set(np.unique(surface)) <= {0, 1})
            x, y = frame["Points"][:, 0], frame["Points"][:, 1]
            column = np.floor(x / DX).astype(int)
            top = np.array([y[column == c].max() for c in column])
            top_row = y > top - 0.5 * DX
            deep = y < top - 1.5 * DX
            self.assertEqual(int(top_row.sum()), 10, "t = %g" % frame["time"])  # one per lattice column
            self.assertTrue(np.all(surface[top_row] == 1), "t = %g: top row %s" % (frame["time"], surface[top_row]))
            self.assertEqual(int(surface[deep].sum()), 0, "t = %g" % frame["time"])

    def test_no_wall_files_by_default(self):
        self.assertFalse([f for f in self.files if f.startswith("walls")])
        self.assertEqual(self.column.wall_paths, [])

    def test_a_flow_that_fills_its_box_has_no_such_array(self):
        tank, _, tmp = run(TANK)
        try:
            for frame in tank.frames:
                self.assertNotIn("free_surface", frame)
                self.assertEqual(len(frame["id"]), 150)
        finally:
            tmp.cleanup()


def expected_images(frame, radius):
    """Brute force: for every particle, its images across the walls within `radius` of it (all four
    sides are walls): one per near wall, and the corner image when two walls are near."""
    points = []
    for (px, py, _), pid in zip(frame["Points"], frame["id"]):
        xs = [2 * BOX[0][0] - px] if px - BOX[0][0] < radius else []
        xs += [2 * BOX[1][0] - px] if BOX[1][0] - px < radius else []
        ys = [2 * BOX[0][1] - py] if py - BOX[0][1] < radius else []
        ys += [2 * BOX[1][1] - py] if BOX[1][1] - py < radius else []
        points += [(pid, gx, py) for gx in xs] + [(pid, px, gy) for gy in ys]
        points += [(pid, gx, gy) for gx in xs for gy in ys]
    return points


class WallPoints(unittest.TestCase):
    def check_walls(self, scene_text, layers_count=None):
        result, files, tmp = run(scene_text, "output.walls=true")
        try:
            self.assertIn("walls.pvd", files)
            self.assertEqual(len(result.wall_paths), len(result))
            np.testing.assert_array_equal(result.wall_times, result.times)
            for i in range(len(result)):
                frame, walls = result.frame(i), result.walls(i)
                radius = support_radius(frame)
                gx, gy = walls["Points"][:, 0], walls["Points"][:, 1]
                n = len(gx)
                self.assertEqual(n, len(expected_images(frame, radius)), "t = %g" % frame["time"])
                if layers_count is not None and i == 0:
                    self.assertEqual(n, layers_count(radius), "the lattice at t = 0")
                # Each point lies outside the box, within one support of a wall.
                outside = (gx < BOX[0][0]) | (gx > BOX[1][0]) | (gy < BOX[0][1]) | (gy > BOX[1][1])
                self.assertTrue(np.all(outside))
                reach = np.maximum.reduce([BOX[0][0] - gx, gx - BOX[1][0], BOX[0][1] - gy, gy - BOX[1][1]])
                self.assertTrue(np.all(reach < radius))
                # Point by point: each is an image of the particle its id names (mirror positions
                # are computed as 2 wall - x: ROUND_OFF of the coordinates).
                ROUND_OFF = 1e-12
                got = sorted(zip(walls["id"].tolist(), np.round(gx / ROUND_OFF), np.round(gy / ROUND_OFF)))
                want = sorted((int(p), np.round(x / ROUND_OFF), np.round(y / ROUND_OFF))
                              for p, x, y in expected_images(frame, radius))
                self.assertEqual(got, want)
                self.assertTrue(np.all(walls["kind"] == 1))
                self.assertNotIn("free_surface", walls)
                self.assertEqual(sorted(k for k in frame if k not in ("free_surface", "time")),
                                 sorted(k for k in walls if k != "time"))
            return result
        finally:
            tmp.cleanup()

    def test_the_tank_walls_are_the_layers_along_each_side_and_the_corners(self):
        """The box filled with 10 x 15 particles: L layers (the lattice rows within one support of
        a side) along each of the four sides and L x L in each corner."""
        def count(radius):
            layers = sum(1 for i in range(20) if (i + 0.5) * DX < radius)
            return 2 * layers * 10 + 2 * layers * 15 + 4 * layers * layers
        self.check_walls(TANK, count)

    def test_the_column_walls_follow_the_particles(self):
        """The column: images of the particles near the floor and the side walls only (the top wall
        is farther than a support from the fluid), at every frame's positions."""
        def count(radius):
            layers = sum(1 for i in range(20) if (i + 0.5) * DX < radius)
            return 2 * layers * 10 + layers * 10 + 2 * layers * layers
        self.check_walls(COLUMN, count)

    def test_the_particle_frames_do_not_change_with_the_key(self):
        plain, _, tmp1 = run(COLUMN)
        walled, _, tmp2 = run(COLUMN, "output.walls=true")
        try:
            for a, b in zip(plain.paths, walled.paths):
                self.assertEqual(Path(a).read_bytes(), Path(b).read_bytes())
        finally:
            tmp1.cleanup()
            tmp2.cleanup()


if __name__ == "__main__":
    unittest.main()
