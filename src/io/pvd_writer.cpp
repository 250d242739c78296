// Hand-written VTK Collection XML (.pvd), rewritten atomically after each frame.
#include "io/pvd_writer.hpp"

#include <cstdio>
#include <filesystem>

#include "io/csv_writer.hpp"  // write_text_atomic

namespace arksph {
namespace {

// Escapes a string for an XML attribute value in double quotes.
std::string xml_attr(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

PvdCollection::PvdCollection(std::string dir, std::string name)
    : path_((std::filesystem::path(std::move(dir)) / name).string()) {}

void PvdCollection::add(double time, const std::string& vtp_filename) {
  frames_.push_back({time, vtp_filename});
  write();
}

void PvdCollection::write() const {
  std::string xml = "<?xml version=\"1.0\"?>\n";
  if (!run_id_.empty()) xml += "<!-- arksph run_id=\"" + xml_attr(run_id_) + "\" -->\n";
  xml +=
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  char t[32];
  for (const Entry& e : frames_) {
    std::snprintf(t, sizeof t, "%.17g", e.time);  // full precision: times are read back exactly
    xml += "    <DataSet timestep=\"" + std::string(t) + "\" group=\"\" part=\"0\" file=\"" + xml_attr(e.file) + "\"/>\n";
  }
  xml += "  </Collection>\n</VTKFile>\n";
  write_text_atomic(path_, xml);
}

}  // namespace arksph
