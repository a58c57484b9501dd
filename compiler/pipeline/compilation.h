// The compilation pipeline as a library (docs/architecture.md): one input file carried through
// load -> validate -> analyse, and the one function that picks what of it is compiled. `gfec
// FILE`, --check, --analyze, `gfec run`, `gfec test` and the tests' helpers all go through here,
// so the stages run in one order with one set of rules; only the driver prints and exits.
#pragma once

#include "diagnostics.h"
#include "file_system.h"
#include "loader.h"
#include "model.h"
#include "name_uses.h"
#include "pipeline/kind.h"
#include "source.h"

#include <optional>
#include <string>

namespace gfec {

namespace scenario {
struct Suite;
}

namespace pipeline {

/// What the front end needs from the command line.
struct FrontEndOptions {
  std::vector<std::string> include_dirs;    ///< -I
  const InputLanguage *language = nullptr;  ///< -x (input_languages.h); null: the file's own
  WarningOptions warnings;                  ///< -W...
  std::size_t error_limit = 50;             ///< -fmax-errors=N
  std::optional<double> period_ms;          ///< --period: an IEC program's scan period (LoadOptions)
  bool analyze = true;                      ///< run the static analyses whose warnings are on (docs/verification.md)
  /// Keep the whole syntax tree in `loaded.program` after validation (a language server reads
  /// it); by default it is dropped, bodies first, so a large chart is never held twice.
  bool keep_syntax_tree = false;
  /// Record in Compilation::name_uses what every name refers to (a language server's
  /// definition, references and rename).
  bool record_name_uses = false;
};

/// What to compile: the question choose() answers.
struct SelectionRequest {
  std::string name;                      ///< --chart NAME; empty: the default (docs/language.md "Sub-charts")
  unsigned among = kSfc | kFsm | kPlan;  ///< the kinds to choose from (kToolbox alone: a toolbox skeleton)
  const char *verb = "compile";          ///< for messages: "compile", "run"
};

/// The selection: the chart, plan or toolbox of the main file chosen to compile (or run), or why
/// there is none. (A "target" is an MCU the engine runs on; this is what of the file is compiled.)
struct Selection {
  unsigned kind = 0;     ///< one Kind bit (pipeline/kind.h); 0 when nothing was chosen
  model::ChartId chart;  ///< the one of `kind` is set, the others are none
  model::PlanId plan;
  model::ToolboxId toolbox;
  std::string name;
  std::string error;      ///< why nothing was chosen ("" when something was)
  bool in_input = false;  ///< the error is the file's (it declares nothing to compile): located, exit 1
  bool chosen() const { return kind != 0; }
};

/// Which chart, plan or toolbox of `m`'s main file `request` names, or by default the only
/// candidate: the charts no chart runs (compiler/roots.h) and the plans, or the toolboxes.
Selection choose(const model::Model &m, const SelectionRequest &request);

/// One input file through the pipeline: the sources read, their diagnostics, the model.
class Compilation {
public:
  explicit Compilation(const FrontEndOptions &options);
  Compilation(const Compilation &) = delete;
  Compilation &operator=(const Compilation &) = delete;

  /// Loads `path` and what it imports, validates (keeping the main file's `test` blocks in
  /// `tests` when given) and runs the analyses: load_and_validate(), then analyze(). False when
  /// the input has errors (in diag) or the main file is unreadable (unreadable()). Stops at the
  /// first stage with errors: validating a tree the parser had to patch up would mostly report
  /// the patches.
  bool front_end(const std::string &path, const FileSystem &fs, scenario::Suite *tests = nullptr);
  /// The same on the real file system.
  bool front_end(const std::string &path);

  /// front_end() without the static analyses, which analyze() runs later: a language server
  /// publishes what the front end found first, as the analyses cost the most on a large chart.
  bool load_and_validate(const std::string &path, const FileSystem &fs, scenario::Suite *tests = nullptr);
  /// The static analyses whose warnings are on (options.analyze), once, when the front end
  /// found no error; the diagnostics they add are annotated as the front end's were. False
  /// when the input has errors.
  bool analyze();
  /// Whether analyze() has analyses left to run.
  bool analysis_pending() const { return analysis_pending_; }

  /// Picks what to compile (choose()) and, for a chart that runs sub-charts, warns about
  /// the charts of the main file it leaves out (-Wunused-chart). Keeps the choice in selection.
  const Selection &select(const SelectionRequest &request);

  bool unreadable() const { return loaded.main_unreadable; }
  /// "cannot read 'x.sfc': no such file", when unreadable().
  std::string cannot_read_main(const std::string &path) const { return cannot_read(path, loaded.main_unreadable_why); }
  bool ok() const { return !loaded.main_unreadable && !diag.has_errors(); }

  FrontEndOptions options;
  SourceManager sources;
  Diagnostics diag;
  LoadResult loaded;
  model::Model model;
  Selection selection;
  /// With FrontEndOptions::record_name_uses: every declaration and resolved use of a name.
  NameUses name_uses;

private:
  bool analysis_pending_ = false;
};

}  // namespace pipeline
}  // namespace gfec
