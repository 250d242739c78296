"""Reads the point-data arrays of an arksph VTP frame (appended raw binary, zlib blocks with UInt64
headers, as io/vtp_writer.cpp writes them) without VTK: read_arrays(path) -> {name: list of values,
components flattened}."""
import re
import struct
import zlib

_TYPES = {"Float64": "d", "Float32": "f", "Int64": "q", "Int32": "i", "UInt8": "B", "UInt64": "Q"}


def read_arrays(path):
    data = open(path, "rb").read()
    start = data.index(b"<AppendedData")
    blob = data[data.index(b"_", start) + 1:]
    head = data[:start].decode("latin-1")
    arrays = {}
    for m in re.finditer(r"<DataArray ([^>]*)>", head):
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', m.group(1)))
        if "offset" not in attrs or attrs.get("type") not in _TYPES:
            continue
        at = int(attrs["offset"])
        nblocks, _, _ = struct.unpack_from("<QQQ", blob, at)
        sizes = struct.unpack_from("<%dQ" % nblocks, blob, at + 24)
        pos = at + 24 + 8 * nblocks
        raw = b""
        for s in sizes:
            raw += zlib.decompress(blob[pos:pos + s])
            pos += s
        code = _TYPES[attrs["type"]]
        arrays[attrs.get("Name", "")] = list(struct.unpack("<%d%s" % (len(raw) // struct.calcsize(code), code), raw))
    return arrays
