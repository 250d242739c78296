"""The particle ODE of an arksph scene as a Python callable: y' = f(t, y)."""
import json
import math
import os
import shutil
import subprocess
import re
import tempfile
import time
from pathlib import Path

import numpy as np

from . import _arksph
from .readers import frames, read_frame


def binary():
    """The arksph executable: $ARKSPH_BINARY, else the one of this build (build/arksph beside
    build/python), else arksph on the PATH."""
    if os.environ.get("ARKSPH_BINARY"):
        return os.environ["ARKSPH_BINARY"]
    built = Path(__file__).resolve().parents[2] / "arksph"
    if built.is_file():
        return str(built)
    found = shutil.which("arksph")
    if not found:
        raise FileNotFoundError("no arksph executable: set ARKSPH_BINARY or build with ./scripts/build.sh")
    return found


def _run_id(folder):
    """The run id that a run folder's particles.pvd names (None: no such file or id)."""
    try:
        text = (Path(folder) / "particles.pvd").read_text(errors="replace")
    except OSError:
        return None
    found = re.search(r'run_id="([^"]*)"', text)
    return found.group(1) if found else None


class RunError(RuntimeError):
    """`arksph run` ended with a non-zero exit code (README.md, "Exit codes"): .code, .message."""

    def __init__(self, code, message):
        super().__init__(f"arksph run exited {code}: {message}")
        self.code = code
        self.message = message


