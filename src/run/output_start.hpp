// The start of a run's output folder (run/output_folder.hpp): a fresh run clears an earlier run's
// outputs and takes a new run id; a restart checks that the folder holds its own run's outputs and
// keeps the checkpoint's run id.
#pragma once
#include <string>

#include "core/scene.hpp"
#include "run/output_folder.hpp"
#include "run/run_result.hpp"

namespace arksph {

// Returns the run id. InputError when a restart finds another run's outputs in the folder.
std::string start_output_folder(const OutputFolder& folder, const Scene& scene, const RunOptions& options);

}  // namespace arksph
