"""Reading arksph's particle frames without VTK: the .vtp files arksph writes (appended raw binary,
zlib-compressed blocks, UInt64 headers) and the particles.pvd that lists them.

    import sys; sys.path.insert(0, "<repo>/scripts")
    from vtp_frames import frames, read_vtp
"""
import re
import struct
import xml.etree.ElementTree as ET
import zlib
from pathlib import Path

import numpy as np

DTYPES = {"Float64": "<f8", "Int64": "<i8", "Int32": "<i4", "Float32": "<f4", "UInt8": "u1"}


def read_vtp(path):
    """The arrays of one frame by name ("Points", "velocity", "id", ...), vectors as (n, components)."""
    raw = Path(path).read_bytes()
    marker = raw.index(b"<AppendedData")
    start = raw.index(b"_", marker) + 1
    head = raw[:marker].decode()
    arrays = {}
    for tag in re.findall(r"<DataArray[^>]*>", head):
        da = dict(re.findall(r'(\w+)="([^"]*)"', tag))
        off = start + int(da.get("offset"))
        nblocks, _, _ = struct.unpack_from("<QQQ", raw, off)
        sizes = struct.unpack_from("<%dQ" % nblocks, raw, off + 24)
        pos = off + 24 + 8 * nblocks
        data = b""
        for s in sizes:
            data += zlib.decompress(raw[pos:pos + s])
            pos += s
        a = np.frombuffer(data, dtype=DTYPES[da.get("type")])
        nc = int(da.get("NumberOfComponents", "1"))
        arrays[da.get("Name")] = a.reshape(-1, nc) if nc > 1 else a
    return arrays


def frames(run):
    """(time, .vtp path) of every frame a run folder's particles.pvd lists, in its order."""
    root = ET.parse(Path(run) / "particles.pvd").getroot()
    return [(float(d.get("timestep")), Path(run) / d.get("file")) for d in root.iter("DataSet")]
