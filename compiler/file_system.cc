#include "file_system.h"

#include <algorithm>
#include <filesystem>
#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gfec {

std::optional<std::string> RealFileSystem::read(const std::string &path) const {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  // read(2) rather than a stream: a filebuf reports a failed read (EIO, or a file like
  // /proc/self/mem that refuses to be read) as the end of the file, and a truncated chart would
  // then be compiled as if it were whole.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return std::nullopt;
  std::string text;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      ::close(fd);
      return std::nullopt;
    }
    if (n == 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return text;
}

std::string unreadable_reason(const std::string &path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  return !fs::exists(st)            ? "no such file"
         : fs::is_directory(st)     ? "it is a folder"
         : !fs::is_regular_file(st) ? "not a regular file; gfec reads no devices, pipes or sockets"
                                    : "permission denied or an I/O error";
}

std::string cannot_read(const std::string &path) { return "cannot read '" + path + "': " + unreadable_reason(path); }

std::vector<std::string> RealFileSystem::list(const std::string &dir) const {
  std::vector<std::string> names;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir.empty() ? "." : dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec)) names.push_back(it->path().filename().string());
  std::sort(names.begin(), names.end());  // directory order is the file system's: sort for stable notes
  return names;
}

std::vector<std::string> MemoryFileSystem::list(const std::string &dir) const {
  std::vector<std::string> names;
  for (const auto &entry : files_) {
    std::filesystem::path p(entry.first);
    std::string parent = p.parent_path().generic_string();
    if (parent == dir || (parent.empty() && dir == ".")) names.push_back(p.filename().string());
  }
  return names;
}

std::optional<std::string> RealFileSystem::identity(const std::string &path) const {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
}

std::optional<std::string> MemoryFileSystem::read(const std::string &path) const {
  auto it = files_.find(path);
  if (it == files_.end()) return std::nullopt;
  return it->second;
}

}  // namespace gfec
