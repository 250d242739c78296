// Error types that map to the exit codes (README.md, "Exit codes"): 2 bad input, 3 numerical
// failure, 5 output could not be written, 6 out of memory.
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

// An output file could not be written (disk full, file size limit, unwritable folder): exit code 5.
// what() is "cannot write PATH: reason".
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A message on one line (the exit-code contract): line breaks, from a multi-line TOML string or an
// expression, become spaces.
inline std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

// A value as echoed in a message: one line, at most about 200 characters. A longer text is cut
// (never inside a UTF-8 character) and ends in "… (N characters)", so that a 1 MB value or a huge
// expression does not flood stderr.
inline std::string echo_value(const std::string& value, std::size_t limit = 200) {
  std::string s = value.size() > limit ? value.substr(0, limit) : value;
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  if (value.size() > limit) {
    // Drop a UTF-8 character cut in two: its lead byte says how many bytes it needs.
    std::size_t i = s.size(), continuation = 0;
    while (i > 0 && continuation < 3 && (static_cast<unsigned char>(s[i - 1]) & 0xC0) == 0x80) --i, ++continuation;
    if (i > 0) {
      const unsigned char lead = static_cast<unsigned char>(s[i - 1]);
      const std::size_t need = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
      if (need != continuation + 1) s.resize(i - 1);
    }
    std::size_t characters = 0;  // UTF-8 characters: bytes that are not continuation bytes
    for (char c : value) characters += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    s += "\u2026 (" + std::to_string(characters) + " characters)";
  }
  return s;
}
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
