// The output folder of one run (output.directory), and what a run may find in it.
//
// No links. Every file a run writes there is opened or renamed inside the folder; a run output name
// (or the lock) that is a symbolic link makes the folder refused (InputError, exit 2), so that no
// write follows a link out of the folder.
//
// Exclusive use. A run holds an advisory lock (flock) on DIR/.arksph.lock from start to exit, so
// two runs never write into the same folder: the second is refused (InputError, exit 2) with the
// pid of the holder. The lock is released by the kernel when the process ends, also on a crash.
//
// Contract for what is already there (docs/user-guide.md, "The output folder"):
//   - a fresh run removes the files a run writes (is_run_output) before writing its own, so no frame
//     of an earlier, longer run is left beside the new ones;
//   - files that are not run outputs make the folder refused (exit 2) unless --overwrite is given;
//     they are never removed;
//   - a run writes its run id into summary.json and particles.pvd; a restart keeps the run id of
//     its checkpoint, and is refused (exit 2) in a folder whose outputs carry another run id or none.
#pragma once
#include <string>
#include <vector>

namespace arksph {

// True for the name of a file that arksph runs write into their folder: frames, collection, CSV
// tables, summary.json, checkpoints, their temporaries, the lock, and the batch runner's run.log
// and batch_run.txt.
bool is_run_output(const std::string& filename);

// A fresh random run id (16 hexadecimal digits).
std::string new_run_id();

class OutputFolder {
 public:
  // Creates `dir` (OutputError if it cannot be created) and takes its lock (InputError naming the
  // pid of the run that holds it). `source` prefixes the messages (the scene, sweep or study file),
  // `key` names the setting that chose the folder (output.directory of a scene, study.output).
  OutputFolder(const std::string& dir, const std::string& source, const std::string& key = "output.directory");
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  // Refuses (InputError) a folder holding files that are not run outputs, naming a few of them.
  void refuse_foreign_files() const;
  // Removes the run outputs of an earlier run (run.log and batch_run.txt stay: the batch runner
  // wrote them for this run) and returns how many files and frames (particles_N.vtp/.pvtp) went.
  // OutputError if one cannot be removed.
  struct Removed {
    long files = 0, frames = 0;
  };
  Removed remove_run_outputs() const;
  // The run id the folder's outputs carry (summary.json, else particles.pvd); "" if none is found.
  // `unidentified` (optional) is set when "" comes from a readable summary.json or collection that
  // carries no id (the output of a run that wrote none).
  std::string run_id(bool* unidentified = nullptr) const;

 private:
  std::string dir_, source_, key_;
  int lock_fd_ = -1;
};

}  // namespace arksph
