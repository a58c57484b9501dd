#include "file_system.h"

#include "escape.h"

#include <algorithm>
#include <filesystem>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statfs.h>
#include <unistd.h>

namespace gfec {

namespace {

namespace fsys = std::filesystem;

/// The paths of `paths` that walk(dir, limits) takes: below `dir`, in no folder deeper than
/// limits.max_depth, nor (limits.skip_hidden) in a hidden folder. Normalised and sorted.
std::vector<std::string> below(const std::string &dir, const std::vector<std::string> &paths,
                               const WalkLimits &limits) {
  const std::string root = normal_path(dir.empty() ? "." : dir);
  std::vector<std::string> out;
  for (const std::string &given : paths) {
    const std::string path = normal_path(given);
    std::string rel;
    if (root == ".") {
      if (path.empty() || path[0] == '/' || path.rfind("../", 0) == 0) continue;
      rel = path;
    } else if (path.size() > root.size() && path.compare(0, root.size(), root) == 0 &&
               (path[root.size()] == '/' || root == "/")) {
      rel = path.substr(root == "/" ? 1 : root.size() + 1);
    } else {
      continue;
    }
    int depth = 0;
    bool hidden = false;
    for (std::size_t at = rel.find('/'), from = 0; at != std::string::npos; from = at + 1, at = rel.find('/', from)) {
      ++depth;
      if (rel[from] == '.') hidden = true;
    }
    if (depth > limits.max_depth || (hidden && limits.skip_hidden)) continue;
    out.push_back(path);
    if (out.size() >= limits.max_entries) break;
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

namespace {

/// The pseudo file systems whose files are the kernel's, not data (linux/magic.h): their sizes
/// say 0 or lie, a read may block (/proc/kmsg), consume (the kernel log) or act (sysfs).
bool kernel_file_system(unsigned long type) {
  switch (type) {
  case 0x9fa0UL:      // procfs
  case 0x62656572UL:  // sysfs
  case 0x64626720UL:  // debugfs
  case 0x74726163UL:  // tracefs
  case 0x73636673UL:  // securityfs
  case 0x27e0ebUL:    // cgroup
  case 0x63677270UL:  // cgroup2
  case 0x62656570UL:  // configfs
  case 0xcafe4a11UL:  // bpf
  case 0xde5e81e4UL:  // efivarfs
  case 0x6165676cUL:  // pstore
  case 0x42494e4dUL:  // binfmt_misc
  case 0x65735543UL:  // fusectl
  case 0xf97cff8cUL:  // selinuxfs
  case 0x43415d53UL:  // smackfs
    return true;
  default: return false;
  }
}

constexpr const char *kKernelFile =
    "a file of /proc, /sys or another of the kernel's pseudo file systems; gfec reads none";

std::string mib(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

/// Why a file with this status is not read, or "" if it may be.
std::string refusal(const struct stat &st, std::size_t max_file) {
  if (S_ISDIR(st.st_mode)) return "it is a folder";
  if (!S_ISREG(st.st_mode)) return "not a regular file; gfec reads no devices, pipes or sockets";
  if (st.st_size > 0 && static_cast<std::uintmax_t>(st.st_size) > max_file)
    return "larger than " + mib(max_file) + ", the most gfec reads of one file";
  return {};
}

std::string error_reason(int error) {
  return error == ENOENT || error == ENOTDIR ? "no such file"
         : error == EACCES                   ? "permission denied"
                                             : std::strerror(error);
}

}  // namespace

FileText RealFileSystem::read(const std::string &path) const {
  auto refused = [](std::string why) { return FileText{std::nullopt, std::move(why)}; };
  // Looked at before it is opened, since opening may act already (a FIFO's open waits for a
  // writer, a device's driver runs), and again on what was opened: the path may have changed
  // in between. Symlinks are followed (a symlinked import is fine): the checks are on the file
  // they lead to.
  struct stat st {};
  struct statfs sfs {};
  if (::stat(path.c_str(), &st) != 0) return refused(error_reason(errno));
  if (std::string why = refusal(st, limits_.max_file); !why.empty()) return refused(why);
  if (::statfs(path.c_str(), &sfs) == 0 && kernel_file_system(static_cast<unsigned long>(sfs.f_type)))
    return refused(kKernelFile);
  // O_NONBLOCK: should a FIFO or device replace the file after the checks, open() returns at
  // once and fstat refuses it; O_NOCTTY: a terminal never becomes gfec's controlling one.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
  if (fd < 0) return refused(error_reason(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  if (::fstat(fd, &st) != 0) return refused(error_reason(errno));
  if (std::string why = refusal(st, limits_.max_file); !why.empty()) return refused(why);
  if (::fstatfs(fd, &sfs) != 0 || kernel_file_system(static_cast<unsigned long>(sfs.f_type)))
    return refused(kKernelFile);
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags < 0 || ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0) return refused(error_reason(errno));

  const std::size_t size = st.st_size > 0 ? static_cast<std::size_t>(st.st_size) : 0;
  const std::size_t before = total_.load();
  auto too_much = [this] {
    return "the files read so far and this one are larger than " + mib(limits_.max_total) +
           ", the most gfec reads for one input";
  };
  if (before + size > limits_.max_total) return refused(too_much());
  // read(2) rather than a stream: a filebuf reports a failed read (EIO, or a file like
  // /proc/self/mem that refuses to be read) as the end of the file, and a truncated chart would
  // then be compiled as if it were whole.
  auto read_some = [fd](char *into, std::size_t count) {
    ssize_t n;
    do n = ::read(fd, into, count);
    while (n < 0 && errno == EINTR);
    return n;
  };
  // Read into a string sized from fstat: appending in chunks would grow it by doubling, and a
  // 90 MB chart would touch three times its size in fresh pages. Reading still goes on to the
  // end of the file, so one that grew meanwhile is read whole and one that shrank is not padded;
  // but never past the limit, whatever the size said.
  std::string text(size, '\0');
  std::size_t used = 0;
  ssize_t n = 1;
  while (used < text.size() && (n = read_some(text.data() + used, text.size() - used)) > 0)
    used += static_cast<std::size_t>(n);
  text.resize(used);
  char buffer[65536];
  while (n > 0 && text.size() <= limits_.max_file && (n = read_some(buffer, sizeof buffer)) > 0)
    text.append(buffer, static_cast<std::size_t>(n));
  if (n < 0) return refused(error_reason(errno));
  if (text.size() > limits_.max_file)
    return refused("larger than " + mib(limits_.max_file) + ", the most gfec reads of one file");
  if (total_.fetch_add(text.size()) + text.size() > limits_.max_total) return refused(too_much());
  return FileText{std::move(text), {}};
}

std::string cannot_read(const std::string &path, const std::string &why) {
  return "cannot read '" + text::printable(path) + "': " + why;
}

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

std::vector<std::string> RealFileSystem::walk_files(const std::string &dir, const WalkLimits &limits) const {
  std::vector<std::string> files;
  std::error_code ec;
  std::size_t seen = 0;
  fsys::recursive_directory_iterator it(dir.empty() ? "." : dir, fsys::directory_options::skip_permission_denied, ec);
  for (fsys::recursive_directory_iterator end; !ec && it != end && seen < limits.max_entries;
       it.increment(ec), ++seen) {
    const std::string name = it->path().filename().string();
    if (it->is_directory(ec)) {
      if (it.depth() >= limits.max_depth || (limits.skip_hidden && !name.empty() && name[0] == '.'))
        it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file(ec)) files.push_back(normal_path(it->path()));
  }
  std::sort(files.begin(), files.end());  // directory order is the file system's
  return files;
}

std::vector<std::string> MemoryFileSystem::walk_files(const std::string &dir, const WalkLimits &limits) const {
  std::vector<std::string> paths;
  for (const auto &entry : files_) paths.push_back(entry.first);
  return below(dir, paths, limits);
}

std::optional<std::string> RealFileSystem::identity(const std::string &path) const {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
}

FileText MemoryFileSystem::read(const std::string &path) const {
  auto it = files_.find(path);
  if (it == files_.end()) return FileText{std::nullopt, "no such file"};
  return FileText{it->second, {}};
}

void OverlayFileSystem::open(const std::string &path, std::string text) {
  buffers_[normal_path(path)] = std::move(text);
}

void OverlayFileSystem::close(const std::string &path) { buffers_.erase(normal_path(path)); }

FileText OverlayFileSystem::read(const std::string &path) const {
  auto it = buffers_.find(normal_path(path));
  if (it != buffers_.end()) return FileText{it->second, {}};
  return base_.read(path);
}

std::vector<std::string> OverlayFileSystem::list(const std::string &dir) const {
  std::vector<std::string> names = base_.list(dir);
  const std::string folder = normal_path(dir.empty() ? "." : dir);
  for (const auto &entry : buffers_) {
    fsys::path p(entry.first);
    if (normal_path(p.parent_path()) == folder) names.push_back(p.filename().string());
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

std::optional<std::string> OverlayFileSystem::identity(const std::string &path) const { return base_.identity(path); }

std::vector<std::string> OverlayFileSystem::walk_files(const std::string &dir, const WalkLimits &limits) const {
  std::vector<std::string> paths = base_.walk(dir, limits);
  for (const auto &entry : buffers_) paths.push_back(entry.first);
  return below(dir, paths, limits);
}

std::string normal_path(const std::string &path) {
  std::string s = fsys::path(path).lexically_normal().generic_string();
  if (s.size() > 1 && s.back() == '/') s.pop_back();
  return s.empty() ? "." : s;
}

}  // namespace gfec
