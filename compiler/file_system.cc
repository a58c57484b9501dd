#include "file_system.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

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

} // namespace gfec
