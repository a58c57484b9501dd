#include "pipeline/compilation.h"

#include "analysis/activation_bounds.h"
#include "pipeline/missing_import.h"
#include "analysis/analysis.h"
#include "roots.h"
#include "scenario/scenario.h"
#include "validate.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec::pipeline {

namespace {

struct Candidate {
  unsigned kind;
  std::string name;
  model::ChartId chart;  ///< the one of `kind`
  model::PlanId plan;
  model::ToolboxId toolbox;
};

}  // namespace

Selection choose(const model::Model &m, const SelectionRequest &request) {
  std::vector<Candidate> candidates;
  std::vector<Candidate> named_only;  ///< sub-charts of the main file: compiled alone by name only
  if (request.among & kToolbox)
    for (model::ToolboxId i : m.toolboxes.ids())
      if (m.toolboxes[i].range.file == m.main_file) candidates.push_back({kToolbox, m.toolboxes[i].name, {}, {}, i});
  if (request.among & (kSfc | kFsm)) {
    // The default root rule (docs/language.md "Sub-charts"): a chart another chart runs is
    // compiled only when --chart names it.
    std::vector<model::ChartId> roots = root_charts(m);
    for (model::ChartId i : m.charts.ids()) {
      const model::Chart &c = m.charts[i];
      unsigned kind = c.kind == model::Chart::Kind::Sfc ? kSfc : kFsm;
      if (!c.in_main_file || !(request.among & kind)) continue;
      bool root = std::find(roots.begin(), roots.end(), i) != roots.end();
      (root ? candidates : named_only).push_back({kind, c.name, i, {}, {}});
    }
  }
  if (request.among & kPlan)
    for (model::PlanId i : m.plans.ids())
      if (m.plans[i].in_main_file) candidates.push_back({kPlan, m.plans[i].name, {}, i, {}});

  auto list = [&] {
    std::string names;
    for (const auto &c : candidates)
      names += fmt::format("{}{} '{}'", names.empty() ? "" : ", ", kind_name(c.kind), c.name);
    return names;
  };
  Selection t;
  const Candidate *chosen = nullptr;
  if (!request.name.empty()) {
    for (const auto *from : {&candidates, &named_only})
      for (const auto &c : *from)
        if (c.name == request.name && !chosen) chosen = &c;
    if (!chosen) {
      t.error = candidates.empty()
                    ? fmt::format("no chart, plan or toolbox named '{}' in the file", request.name)
                    : fmt::format("no '{}' to {}; the file declares {}", request.name, request.verb, list());
      return t;
    }
  } else if (candidates.size() == 1) {
    chosen = &candidates.front();
  } else if (candidates.empty()) {
    t.error = request.among == kToolbox ? std::string("the file declares no toolbox")
                                        : fmt::format("nothing to {}: the file declares no {}", request.verb,
                                                      kinds_text(request.among, "or"));
    t.in_input = true;
    return t;
  } else {
    // The reader may know which one the file means (an IEC CONFIGURATION's task runs it).
    for (const auto &c : candidates)
      if (!m.default_chart.empty() && c.name == m.default_chart && !chosen) chosen = &c;
    if (!chosen) {
      t.error = fmt::format("the file declares several things to {} ({}); choose one with --chart NAME", request.verb,
                            list());
      return t;
    }
  }
  t.kind = chosen->kind;
  t.name = chosen->name;
  t.chart = chosen->chart;
  t.plan = chosen->plan;
  t.toolbox = chosen->toolbox;
  return t;
}

Compilation::Compilation(const FrontEndOptions &o) : options(o), diag(o.warnings, o.error_limit) {}

bool Compilation::front_end(const std::string &path, const FileSystem &fs, scenario::Suite *tests) {
  return load_and_validate(path, fs, tests) && analyze();
}

bool Compilation::load_and_validate(const std::string &path, const FileSystem &fs, scenario::Suite *tests) {
  analysis_pending_ = false;
  LoadOptions load;
  load.include_dirs = options.include_dirs;
  load.language = options.language;
  load.period_ms = options.period_ms;
  loaded = load_program(path, load, fs, sources, diag);
  if (tests && !loaded.program.files.empty() && loaded.program.files.front())
    for (const auto &t : loaded.program.files.front()->tests) tests->written.push_back(t.name);
  if (loaded.main_unreadable || diag.has_errors()) {
    annotate_diagnostics(diag, loaded);  // a JSON member named twice: which plan element it is in
    return false;
  }
  ValidateOptions validation;
  validation.keep_tree = options.keep_syntax_tree;
  if (options.record_name_uses) validation.name_uses = &name_uses;
  MissingImportFinder missing_import(fs, path, options.include_dirs);
  validation.declaring_files = [&missing_import](const std::string &function) { return missing_import(function); };
  scenario::Suite unkept;  // validate checks the tests either way; only gfec test keeps them
  model = validate(loaded.program, sources, diag, tests ? *tests : unkept, validation);
  model.default_chart = loaded.default_chart;
  // The model holds all the back ends need: the syntax tree goes before they run, so a large
  // chart does not keep both in memory (docs/performance.md).
  if (!options.keep_syntax_tree) loaded.program = {};
  // The facts the back ends read (docs/architecture.md): proven once here, cheap and linear, so
  // they are recorded even when the analyses' warnings are off (--check, -w).
  if (!diag.has_errors()) analysis::record_activation_bounds(model);
  // ALICA input: say which plan element (name and id) each diagnostic is about.
  annotate_diagnostics(diag, loaded);
  analysis_pending_ = options.analyze && !diag.has_errors();
  return !diag.has_errors();
}

bool Compilation::analyze() {
  if (analysis_pending_) {
    analysis_pending_ = false;
    // Only what the analyses add: a diagnostic annotated twice would say "this is ..." twice.
    const std::size_t first = diag.all().size();
    // The static analyses whose warnings are on (compiler/analysis/, docs/verification.md).
    analysis::analyze(model, diag);
    annotate_diagnostics(diag, loaded, first);
  }
  return !diag.has_errors();
}

bool Compilation::front_end(const std::string &path) {
  RealFileSystem fs;
  return front_end(path, fs);
}

const Selection &Compilation::select(const SelectionRequest &request) {
  selection = choose(model, request);
  if (selection.chart) warn_unused_charts(model, selection.chart, diag);
  return selection;
}

}  // namespace gfec::pipeline
