"""Reading arksph's run folders with NumPy only (no VTK needed).

A run folder holds particles.pvd (the list of frames and their times), one frame per output time
(particles_NNNNNN.vtp, or with output.pieces on several MPI ranks an index particles_NNNNNN.pvtp
naming one .vtp piece per rank), timeseries.csv and summary.json; with output.walls also walls.pvd
and one walls_NNNNNN.vtp (or .pvtp) per frame, the wall points (kind 1, "id" the particle imaged).

    from arksph.readers import read_run, read_frame, frames

    run = read_run("runs/taylor_green")
    last = run.frame(-1)          # {"time", "Points", "velocity", "pressure", "id", ...}
    u = last["velocity"][:, 0]

The .vtp files are VTK XML PolyData with appended raw binary data, as io/vtp_writer.cpp writes
them (zlib-compressed blocks, UInt64 headers); uncompressed data and UInt32 headers are read too.
Inline (base64) and ASCII arrays are not: arksph never writes them.
"""
import json
import struct
import xml.etree.ElementTree as ET
import zlib
from pathlib import Path

import numpy as np

__all__ = ["read_frame", "frames", "wall_frames", "read_run", "read_timeseries", "Run"]

# VTK XML type names -> NumPy type codes (the byte order is added from the file).
_TYPES = {"Float64": "f8", "Float32": "f4", "Int64": "i8", "Int32": "i4", "Int16": "i2", "Int8": "i1",
          "UInt64": "u8", "UInt32": "u4", "UInt16": "u2", "UInt8": "u1"}
_HEADER_TYPES = {"UInt64": "Q", "UInt32": "I"}


def _corrupt(path, reason):
    return ValueError("%s: truncated or corrupt VTK file (%s)" % (path, reason))


def _xml_root(path, text):
    try:
        return ET.fromstring(text)
    except ET.ParseError as e:
        raise _corrupt(path, "XML: %s" % e) from None


def _appended_array(path, raw, start, da, header, compressed, order):
    """The values of one appended DataArray, flat, in the file's type."""
    if da.get("format") != "appended":
        raise ValueError("%s: array %r is %r data; only appended raw data is read"
                         % (path, da.get("Name"), da.get("format")))
    dtype = np.dtype(order + _TYPES[da.get("type")]) if da.get("type") in _TYPES else None
    if dtype is None:
        raise ValueError("%s: array %r has unsupported type %r" % (path, da.get("Name"), da.get("type")))
    word = struct.calcsize(header)
    offset = da.get("offset", "")
    if not offset.isdigit():
        raise struct.error("array %r has no offset" % da.get("Name"))
    pos = start + int(offset)
    if compressed:
        # [blocks, block size, size of the last block (0: a full block), compressed sizes...]
        nblocks, block, last = struct.unpack_from(order + 3 * header, raw, pos)
        if pos + (3 + nblocks) * word > len(raw):
            raise struct.error("array %r: block sizes past the end of the file" % da.get("Name"))
        sizes = struct.unpack_from(order + "%d%s" % (nblocks, header), raw, pos + 3 * word)
        pos += (3 + nblocks) * word
        parts = []
        for s in sizes:
            if pos + s > len(raw):
                raise struct.error("block past the end of the file")
            parts.append(zlib.decompress(raw[pos:pos + s]))
            pos += s
        data = b"".join(parts)
        expected = 0 if nblocks == 0 else (nblocks - 1) * block + (last or block)
    else:
        (expected,) = struct.unpack_from(order + header, raw, pos)
        data = raw[pos + word:pos + word + expected]
    if len(data) != expected or expected % dtype.itemsize:
        raise struct.error("array %r has %d bytes, its header says %d" % (da.get("Name"), len(data), expected))
    # A writable copy in the machine's byte order.
    return np.frombuffer(data, dtype=dtype).astype(dtype.newbyteorder("="))


def _shaped(path, values, da, n):
    nc = int(da.get("NumberOfComponents", "1"))
    if values.size != n * nc:
        raise _corrupt(path, "array %r has %d values for %d points of %d components"
                       % (da.get("Name"), values.size, n, nc))
    return values.reshape(n, nc) if nc > 1 else values


