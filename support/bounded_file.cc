#include "bounded_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gfec::bounded_file {

namespace {

const char *kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

bool read(const std::string &path, std::size_t max_bytes, std::string &text, std::string &error) {
  // O_NONBLOCK: opening a FIFO with no writer would otherwise wait for one for ever.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    error = std::strerror(errno);
    return false;
  }
  struct stat st {};
  bool ok = ::fstat(fd, &st) == 0;
  if (!ok) error = std::strerror(errno);
  else if (!S_ISREG(st.st_mode)) {
    error = std::string("not a regular file (") + kind_of(st.st_mode) + ")";
    ok = false;
  } else if (static_cast<unsigned long long>(st.st_size) > max_bytes) {
    error = "the file is " + std::to_string(st.st_size) + " bytes; at most " + std::to_string(max_bytes) + " are read";
    ok = false;
  }
  text.clear();
  // Read at most one byte past the limit: a file that grows while it is read is still bounded.
  char buffer[65536];
  while (ok) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      error = std::strerror(errno);
      ok = false;
    } else if (n == 0) {
      break;
    } else if (text.size() + static_cast<std::size_t>(n) > max_bytes) {
      error = "the file grew past " + std::to_string(max_bytes) + " bytes while it was read";
      ok = false;
    } else {
      text.append(buffer, static_cast<std::size_t>(n));
    }
  }
  ::close(fd);
  if (!ok) text.clear();
  return ok;
}

}  // namespace gfec::bounded_file
