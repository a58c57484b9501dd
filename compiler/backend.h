// The one interface every back end implements. Back ends read the model and write text to the
// streams an OutputSink gives them; the driver owns the file system (temporary files, renames,
// dependency files) and decides what is compiled (pipeline/compilation.h).
#pragma once

#include "model.h"

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace gfec {

struct OutputFile {
  std::string path;
  std::string contents;
};

/// The layout of a C engine (docs/c-engine.md, docs/performance.md): GFE's readable form visits
/// every transition and place each tick; the scalable form visits only what is active. Auto
/// picks the readable form for small charts and the scalable one above a size.
enum class EngineForm { Auto, Readable, Scalable };

/// A back end's own options (the C engine's --context and --names): a struct of the back end's
/// deriving from this, carried by EmitOptions::backend; nothing generic reads it.
struct BackendOptions {
  virtual ~BackendOptions() = default;
};

struct EmitOptions {
  std::string output_path;      ///< the primary output as the user named it (e.g. "engine.c")
  std::string source_name;      ///< the chart file as the user named it, for the header comment
  bool line_directives = true;  ///< `#line` back to the chart
  // What to compile, as pipeline::choose() picked it; exactly the one the back end accepts
  // is set (a back end given none is a bug of its caller and throws std::invalid_argument).
  model::ChartId chart;                  ///< the sfc or fsm to compile, or none
  model::PlanId plan;                    ///< the plan to compile, or none
  model::ToolboxId toolbox;              ///< the toolbox to write a skeleton for, or none
  EngineForm engine = EngineForm::Auto;  ///< C back end: `--engine=auto|readable|scalable`
  /// The chosen back end's own options (its registry row's option group made them,
  /// backends/backend_registry.h), or null: its defaults. Read with backend_options<T>().
  std::shared_ptr<const BackendOptions> backend;
};

/// The back end's own options of type T that `o` carries, or T's defaults.
template <class T> const T &backend_options(const EmitOptions &o) {
  static const T defaults{};
  const T *own = dynamic_cast<const T *>(o.backend.get());
  return own ? *own : defaults;
}

/// A program a back end's output goes through (OutputSink::filter): it reads the text on its
/// standard input and writes the output on its standard output.
struct ExternalTool {
  std::vector<std::string> command;  ///< the program, found on PATH, and its arguments
  std::string purpose;               ///< for messages: "--emit=svg runs Graphviz's 'dot'"
  std::string if_missing;            ///< what the user can do when the program cannot be started
};

/// Runs `tool` over `input` and returns its standard output (the driver's run_external_tool).
using ToolRunner = std::function<std::string(const ExternalTool &tool, const std::string &input)>;

/// Where a back end writes: one stream per output file, opened in order, the primary output
/// first (e.g. engine.c, then engine.h beside it). The driver's sink writes each to its safe
/// temporary file (support/safe_output.h) and renames them into place only when the
/// whole compile succeeded; a name it refuses gives a stream that discards (the driver reports).
class OutputSink {
public:
  /// `tools` runs the external tools of filter(); without it filter() throws.
  explicit OutputSink(ToolRunner tools) : tools_(std::move(tools)) {}
  virtual ~OutputSink() = default;
  /// The stream for the output `path`; valid until the next open() or the end of emit().
  virtual std::ostream &open(const std::string &path) = 0;
  /// The output `path` is `input` put through an external tool (e.g. Graphviz's `dot -Tsvg`).
  /// The sink's owner runs it, so that back ends never start processes or touch the file
  /// system; throws std::runtime_error with a message for the user when the tool is missing or
  /// fails.
  void filter(const std::string &path, const ExternalTool &tool, const std::string &input);

private:
  ToolRunner tools_;
};

class Backend {
public:
  virtual ~Backend() = default;
  /// Writes the outputs for the chart, plan or toolbox `options` names.
  virtual void emit(const model::Model &model, const EmitOptions &options, OutputSink &sink) const = 0;
  /// The output's name without -o when the back end's contract fixes it (a toolbox skeleton's
  /// header is the one the plans' wiring includes); empty: the input's name with the extension.
  virtual std::string default_output(const model::Model &, const EmitOptions &) const { return {}; }
};

/// The outputs in memory, in the order the back end opened them: for tests and for uses inside
/// the process (the run viewer's picture). Outputs that go through an external tool need
/// `tools`; without it they throw std::runtime_error.
std::vector<OutputFile> emit_to_memory(const Backend &backend, const model::Model &model, const EmitOptions &options,
                                       const ToolRunner &tools = {});

/// "dir/engine.c" with extension ".h" -> "dir/engine.h"; a name without extension gets it added.
std::string replace_extension(const std::string &path, const std::string &ext);
/// The last path component: "dir/engine.h" -> "engine.h".
std::string base_name(const std::string &path);

}  // namespace gfec
