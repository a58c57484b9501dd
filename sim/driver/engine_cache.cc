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
                             const std::vector<std::string>& header_dirs, const std::string& blank) {
  // `blank` (the build's temporary folder) is left out wherever it appears: in the command and
  // in gfec's `#line` directives back to the engine itself.
  auto blanked = [&](std::string text) {
    if (blank.empty()) return text;
    for (std::size_t at = 0; (at = text.find(blank, at)) != std::string::npos; at += 5)
      text.replace(at, blank.size(), "<dir>");
    return text;
  };
  Hash h;
  for (const std::string& a : command) h.add(blanked(a));
  for (const std::string& f : inputs) h.add(blanked(slurp(f)));
  for (const std::string& dir : header_dirs) {
    std::vector<std::string> headers;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
      if (it->path().extension() == ".h" || it->path().extension() == ".hpp") headers.push_back(it->path().string());
    std::sort(headers.begin(), headers.end());  // directory order is not stable
    for (const std::string& f : headers) {
      // The name below its folder, not the whole path: the engine's folder is a fresh temporary
      // one every run, and a key naming it never hit (issue 42).
      h.add(fs::path(f).lexically_relative(dir).string());
      h.add(slurp(f));
    }
  }
  return fmt::format("{:016x}", h.h);
}

bool EngineCache::fetch(const std::string& key, const std::string& output) const {
  if (dir_.empty()) return false;
  std::error_code ec;
  const fs::path entry = fs::path(dir_) / (key + ".so");
  if (!fs::is_regular_file(entry, ec)) return false;
  if (!fs::copy_file(entry, output, fs::copy_options::overwrite_existing, ec)) return false;
  // Used now: the eviction keeps the most recently used entries.
  fs::last_write_time(entry, fs::file_time_type::clock::now(), ec);
  return true;
}

void EngineCache::evict(std::size_t keep) const {
  if (dir_.empty()) return;
  std::error_code ec;
  std::vector<std::pair<fs::file_time_type, fs::path>> entries;
  for (auto it = fs::directory_iterator(dir_, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
    std::error_code e;
    if (it->path().extension() == ".so" && it->is_regular_file(e))
      entries.emplace_back(it->last_write_time(e), it->path());
  }
  if (entries.size() <= keep) return;
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t i = keep; i < entries.size(); ++i) fs::remove(entries[i].second, ec);
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
  evict(kMaxEntries);
}

}  // namespace carbot::driver
