// Error types that map to the exit codes (2 bad input, 3 numerical failure).
#pragma once
#include <stdexcept>
#include <string>

namespace arksph {

// Bad input (scene, option, value): exit code 2. what() is one line "FILE: KEY: reason".
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The simulation failed numerically (NaN, blow-up, escape): exit code 3.
struct NumericalFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace arksph
