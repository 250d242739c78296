#!/usr/bin/python3
"""Checks the layout of arksph checkpoints with h5py (src/io/checkpoint_layout.md).

usage:
  read_checkpoint.py FILE.h5 [...]     check existing checkpoints
  read_checkpoint.py --run ARKSPH      make two short runs (2D with a density block, 1D without, with
                                       the energy budget) in a temporary directory and check their checkpoints

Exit code 0: layout as documented; 1: a check failed (the message says which); 77: h5py is not
installed (ctest SKIP_RETURN_CODE). Use Debian's /usr/bin/python3 (python3-h5py).
"""
import os
import subprocess
import sys
import tempfile

try:
    import h5py
    import numpy as np
except ImportError as e:  # pragma: no cover
    print(f"read_checkpoint.py: skipped: {e}")
    sys.exit(77)

try:
    import tomllib  # Python >= 3.11
except ImportError:  # pragma: no cover
    tomllib = None

INT32, INT64, F64 = np.dtype("<i4"), np.dtype("<i8"), np.dtype("<f8")
ROOT_ATTRS = {
    "format": str, "format_version": INT32, "dimension": INT32, "has_density": INT32,
    "particles": INT64, "time": F64, "steps": INT64, "rhs_evals": INT64, "step_attempts": INT64,
    "error_test_fails": INT64, "last_step": F64, "next_step": F64, "output_frame": INT64,
    "checkpoint_index": INT64, "wall_reflections": INT64, "scene_toml": str,
}
PARTICLE_SETS = {"mass": F64, "rho0": F64, "id": INT64, "phase": INT32}

ONE_D_SCENE = """
[scene]
name = "layout_1d"
dimension = 1
[domain]
min = [0.0]
max = [1.0]
[boundary]
left = { kind = "periodic" }
right = { kind = "periodic" }
[fluid]
spacing = 0.02
[initial]
velocity = ["0.1*sin(2*pi*x)"]
[method]
density_mode = "summation"
[time]
end = 0.01
dt = 0.001
"""


class LayoutError(Exception):
    pass


def require(cond, what):
    if not cond:
        raise LayoutError(what)


def attr_type(f, name):
    a = f.attrs.get_id(name)
    return a.dtype, a.shape


def check_file(path):
    with h5py.File(path, "r") as f:
        for name, kind in ROOT_ATTRS.items():
            require(name in f.attrs, f"root attribute '{name}' missing")
            dtype, shape = attr_type(f, name)
            require(shape == (), f"attribute '{name}' is not a scalar (shape {shape})")
            if kind is str:
                require(h5py.check_string_dtype(dtype) is not None, f"attribute '{name}' is not a string")
            else:
                require(dtype == kind, f"attribute '{name}' has type {dtype}, expected {kind}")
        if "run_id" in f.attrs:  # optional
            require(h5py.check_string_dtype(attr_type(f, "run_id")[0]) is not None, "attribute 'run_id' is not a string")
        if "viscous_dissipation" in f.attrs:  # optional: metrics.energy_budget
            require(attr_type(f, "viscous_dissipation") == (F64, ()),
                    "attribute 'viscous_dissipation' is not a float64 scalar")
        a = f.attrs
        fmt = a["format"]
        fmt = fmt.decode() if isinstance(fmt, bytes) else fmt
        require(fmt == "arksph checkpoint", f"format = {fmt!r}")
        require(a["format_version"] == 1, f"format_version = {a['format_version']}")
        dim, n, has_rho = int(a["dimension"]), int(a["particles"]), int(a["has_density"])
        require(dim in (1, 2), f"dimension = {dim}")
        require(n > 0, f"particles = {n}")
        require(has_rho in (0, 1), f"has_density = {has_rho}")
        require(a["time"] >= 0 and np.isfinite(a["time"]), f"time = {a['time']}")
        require(a["steps"] >= 0 and a["rhs_evals"] >= a["steps"], "steps / rhs_evals inconsistent")
        require(a["output_frame"] >= 1, f"output_frame = {a['output_frame']}")
        require(a["checkpoint_index"] >= 1, f"checkpoint_index = {a['checkpoint_index']}")

        toml_text = a["scene_toml"]
        toml_text = toml_text.decode() if isinstance(toml_text, bytes) else toml_text
        require("[scene]" in toml_text and "[output]" in toml_text, "scene_toml is not a resolved scene")
        if tomllib is not None:
            scene = tomllib.loads(toml_text)
            require(scene["scene"]["dimension"] == dim, "scene_toml dimension differs from the attribute")
            require("checkpoint_every" in scene["output"], "scene_toml lacks output.checkpoint_every")

        expected_state = ["x", "y", "u", "v"] if dim == 2 else ["x", "u"]
        if has_rho:
            expected_state.append("rho")
        groups = set(f.keys())
        require(groups in ({"state", "particles"}, {"state", "particles", "diagnostics"}), f"root groups {sorted(groups)}")
        if "diagnostics" in groups:  # the steady-state monitor's samples: rows of steady_columns values
            g = f["diagnostics"]
            cols = int(g.attrs["steady_columns"])
            samples = g["steady_samples"]
            require(cols >= 2, f"steady_columns = {cols}")
            require(samples.ndim == 1 and samples.shape[0] % cols == 0 and samples.shape[0] > 0,
                    f"steady_samples has shape {samples.shape}, not rows of {cols}")
            rows = samples[:].reshape(-1, cols)
            require(np.all(np.diff(rows[:, 0]) > 0) and rows[-1, 0] <= a["time"] + 1e-9,
                    "steady sample times not increasing up to the checkpoint time")
        require(sorted(f["state"].keys()) == sorted(expected_state),
                f"/state holds {sorted(f['state'].keys())}, expected {sorted(expected_state)}")
        require(sorted(f["particles"].keys()) == sorted(PARTICLE_SETS),
                f"/particles holds {sorted(f['particles'].keys())}")
        datasets = [(f"state/{k}", F64) for k in expected_state] + [(f"particles/{k}", t) for k, t in PARTICLE_SETS.items()]
        for name, dtype in datasets:
            d = f[name]
            require(d.shape == (n,), f"{name} has shape {d.shape}, expected ({n},)")
            require(d.dtype == dtype, f"{name} has type {d.dtype}, expected {dtype}")
            require(d.chunks is not None and d.maxshape == (None,), f"{name} is not chunked with unlimited maxshape")
            require(d.compression == "gzip" and d.compression_opts == 4, f"{name}: compression {d.compression} {d.compression_opts}")
            require(d.shuffle and d.fletcher32, f"{name}: shuffle/fletcher32 missing")
            values = d[:]
            if dtype == F64:
                require(np.all(np.isfinite(values)), f"{name} holds non-finite values")
        require(np.all(f["particles/mass"][:] > 0) and np.all(f["particles/rho0"][:] > 0), "mass / rho0 not positive")
        require(len(np.unique(f["particles/id"][:])) == n, "ids are not unique")
        if has_rho:
            require(np.all(f["state/rho"][:] > 0), "rho not positive")
        return dim, n, has_rho, float(a["time"])


