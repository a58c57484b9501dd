#include "loader.h"

#include "input_languages.h"
#include "parser.h"
#include "standard_blocks.h"
#include "did_you_mean.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>

namespace gfec {

namespace {

namespace fsys = std::filesystem;

/// Imports deeper than this are refused: a chain this long is a generated mistake, and the
/// loader recurses once per level.
constexpr std::size_t kMaxImportDepth = 200;
constexpr std::size_t kMaxImportPath = 4096;  // PATH_MAX: no longer path opens

std::string normal(const fsys::path &p) {
  std::string s = p.lexically_normal().generic_string();
  return s.empty() ? "." : s;
}

class Loader {
public:
  Loader(const LoadOptions &options, const FileSystem &fs, SourceManager &sources, Diagnostics &diag,
         LoadResult &result)
      : options_(options), fs_(fs), sources_(sources), diag_(diag), result_(result) {}

  void read_main(const std::string &path, std::string text) { load(normal(path), std::move(text)); }

private:
  enum class State { Loading, Done };

  void load(const std::string &path, std::string text) {
    if (auto id = fs_.identity(path)) by_identity_.emplace(*id, path);
    // An imported file of another input language (`import "mixer.st";`, an IEC program a test
    // file runs) is read by that language's reader, into the same program: its charts are
    // visible as an imported chart file's are (docs/testing-charts.md).
    // `-x LANG` says what every file is, imports included (as gcc's -x does).
    if (!stack_.empty() && !options_.language) {
      const InputLanguage &language = input_language_of(path, text);
      if (&language != &chart_text_language()) {
        state_[path] = State::Loading;
        language.read(path, std::move(text), options_, fs_, sources_, diag_, result_);
        state_[path] = State::Done;
        return;
      }
    }
    state_[path] = State::Loading;
    stack_.push_back(path);
    FileId id = sources_.add(path, std::move(text));
    result_.paths.push_back(path);
    result_.program.files.push_back(parse_file(sources_, id, diag_));
    // Keep a raw pointer: push_back of imported files may move the unique_ptrs, not the File.
    const ast::File &file = *result_.program.files.back();
    for (const ast::Import &import : file.imports) follow(path, import);
    stack_.pop_back();
    state_[path] = State::Done;
  }

  void follow(const std::string &from, const ast::Import &import) {
    // A NUL would cut the path short: the file opened would not be the one named.
    if (import.path.find('\0') != std::string::npos) {
      diag_.error(import.range, ErrorKind::Import, "an import path cannot contain a NUL character");
      return;
    }
    // No system opens a longer path (PATH_MAX); refused before it is split, searched or quoted
    // in notes, so a megabyte-long string costs nothing.
    if (import.path.size() > kMaxImportPath) {
      diag_.error(
          import.range, ErrorKind::Import,
          fmt::format("an import path is at most {} bytes; this one has {}", kMaxImportPath, import.path.size()));
      return;
    }
    std::vector<std::string> tried;
    std::vector<std::pair<std::string, std::string>> refused;  ///< path, why
    fsys::path dir = fsys::path(from).parent_path();
    std::vector<fsys::path> candidates;
    fsys::path wanted(import.path);
    if (wanted.is_absolute()) {
      candidates.push_back(wanted);
    } else {
      candidates.push_back(dir / wanted);
      for (const auto &inc : options_.include_dirs) candidates.push_back(fsys::path(inc) / wanted);
    }
    for (const auto &candidate : candidates) {
      std::string path = normal(candidate);
      auto seen = state_.find(path);
      if (seen != state_.end()) {
        if (seen->second == State::Loading) report_cycle(import, path);
        return;  // a file imported twice is read once
      }
      tried.push_back(path);
      auto text = fs_.read(path);
      if (!text) {
        if (fs_.identity(path)) refused.emplace_back(path, text.why);  // there, but not read
        continue;
      }
      // The same file by another path (absolute, or through a symlinked folder): read once.
      if (auto id = fs_.identity(path)) {
        auto same = by_identity_.find(*id);
        if (same != by_identity_.end()) {
          if (state_[same->second] == State::Loading) report_cycle(import, same->second);
          return;
        }
      }
      if (stack_.size() >= kMaxImportDepth) {
        diag_.error(import.range, ErrorKind::Import, fmt::format("imports nested more than {} deep", kMaxImportDepth));
        return;
      }
      via_.push_back(import.range);
      load(path, std::move(*text));
      via_.pop_back();
      return;
    }
    // A file that is there but cannot be read (a device, a folder, an I/O error) is no typo.
    if (!refused.empty()) {
      diag_.error(import.range, ErrorKind::Import,
                  fmt::format("cannot read imported file '{}': {}", refused.front().first, refused.front().second));
      return;
    }
    auto &d = diag_.error(import.range, ErrorKind::Import, fmt::format("cannot find imported file '{}'", import.path));
    for (const auto &t : tried) d.note(fmt::format("looked for '{}'", t));
    result_.missing.insert(result_.missing.end(), tried.begin(), tried.end());
    suggest_file(d, import, candidates);
  }

