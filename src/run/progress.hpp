// Progress on stderr: a live line on a terminal. Otherwise (a log file, a batch or cluster job) a
// line per output frame, and one at least every `log_every` wall seconds between frames, so that a
// run with few frames (output.every = 0) still shows in its log that it is alive and how far it got.
#pragma once
#include <chrono>
#include <string>

namespace arksph {

class Progress {
 public:
  Progress(double t_end, bool quiet, double log_every = 30);
  void step(double t, long steps, double dt);   // called every step; rate-limited
  void frame(double t, long steps, double dt);  // called at every output time
  void finish();

 private:
  double eta(double t) const;
  void line(double t, long steps, double dt);  // one log line
  double t_end_, log_every_;
  bool quiet_, tty_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace arksph
