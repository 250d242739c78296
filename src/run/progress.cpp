#include "run/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace arksph {

Progress::Progress(double t_end, bool quiet, double log_every)
    : t_end_(t_end), log_every_(log_every), quiet_(quiet), tty_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

double Progress::eta(double t) const {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return t > 0 ? elapsed * (t_end_ - t) / t : 0.0;
}

void Progress::step(double t, long steps, double dt) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  if (!tty_) {
    if (std::chrono::duration<double>(now - last_).count() >= log_every_) line(t, steps, dt);
    return;
  }
  if (std::chrono::duration<double>(now - last_).count() < 0.2) return;
  last_ = now;
  std::fprintf(stderr, "\r  t = %-10.5g / %g  steps %-9ld dt %-10.3g ETA %6.1f s   ", t, t_end_, steps, dt, eta(t));
  std::fflush(stderr);
}

void Progress::frame(double t, long steps, double dt) {
  if (quiet_ || tty_) return;
  line(t, steps, dt);
}

void Progress::line(double t, long steps, double dt) {
  last_ = std::chrono::steady_clock::now();
  std::fprintf(stderr, "  t = %.6g / %g  steps %ld  dt %.4g  ETA %.1f s\n", t, t_end_, steps, dt, eta(t));
  std::fflush(stderr);
}

void Progress::finish() {
  if (!quiet_ && tty_) std::fprintf(stderr, "\r%80s\r", "");
}

}  // namespace arksph
