// What a run is asked to do besides its scene (RunOptions) and how it ended (RunResult).
#pragma once
#include <string>

namespace arksph {

struct Checkpoint;  // io/checkpoint.hpp

struct RunOptions {
  bool quiet = false;        // no progress output
  double progress_every = 30;  // stderr not a terminal: wall seconds between progress lines (0: every step)
  bool write_frames = true;  // VTP frames and PVD
  const Checkpoint* restart = nullptr;  // arksph run --restart: continue from this checkpoint
  std::string restart_path;             // its file (for messages)
  bool overwrite = false;  // --overwrite: write into a folder that holds files other than run outputs
};

struct RunResult {
  int exit_code = 0;  // 0 ok, 3 numerical failure, 5 output could not be written, 6 out of memory, 128 + signal
  std::string message;
  bool interrupted = false;  // SIGHUP/SIGINT/SIGQUIT/SIGTERM: exit code 128 + signal, checkpoint written
  std::string checkpoint;    // the last checkpoint written ("" if none)
  double steady_time = -1;   // time.steady_tolerance: the output time at which the run stopped at steady state
  double steady_rate = 0;    // the steady-state change rate there (diagnostics/steady_state.hpp)
  double final_time = -1;    // the simulated time reached (the last completed step); -1 before the loop ran
};

}  // namespace arksph
