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
  // Read into a string sized from fstat: appending in chunks would grow it by doubling, and a
  // 90 MB chart would touch three times its size in fresh pages. Reading still goes on to the
  // end of the file, so one that grew meanwhile is read whole and one that shrank is not padded.
  auto read_some = [fd](char *into, std::size_t size) {
    ssize_t n;
    do n = ::read(fd, into, size);
    while (n < 0 && errno == EINTR);
    return n;
  };
  struct stat st {};
  std::string text;
  if (::fstat(fd, &st) == 0 && st.st_size > 0) text.resize(static_cast<std::size_t>(st.st_size));
  std::size_t used = 0;
  ssize_t n = 1;
  while (used < text.size() && (n = read_some(text.data() + used, text.size() - used)) > 0)
    used += static_cast<std::size_t>(n);
  text.resize(used);
  char buffer[65536];
  while (n > 0 && (n = read_some(buffer, sizeof buffer)) > 0) text.append(buffer, static_cast<std::size_t>(n));
  ::close(fd);
  if (n < 0) return std::nullopt;
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
