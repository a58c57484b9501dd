#include "driver/engine_cache.h"

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "safe_output.h"

namespace fs = std::filesystem;

namespace carbot::driver {
namespace {

/// FNV-1a, 64 bits: not cryptographic, but the inputs are our own files, not an adversary's.
struct Hash {
  std::uint64_t h = 1469598103934665603ull;
  void add(const std::string& s) {
    for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
    h = (h ^ 0xff) * 1099511628211ull;  // separator: "ab"+"c" != "a"+"bc"
  }
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string EngineCache::key(const std::vector<std::string>& command, const std::vector<std::string>& inputs,
                             const std::vector<std::string>& header_dirs) {
  Hash h;
  for (const std::string& a : command) h.add(a);
  for (const std::string& f : inputs) h.add(slurp(f));
  for (const std::string& dir : header_dirs) {
    std::vector<std::string> headers;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
      if (it->path().extension() == ".h" || it->path().extension() == ".hpp") headers.push_back(it->path().string());
    std::sort(headers.begin(), headers.end());  // directory order is not stable
    for (const std::string& f : headers) {
      h.add(f);
      h.add(slurp(f));
    }
  }
  return fmt::format("{:016x}", h.h);
}

bool EngineCache::fetch(const std::string& key, const std::string& output) const {
  if (dir_.empty()) return false;
  std::error_code ec;
  const fs::path entry = fs::path(dir_) / (key + ".so");
  if (!fs::exists(entry, ec)) return false;
  return fs::copy_file(entry, output, fs::copy_options::overwrite_existing, ec);
}

void EngineCache::store(const std::string& key, const std::string& output) const {
  if (dir_.empty()) return;
  std::error_code ec;
  fs::create_directories(dir_, ec);
  // Through a temporary with an unpredictable name, then renamed (safe_output.h), so a parallel
  // run never loads a half-copied file and nothing planted in the cache folder is followed.
  std::ifstream in(output, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in) return;
  gfec::safe_output::write_all({{(fs::path(dir_) / (key + ".so")).string(), bytes.str()}},
                               {});  // a cache: failure is no error
}

}  // namespace carbot::driver