def _read_vtp(path):
    """{name: array} of one .vtp file: the point-data arrays and "Points"."""
    raw = path.read_bytes()
    if not raw.rstrip().endswith(b"</VTKFile>"):
        raise _corrupt(path, "it does not end with </VTKFile>")
    marker = raw.find(b"<AppendedData")
    underscore = raw.find(b"_", marker)
    if marker < 0 or underscore < 0:
        raise _corrupt(path, "no appended data section")
    # The XML before the binary section, closed so that it parses on its own.
    root = _xml_root(path, raw[:marker] + b"</VTKFile>")
    if root.get("type") != "PolyData":
        raise ValueError("%s: a VTK %r file, not PolyData" % (path, root.get("type")))
    order = "<" if root.get("byte_order", "LittleEndian") == "LittleEndian" else ">"
    header = _HEADER_TYPES.get(root.get("header_type", "UInt32"))
    compressor = root.get("compressor")
    if header is None or compressor not in (None, "vtkZLibDataCompressor"):
        raise ValueError("%s: unsupported header type %r or compressor %r"
                         % (path, root.get("header_type"), compressor))
    pieces = root.findall("PolyData/Piece")
    if len(pieces) != 1:
        raise ValueError("%s: %d pieces in one .vtp file; arksph writes one" % (path, len(pieces)))
    piece = pieces[0]
    n = int(piece.get("NumberOfPoints"))
    named = [(da.get("Name"), da) for da in piece.findall("PointData/DataArray")]
    named += [("Points", da) for da in piece.findall("Points/DataArray")]
    arrays = {}
    for name, da in named:
        try:
            values = _appended_array(path, raw, underscore + 1, da, header, compressor is not None, order)
        except (struct.error, zlib.error) as e:
            raise _corrupt(path, str(e)) from None
        arrays[name] = _shaped(path, values, da, n)
    if "Points" not in arrays:
        raise _corrupt(path, "no Points array")
    return arrays


def _read_pvtp(path):
    """{name: array} of the pieces a .pvtp index lists, concatenated in the index's order."""
    root = _xml_root(path, path.read_bytes())
    if root.get("type") != "PPolyData":
        raise ValueError("%s: a VTK %r file, not PPolyData" % (path, root.get("type")))
    sources = [p.get("Source") for p in root.iter("Piece")]
    for s in sources:
        if not (path.parent / s).is_file():
            raise FileNotFoundError("%s: its piece %s is missing" % (path, s))
    parts = [_read_vtp(path.parent / s) for s in sources]
    if not parts:
        raise ValueError("%s: the index lists no pieces" % path)
    names = list(parts[0])
    for s, p in zip(sources, parts):
        if sorted(p) != sorted(names):
            raise ValueError("%s: piece %s has arrays %s, the first piece %s" % (path, s, sorted(p), sorted(names)))
    return {k: np.concatenate([p[k] for p in parts]) for k in names}


def read_frame(path):
    """One frame file (.vtp, or a .pvtp index and its pieces) as {name: NumPy array}.

    "Points" is (n, 3) (z = 0 in 2D, y = z = 0 in 1D), vector fields are (n, components) ("velocity"
    is (n, 3)), scalar fields 1-D ("pressure", "density", "summation_density", "mass", "h" as
    float64; "id" int64; "phase", "kind" int32; "free_surface" uint8, only in the frames of a scene with
    fluid.region). Rows are in the file's order, which arksph changes
    between frames (it re-sorts particles in memory); match rows across frames by "id".
    Raises FileNotFoundError for a missing file, ValueError naming the file if it is truncated,
    corrupt or in a format arksph does not write.
    """
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError("no frame file %s" % path)
    if path.suffix == ".pvtp":
        return _read_pvtp(path)
    return _read_vtp(path)


def _run_folder(run_dir):
    run_dir = Path(run_dir)
    if not run_dir.is_dir():
        raise FileNotFoundError("no run folder %s" % run_dir)
    return run_dir


def frames(run_dir):
    """[(time, frame path)] of a run folder, as its particles.pvd lists them (in time order)."""
    pvd = _run_folder(run_dir) / "particles.pvd"
    if not pvd.is_file():
        raise FileNotFoundError("no particles.pvd in %s (a run without frames, or not a run folder)" % run_dir)
    return _collection(pvd)


def wall_frames(run_dir):
    """[(time, wall file path)] of a run folder with output.walls, as its walls.pvd lists them; []
    when the run wrote no walls."""
    pvd = _run_folder(run_dir) / "walls.pvd"
    return _collection(pvd) if pvd.is_file() else []


def _collection(pvd):
    root = _xml_root(pvd, pvd.read_bytes())
    try:
        return [(float(d.get("timestep")), pvd.parent / d.get("file")) for d in root.iter("DataSet")]
    except (TypeError, ValueError):
        raise ValueError("%s: a DataSet without a numeric timestep or a file" % pvd) from None


