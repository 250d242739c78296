// The whole content of a file as bytes; empty when it cannot be read (a missing lock, a folder
// without timeseries.csv): the callers treat "no file" and "empty file" alike.
#pragma once
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace arksph {

inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace arksph
