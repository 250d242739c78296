"""arksph.Model, the particle ODE from Python, against `arksph run` on the Taylor-Green vortex.

Run by ctest (label python) with PYTHONPATH=build/python and ARKSPH_BINARY=build/arksph.
"""
import math
import os
import subprocess
import tempfile
import unittest
from pathlib import Path

import numpy as np

import arksph
from arksph.model import overrides

ROOT = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("ARKSPH_BINARY", str(ROOT / "build" / "arksph"))
VORTEX = ROOT / "cases" / "taylor_green" / "scene.toml"
WCSPH = {"method.scheme": "wcsph", "fluid.spacing": 1 / 16}
CONSTRAINED = {"method.scheme": "isph", "method.projection": "constrained", "fluid.spacing": 1 / 16}
CR = {"method.scheme": "isph", "method.projection": "cummins_rudman", "fluid.spacing": 1 / 16}


def arksph_run(out, settings):
    """`arksph run` of the vortex with these settings into out; fails the test on a non-zero exit."""
    command = [BINARY, "run", str(VORTEX), "--quiet", "--out", str(out)]
    for s in overrides(settings):
        command += ["--set", s]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise AssertionError(f"{' '.join(command)} exited {done.returncode}: {done.stderr}")


def frame_state(model, path):
    """The state of a frame file in the model's layout (particles by increasing id)."""
    f = arksph.read_frame(path)
    order = np.argsort(f["id"], kind="stable")
    np.testing.assert_array_equal(f["id"][order], model.ids)
    y = np.empty(model.y0.size)
    blocks = {"x": f["Points"][:, 0], "y": f["Points"][:, 1], "u": f["velocity"][:, 0], "v": f["velocity"][:, 1],
              "rho": f["density"]}
    for name, part in model.layout.items():
        y[part] = blocks[name][order]
    return y


def periodic_difference(model, a, b):
    """a - b with the position blocks taken modulo the vortex's unit period: frames hold positions
    wrapped into the box, an integrator's state need not."""
    d = a - b
    for name in ("x", "y"):
        d[model.layout[name]] -= np.round(d[model.layout[name]])
    return d


def last_frame(out):
    return arksph.frames(out)[-1]


def runge_kutta(f, table, y, t_end, dt):
    """Fixed steps of an explicit Runge-Kutta table (the docs' 15-line integrator)."""
    A, b, c = table["A"], table["b"], table["c"]
    t = 0.0
    for _ in range(round(t_end / dt)):
        k = []
        for i in range(len(b)):
            z = y + dt * sum(a * kj for a, kj in zip(A[i][:i], k)) if i else y
            k.append(f(t + c[i] * dt, z))
        y = y + dt * sum(bi * ki for bi, ki in zip(b, k))
        t += dt
    return y


class FirstEvaluation(unittest.TestCase):
    """model.rhs(0, y0) is the run's own first f: one forward Euler step of `arksph run` is
    y0 + dt f(0, y0) bit for bit (ERKStep forms y + (h b_1) k_1 with b_1 = 1, as below)."""

    def check(self, settings):
        dt = 1e-4
        model = arksph.Model(VORTEX, set=settings)
        with tempfile.TemporaryDirectory() as out:
            arksph_run(out, {**settings, "time.integrator": "ARKSPH_FORWARD_EULER_1_1", "time.dt": dt, "time.end": dt,
                             "output.every": dt})
            (t0, first), (t1, second) = arksph.frames(out)
            np.testing.assert_array_equal(frame_state(model, first), model.y0)
            expected = model.y0 + dt * model.rhs(0.0, model.y0)
            np.testing.assert_array_equal(frame_state(model, second), expected)
        self.assertEqual(t1, dt)

    def test_wcsph(self):
        self.check(WCSPH)

    def test_constrained_isph(self):
        self.check(CONSTRAINED)

    def test_cr_projection_after_the_step(self):
        """C&R's projection: the run's step is the Euler step of f, then the projection."""
        dt = 1e-3
        model = arksph.Model(VORTEX, set=CR)
        y0 = model.y0
        star = y0 + dt * model.rhs(0.0, y0)
        projected = model.project(dt, star, 0.0, y0)
        with tempfile.TemporaryDirectory() as out:
            arksph_run(out, {**CR, "time.integrator": "ARKSPH_FORWARD_EULER_1_1", "time.dt": dt, "time.end": dt,
                             "output.every": dt})
            np.testing.assert_array_equal(frame_state(model, last_frame(out)[1]), projected)
        self.assertFalse(np.array_equal(projected, star))  # the projection did something