def read_timeseries(path):
    """timeseries.csv as a pandas DataFrame when pandas imports, else a NumPy structured array with
    the CSV's column names (float64, "steps" int64); one row per output time."""
    path = Path(path)
    try:
        import pandas
        return pandas.read_csv(path, comment="#")
    except ImportError:
        pass
    lines = [l for l in path.read_text().splitlines() if l.strip() and not l.startswith("#")]
    if not lines:
        raise ValueError("%s: no header line" % path)
    names = [c.strip() for c in lines[0].split(",")]
    dtype = [(c, "i8" if c == "steps" else "f8") for c in names]
    rows = []
    for k, line in enumerate(lines[1:], start=2):
        cells = line.split(",")
        if len(cells) != len(names):
            raise ValueError("%s: row %d has %d values for %d columns" % (path, k, len(cells), len(names)))
        try:
            rows.append(tuple(int(v) if t == "i8" else float(v) for v, (_, t) in zip(cells, dtype)))
        except ValueError:
            raise ValueError("%s: row %d is not numeric" % (path, k)) from None
    return np.array(rows, dtype=dtype)


def _sorted_by_id(path, arrays):
    if "id" not in arrays:
        raise ValueError("%s: no 'id' array to sort by" % path)
    order = np.argsort(arrays["id"], kind="stable")
    return {k: v[order] for k, v in arrays.items()}


class _Frames:
    """The frames of a run as a read-only sequence that reads a file at each access (nothing kept)."""

    def __init__(self, run):
        self._run = run

    def __len__(self):
        return len(self._run.paths)

    def __getitem__(self, i):
        if isinstance(i, slice):
            return [self._run.frame(k) for k in range(*i.indices(len(self)))]
        return self._run.frame(i)

    def __iter__(self):
        return (self._run.frame(k) for k in range(len(self)))


class Run:
    """A run folder (read_run).

    Attributes:
      path        the folder (pathlib.Path)
      times       1-D float64 array of the frame times, from particles.pvd
      paths       the frame files (.vtp or .pvtp), one per time
      wall_times, wall_paths  output.walls: the times and wall files walls.pvd lists (empty without)
      frames      sequence of the frames (len, index, slice, iterate); each access reads the file
                  again and nothing is kept, so list(run.frames) holds every frame in memory
      timeseries  timeseries.csv (read_timeseries), None if the folder has none
      summary     summary.json as a dict, None if the folder has none
      sort_by_id  whether frame rows are ordered by particle id

    frame(i) reads frame i (negative i counts from the end): a dict of the read_frame arrays plus
    "time" (float). With sort_by_id the rows are ordered by "id", so a particle has the same row in
    every frame of the run.

    walls(i) reads the wall points of frame i (output.walls): the read_frame arrays of walls_NNNNNN
    plus "time", rows in id order of the particles imaged (several rows per particle near a corner).
    Raises FileNotFoundError for a run without wall files.
    """

    def __init__(self, run_dir, sort_by_id=True):
        self.path = _run_folder(run_dir)
        listed = frames(self.path)
        self.times = np.array([t for t, _ in listed], dtype=float)
        self.paths = [p for _, p in listed]
        walls = wall_frames(self.path)
        self.wall_times = np.array([t for t, _ in walls], dtype=float)
        self.wall_paths = [p for _, p in walls]
        self.sort_by_id = sort_by_id
        self.frames = _Frames(self)
        csv = self.path / "timeseries.csv"
        self.timeseries = read_timeseries(csv) if csv.is_file() else None
        summary = self.path / "summary.json"
        try:
            self.summary = json.loads(summary.read_text()) if summary.is_file() else None
        except ValueError as e:
            raise ValueError("%s: not valid JSON (%s)" % (summary, e)) from None

    def __len__(self):
        return len(self.paths)

    def __repr__(self):
        return "Run(%r, %d frames, t = %s .. %s)" % (
            str(self.path), len(self), self.times[0] if len(self) else "-", self.times[-1] if len(self) else "-")

    def frame(self, i):
        path = self.paths[i]
        arrays = read_frame(path)
        if self.sort_by_id:
            arrays = _sorted_by_id(path, arrays)
        arrays["time"] = float(self.times[i])
        return arrays


    def walls(self, i):
        if not self.wall_paths:
            raise FileNotFoundError("no walls.pvd in %s (a run without output.walls)" % self.path)
        arrays = read_frame(self.wall_paths[i])
        arrays["time"] = float(self.wall_times[i])
        return arrays


def read_run(run_dir, sort_by_id=True):
    """A run folder as a Run (see Run for its attributes). Raises FileNotFoundError for a missing
    folder or a folder without particles.pvd, ValueError naming the file for a corrupt one."""
    return Run(run_dir, sort_by_id=sort_by_id)
