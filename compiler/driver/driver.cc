#include "driver.h"

#include "backend_registry.h"
#include "diagnostic_printer.h"
#include "loader.h"
#include "output_files.h"
#include "validate.h"

#include <fmt/format.h>

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

void print_diagnostics(const Compilation &c, const Options &, std::ostream &err) {
  for (const auto &d : c.diag.all()) err << render_text(d, c.sources);
  if (c.diag.limit_reached())
    err << fmt::format("gfec: compilation stopped after {} errors (-fmax-errors)\n", c.diag.error_count());
}

/// Runs lexer, parser and validator. False if the input has errors (already reported).
bool front_end(const std::string &path, const Options &o, Compilation &c) {
  RealFileSystem fs;
  c.loaded = load_program(path, {o.include_dirs}, fs, c.sources, c.diag);
  if (c.loaded.main_unreadable) return false;
  // Validating a tree the parser had to patch up would mostly report the patches.
  if (c.diag.has_errors()) return false;
  c.model = validate(c.loaded.program, c.sources, c.diag);
  return !c.diag.has_errors();
}

struct Selection {
  std::string backend;
  EmitOptions emit;
  std::string error;
};

/// Which chart, plan or toolbox of the main file to compile, and with which back end (§5.4).
Selection select(const model::Model &m, const Options &o) {
  Selection s;
  struct Candidate {
    std::string kind, name;
    int chart = -1, plan = -1, toolbox = -1;
  };
  std::vector<Candidate> candidates;
  bool skeleton = o.emit == "toolbox-skeleton";
  if (skeleton) {
    for (std::size_t i = 0; i < m.toolboxes.size(); ++i)
      if (m.toolboxes[i].range.file == m.main_file)
        candidates.push_back({"toolbox", m.toolboxes[i].name, -1, -1, static_cast<int>(i)});
  } else {
    for (std::size_t i = 0; i < m.charts.size(); ++i)
      if (m.charts[i].in_main_file)
        candidates.push_back({m.charts[i].kind == model::Chart::Kind::Sfc ? "sfc" : "fsm", m.charts[i].name,
                              static_cast<int>(i), -1, -1});
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
    for (const auto &c : candidates)
      if (c.name == o.chart) chosen = &c;
    if (!chosen) {
      s.error = candidates.empty() ? fmt::format("no chart, plan or toolbox named '{}' in the file", o.chart)
                                   : fmt::format("no '{}' to compile; the file declares {}", o.chart, list());
      return s;
    }
  } else if (candidates.size() == 1) {
    chosen = &candidates.front();
  } else if (candidates.empty()) {
    s.error = skeleton ? "the file declares no toolbox" : "nothing to compile: the file declares no sfc, fsm or plan";
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
                                                                                                     : "." + backend;
  return replace_extension(base_name(input), ext);
}

int compile(const Options &o, std::ostream &err) {
  const std::string &input = o.inputs.front();
  Compilation c(o);
  bool ok = front_end(input, o, c);
  print_diagnostics(c, o, err);
  if (c.loaded.main_unreadable) {
    err << fmt::format("gfec: error: cannot read '{}'\n", input);
    return kExitUsageOrIo;
  }
  if (!ok) return kExitInputError;
  if (o.check_only) return kExitOk;

  Selection s = select(c.model, o);
  if (!s.error.empty()) {
    err << fmt::format("{}: error: {}\n", input, s.error);
    return kExitUsageOrIo;
  }
  auto backend = make_backend(s.backend);
  if (!backend) {
    std::string known;
    for (const auto &n : backend_names()) known += (known.empty() ? "" : ", ") + n;
    err << fmt::format("gfec: error: unknown back end '{}' (known: {})\n", s.backend, known);
    return kExitUsageOrIo;
  }
  s.emit.output_path = o.output.empty() ? default_output(input, s.backend) : o.output;
  s.emit.source_name = input;
  s.emit.line_directives = o.line_directives;
  std::string failure = write_atomically(backend->emit(c.model, s.emit));
  if (!failure.empty()) {
    err << "gfec: error: " << failure << "\n";
    return kExitUsageOrIo;
  }
  return kExitOk;
}

int check_all(const Options &o, std::ostream &err) {
  int worst = kExitOk;
  for (const auto &input : o.inputs) {
    Options one = o;
    one.inputs = {input};
    worst = std::max(worst, compile(one, err));
  }
  return worst;
}

} // namespace

int run(const Options &o, std::ostream &, std::ostream &err) {
  if (o.diagnostics_format != DiagnosticsFormat::Text) {
    err << "gfec: error: only -fdiagnostics-format=text is available in this build\n";
    return kExitUsageOrIo;
  }
  return o.check_only ? check_all(o, err) : compile(o, err);
}

} // namespace gfec