def make_checkpoints(binary, workdir):
    scene_1d = os.path.join(workdir, "layout_1d.toml")
    with open(scene_1d, "w") as out:
        out.write(ONE_D_SCENE)
    runs = [
        ["run", "--quiet", "--out", os.path.join(workdir, "cavity"), "--set", "time.end=0.01",
         "--set", "output.every=0.002", "--set", "time.steady_tolerance=1e-9", "--set", "time.steady_window=0.004"],
        ["run", scene_1d, "--quiet", "--out", os.path.join(workdir, "one_d"), "--set", "metrics.energy_budget=true"],
    ]
    for args in runs:
        r = subprocess.run([binary] + args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if r.returncode != 0:
            raise LayoutError(f"{' '.join(args)} exited {r.returncode}: {r.stderr.strip()}")
    return [os.path.join(workdir, "cavity", "checkpoint.h5"), os.path.join(workdir, "one_d", "checkpoint.h5")]


def main(argv):
    if len(argv) == 2 and argv[0] == "--run":
        with tempfile.TemporaryDirectory(prefix="arksph_layout_") as work:
            try:
                files = make_checkpoints(argv[1], work)
                results = [check_file(p) for p in files]
            except LayoutError as e:
                print(f"read_checkpoint.py: FAIL: {e}")
                return 1
            with h5py.File(files[1], "r") as f:  # the 1D run has the energy budget on
                if "viscous_dissipation" not in f.attrs:
                    print("read_checkpoint.py: FAIL: the 1D run with metrics.energy_budget has no 'viscous_dissipation'")
                    return 1
            require_kinds = {(r[0], r[2]) for r in results}
            if require_kinds != {(2, 1), (1, 0)}:
                print(f"read_checkpoint.py: FAIL: expected a 2D checkpoint with rho and a 1D one without, got {results}")
                return 1
            for p, r in zip(files, results):
                print(f"read_checkpoint.py: OK {os.path.basename(os.path.dirname(p))}: dimension {r[0]}, "
                      f"{r[1]} particles, density block {bool(r[2])}, t = {r[3]}")
            return 0
    if not argv or argv[0].startswith("-"):
        print(__doc__)
        return 2
    status = 0
    for path in argv:
        try:
            dim, n, has_rho, t = check_file(path)
            print(f"read_checkpoint.py: OK {path}: dimension {dim}, {n} particles, density block {bool(has_rho)}, t = {t}")
        except (LayoutError, OSError, KeyError) as e:
            print(f"read_checkpoint.py: FAIL {path}: {e}")
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
