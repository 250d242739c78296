// Error types that map to the exit codes (2 bad input, 3 numerical failure, 6 out of memory).
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

// An allocation failed (std::bad_alloc) although the estimate let the run start: exit code 6.
// what() names what was being allocated.
struct OutOfMemory : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A number for a message: "%g" with NaN of either sign as "NaN" (printf gives "-nan" for some).
std::string message_number(double v);

// What the program is doing, for the message of an allocation failure that reaches main() as a bare
// std::bad_alloc: set at the start of each phase of set-up ("building the particle lattice ...").
void set_activity(std::string what);
const std::string& activity();

}  // namespace arksph
