// Progress on stderr: a live line on a terminal, one quiet line per output frame otherwise.
#pragma once
#include <chrono>
#include <string>

namespace arksph {

class Progress {
 public:
  Progress(double t_end, bool quiet);
  void step(double t, long steps, double dt);   // called every step; rate-limited on a terminal
  void frame(double t, long steps, double dt);  // called at every output time
  void finish();

 private:
  double eta(double t) const;
  double t_end_;
  bool quiet_, tty_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace arksph