class PythonRungeKutta(unittest.TestCase):
    """A Runge-Kutta method written in Python with ARKODE's Zonneveld 5-3-4 coefficients."""

    TABLE = "ARKODE_ZONNEVELD_5_3_4"

    def test_table_is_classical_rk4_plus_an_embedding_stage(self):
        t = arksph.erk_table(self.TABLE)
        self.assertEqual((t["order"], t["embedded_order"], len(t["b"])), (4, 3, 5))
        self.assertEqual(t["b"], [1 / 6, 1 / 3, 1 / 3, 1 / 6, 0.0])
        self.assertEqual(t["c"][:4], [0.0, 0.5, 0.5, 1.0])

    def test_agrees_with_arksph_run_at_the_same_step(self):
        """Relative 1e-12: the same arithmetic up to the order of the stage sums (ARKODE's linear
        combinations against numpy's), about 1e-15 a step over 50 steps."""
        dt, t_end = 2e-3, 0.1
        model = arksph.Model(VORTEX, set=WCSPH)
        mine = runge_kutta(model.rhs, arksph.erk_table(self.TABLE), model.y0, t_end, dt)
        with tempfile.TemporaryDirectory() as out:
            arksph_run(out, {**WCSPH, "time.integrator": self.TABLE, "time.dt": dt, "time.end": t_end,
                             "output.every": t_end})
            t, path = last_frame(out)
            self.assertAlmostEqual(t, t_end, delta=1e-12)
            theirs = frame_state(model, path)
        scale = np.abs(theirs).max()
        self.assertLess(np.abs(periodic_difference(model, mine, theirs)).max() / scale, 1e-12)

    def test_order_four(self):
        """Three fixed steps, each half the last, to t = 0.1: the order from the ratio of successive
        differences (Richardson), 4.0 +- 0.3. The steps are below the stability limit (2.9e-3), in
        the asymptotic range (3.97 here, 3.92 a step coarser), and the finest difference (1e-9)
        stays far above round-off."""
        t_end = 0.1
        model = arksph.Model(VORTEX, set=WCSPH)
        table = arksph.erk_table(self.TABLE)
        y = [runge_kutta(model.rhs, table, model.y0, t_end, dt) for dt in (1e-3, 5e-4, 2.5e-4)]
        coarse, fine = np.abs(y[0] - y[1]).max(), np.abs(y[1] - y[2]).max()
        self.assertGreater(fine, 1e-11)
        order = math.log2(coarse / fine)
        self.assertLess(abs(order - 4.0), 0.3, f"order {order:.3f}")