def toml_value(value):
    """A Python value as the TOML text of a --set override (bool, int, float, str, list)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)  # a JSON string is a TOML basic string
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    raise TypeError(f"a scene value must be a bool, number, string or list, not {type(value).__name__}")


def overrides(settings):
    """{"time.end": 0.5} -> ["time.end=0.5"], the form of `arksph run --set`."""
    return [f"{key}={toml_value(value)}" for key, value in (settings or {}).items()]


class Model:
    """The semi-discrete particle system of a scene, set up as `arksph run` sets it up.

    Model("scene.toml", set={"fluid.spacing": 0.02})   a scene file with overrides
    Model()                                             the embedded default scene
    Model(text="...")                                   a scene given as TOML text

    The state y is a flat float64 array of blocks of n values each, one value per particle in the
    order of increasing particle id (`ids`): positions x (and y), velocities u (and v), then the
    density rho when it is a state variable (WCSPH's continuity equation) and the specific energy
    when the equation of state needs it. `layout` maps each block's name to its slice of y.
    """

    def __init__(self, scene=None, set=None, text=None):
        path = os.fspath(scene) if scene is not None else ""
        self._ode = _arksph.ParticleOde(path, text or "", overrides(set))
        self.n = self._ode.n
        self.dim = self._ode.dim
        self.layout = self._ode.layout
        self.ids = self._ode.ids
        self.h = self._ode.h
        self.scheme = self._ode.scheme
        self.end_time = self._ode.end_time
        self.periods = self._ode.periods
        self.sound_speed = self._ode.sound_speed  # WCSPH's c (0 for the projection schemes)

    @property
    def y0(self):
        """The initial state (a new array each time): the state the first step of `arksph run` starts from."""
        return self._ode.y0

    @property
    def scene_toml(self):
        """The scene with every key resolved, as TOML text (what the run's summary records)."""
        return self._ode.scene_toml

    @property
    def evaluations(self):
        """The number of evaluations of f so far."""
        return self._ode.evaluations

    def rhs(self, t, y):
        """dy/dt = f(t, y); for the constrained projection f holds the pressure that keeps div u = 0."""
        return self._ode.rhs(float(t), y)

    def project(self, t, y, t_start, y_start):
        """C&R's projection after a step from (t_start, y_start) to (t, y): the projected state (a new
        array). For method.scheme = "isph" / "isph-gpps" with method.projection = "cummins_rudman" only."""
        return self._ode.project(float(t), y, float(t_start), y_start)

    @property
    def has_projection(self):
        """Whether the scheme projects the velocity (C&R's projection after each step, or constrained in f)."""
        return self._ode.has_projection

    @property
    def constrained(self):
        """Whether the projection is inside f (method.projection = "constrained")."""
        return self._ode.constrained

    def explicit_rhs(self, t, y):
        """f_E of the IMEX split (time.imex): everything but the viscous acceleration."""
        return self._ode.explicit_rhs(float(t), y)

    def implicit_rhs(self, t, y):
        """f_I of the IMEX split: the viscous acceleration (velocity blocks; zero elsewhere)."""
        return self._ode.implicit_rhs(float(t), y)

    def implicit_jvp(self, t, y, v):
        """J v with J = df_I/dy at y, positions and densities frozen: exact for v in the velocity blocks."""
        return self._ode.implicit_jvp(float(t), y, v)

    def stable_step(self, y):
        """The largest stable step at y (CFL, viscous and force limits) from the fields of the last f."""
        return self._ode.stable_step(y)

    def run(self, t_end=None, every=None, out=None, restart=False, set=None, poll=0.2):
        """Runs the scene with arksph's own integrator and run loop (`arksph run`: adaptive or fixed
        step, projection, re-sorting, checkpoints) and yields its frames as (t, y) in this model's
        layout, each as soon as the run has written it. `out`: the output folder (a temporary one
        if None, removed after the last frame); `restart=True` continues the run in `out` from its
        checkpoint.h5 (the frames of the earlier part come first); `set`: further overrides. A run
        that fails raises RunError with its exit code and message after the frames it wrote."""
        settings = dict(set or {})
        if t_end is not None:
            settings["time.end"] = float(t_end)
        if every is not None:
            settings["output.every"] = float(every)
        temporary = None if out is not None else tempfile.TemporaryDirectory(prefix="arksph_run_")
        folder = Path(out if out is not None else temporary.name)
        earlier = None if restart else _run_id(folder)  # an earlier run's frames are not this run's
        try:
            with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as scene:
                scene.write(self.scene_toml)
            if restart:  # the checkpoint holds the scene; --set may change what a restart allows
                command = [binary(), "run", "--restart", str(folder / "checkpoint.h5"), "--quiet"]
            else:
                command = [binary(), "run", scene.name, "--quiet", "--out", str(folder), "--overwrite"]
            for s in overrides(settings):
                command += ["--set", s]
            with tempfile.TemporaryFile("w+") as messages:
                process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=messages, text=True)
                seen = 0
                try:
                    while True:
                        finished = process.poll() is not None
                        listed = frames(folder) if (folder / "particles.pvd").is_file() else []
                        if listed and (earlier is None or _run_id(folder) != earlier):
                            for t, path in listed[seen:]:
                                self._last = (t, self.state_of_frame(path))
                                yield self._last
                            seen = len(listed)
                        if finished:
                            break
                        time.sleep(poll)
                finally:
                    if process.poll() is None:  # the caller stopped iterating: stop the run too
                        process.terminate()
                        process.wait()
                    os.unlink(scene.name)
                if process.returncode != 0:
                    messages.seek(0)
                    lines = messages.read().strip().splitlines()
                    raise RunError(process.returncode, lines[-1] if lines else "(no message)")
        finally:
            if temporary is not None:
                temporary.cleanup()

    def state(self):
        """(t, y) of the last frame run() yielded."""
        if getattr(self, "_last", None) is None:
            raise RuntimeError("no frame yet: iterate over model.run(...) first")
        return self._last

    def state_of_frame(self, path):
        """The state y of a frame file (.vtp or .pvtp) of a run of this scene, in this model's layout.
        With periodic sides the frames hold positions wrapped into the box."""
        f = read_frame(path)
        order = np.argsort(f["id"], kind="stable")
        if not np.array_equal(f["id"][order], self.ids):
            raise ValueError(f"{path}: its particles are not this model's (ids differ)")
        blocks = {"x": f["Points"][:, 0], "y": f["Points"][:, 1], "u": f["velocity"][:, 0], "v": f["velocity"][:, 1],
                  "rho": f["density"]}
        y = np.empty(self.y0.size)
        for name, part in self.layout.items():
            if name not in blocks:
                raise ValueError(f"{path}: the frames do not hold the block {name!r} of the state")
            y[part] = blocks[name][order]
        return y

    def difference(self, a, b):
        """a - b, the position blocks across periodic sides (the nearest image): frames hold positions
        wrapped into the box, an integrator's state need not."""
        d = np.asarray(a, dtype=float) - np.asarray(b, dtype=float)
        for name, period in zip(("x", "y"), self.periods):
            if period is not None:
                block = d[self.layout[name]]
                block -= period * np.round(block / period)
        return d

    def field(self, y, name):
        """One block of y by its layout name ("x", "y", "u", "v", "rho", "energy"), as a view."""
        return np.asarray(y)[self.layout[name]]


def erk_table(name):
    """The Butcher table of an ERK method by its time.integrator name, with ARKODE's coefficients:
    a dict of A (list of rows), b, c, d (the embedding's weights, [] without one), order and
    embedded_order."""
    return _arksph.erk_table(name)
