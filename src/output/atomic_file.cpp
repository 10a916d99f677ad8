#include "fabform/output/atomic_file.hpp"

#include <cerrno>
#include <cstdio>

#include <fcntl.h>
#include <unistd.h>

#include "fabform/error.hpp"

namespace fabform {
namespace {

// POSIX calls rather than streams, so that the reason of a failure (errno) is the write's own.
int write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

}  // namespace

void write_file(const std::string& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw SystemError(path, "write", system_reason(errno));
  int failure = write_all(fd, text);
  // A full disk on some file systems shows only when the file is closed.
  if (::close(fd) != 0 && failure == 0) failure = errno;
  if (failure != 0) {
    std::remove(path.c_str());
    throw SystemError(path, "write", system_reason(failure));
  }
}

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  write_file(temporary, text);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int failure = errno;
    std::remove(temporary.c_str());
    throw SystemError(path, "write", system_reason(failure));
  }
}

}  // namespace fabform
