#include "run/output_start.hpp"

#include <cstdio>

#include "core/errors.hpp"
#include "io/checkpoint.hpp"

namespace arksph {

std::string start_output_folder(const OutputFolder& folder, const Scene& scene, const RunOptions& options) {
  if (!options.restart) {
    const OutputFolder::Removed removed = folder.remove_run_outputs();
    if (removed.files > 0)
      std::printf("arksph: replacing the earlier run in %s: %ld frames, %ld files removed\n", scene.directory.c_str(),
                  removed.frames, removed.files);
    return new_run_id();
  }
  const std::string& mine = options.restart->run_id;
  bool unidentified = false;  // output without a run id cannot be this run's: it writes its id
  const std::string found = folder.run_id(&unidentified);
  if (!mine.empty() && ((!found.empty() && found != mine) || unidentified))
    throw InputError(options.restart_path + ": output.directory: " + scene.directory +
                     " holds the output of another run (run id " + (found.empty() ? "none" : echo_value(found, 40)) +
                     ", the checkpoint's is " + mine + "); continue in the run's own folder or give an empty --out");
  return mine.empty() ? new_run_id() : mine;
}

}  // namespace arksph
