#include "io/pvtp_writer.hpp"

#include <cstdio>

#include "io/csv_writer.hpp"  // write_text_atomic
#include "io/output_fields.hpp"

namespace arksph {

std::string piece_file_name(int frame, int rank, const char* prefix) {
  char name[96];
  std::snprintf(name, sizeof name, "%s_%06d_r%d.vtp", prefix, frame, rank);
  return name;
}

void write_pvtp(const std::string& path, const std::vector<std::string>& pieces, bool free_surface) {
  std::string x = "<?xml version=\"1.0\"?>\n"
                  "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
                  "  <PPolyData GhostLevel=\"0\">\n    <PPointData>\n";
  const auto declare = [&](const OutputField& f) {
    x += std::string("      <PDataArray type=\"") + field_type_name(f.type) + "\" Name=\"" + f.name +
         "\" NumberOfComponents=\"" + std::to_string(f.components) + "\"/>\n";
  };
  for (const OutputField& f : kOutputFields) declare(f);
  if (free_surface) declare(kOptionalOutputFields[0]);
  x += "    </PPointData>\n    <PPoints>\n"
       "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
  for (const std::string& p : pieces) x += "    <Piece Source=\"" + p + "\"/>\n";
  x += "  </PPolyData>\n</VTKFile>\n";
  write_text_atomic(path, x);
}

}  // namespace arksph
