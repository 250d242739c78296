// Runs of the periodic Taylor-Green vortex of tests/scenes/taylor_green_vortex_25.toml, scored by the
// relative L1 velocity error against the exact decay that the run writes to summary.json.
#pragma once
#include <doctest/doctest.h>

#include <sstream>
#include <string>
#include <vector>

#include "io/json_reader.hpp"
#include "io/scene_reader.hpp"
#include "run/simulation.hpp"
#include "test_support.hpp"

namespace arksph::testing {

inline const std::string kTaylorGreenVortex25 = test_scene("taylor_green_vortex_25.toml");

// The relative L1 velocity error at the end of the vortex run with the --set values `sets`, its
// output in dir/name.
inline double vortex_l1_error(const ScratchDir& dir, const std::string& name, std::vector<std::string> sets) {
  const std::string out = dir / name;
  sets.push_back("output.directory=\"" + out + "\"");
  std::ostringstream warnings;
  const Scene scene = read_scene_text(kTaylorGreenVortex25, "<test>", sets, warnings);
  RunOptions opt;
  opt.quiet = true;
  opt.write_frames = false;
  REQUIRE(run_simulation(scene, opt).exit_code == 0);
  const JsonValue j = read_json_file(out + "/summary.json");
  const JsonValue* v = j.find("metrics")->find("velocity_l1_relative");
  REQUIRE(v != nullptr);
  return v->number;
}

}  // namespace arksph::testing