class SolveIvp(unittest.TestCase):
    def check(self, settings):
        """solve_ivp's RK45 and arksph's Dormand-Prince at rtol 1e-8 (atol 1e-10 in both) end within
        1e-6 of each other: each is within about its tolerance of the exact trajectory (measured:
        4.7e-10 for WCSPH, 3.7e-9 for the constrained ISPH)."""
        from scipy.integrate import solve_ivp

        t_end, rtol, atol = 0.1, 1e-8, 1e-10
        model = arksph.Model(VORTEX, set=settings)
        solution = solve_ivp(model.rhs, (0.0, t_end), model.y0, method="RK45", rtol=rtol, atol=atol)
        self.assertTrue(solution.success, solution.message)
        with tempfile.TemporaryDirectory() as out:
            arksph_run(out, {**settings, "time.integrator": "ARKODE_DORMAND_PRINCE_7_4_5", "time.rtol": rtol,
                             "time.atol": atol, "time.end": t_end, "output.every": t_end})
            theirs = frame_state(model, last_frame(out)[1])
        self.assertLess(np.abs(periodic_difference(model, solution.y[:, -1], theirs)).max(), 1e-6)

    def test_wcsph(self):
        self.check(WCSPH)

    def test_constrained_isph(self):
        self.check(CONSTRAINED)


class ImexSplit(unittest.TestCase):
    def test_split_adds_up_and_jvp_is_the_velocity_derivative(self):
        """f_E + f_I = f (one rounding per entry: relative 1e-13 of the largest term), and f_I is
        affine in the velocities: f_I(y + v) - f_I(y) = J v (round-off of the sums, relative 1e-10)."""
        model = arksph.Model(VORTEX, set={**WCSPH, "fluid.viscosity": 0.1})
        y = model.y0
        full = model.rhs(0.0, y)
        fe, fi = model.explicit_rhs(0.0, y), model.implicit_rhs(0.0, y)
        self.assertLess(np.abs(fe + fi - full).max(), 1e-13 * np.abs(full).max())
        self.assertGreater(np.abs(fi).max(), 0.0)
        v = np.zeros_like(y)
        rng = np.random.default_rng(1)
        for name in ("u", "v"):
            v[model.layout[name]] = rng.standard_normal(model.n)
        jv = model.implicit_jvp(0.0, y, v)
        difference = model.implicit_rhs(0.0, y + v) - fi
        self.assertLess(np.abs(jv - difference).max(), 1e-10 * np.abs(jv).max())


class Periods(unittest.TestCase):
    def test_difference_takes_the_nearest_image_on_periodic_sides_only(self):
        vortex = arksph.Model(VORTEX, set=WCSPH)
        self.assertEqual(vortex.periods, [1.0, 1.0])
        y = vortex.y0
        shifted = y.copy()
        shifted[vortex.layout["x"]] += 1.0
        np.testing.assert_array_equal(vortex.difference(shifted, y), 0.0)
        shifted[vortex.layout["u"]] += 1.0  # velocities are not periodic
        u = vortex.layout["u"]
        np.testing.assert_array_equal(vortex.difference(shifted, y)[u], shifted[u] - y[u])
        cavity = arksph.Model(set={"fluid.spacing": 0.1})  # the embedded default: walls all round
        self.assertEqual(cavity.periods, [None, None])


class RunFromPython(unittest.TestCase):
    def test_frames_and_a_restart(self):
        """model.run steps with arksph's integrator: its first frame is y0; a run stopped at 0.05 and
        restarted from its checkpoint to 0.1 ends bit for bit where the run straight to 0.1 ends
        with a checkpoint at 0.05 (docs/user-guide.md: at a checkpoint the run re-initialises ARKODE
        and its neighbour list exactly as a restart does)."""
        model = arksph.Model(VORTEX, set=WCSPH)
        straight = list(model.run(t_end=0.1, every=0.05, set={"output.checkpoint_every": 0.05}))
        self.assertEqual([t for t, _ in straight], [0.0, 0.05, 0.1])
        np.testing.assert_array_equal(straight[0][1], model.y0)
        self.assertEqual(model.state()[0], 0.1)
        with tempfile.TemporaryDirectory() as out:
            first = list(model.run(t_end=0.05, every=0.05, out=out))
            self.assertEqual(first[-1][0], 0.05)
            again = list(model.run(t_end=0.1, every=0.05, out=out, restart=True))
        self.assertEqual(again[-1][0], 0.1)
        np.testing.assert_array_equal(periodic_difference(model, again[-1][1], straight[-1][1]), 0.0)

    def test_frames_arrive_while_the_run_goes_on_and_stopping_stops_it(self):
        """The first frame is yielded while the run is still going (to t = 1,000, hours away);
        closing the iteration stops the run with SIGTERM, which ends it after its step with a
        checkpoint a restart continues from (exit 143, README's exit codes)."""
        model = arksph.Model(VORTEX, set=WCSPH)
        with tempfile.TemporaryDirectory() as out:
            frames = model.run(t_end=1000.0, every=0.01, out=out)
            t, y = next(frames)
            self.assertEqual(t, 0.0)
            frames.close()
            summary = arksph.read_run(out).summary
            self.assertLess(summary["final_time"], 1000.0)
            self.assertTrue((Path(out) / "checkpoint.h5").is_file())

    def test_a_failed_run_raises_with_its_exit_code(self):
        model = arksph.Model(VORTEX, set=WCSPH)
        with self.assertRaises(arksph.RunError) as caught:
            list(model.run(t_end=0.1, set={"time.max_steps": 2}))
        self.assertNotEqual(caught.exception.code, 0)
        self.assertTrue(caught.exception.message)


