// Reading a scene, sweep or study file: only a regular file of at most kMaxInputFileBytes is read,
// so that a directory gives a clear message and /dev/zero or /dev/urandom is refused instead of
// being read forever.
#pragma once
#include <cstddef>
#include <string>

namespace arksph {

constexpr std::size_t kMaxInputFileBytes = 16u << 20;  // 16 MiB: far beyond any scene

// The whole file. Throws InputError("PATH: cannot read the WHAT file: reason") if it is missing,
// not a regular file, larger than kMaxInputFileBytes or unreadable.
std::string read_input_file(const std::string& path, const std::string& what);

}  // namespace arksph
