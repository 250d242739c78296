// Wall seconds since a time point of the steady clock (the timings of summary.json and the solvers).
#pragma once
#include <chrono>

namespace arksph {

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace arksph