  /// Did-you-mean for an import: the file name nearest the one asked for in the folders
  /// searched ("crosing.iface" -> "crossing.iface"), a typo's distance apart (a third of it).
  void suggest_file(Diagnostic &d, const ast::Import &import, const std::vector<fsys::path> &searched) {
    fsys::path wanted(import.path);
    std::string name = wanted.filename().string();
    NearestName nearest(name, typo_limit(name.size()));
    std::string best;
    for (const auto &candidate : searched)
      for (const std::string &file : fs_.list(normal(candidate.parent_path())))
        if (file != name && nearest.offer(file)) best = file;
    if (best.empty()) return;
    std::string path = (wanted.parent_path() / best).generic_string();
    if (path.find_first_of("\\\"") == std::string::npos) d.fix(import.range, fmt::format("\"{}\"", path));
    d.note(fmt::format("did you mean '{}'?", path));
  }

  void report_cycle(const ast::Import &import, const std::string &target) {
    auto &d =
        diag_.error(import.range, ErrorKind::ImportCycle, fmt::format("import cycle: '{}' imports itself", target));
    bool in_cycle = false;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      if (stack_[i] == target) in_cycle = true;
      if (!in_cycle) continue;
      // Each step at its own import; the last one is the error's (shown once).
      if (i + 1 < stack_.size()) d.note(via_[i], fmt::format("'{}' imports '{}'", stack_[i], stack_[i + 1]));
      else d.note(fmt::format("'{}' imports '{}'", stack_[i], target));
    }
  }

  const LoadOptions &options_;
  const FileSystem &fs_;
  SourceManager &sources_;
  Diagnostics &diag_;
  LoadResult &result_;
  std::map<std::string, State> state_;
  std::map<std::string, std::string> by_identity_;  ///< device:inode -> the path it was read by
  std::vector<std::string> stack_;
  std::vector<SourceRange> via_;  ///< via_[i]: the import by which stack_[i] read stack_[i + 1]
};

}  // namespace

void read_chart_program(const std::string &main_path, std::string text, const LoadOptions &options,
                        const FileSystem &fs, SourceManager &sources, Diagnostics &diag, LoadResult &result) {
  Loader(options, fs, sources, diag, result).read_main(main_path, std::move(text));
}

const InputLanguage &chart_text_language() {
  static const InputLanguage row{
      "gfec",
      "chart text",
      // What the files of docs/language.md are called; any other name not claimed by another
      // language is chart text too, since any declaration may stand in any file.
      {{".sfc", "an sfc chart"},
       {".fsm", "an fsm chart"},
       {".plan", "a plan"},
       {".test", "scenario tests"},
       {".toolbox", "a toolbox", false},
       {".iface", "an interface", false}},
      nullptr,
      read_chart_program,
      true,
      "//",
      nullptr,
  };
  return row;
}

LoadResult load_program(const std::string &main_path, const LoadOptions &options, const FileSystem &fs,
                        SourceManager &sources, Diagnostics &diag) {
  LoadResult result;
  auto text = fs.read(main_path);
  if (!text) {
    result.main_unreadable = true;
    result.main_unreadable_why = text.why;
    return result;
  }
  const InputLanguage &language = options.language ? *options.language : input_language_of(main_path, *text);
  result.language = &language;
  language.read(main_path, std::move(*text), options, fs, sources, diag, result);
  add_standard_blocks(result.program, sources, diag);
  if (options.period_ms && !language.reads_period && !result.program.files.empty() && result.program.files.front())
    diag.error({result.program.files.front()->id, 0, 0}, ErrorKind::Period,
               fmt::format("--period is for IEC programs (-x iec-st, plcopen), not {}{}", language.summary,
                           language.chart_text ? ": a chart declares its own 'period'" : ""));
  return result;
}

void annotate_diagnostics(Diagnostics &diag, const LoadResult &loaded, std::size_t first) {
  if (loaded.language && loaded.language->annotate) loaded.language->annotate(diag, loaded, first);
}

}  // namespace gfec
