"""arksph from Python: the particle ODE of a scene as a callable, and the readers of a run's output.

    import arksph                       # PYTHONPATH=build/python after ./scripts/build.sh
    model = arksph.Model("cases/taylor_green/scene.toml", set={"fluid.spacing": 1 / 16})
    dydt = model.rhs(0.0, model.y0)
    run = arksph.read_run("out/taylor_green")

docs/python.md has the guide. The readers are pure Python (numpy); the model needs the compiled
module that the build puts beside this file.
"""
from .readers import frames, read_frame, read_run

try:
    from ._arksph import InputError, NumericalFailure
    from .model import Model, RunError, erk_table
except ImportError as missing:  # the readers work from the source tree without a build
    _why = str(missing)

    def _needs_build(*args, **kwargs):
        raise ImportError("arksph.Model and arksph.erk_table need the compiled module: run ./scripts/build.sh "
                          f"and use PYTHONPATH=build/python ({_why})")

    Model = erk_table = _needs_build

    class RunError(RuntimeError):
        pass

    class InputError(ValueError):
        pass

    class NumericalFailure(RuntimeError):
        pass

__all__ = ["Model", "RunError", "erk_table", "InputError", "NumericalFailure", "read_run", "read_frame", "frames"]
