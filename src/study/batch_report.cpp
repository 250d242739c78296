// batch.csv and batch.json of `arksph batch` (see batch.hpp).
#include <fstream>
#include <sstream>
#include <set>

#include "core/errors.hpp"
#include "io/csv_writer.hpp"  // write_text_atomic
#include "io/summary_json.hpp"
#include "study/batch.hpp"

namespace arksph {

namespace {
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// Metric names in order of first appearance over the runs.
std::vector<std::string> metric_names(const BatchResult& res) {
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const auto& r : res.runs)
    for (const auto& [k, v] : r.metrics)
      if (seen.insert(k).second) names.push_back(k);
  return names;
}
}  // namespace

void write_batch_csv(const Sweep& sw, const BatchResult& res, const std::string& path) {
  std::ostringstream f;
  const auto names = metric_names(res);
  f << "run";
  for (const auto& key : sw.columns) f << "," << csv_field(key);
  f << ",status,exit_code,skipped,wall_seconds,steps,rhs_evals,resumed";
  for (const auto& n : names) f << "," << csv_field(n);
  f << "\n";
  for (const auto& r : res.runs) {
    f << csv_field(r.name);
    for (const auto& v : r.values) f << "," << csv_field(v);
    f << "," << r.status << "," << r.exit_code << "," << (r.skipped ? 1 : 0) << "," << r.wall_seconds << "," << r.steps
      << "," << r.rhs_evals << "," << (r.resumed ? 1 : 0);
    for (const auto& n : names) {
      std::string value;
      for (const auto& [k, v] : r.metrics)
        if (k == n) value = v;
      f << "," << value;
    }
    f << "\n";
  }
  write_text_atomic(path, f.str());  // OutputError (exit 5) if it cannot be written
}

void write_batch_json(const Sweep& sw, const BatchResult& res, const std::string& path) {
  Json j = Json::object();
  j.set("sweep", sw.source).set("scene", sw.scene);
  j.set("common_set", sw.common_sets);
  Json keys = Json::array();
  for (const auto& key : sw.columns) keys.push(key);
  j.set("vary", keys);
  j.set("runs_total", res.runs.size()).set("runs_not_ok", res.failed).set("runs_skipped", res.skipped);
  j.set("wall_seconds", res.wall_seconds);
  Json runs = Json::array();
  for (const auto& r : res.runs) {
    Json o = Json::object();
    o.set("run", r.name).set("dir", r.dir);
    Json set = Json::object();
    for (std::size_t c = 0; c < sw.columns.size(); ++c) set.set(sw.columns[c], r.values[c]);
    o.set("set", set);
    o.set("status", r.status).set("exit_code", r.exit_code).set("skipped", r.skipped);
    o.set("wall_seconds", r.wall_seconds).set("steps", r.steps).set("rhs_evals", r.rhs_evals);
    o.set("resumed", r.resumed);
    Json m = Json::object();
    for (const auto& [k, v] : r.metrics) m.set(k, std::strtod(v.c_str(), nullptr));
    o.set("metrics", m);
    runs.push(o);
  }
  j.set("runs", runs);
  std::ostringstream f;
  f << j.dump(2) << "\n";
  write_text_atomic(path, f.str());
}

}  // namespace arksph
