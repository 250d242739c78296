"""arksph from Python: reading run folders (arksph.readers, pure Python with NumPy)."""
from .readers import read_run, read_frame, frames
