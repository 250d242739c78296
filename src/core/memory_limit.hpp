// How much memory a run may use (run/memory_estimate.hpp compares a run's needs with it): the
// smaller of the machine's available memory (MemAvailable of /proc/meminfo) and the address-space
// limit of the process (RLIMIT_AS, `ulimit -v`); the environment variable ARKSPH_MEMORY_LIMIT
// replaces it (bytes, or with a suffix K, M, G, T: "4G" = 4 * 2^30 bytes).
#pragma once
#include <string>

namespace arksph {

struct MemoryLimit {
  double bytes = 0;    // +infinity when nothing limits it
  std::string source;  // "MemAvailable", "RLIMIT_AS" or "ARKSPH_MEMORY_LIMIT"
};

// The limit in force now. Throws InputError when ARKSPH_MEMORY_LIMIT cannot be read.
MemoryLimit memory_limit();

// "4G" -> 4294967296; a plain number is bytes. Throws InputError naming `what` if malformed.
double parse_byte_count(const std::string& text, const std::string& what);

// "3.2 GB", "512 MB", "40 kB" (decimal units).
std::string format_bytes(double bytes);

}  // namespace arksph
