// One run of a scene: set-up from the scene, the time loop, diagnostics and output.
#pragma once
#include <string>

#include "core/scene.hpp"
#include "run/run_result.hpp"

namespace arksph {

// Runs the scene into scene.directory. Throws InputError for bad input discovered at set-up (also:
// the folder is locked by another run, holds foreign files, or another run's output on restart),
// OutputError if the folder cannot be created. A write failure during the run gives exit code 5
// with the checkpoint and summary.json written where space allows.
// InterruptedDuringSetup for a signal before the first step (run/interrupt.hpp).
RunResult run_simulation(const Scene& scene, const RunOptions& options);

}  // namespace arksph
