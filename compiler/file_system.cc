#include "file_system.h"

#include "bounded_file.h"
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

FileText RealFileSystem::read(const std::string &path) const {
  auto refused = [](std::string why) { return FileText{std::nullopt, std::move(why)}; };
  const std::size_t before = total_.load();
  const std::size_t room = before >= limits_.max_total ? 0 : limits_.max_total - before;
  auto too_much = [this] {
    return "the files read so far and this one are larger than " + bounded_file::mib(limits_.max_total) +
           ", the most gfec reads for one input";
  };
  bounded_file::Text file = bounded_file::read(path, std::min(limits_.max_file, room));
  if (file.too_large)
    return refused(limits_.max_file <= room
                       ? "larger than " + bounded_file::mib(limits_.max_file) + ", the most gfec reads of one file"
                       : too_much());
  if (!file.text) return refused(file.why);
  const std::size_t size = file.text->size();
  if (total_.fetch_add(size) + size > limits_.max_total) return refused(too_much());
  return FileText{std::move(*file.text), {}};
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
