// Helpers shared by the unit tests: run the front end on in-memory files and render what it said.
#pragma once

#include "diagnostic_printer.h"
#include "loader.h"
#include "pipeline/compilation.h"

#include <cstddef>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace gfec::test {

/// One front-end run over in-memory files; the first file is the main one.
struct FrontEnd {
  SourceManager sources;
  Diagnostics diag;
  LoadResult loaded;

  FrontEnd(std::initializer_list<std::pair<std::string, std::string>> files, WarningOptions w = {}) : diag(w) {
    MemoryFileSystem fs;
    for (auto &f : files) fs.add(f.first, f.second);
    loaded = load_program(files.begin()->first, {}, fs, sources, diag);
  }

  /// Every diagnostic as gfec prints it.
  std::string text() const {
    std::string out;
    for (const auto &d : diag.all()) out += render_text(d, sources);
    return out;
  }
};

/// In-memory files by name.
inline MemoryFileSystem files(std::initializer_list<std::pair<std::string, std::string>> named) {
  MemoryFileSystem fs;
  for (const auto &[name, text] : named) fs.add(name, text);
  return fs;
}

/// One file through the pipeline gfec runs (compiler/pipeline/compilation.h) without the static
/// analyses, whose warnings are tested apart: what the loader and the validator said, and the
/// model. Every test that needs a model starts here. Never moves: the model points into `sources`.
struct Pipeline {
  pipeline::Compilation c;
  SourceManager &sources = c.sources;
  Diagnostics &diag = c.diag;
  LoadResult &loaded = c.loaded;  ///< the files read; the syntax tree is gone after validation
  model::Model &model = c.model;

  /// `tests`: where the main file's `test` blocks go (docs/testing-charts.md), if anywhere.
  Pipeline(const std::string &main, const FileSystem &fs, WarningOptions w = {}, scenario::Suite *tests = nullptr)
      : c(options(w)) {
    c.front_end(main, fs, tests);
  }
  Pipeline(const Pipeline &) = delete;
  static pipeline::FrontEndOptions options(WarningOptions w) {
    pipeline::FrontEndOptions f;
    f.warnings = w;
    f.analyze = false;
    return f;
  }

  /// Every diagnostic as gfec prints it.
  std::string text() const {
    std::string out;
    for (const auto &d : diag.all()) out += render_text(d, sources);
    return out;
  }
};

/// What a command printed and how it ended.
struct CommandResult {
  int exit_code = -1;
  std::string out;  ///< standard output and standard error, interleaved as they came
};

/// Runs `command` through the shell (stderr folded into stdout).
CommandResult run_command(const std::string &command);

/// A fresh, empty folder under the build tree for one test's files.
std::string scratch_dir(const std::string &name);

/// Reads a whole file ("" if it does not exist).
std::string read_file(const std::string &path);
void write_file(const std::string &path, const std::string &text);

/// Every warning on, as `-Wall -Wextra` and the off-by-default ones would have it.
inline WarningOptions all_warnings() {
  WarningOptions w;
  for (int i = 0; i < static_cast<int>(Warning::Count_); ++i) w.set(static_cast<Warning>(i), true);
  return w;
}

/// The one line where two texts first differ (1-based), for a readable failure.
std::string first_difference(const std::string &expected, const std::string &actual);

/// Ids of one table, by position, to compare with what the model refers to:
/// `CHECK(chart.functions == ids<model::FunctionId>({0, 1, 3}))` (a PlaceList or an Expr's path
/// compares with it too).
template <typename IdT> std::vector<IdT> ids(std::initializer_list<std::size_t> positions) {
  std::vector<IdT> out;
  for (std::size_t p : positions) out.push_back(IdT(p));
  return out;
}

/// Parses one file called "t.sfc" and returns the printed diagnostics.
inline std::string parse_errors(const std::string &source) { return FrontEnd({{"t.sfc", source}}).text(); }

}  // namespace gfec::test