class BadInput(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.model = arksph.Model(VORTEX, set=WCSPH)

    def test_unknown_key_raises_the_command_lines_message(self):
        with self.assertRaises(arksph.InputError) as caught:
            arksph.Model(VORTEX, set={"fluid.spacingg": 0.1})
        self.assertIn("fluid.spacingg", str(caught.exception))
        self.assertEqual(len(str(caught.exception).splitlines()), 1)
        self.assertIsInstance(caught.exception, ValueError)

    def test_missing_scene_file(self):
        with self.assertRaises(arksph.InputError) as caught:
            arksph.Model("/nonexistent/scene.toml")
        self.assertIn("/nonexistent/scene.toml", str(caught.exception))

    def test_wrong_length(self):
        with self.assertRaises(arksph.InputError) as caught:
            self.model.rhs(0.0, self.model.y0[:-1])
        self.assertIn(str(self.model.y0.size - 1), str(caught.exception))
        with self.assertRaises(arksph.InputError):
            self.model.rhs(0.0, self.model.y0.reshape(-1, 1))

    def test_nan_names_its_index(self):
        y = self.model.y0
        where = self.model.layout["v"].start + 7
        y[where] = np.nan
        with self.assertRaises(arksph.InputError) as caught:
            self.model.rhs(0.0, y)
        self.assertIn(f"y[{where}] is NaN", str(caught.exception))
        self.assertIn("block v", str(caught.exception))

    def test_projection_of_a_scheme_without_one(self):
        with self.assertRaises(arksph.InputError):
            self.model.project(1e-3, self.model.y0, 0.0, self.model.y0)

    def test_the_model_still_works_after_errors(self):
        a = self.model.rhs(0.0, self.model.y0)
        self.assertTrue(np.all(np.isfinite(a)))
        np.testing.assert_array_equal(a, self.model.rhs(0.0, self.model.y0))


class Layout(unittest.TestCase):
    def test_blocks_cover_the_state_once(self):
        model = arksph.Model(VORTEX, set=WCSPH)
        covered = np.zeros(model.y0.size, dtype=int)
        for part in model.layout.values():
            covered[part] += 1
        np.testing.assert_array_equal(covered, 1)
        self.assertEqual(sorted(model.layout), sorted(["x", "y", "u", "v", "rho"]))
        self.assertTrue(np.all(np.diff(model.ids) > 0))
        # the initial velocity of the vortex at the initial positions, particle by particle
        x, y = model.field(model.y0, "x"), model.field(model.y0, "y")
        np.testing.assert_allclose(model.field(model.y0, "u"), -np.cos(2 * np.pi * x) * np.sin(2 * np.pi * y),
                                   atol=1e-14)


if __name__ == "__main__":
    unittest.main()
