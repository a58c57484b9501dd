// A cache of compiled engines: compiling a plan engine against the afp headers takes seconds,
// and tests and demos run the same chart again and again. The key is a hash of everything
// the compile reads (sources, the headers it includes, the command line), so a stale entry
// cannot be hit.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace carbot::driver {

class EngineCache {
 public:
  /// Caches in `dir` ("" = no caching).
  explicit EngineCache(std::string dir) : dir_(std::move(dir)) {}

  /// The key for compiling `command` over the files `inputs` (contents are hashed) and every
  /// header under `header_dirs` (by its name below the folder and its contents), with the text
  /// `blank` (the build's fresh folder) left out of the command and the inputs.
  static std::string key(const std::vector<std::string>& command, const std::vector<std::string>& inputs,
                         const std::vector<std::string>& header_dirs, const std::string& blank = "");

  /// Copies a cached build for `key` to `output`; false if there is none.
  bool fetch(const std::string& key, const std::string& output) const;

  /// Stores `output` under `key` (best effort: a failure only costs the next compile), then
  /// evicts all but the kMaxEntries most recently used entries.
  void store(const std::string& key, const std::string& output) const;

  /// The most engines the cache keeps: a few megabytes, and every chart a test suite runs.
  static constexpr std::size_t kMaxEntries = 64;

  /// Removes all but the `keep` most recently stored or fetched entries.
  void evict(std::size_t keep) const;

 private:
  std::string dir_;
};

}  // namespace carbot::driver
