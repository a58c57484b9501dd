// The note on "unknown function" when the chart forgot an import (issue 41): which interface
// files in the main file's folder and the -I folders declare the function. The validator asks
// through ValidateOptions::declaring_files; this answers, reading files only through the file
// system layer and only a bounded number of them.
#pragma once

#include "file_system.h"

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gfec {

class MissingImportFinder {
public:
  /// At most this many interface files are read, smallest folders first in search order, each
  /// at most kMaxBytes: a hint must not make a compile that fails slow.
  static constexpr std::size_t kMaxFiles = 32;
  static constexpr std::size_t kMaxBytes = std::size_t{1} << 20;

  MissingImportFinder(const FileSystem &fs, const std::string &main_path, std::vector<std::string> include_dirs);

  /// The files declaring `function`, as an import names them (the name in its folder, which the
  /// import's search finds); none when nothing read declares it. Reads the files on first use.
  std::vector<std::string> operator()(const std::string &function);

private:
  void scan();

  const FileSystem &fs_;
  std::vector<std::string> folders_;
  std::optional<std::map<std::string, std::vector<std::string>>> declared_;  ///< function -> files
};

}  // namespace gfec
