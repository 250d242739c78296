// Sweep files for `arksph batch`: a base scene and lists of --set values whose Cartesian product
// is run, one folder per run.
//
//   [sweep]
//   scene = "taylor_green.toml"      # relative to the sweep file
//   output = "runs/ci_sweep"         # batch folder (relative to the working directory); --out overrides
//   jobs = 2                         # runs at a time; --jobs overrides; default: the number of cores
//   set = ["time.end=0.1"]           # --set values applied to every run (optional)
//
//   [[vary]]                         # one table per axis; the first axis varies slowest
//   key = "method.kernel"
//   values = ["cubic_spline", "wendland_quintic"]
//
//   [[vary]]                         # linked keys: varied together, one array of values per point
//   key = ["fluid.spacing", "method.h_over_dx"]
//   values = [[0.04, 1.2], [0.02, 1.6]]
//
// Run folders are named <index>_<last key part>-<value>_..., e.g.
// "03_kernel-wendland_quintic_integrator-ARKODE_HEUN_EULER_2_1_2", with characters other than
// [A-Za-z0-9._-] replaced by '_': deterministic, so a second invocation finds its runs again. A
// value longer than 40 characters is cut and ends in "~" and a hash of the whole value; a name
// longer than 120 characters likewise. A key may be varied or set (sweep.set, batch --set), not
// both; output.directory is neither (each run has its own folder).
#pragma once
#include <string>
#include <vector>

namespace arksph {

struct SweepAxis {
  std::vector<std::string> keys;                 // dotted scene keys (more than one: linked, varied together)
  std::vector<std::vector<std::string>> values;  // per point of the axis, one --set value per key (TOML text; strings bare)
};

struct SweepRun {
  std::string name;                    // folder name
  std::vector<std::string> values;     // one per column (Sweep::columns)
  std::vector<std::string> sets;       // common sets, then "key=value" per axis
};

struct Sweep {
  std::string source;      // the sweep file
  std::string scene;       // the base scene, resolved against the sweep file's folder
  std::string output;      // batch folder
  int jobs = 0;            // 0: not given
  std::vector<std::string> common_sets;
  std::vector<SweepAxis> axes;
  std::vector<std::string> columns;  // every varied key, axis by axis
  std::vector<SweepRun> runs;  // the Cartesian product, first axis slowest
};

// Reads and checks the sweep file; throws InputError "<file>: <key>: <reason>" (one line).
Sweep read_sweep_file(const std::string& path);
Sweep read_sweep_text(const std::string& text, const std::string& source);

// The varied key that the override "KEY=VALUE" would replace (the same key, or a table holding it,
// or a key inside it), or output.directory; "" if none.
std::string varied_key_overridden(const Sweep& sw, const std::string& set);

}  // namespace arksph
