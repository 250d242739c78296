// One run of a scene: set-up from the scene, the time loop, diagnostics and output.
#pragma once
#include <string>

#include "core/scene.hpp"

namespace arksph {

struct RunOptions {
  bool quiet = false;        // no progress output
  bool write_frames = true;  // VTP frames and PVD
};

struct RunResult {
  int exit_code = 0;  // 0 ok, 3 numerical failure (INTERFACE.md)
  std::string message;
};

// Runs the scene into scene.directory. Throws InputError for bad input discovered at set-up.
RunResult run_simulation(const Scene& scene, const RunOptions& options);

}  // namespace arksph
