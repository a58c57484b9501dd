#include "driver.h"

#include "analyze_command.h"

#include "backend_registry.h"
#include "dependency_file.h"
#include "diagnostic_report.h"
#include "escape.h"
#include "external_tool.h"
#include "file_system.h"
#include "input_languages.h"
#include "pipeline/compilation.h"
#include "safe_output.h"
#include "validate.h"

#include <fmt/format.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <ostream>

namespace gfec {

pipeline::FrontEndOptions front_end_options(const Options &o) {
  pipeline::FrontEndOptions f;
  f.include_dirs = o.include_dirs;
  f.language = find_input_language(o.language);  // -x was checked against the same table
  f.warnings = o.warnings;
  f.error_limit = o.error_limit;
  f.period_ms = o.period_ms;
  return f;
}

namespace {

/// The back end's outputs go straight to their safe temporaries (safe_output.h); the paths are
/// kept for the dependency file.
class TemporarySink : public OutputSink {
public:
  explicit TemporarySink(safe_output::Transaction &t) : OutputSink(run_external_tool), t_(t) {}
  std::ostream &open(const std::string &path) override {
    paths.push_back(path);
    std::ostream *out = t_.open(path);
    return out ? *out : discard_;  // refused: the transaction keeps why, the driver reports it
  }
  std::vector<std::string> paths;

private:
  safe_output::Transaction &t_;
  std::ostream discard_{nullptr};  // no buffer: badbit, writes ignored
};

/// Adds the -MD dependency file to the outputs: the files written depend on every file read.
/// Returns why it cannot be written (a name make cannot read), or "".
std::string add_dependency_file(const Options &o, const LoadResult &loaded, const std::vector<std::string> &outputs,
                                safe_output::Transaction &t) {
  std::vector<DependencyTarget> targets = o.deps.targets;
  if (targets.empty())
    for (const auto &f : outputs) targets.push_back({f, true});
  std::string name = dependency_file_name(o.deps, outputs.front());
  std::vector<std::string> names;
  for (const auto &target : targets) names.push_back(target.name);
  names.insert(names.end(), loaded.paths.begin(), loaded.paths.end());
  for (const auto &path : names) {
    std::string why = make_unreadable(path);
    if (!why.empty())
      return fmt::format("cannot write the dependency file '{}': the name '{}' contains {}, which make cannot read "
                         "in a rule (docs/build-integration.md)",
                         name, text::printable(path), why);
  }
  if (std::ostream *out = t.open(name)) *out << dependency_rule(targets, loaded.paths, o.deps.phony);
  return t.error();
}

/// Compiles (or with --check, validates) the one input of `o`; returns its exit code.
int compile(const Options &o, DiagnosticReport &report, std::ostream &out) {
  const std::string &input = o.inputs.front();
  pipeline::Compilation c(front_end_options(o));
  const BackendInfo *chosen_backend = o.emit.empty() ? nullptr : find_backend(o.emit);
  bool ok = c.front_end(input);
  if (ok && !o.check_only) {
    pipeline::SelectionRequest request;
    request.name = o.chart;
    // A back end that compiles toolboxes only chooses among the toolboxes (§5.4).
    request.among = chosen_backend && chosen_backend->accepts == pipeline::kToolbox
                        ? static_cast<unsigned>(pipeline::kToolbox)
                        : pipeline::kCharts | pipeline::kPlan;
    c.select(request);
    // A back end's own options may add warnings about what was selected (the C engine's --context).
    for (const auto &given : o.backend_options) given.group->check_selection(c.model, c.selection, c.diag);
    ok = !c.diag.has_errors();  // -Werror
  }
  report.add(input, c.diag, c.sources);
  if (c.unreadable()) {
    report.tool_error(input, c.cannot_read_main(input), false);
    return kExitUsageOrIo;
  }
  if (!ok) return kExitInputError;
  if (o.check_only) return kExitOk;

  const pipeline::Selection &selection = c.selection;
  if (!selection.chosen() && selection.in_input) {
    Diagnostics located(o.warnings, o.error_limit);
    located.error({c.model.main_file, 0, 0}, ErrorKind::NothingToCompile, selection.error);
    report.add(input, located, c.sources);
    return kExitInputError;
  }
  if (!selection.chosen()) {
    report.tool_error(input, selection.error, true);
    return kExitUsageOrIo;
  }
  if (!o.emit.empty() && !chosen_backend) {
    report.tool_error(input, fmt::format("unknown back end '{}' (known: {})", o.emit, backend_names_list()), false);
    return kExitUsageOrIo;
  }
  const BackendInfo &info = chosen_backend ? *chosen_backend : default_backend(selection.kind);
  if (!info.accepts_kind(selection.kind)) {
    report.tool_error(input,
                      fmt::format("--emit={} compiles {} only; '{}' is {}", info.name, accepted_kinds(info),
                                  selection.name, pipeline::kind_name(selection.kind), selection.name),
                      true);
    return kExitUsageOrIo;
  }
  // A back end's own options are for it alone.
  std::shared_ptr<const BackendOptions> own;
  for (const auto &given : o.backend_options) {
    if (given.backend == &info) {
      own = given.group->options();
      continue;
    }
    if (std::string flag = given.group->given(); !flag.empty()) {
      report.tool_error(
          input,
          fmt::format("{} applies only to {}; --emit={} does not take it", flag, given.group->owner(), info.name),
          false);
      return kExitUsageOrIo;
    }
  }
  EmitOptions emit;
  // EmitOptions (compiler/backend.h) still numbers them, -1 for none.
  emit.chart = selection.chart;
  emit.plan = selection.plan;
  emit.toolbox = selection.toolbox;
  emit.output_path = o.output.empty() ? replace_extension(base_name(input), info.extension) : o.output;
  emit.source_name = input;
  emit.line_directives = o.line_directives;
  emit.engine = o.engine == "readable"   ? EngineForm::Readable
                : o.engine == "scalable" ? EngineForm::Scalable
                                         : EngineForm::Auto;
  emit.backend = own;
  auto backend = info.make();
  if (o.output.empty())
    if (std::string fixed = backend->default_output(c.model, emit); !fixed.empty()) emit.output_path = fixed;
  if (o.output == "-") {
    // "-o -": the one output on stdout, for pipes (gfec --emit=dot x.sfc -o - | dot -Tpng).
    if (!info.single_file()) {
      report.tool_error(input,
                        fmt::format("-o - needs a back end that writes one file; '{}' writes {} and {}", info.name,
                                    info.extension, info.companions),
                        false);
      return kExitUsageOrIo;
    }
    try {
      // In memory first, so that a failing back end leaves nothing half-written on stdout.
      std::vector<OutputFile> outputs = emit_to_memory(*backend, c.model, emit);
      for (const auto &f : outputs) out << f.contents;
      out << std::flush;
    } catch (const ToolTimeLimit &e) {
      report.tool_error(input, e.what(), false);
      return kExitInputError;
    } catch (const std::exception &e) {
      report.tool_error(input, e.what(), false);
      return kExitUsageOrIo;
    }
    return kExitOk;
  }
  // Every output is streamed to its temporary as the back end writes it, and renamed into place
  // only when everything succeeded (docs/security.md); any failure removes the temporaries.
  safe_output::Transaction files(c.loaded.paths);
  TemporarySink sink(files);
  try {
    backend->emit(c.model, emit, sink);
  } catch (const ToolTimeLimit &e) {
    report.tool_error(input, e.what(), false);  // a chart too large to draw in time
    return kExitInputError;
  } catch (const std::exception &e) {
    // Back ends report no user errors; what reaches here is the environment (e.g. --emit=svg
    // without Graphviz installed).
    report.tool_error(input, e.what(), false);
    return kExitUsageOrIo;
  }
  if (o.deps.write && files.error().empty() && !sink.paths.empty()) {
    std::string why = add_dependency_file(o, c.loaded, sink.paths, files);
    if (!why.empty()) {
      report.tool_error(input, why, false);
      return kExitUsageOrIo;
    }
  }
  std::string failure = files.commit();
  if (!failure.empty()) {
    report.tool_error(input, failure, false);
    return kExitUsageOrIo;
  }
  return kExitOk;
}

/// Whether --check takes `path`, found in a folder it was given: a main file of an input
/// language, or chart text of any kind (an interface or toolbox checks on its own). An
/// extension several languages share is read and asked (input_language_of), as the loader does.
bool checked_in_folder(const FileSystem &fs, const std::string &path) {
  for (const InputLanguage *language : input_languages()) {
    const FileType *type = language->file_type(path);
    if (!type || !(type->main || language->chart_text)) continue;
    if (!language->sniff) return true;
    FileText text = fs.read(path);
    if (text && &input_language_of(path, *text) == language) return true;
  }
  return false;
}

/// --check: every file is validated and every diagnostic reported; the worst exit code wins. A
/// folder stands for the files below it that checked_in_folder takes, in path order, as far as
/// the file system layer's walk goes (its WalkLimits: hidden folders are skipped).
int check_all(const Options &o, DiagnosticReport &report, std::ostream &out) {
  int worst = kExitOk;
  RealFileSystem fs;
  for (const auto &input : o.inputs) {
    std::vector<std::string> files{input};
    std::error_code ec;
    if (std::filesystem::is_directory(input, ec)) {
      files.clear();
      for (const std::string &path : fs.walk(input))
        if (checked_in_folder(fs, path)) files.push_back(path);
      if (files.empty()) {
        report.tool_error(input,
                          fmt::format("folder '{}' holds no file of a language gfec reads (docs/cli.md lists "
                                      "their extensions)",
                                      input),
                          false);
        worst = std::max<int>(worst, kExitUsageOrIo);
      }
    }
    for (const std::string &file : files) {
      Options one = o;
      one.inputs = {file};
      worst = std::max(worst, compile(one, report, out));
    }
  }
  return worst;
}

}  // namespace

int finish_report(DiagnosticReport &report, int code, std::ostream &err) {
  std::string failure = report.finish(code);
  if (failure.empty()) return code;
  err << "gfec: error: " << text::printable(failure) << "\n";
  return kExitUsageOrIo;
}

int compile_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err) {
  ParsedCommandLine cl = parse_command_line(argc, argv);
  if (cl.exit_now) {
    (cl.exit_code == 0 ? out : err) << cl.message;
    return cl.exit_code;
  }
  return run(cl.options, out, err);
}

int run(const Options &o, std::ostream &out, std::ostream &err) {
  if (o.analyze) return analyze_command(o, out, err);
  auto report = make_report(o, err);
  return finish_report(*report, o.check_only ? check_all(o, *report, out) : compile(o, *report, out), err);
}

}  // namespace gfec
