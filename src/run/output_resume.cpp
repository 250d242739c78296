// Output continuation after a restart: read what the earlier run wrote, then carry it into the new
// RunOutput (frame numbering, PVD entries, CSV rows, the Poiseuille window maximum).
#include "run/output_resume.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/file_text.hpp"
#include "run/checkpointing.hpp"  // scheduled_time
#include "run/run_output.hpp"
#include "io/csv_writer.hpp"

namespace arksph {

namespace {

// The value of attribute `name="..."` in an XML element line, entities decoded; "" if absent.
std::string xml_attribute(const std::string& line, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const auto b = line.find(key);
  if (b == std::string::npos) return {};
  const auto start = b + key.size();
  const auto e = line.find('"', start);
  if (e == std::string::npos) return {};
  std::string raw = line.substr(start, e - start), out;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] != '&') {
      out += raw[i];
      continue;
    }
    static const std::pair<const char*, char> entities[] = {{"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}};
    bool done = false;
    for (const auto& [ent, c] : entities)
      if (raw.compare(i, std::char_traits<char>::length(ent), ent) == 0) {
        out += c;
        i += std::char_traits<char>::length(ent) - 1;
        done = true;
        break;
      }
    if (!done) out += '&';
  }
  return out;
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream ss(line);
  while (std::getline(ss, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// Row times are printed with 10 significant digits: allow for that rounding.
bool at_or_before(double t, double time) { return t <= time + 1e-9 * std::max(1.0, std::abs(time)); }

// particles.pvd missing or unreadable: the entries of the particles_NNNNNN.vtp files found before the
// checkpoint's frame, at the time of the timeseries.csv row of the same index (one row per frame),
// or at frame * output.every without that row. Warns on stderr, except for a new folder (no
// collection, no frame).
void rebuild_collection(OutputHistory& h, const std::string& dir, double every, const char* state) {
  long found = 0;
  for (long k = 0; k < h.frames; ++k) {
    char name[64];
    std::snprintf(name, sizeof name, "particles_%06ld.vtp", k);
    if (!std::filesystem::is_regular_file(std::filesystem::path(dir) / name)) continue;
    const double t = k < static_cast<long>(h.csv_rows.size()) ? h.csv_rows[k][0] : scheduled_time(k, every);
    h.pvd.emplace_back(t, name);
    ++found;
  }
  if (found == 0 && std::string(state) == "missing") return;  // a new folder (--out): nothing was lost
  std::fprintf(stderr,
               "arksph: warning: particles.pvd of the earlier run is %s; rebuilt from the %ld particles_*.vtp "
               "frame(s) found before frame %ld\n",
               state, found, h.frames);
}

}  // namespace

OutputHistory read_output_history(const std::string& dir, double time, long frames, double every) {
  OutputHistory h;
  h.frames = frames;
  h.time = time;
  const std::string pvd_text = file_text(dir + "/particles.pvd");
  const bool pvd_ok = pvd_text.find("<VTKFile") != std::string::npos && pvd_text.find("<Collection") != std::string::npos &&
                      pvd_text.find("</VTKFile>") != std::string::npos;
  std::istringstream pvd(pvd_ok ? pvd_text : std::string());
  for (std::string line; std::getline(pvd, line);) {
    if (line.find("<DataSet") == std::string::npos) continue;
    const std::string t = xml_attribute(line, "timestep"), file = xml_attribute(line, "file");
    if (t.empty() || file.empty()) continue;
    const double tv = std::strtod(t.c_str(), nullptr);
    if (tv <= time) h.pvd.emplace_back(tv, file);  // written with %.17g: exact
  }
  h.csv_text = file_text(dir + "/timeseries.csv");
  std::istringstream csv(h.csv_text);
  std::string line;
  if (std::getline(csv, line)) h.csv_header = split_commas(line);
  while (std::getline(csv, line)) {
    if (line.empty()) continue;
    std::vector<double> row;
    for (const std::string& cell : split_commas(line)) row.push_back(std::strtod(cell.c_str(), nullptr));
    if (row.size() != h.csv_header.size()) break;  // a row cut short by a kill: the rest is unreliable
    if (!at_or_before(row[0], time)) break;          // rows are in time order
    h.csv_rows.push_back(std::move(row));
  }
  if (!pvd_ok && frames > 0) rebuild_collection(h, dir, every, pvd_text.empty() ? "missing" : "unreadable");
  return h;
}

// Declared in run/run_output.hpp. Rows are re-printed with the same %.10g format, which gives back
// the same text.
void RunOutput::resume(const OutputHistory& h) {
  frames_ = static_cast<int>(h.frames);
  last_t_ = h.time;
  if (pvd_)
    for (const auto& [t, file] : h.pvd) pvd_->add(t, file);
  if (walls_pvd_)  // output.walls: the earlier frames' wall files that are there (walls_NNNNNN beside particles_NNNNNN)
    for (const auto& [t, file] : h.pvd) {
      const std::string walls = file.rfind("particles_", 0) == 0 ? "walls_" + file.substr(10) : std::string();
      if (!walls.empty() && std::filesystem::exists(scene_.directory + "/" + walls)) walls_pvd_->add(t, walls);
    }
  const std::vector<std::string> columns = csv_columns();
  if (!h.csv_text.empty() && h.csv_header != columns) {
    const std::string kept = scene_.directory + "/timeseries_before_restart.csv";
    write_text_atomic(kept, h.csv_text);
    std::fprintf(stderr, "arksph: warning: timeseries.csv of the earlier run has other columns; kept as %s\n",
                 kept.c_str());
    return;
  }
  std::size_t tstar = columns.size(), eps = columns.size();
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == "tstar") tstar = i;
    if (columns[i] == "poiseuille_eps") eps = i;
  }
  for (const auto& row : h.csv_rows) {
    csv_.row(row);
    if (tstar < row.size() && eps < row.size() && row[tstar] >= 0.5 - 1e-9 && row[tstar] <= 2.0 + 1e-9 &&
        std::isfinite(row[eps]))
      eps_max_window_ = std::max(eps_max_window_, row[eps]);
  }
}

}  // namespace arksph
