#include "file_system.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gfec {

std::optional<std::string> RealFileSystem::read(const std::string &path) const {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return text.str();
}

std::vector<std::string> RealFileSystem::list(const std::string &dir) const {
  std::vector<std::string> names;
  std::error_code ec;
  std::filesystem::directory_iterator it(dir.empty() ? "." : dir, ec), end;
  for (; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec)) names.push_back(it->path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> MemoryFileSystem::list(const std::string &dir) const {
  std::vector<std::string> names;
  std::string prefix = dir.empty() || dir == "." ? "" : dir + "/";
  for (const auto &f : files_)
    if (f.first.rfind(prefix, 0) == 0 && f.first.find('/', prefix.size()) == std::string::npos)
      names.push_back(f.first.substr(prefix.size()));
  return names;
}

std::optional<std::string> MemoryFileSystem::read(const std::string &path) const {
  auto it = files_.find(path);
  if (it == files_.end()) return std::nullopt;
  return it->second;
}

} // namespace gfec
