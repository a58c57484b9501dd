#include "output_files.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <unistd.h>

namespace gfec {

std::string write_atomically(const std::vector<OutputFile> &files) {
  std::vector<std::string> temps;
  auto cleanup = [&] {
    for (const auto &t : temps) std::remove(t.c_str());
  };
  for (const auto &f : files) {
    std::string temp = fmt::format("{}.gfec-tmp-{}", f.path, ::getpid());
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) {
      std::string why = std::strerror(errno);
      cleanup();
      return fmt::format("cannot write '{}': {}", f.path, why);
    }
    temps.push_back(temp);
    out << f.contents;
    out.close();
    if (!out) {
      cleanup();
      return fmt::format("cannot write '{}': write failed", f.path);
    }
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (std::rename(temps[i].c_str(), files[i].path.c_str()) != 0) {
      std::string why = std::strerror(errno);
      cleanup();
      return fmt::format("cannot write '{}': {}", files[i].path, why);
    }
  }
  return {};
}

} // namespace gfec
