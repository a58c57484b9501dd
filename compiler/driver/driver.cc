#include "driver.h"

#include "analysis/analysis.h"
#include "analyze_command.h"

#include "backend_registry.h"
#include "dependency_file.h"
#include "diagnostic_report.h"
#include "loader.h"
#include "output_files.h"
#include "roots.h"
#include "validate.h"

#include <fmt/format.h>

#include <algorithm>
#include <exception>
#include <ostream>

namespace gfec {

namespace {

/// One input file carried through the pipeline.
struct Compilation {
  SourceManager sources;
  Diagnostics diag;
  LoadResult loaded;
  model::Model model;

  explicit Compilation(const Options &o) : diag(o.warnings, o.error_limit) {}
};

/// Runs lexer, parser and validator. False if the input has errors (already reported).
bool front_end(const std::string &path, const Options &o, Compilation &c) {
  RealFileSystem fs;
  LoadOptions load{o.include_dirs};
  load.language = o.language == "alica"  ? InputLanguage::Alica
                  : o.language == "gfec" ? InputLanguage::Gfec
                                         : InputLanguage::Auto;
  c.loaded = load_program(path, load, fs, c.sources, c.diag);
  if (c.loaded.main_unreadable) return false;
  // Validating a tree the parser had to patch up would mostly report the patches.
  if (c.diag.has_errors()) return false;
  c.model = validate(c.loaded.program, c.sources, c.diag);
  // The static analyses whose warnings are on (compiler/analysis/, docs/verification.md).
  if (!c.diag.has_errors()) analysis::analyze(c.model, c.diag);
  // ALICA input: say which plan element (name and id) each diagnostic is about.
  annotate_elements(c.diag, c.loaded);
  return !c.diag.has_errors();
}

struct Selection {
  std::string backend;
  EmitOptions emit;
  std::string error;
  bool in_input = false;  ///< the error is the input's (nothing to compile in it): exit 1, located
};

/// Which chart, plan or toolbox of the main file to compile, and with which back end (§5.4).
Selection select(const model::Model &m, const Options &o) {
  Selection s;
  struct Candidate {
    std::string kind, name;
    int chart = -1, plan = -1, toolbox = -1;
  };
  std::vector<Candidate> candidates;
  std::vector<Candidate> named_only;  ///< sub-charts of the main file: compiled alone by name only
  bool skeleton = o.emit == "toolbox-skeleton";
  if (skeleton) {
    for (std::size_t i = 0; i < m.toolboxes.size(); ++i)
      if (m.toolboxes[i].range.file == m.main_file)
        candidates.push_back({"toolbox", m.toolboxes[i].name, -1, -1, static_cast<int>(i)});
  } else {
    // The default root rule (docs/language.md "Sub-charts"): a chart another chart runs is
    // compiled only when --chart names it.
    std::vector<int> roots = root_charts(m);
    for (std::size_t i = 0; i < m.charts.size(); ++i) {
      if (!m.charts[i].in_main_file) continue;
      bool root = std::find(roots.begin(), roots.end(), static_cast<int>(i)) != roots.end();
      (root ? candidates : named_only)
          .push_back({m.charts[i].kind == model::Chart::Kind::Sfc ? "sfc" : "fsm", m.charts[i].name,
                      static_cast<int>(i), -1, -1});
    }
    for (std::size_t i = 0; i < m.plans.size(); ++i)
      if (m.plans[i].in_main_file) candidates.push_back({"plan", m.plans[i].name, -1, static_cast<int>(i), -1});
  }
  auto list = [&] {
    std::string names;
    for (const auto &c : candidates) names += fmt::format("{}{} '{}'", names.empty() ? "" : ", ", c.kind, c.name);
    return names;
  };
  const Candidate *chosen = nullptr;
  if (!o.chart.empty()) {
    for (const auto *from : {&candidates, &named_only})
      for (const auto &c : *from)
        if (c.name == o.chart && !chosen) chosen = &c;
    if (!chosen) {
      s.error = candidates.empty() ? fmt::format("no chart, plan or toolbox named '{}' in the file", o.chart)
                                   : fmt::format("no '{}' to compile; the file declares {}", o.chart, list());
      return s;
    }
  } else if (candidates.size() == 1) {
    chosen = &candidates.front();
  } else if (candidates.empty()) {
    s.error = skeleton ? "the file declares no toolbox" : "nothing to compile: the file declares no sfc, fsm or plan";
    s.in_input = true;
    return s;
  } else {
    s.error = fmt::format("the file declares several things to compile ({}); choose one with --chart NAME", list());
    return s;
  }
  s.emit.chart = chosen->chart;
  s.emit.plan = chosen->plan;
  s.emit.toolbox = chosen->toolbox;
  s.backend = !o.emit.empty() ? o.emit : chosen->plan >= 0 ? "cpp" : "c";
  return s;
}

std::string default_output(const std::string &input, const std::string &backend) {
  std::string ext = backend == "c" ? ".c" : backend == "cpp" ? ".cpp" : backend == "toolbox-skeleton" ? ".hpp"
                  : backend == "chart"                                                              ? ".sfc"
                                                                                                     : "." + backend;
  return replace_extension(base_name(input), ext);
}

/// `path` with control characters spelled as C escapes, for a message on one line.
std::string printable(const std::string &path) {
  std::string out;
  for (char c : path) {
    auto u = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (u < 0x20 || u == 0x7f) out += fmt::format("\\x{:02x}", u);
    else out += c;
  }
  return out;
}

/// Adds the -MD dependency file to the outputs: the files written depend on every file read.
/// Returns why it cannot be written (a name make cannot read), or "".
std::string add_dependency_file(const Options &o, const LoadResult &loaded, std::vector<OutputFile> &outputs) {
  std::vector<DependencyTarget> targets = o.deps.targets;
  if (targets.empty())
    for (const auto &f : outputs) targets.push_back({f.path, true});
  std::string name = dependency_file_name(o.deps, outputs.front().path);
  std::vector<std::string> names;
  for (const auto &t : targets) names.push_back(t.name);
  names.insert(names.end(), loaded.paths.begin(), loaded.paths.end());
  for (const auto &path : names) {
    std::string why = make_unreadable(path);
    if (!why.empty())
      return fmt::format("cannot write the dependency file '{}': the name '{}' contains {}, which make cannot read "
                         "in a rule (docs/build-integration.md)",
                         name, printable(path), why);
  }
  outputs.push_back({name, dependency_rule(targets, loaded.paths, o.deps.phony)});
  return {};
}

/// Compiles (or with --check, validates) the one input of `o`; returns its exit code.
int compile(const Options &o, DiagnosticReport &report, std::ostream &out) {
  const std::string &input = o.inputs.front();
  Compilation c(o);
  bool ok = front_end(input, o, c);
  Selection s;
  if (ok && !o.check_only) {
    s = select(c.model, o);
    if (s.error.empty() && s.emit.chart >= 0) warn_unused_charts(c.model, s.emit.chart, c.diag);
    ok = !c.diag.has_errors();  // -Werror
  }
  report.add(input, c.diag, c.sources);
  if (c.loaded.main_unreadable) {
    report.tool_error(input, fmt::format("cannot read '{}'", input), false);
    return kExitUsageOrIo;
  }
  if (!ok) return kExitInputError;
  if (o.check_only) return kExitOk;

  if (!s.error.empty() && s.in_input) {
    Diagnostics located(o.warnings, o.error_limit);
    located.error({c.model.main_file, 0, 0}, ErrorKind::NothingToCompile, s.error);
    report.add(input, located, c.sources);
    return kExitInputError;
  }
  if (!s.error.empty()) {
    report.tool_error(input, s.error, true);
    return kExitUsageOrIo;
  }
  auto backend = make_backend(s.backend);
  if (!backend) {
    std::string known;
    for (const auto &n : backend_names()) known += (known.empty() ? "" : ", ") + n;
    report.tool_error(input, fmt::format("unknown back end '{}' (known: {})", s.backend, known), false);
    return kExitUsageOrIo;
  }
  s.emit.output_path = o.output.empty() ? default_output(input, s.backend) : o.output;
  s.emit.source_name = input;
  s.emit.line_directives = o.line_directives;
  s.emit.engine = o.engine == "readable"   ? EngineForm::Readable
                  : o.engine == "scalable" ? EngineForm::Scalable
                                           : EngineForm::Auto;
  std::vector<OutputFile> outputs;
  try {
    outputs = backend->emit(c.model, s.emit);
  } catch (const std::exception &e) {
    // Back ends report no user errors; what reaches here is the environment (e.g. --emit=svg
    // without Graphviz installed).
    report.tool_error(input, e.what(), false);
    return kExitUsageOrIo;
  }
  if (o.output == "-") {
    // "-o -": the one output on stdout, for pipes (gfec --emit=dot x.sfc -o - | dot -Tpng).
    if (outputs.size() != 1) {
      report.tool_error(input, fmt::format("-o - needs a back end that writes one file; '{}' writes {}", s.backend,
                                           outputs.size()), false);
      return kExitUsageOrIo;
    }
    out << outputs.front().contents << std::flush;
    return kExitOk;
  }
  if (o.deps.write && !outputs.empty()) {
    std::string why = add_dependency_file(o, c.loaded, outputs);
    if (!why.empty()) {
      report.tool_error(input, why, false);
      return kExitUsageOrIo;
    }
  }
  std::string failure = write_atomically(outputs, c.loaded.paths);
  if (!failure.empty()) {
    report.tool_error(input, failure, false);
    return kExitUsageOrIo;
  }
  return kExitOk;
}

/// --check: every file is validated and every diagnostic reported; the worst exit code wins.
int check_all(const Options &o, DiagnosticReport &report, std::ostream &out) {
  int worst = kExitOk;
  for (const auto &input : o.inputs) {
    Options one = o;
    one.inputs = {input};
    worst = std::max(worst, compile(one, report, out));
  }
  return worst;
}

} // namespace

int run(const Options &o, std::ostream &out, std::ostream &err) {
  if (o.analyze) return analyze_command(o, out, err);
  auto report = make_report(o, err);
  int code = o.check_only ? check_all(o, *report, out) : compile(o, *report, out);
  std::string failure = report->finish(code);
  if (!failure.empty()) {
    err << "gfec: error: " << failure << "\n";
    return kExitUsageOrIo;
  }
  return code;
}

} // namespace gfec
