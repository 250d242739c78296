// Continuing a run's output directory after a restart (arksph run --restart): the frames written
// before the checkpoint keep their numbers, particles.pvd keeps their entries, timeseries.csv keeps
// their rows; what the interrupted run wrote after the checkpoint time is superseded.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace arksph {

struct OutputHistory {
  long frames = 0;                                  // frames written up to the checkpoint (next index)
  double time = 0;                                  // the checkpoint time
  std::vector<std::pair<double, std::string>> pvd;  // particles.pvd entries at t <= time
  std::string csv_text;                             // timeseries.csv as found ("" if none)
  std::vector<std::string> csv_header;
  std::vector<std::vector<double>> csv_rows;        // rows at t <= time
};

// Reads what an earlier run left in `dir`. Must be called before RunOutput (which truncates the
// CSV) is constructed; RunOutput::resume then carries it over. A missing timeseries.csv gives no
// rows. A missing or unreadable particles.pvd is rebuilt from the particles_NNNNNN.vtp files found
// before frame `frames` (times from timeseries.csv, else frame * `every`), with a warning on stderr.
OutputHistory read_output_history(const std::string& dir, double time, long frames, double every);

}  // namespace arksph
