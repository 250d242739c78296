// libFuzzer target for the scene reader (fuzz/README.md). Bad input must end in arksph::InputError;
// any other exception, a crash, a sanitizer report, a hang or a huge allocation is a finding.
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <streambuf>
#include <string>

#include "core/errors.hpp"
#include "io/scene_reader.hpp"

namespace {
// Discards the warnings.
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static NullBuffer null_buffer;
  static std::ostream null_ostream(&null_buffer);
  try {
    (void)arksph::read_scene_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz", {},
                                  null_ostream);
  } catch (const arksph::InputError&) {
    // expected: bad input is reported with one line
  }
  return 0;
}
