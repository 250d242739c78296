// One VTK XML PolyData (.vtp) frame: points (x, y, 0), one vertex cell per particle, and the
// point-data arrays of the output-field table (io/output_fields.hpp), and the optional ones the frame
// carries (carries()).
#pragma once
#include <string>

#include "io/frame.hpp"
#include "io/output_fields.hpp"

namespace arksph {

// Whether a frame carries an optional field (kOptionalOutputFields): free_surface when f.free_surface is set.
bool carries(const OutputField& field, const Frame& f);

// Writes f to path: binary appended data, raw (not base64), zlib level 5, UInt64 headers.
// Written to path + ".tmp" and renamed onto path, so a reader never sees a partial frame.
// Throws std::invalid_argument if a field the frame must carry is null, and
// std::runtime_error("cannot write <path>: <reason>") on an I/O error (no temporary is left).
void write_vtp(const std::string& path, const Frame& f);

}  // namespace arksph
