// The index of a frame written in pieces (output.pieces, runs over several MPI ranks): a VTK XML
// PPolyData file (.pvtp) that declares the points and the point-data arrays of the output-field
// table (io/output_fields.hpp), as every piece carries them (io/vtp_writer.hpp), and names the
// pieces, one .vtp per rank. ParaView and VTK's vtkXMLPPolyDataReader read the pieces as one data set.
#pragma once
#include <string>
#include <vector>

namespace arksph {

// particles_NNNNNN_rR.vtp: the piece of frame `frame` written by rank `rank` (walls_NNNNNN_rR.vtp
// with prefix "walls", output.walls).
std::string piece_file_name(int frame, int rank, const char* prefix = "particles");

// Writes the index atomically; `pieces` are file names relative to the index's folder. Throws
// OutputError("cannot write <path>: reason"). `free_surface`: the pieces carry the free_surface array
// too (io/output_fields.hpp, kOptionalOutputFields).
void write_pvtp(const std::string& path, const std::vector<std::string>& pieces, bool free_surface = false);

}  // namespace arksph
