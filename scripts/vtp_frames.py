"""The frame readers of python/arksph/readers.py under the names the case scripts use, importable
from scripts/ without a build:

    import sys; sys.path.insert(0, "<repo>/scripts")
    from vtp_frames import frames, read_vtp

read_vtp(path): the arrays of one .vtp or .pvtp frame by name ("Points", "velocity", "id", ...),
vectors as (n, components), rows in the file's order. frames(run): [(time, path)] of particles.pvd.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "python"))
from arksph.readers import frames, read_frame, read_run  # noqa: E402,F401

read_vtp = read_frame
