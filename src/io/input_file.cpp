#include "io/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/errors.hpp"

namespace arksph {

std::string read_input_file(const std::string& path, const std::string& what) {
  const auto fail = [&](const std::string& reason) {
    return InputError(echo_value(path) + ": cannot read the " + what + " file: " + reason);
  };
  // Opened without blocking (a FIFO would wait for a writer), then checked on the open descriptor.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw fail(std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    throw fail(std::strerror(err));
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    throw fail(S_ISDIR(st.st_mode) ? "is a directory" : "not a regular file (a device, FIFO or socket)");
  }
  if (static_cast<unsigned long long>(st.st_size) > kMaxInputFileBytes) {
    ::close(fd);
    throw fail(std::to_string(st.st_size) + " bytes, more than the limit of " + std::to_string(kMaxInputFileBytes) +
               " bytes (16 MiB)");
  }
  std::string text;
  char buf[65536];
  for (;;) {
    const ssize_t r = ::read(fd, buf, sizeof buf);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) {
      const int err = errno;
      ::close(fd);
      throw fail(std::strerror(err));
    }
    if (r == 0) break;
    text.append(buf, static_cast<std::size_t>(r));
    if (text.size() > kMaxInputFileBytes) {  // grew while being read
      ::close(fd);
      throw fail("more than the limit of " + std::to_string(kMaxInputFileBytes) + " bytes (16 MiB)");
    }
  }
  ::close(fd);
  return text;
}

}  // namespace arksph
