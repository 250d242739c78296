"""The point-data arrays and "Points" of an arksph frame (.vtp, or a .pvtp index of pieces) as the
MPI checks use them: read_arrays(path) -> {name: list of values, components flattened}. The file is
read by python/arksph/readers.py (NumPy, no VTK)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from arksph.readers import read_frame  # noqa: E402


def read_arrays(path):
    return {name: values.ravel().tolist() for name, values in read_frame(path).items()}
