// What the C back end's tests share (tests/unit/c_backend_*_test.cc): a builder for hand-made
// models, the real pipeline from chart text to engine, scratch directories, running commands,
// and the generator of the C harness that compile-and-run tests link with an engine.
#pragma once

#include "analysis/activation_bounds.h"
#include "backend.h"
#include "c_backend.h"
#include "c_engine_options.h"
#include "c_harness.h"
#include "diagnostic_printer.h"
#include "file_system.h"
#include "loader.h"
#include "model.h"
#include "pipeline/compilation.h"
#include "../unit/support.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cbt {

namespace fs = std::filesystem;
using namespace gfec;
using model::Expr;
using model::Stmt;
using model::Type;

// ------------------------------------------------------------------ hand-built models

/// Builds one chart into a model, every element on a line of its own in a fake chart file so
/// that #line directives have somewhere to point.
class ChartBuilder {
public:
  ChartBuilder(std::string name, model::Chart::Kind kind, std::string path = "hand.sfc")
      : sources_(std::make_unique<SourceManager>()) {
    sources_->add(std::move(path), std::string(400, '\n'));
    model_.set_sources(*sources_);
    model::Chart c;
    c.name = std::move(name);
    c.kind = kind;
    c.in_main_file = true;
    model_.charts.push_back(std::move(c));
  }

  model::Chart &chart() { return model_.charts.at(current_); }
  /// The model as the pipeline hands it to the back ends: with the facts it records after
  /// validation (compiler/pipeline/compilation.cc), proven for the charts as built so far.
  const model::Model &model() {
    analysis::record_activation_bounds(model_);
    return model_;
  }

  /// Sub-charts: adds a chart (1, 2, ...) and makes it the one the other calls build, until
  /// select() goes back (chart 0 is the one compiled).
  model::ChartId begin_chart(std::string name, model::Chart::Kind kind) {
    model::Chart c;
    c.name = std::move(name);
    c.kind = kind;
    c.in_main_file = true;
    current_ = model_.charts.next_id();
    model_.charts.push_back(std::move(c));
    return current_;
  }
  void select(model::ChartId chart) { current_ = chart; }
  /// Place `place` of the current chart runs chart `sub`.
  void runs(const std::string &place, model::ChartId sub) { chart().places.at(place_id(place)).runs = sub; }
  /// `active(P.Q.R)`: the names resolved chart by chart from the current one.
  Expr active(const std::vector<std::string> &path) const {
    Expr e;
    e.kind = Expr::Kind::Active;
    model::ChartId c = current_;
    for (const auto &name : path) {
      const auto &places = model_.charts.at(c).places;
      model::PlaceId found;
      for (model::PlaceId p : places.ids())
        if (places[p].name == name) found = p;
      if (!found) throw std::invalid_argument("no place " + name);
      e.path.push_back(found);
      c = places[found].runs ? places[found].runs : model::ChartId(0);
    }
    return e;
  }
  /// `succeeded(P)` / `failed(P)`.
  Expr status(const std::string &place, bool succeeded) const {
    Expr e;
    e.kind = succeeded ? Expr::Kind::Succeeded : Expr::Kind::Failed;
    e.refer_to(place_id(place));
    return e;
  }

  /// Declares an interface function (once) and marks it used by the chart.
  ChartBuilder &fn(const std::string &name, Type result = Type::Void, std::vector<model::Param> params = {}) {
    for (model::FunctionId i : model_.functions.ids())
      if (model_.functions[i].name == name) {  // declared for another chart: used by this one too
        chart().functions.push_back(i);
        return *this;
      }
    model::Function f;
    f.name = name;
    f.result = result;
    f.params = std::move(params);
    f.interface_name = "Bot";
    f.range = next_range();
    chart().functions.push_back(model_.functions.next_id());
    model_.functions.push_back(f);
    return *this;
  }

  model::Place &place(const std::string &name, bool initial = false, std::vector<Stmt> action = {}) {
    model::Place p;
    p.name = name;
    p.initial = initial;
    p.action = std::move(action);
    p.range = next_range();
    chart().places.push_back(std::move(p));
    return chart().places.back();
  }

  model::Transition &transition(const std::vector<std::string> &in, const std::vector<std::string> &out,
                                std::optional<Expr> condition = {}, const std::string &name = "") {
    model::Transition t;
    t.name = name.empty() ? fmt::format("T{}", chart().transitions.size()) : name;
    t.named = !name.empty();
    for (const auto &p : in) t.inputs.push_back(place_id(p));
    for (const auto &p : out) t.outputs.push_back(place_id(p));
    t.range = next_range();
    if (condition) {
      t.condition = std::move(condition);
      t.condition->range = t.range;
    }
    chart().transitions.push_back(std::move(t));
    return chart().transitions.back();
  }

  model::VarId var(const std::string &name, Type type, std::optional<Expr> init = {}) {
    model::Var v;
    v.name = name;
    v.type = type;
    v.init = std::move(init);
    v.range = next_range();
    const model::VarId id = chart().vars.next_id();
    chart().vars.push_back(std::move(v));
    return id;
  }

  model::ConstId constant(const std::string &name, Expr value) {
    model::Const k;
    k.name = name;
    k.type = value.type;
    k.value = std::move(value);
    k.range = next_range();
    const model::ConstId id = model_.consts.next_id();
    model_.consts.push_back(std::move(k));
    chart().consts.push_back(id);
    return id;
  }

  void verbatim(const std::string &text) { model_.verbatims.push_back({text, next_range()}); }

  // Expressions and statements.
  Expr call(const std::string &name, std::vector<Expr> args = {}) const {
    Expr e;
    e.kind = Expr::Kind::Call;
    e.refer_to(function_id(name));
    e.type = model_.functions[e.function()].result;
    e.args = std::move(args);
    return e;
  }
  Stmt act(const std::string &name, std::vector<Expr> args = {}) {
    Stmt s;
    s.kind = Stmt::Kind::Call;
    s.expr = call(name, std::move(args));
    s.range = next_range();
    return s;
  }
  Stmt assign(const std::string &var, AssignOp op, Expr value) {
    Stmt s;
    s.kind = Stmt::Kind::Assign;
    s.var = var_id(var);
    s.op = op;
    s.expr = std::move(value);
    s.range = next_range();
    return s;
  }
  Stmt verbatim_stmt(const std::string &text) {
    Stmt s;
    s.kind = Stmt::Kind::Verbatim;
    s.verbatim = text;
    s.range = next_range();
    return s;
  }
  Expr var_ref(const std::string &name) const {
    Expr e;
    e.kind = Expr::Kind::Var;
    e.refer_to(var_id(name));
    e.type = chart_const().vars[e.var()].type;
    return e;
  }
  Expr const_ref(model::ConstId constant) const {
    Expr e;
    e.kind = Expr::Kind::Const;
    e.refer_to(constant);
    e.type = model_.consts[constant].type;
    return e;
  }
  Expr elapsed(const std::string &place) {
    Expr e;
    e.kind = Expr::Kind::Elapsed;
    e.type = Type::Duration;
    e.refer_to(place_id(place));
    chart().places[e.place()].timed = true;
    return e;
  }
  static Expr ticks(unsigned long n, double ms) {
    Expr e;
    e.kind = Expr::Kind::Ticks;
    e.type = Type::Duration;
    e.ticks = n;
    e.float_value = ms;
    return e;
  }
  static Expr lit(Expr::Kind kind, const std::string &text, Type type) {
    Expr e;
    e.kind = kind;
    e.text = text;
    e.type = type;
    // The values the validator would have parsed from the spelling (model.h).
    if (kind == Expr::Kind::Int) e.int_value = static_cast<std::int32_t>(std::stoll(text));
    if (kind == Expr::Kind::Float) e.float_value = std::stod(text);
    return e;
  }
  static Expr int_lit(const std::string &text) { return lit(Expr::Kind::Int, text, Type::Int); }
  static Expr float_lit(const std::string &text) { return lit(Expr::Kind::Float, text, Type::Float); }
  static Expr bool_lit(bool value) {
    Expr e;
    e.kind = Expr::Kind::Bool;
    e.bool_value = value;
    return e;
  }
  static Expr bin(BinaryOp op, Expr a, Expr b) {
    Expr e;
    e.kind = Expr::Kind::Binary;
    e.binary_op = op;
    e.args.push_back(std::move(a));
    e.args.push_back(std::move(b));
    return e;
  }
  static Expr un(UnaryOp op, Expr a) {
    Expr e;
    e.kind = Expr::Kind::Unary;
    e.unary_op = op;
    e.args.push_back(std::move(a));
    return e;
  }
  static Expr paren(Expr a) {
    Expr e;
    e.kind = Expr::Kind::Paren;
    e.type = a.type;
    e.args.push_back(std::move(a));
    return e;
  }

  model::PlaceId place_id(const std::string &name) const {
    for (model::PlaceId p : chart_const().places.ids())
      if (chart_const().places[p].name == name) return p;
    throw std::invalid_argument("no place " + name);
  }

private:
  const model::Chart &chart_const() const { return model_.charts.at(current_); }
  model::FunctionId function_id(const std::string &name) const {
    for (model::FunctionId f : model_.functions.ids())
      if (model_.functions[f].name == name) return f;
    throw std::invalid_argument("no function " + name);
  }
  model::VarId var_id(const std::string &name) const {
    for (model::VarId v : chart_const().vars.ids())
      if (chart_const().vars[v].name == name) return v;
    throw std::invalid_argument("no var " + name);
  }
  SourceRange next_range() {
    ++line_;
    return {0, line_ - 1, line_ - 1};  // offset k is the start of line k+1 in the fake file
  }

  std::unique_ptr<SourceManager> sources_;
  model::Model model_;
  std::uint32_t line_ = 0;
  model::ChartId current_{0};
};

/// The C engine's own options (--context-type, --names) as EmitOptions carries them.
inline std::shared_ptr<const BackendOptions> c_engine_options(const std::string &context_type, bool names = false) {
  auto c = std::make_shared<c_backend::CEngineOptions>();
  c->context_type = context_type;
  c->names = names;
  return c;
}

/// Runs the C back end on a model: {engine.c, engine.h} for output `output`.
inline std::vector<OutputFile> emit_c(const model::Model &m, const std::string &output = "engine.c",
                                      bool line_directives = true, const std::string &source = "hand.sfc",
                                      EngineForm engine = EngineForm::Auto, const std::string &context_type = "") {
  EmitOptions o;
  o.output_path = output;
  o.source_name = source;
  o.line_directives = line_directives;
  o.engine = engine;
  o.backend = c_engine_options(context_type);
  o.chart = model::ChartId(0);
  return emit_to_memory(*make_c_backend(), m, o);
}

// ------------------------------------------------------------------ the real pipeline

/// Chart text through loader, validator and back end, all in memory. Files are named as given
/// (relative names keep #line paths short and the output byte-stable).
struct Compiled : test::Pipeline {
  using Pipeline::Pipeline;
  std::vector<OutputFile> files;
  std::string errors;    ///< rendered diagnostics when the chart did not compile
  model::ChartId chart;  ///< the chart compiled: the default root of the main file

  const model::Chart &the_chart() const { return model.charts.at(chart); }
};

inline std::unique_ptr<Compiled> compile_chart(const std::map<std::string, std::string> &files, const std::string &main,
                                               const std::string &output, bool line_directives = true,
                                               EngineForm engine = EngineForm::Auto,
                                               const std::string &context_type = "", bool names = false) {
  MemoryFileSystem mem;
  for (const auto &[path, text] : files) mem.add(path, text);
  auto c = std::make_unique<Compiled>(main, mem);
  // The chart gfec compiles by default: the one no other chart runs (docs/language.md "Sub-charts").
  pipeline::SelectionRequest request;
  request.among = pipeline::kSfc | pipeline::kFsm;
  const pipeline::Selection &target = c->c.diag.has_errors() ? c->c.selection : c->c.select(request);
  c->errors = c->text();
  if (c->diag.has_errors() || c->model.charts.empty()) return c;
  if (!target.chosen()) {
    c->errors += target.error + "\n";
    return c;
  }
  EmitOptions o;
  o.output_path = output;
  o.source_name = main;
  o.line_directives = line_directives;
  o.engine = engine;
  o.backend = c_engine_options(context_type, names);
  o.chart = target.chart;
  c->chart = target.chart;
  c->files = emit_to_memory(*make_c_backend(), c->model, o);
  return c;
}

// ------------------------------------------------------------------ files and commands

inline std::string read_file(const fs::path &path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const fs::path &path, const std::string &text) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
}

/// A fresh directory for one test under the build tree.
inline fs::path scratch_dir(const std::string &name) {
  fs::path dir = fs::path(GFEC_BINARY_DIR) / "test-scratch" / "c_backend" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

struct CommandResult {
  int status = -1;
  std::string output;  ///< stdout and stderr together
};

inline CommandResult run_command(const std::string &command, const fs::path &log) {
  CommandResult r;
  r.status = std::system((command + " > '" + log.string() + "' 2>&1").c_str());
  r.output = read_file(log);
  return r;
}

inline bool have_tool(const std::string &tool) {
  return std::system(("command -v " + tool + " > /dev/null 2>&1").c_str()) == 0;
}

/// The compilers the generated C must satisfy; clang is skipped (with a warning by the caller)
/// where it is not installed.
inline std::vector<std::string> c_compilers() {
  std::vector<std::string> cc{"gcc"};
  if (have_tool("clang")) cc.push_back("clang");
  return cc;
}

inline const char *kStrictFlags = "-std=c99 -Wall -Wextra -Wpedantic -Werror";

/// Writes `files` into the scratch directory `test` and compiles `source` alone (-c) with every
/// C compiler at kStrictFlags, once with each of `defines`: every build must pass.
inline void check_compiles(const std::string &test, const std::vector<OutputFile> &files, const std::string &source,
                           const std::vector<std::string> &defines = {""}) {
  fs::path dir = scratch_dir(test);
  for (const auto &f : files) write_file(dir / f.path, f.contents);
  for (const auto &cc : c_compilers())
    for (const auto &d : defines) {
      auto r =
          run_command(fmt::format("cd '{}' && {} {} {} -c {} -o /dev/null", dir.string(), cc, kStrictFlags, d, source),
                      dir / "build.log");
      INFO(cc << " " << d << "\n" << r.output);
      CHECK(r.status == 0);
    }
}

// ------------------------------------------------------------------ the run harness

/// The program the compile-and-run tests link with an engine (backends/c/c_harness.h, Script
/// inputs and the Compact log): every interface function the chart calls answers from a script
/// read on stdin, one line per tick (`Left_IR_Black Distance=12.5`: listed sensing functions
/// return 1 or the value, others 0), and logs each call (`cond F -> 1`, `act G(0, 0.6)`); after
/// each tick it prints the activation (`av A B:2` lists the active places, counts above one after
/// a colon; an fsm prints `state S status 0`). With -DX_HOOKS it logs the hooks too (`hook lost
/// A`, `hook gained B`, `hook enabled T0`); with -DHARNESS_INSTANCES each sub-chart instance's
/// active places (`in A.M1: L2`). `context`: the engine was made with --context (void *); main
/// gives it a device of its own, and every interface function first checks that it received
/// exactly that (else it prints `wrong context` and exits with 3), so the log is the same as
/// without the context.
inline c_backend::HarnessSources harness_source(const model::Model &m, const model::Chart &chart,
                                                const std::string &header, bool context = false) {
  EmitOptions emit;
  for (model::ChartId c : m.charts.ids())
    if (&m.charts[c] == &chart) emit.chart = c;
  if (context) emit.backend = c_engine_options("void *");
  c_backend::HarnessOptions o;
  o.inputs = c_backend::HarnessInputs::Script;
  o.log = c_backend::HarnessLog::Compact;
  o.header = header;
  o.context = context;
  return c_backend::write_harness(m, emit.chart, emit, o);
}

/// Writes the engine and the harness into a scratch directory, compiles them with every C
/// compiler at kStrictFlags (plus `defines`), runs each on `script` and returns the log, which
/// must be the same for every compiler. `exit_ok`: the run must exit with status 0.
inline std::string compile_and_run(const std::string &test, const std::vector<OutputFile> &files, const model::Model &m,
                                   const model::Chart &chart, const std::string &script,
                                   const std::string &defines = "", bool exit_ok = true, bool context = false) {
  REQUIRE(files.size() == 2);
  fs::path dir = scratch_dir(test);
  for (const auto &f : files) write_file(dir / base_name(f.path), f.contents);
  const c_backend::HarnessSources harness = harness_source(m, chart, base_name(files[1].path), context);
  write_file(dir / "glue.c", harness.glue);
  write_file(dir / "harness.c", harness.main);
  write_file(dir / "script.txt", script);
  if (!have_tool("clang")) WARN("clang is not installed: the generated code is tested with gcc only");
  std::string first;
  bool have_first = false;
  for (const auto &cc : c_compilers()) {
    fs::path exe = dir / ("run-" + cc);
    auto build = run_command(fmt::format("cd '{}' && {} {} {} glue.c harness.c {} -o '{}'", dir.string(), cc,
                                         kStrictFlags, defines, base_name(files[0].path), exe.string()),
                             dir / ("build-" + cc + ".log"));
    INFO(cc << " " << defines << " in " << dir.string() << ":\n" << build.output);
    REQUIRE(build.status == 0);
    auto run = run_command(fmt::format("'{}' < '{}'", exe.string(), (dir / "script.txt").string()),
                           dir / ("run-" + cc + ".log"));
    if (exit_ok) REQUIRE(run.status == 0);
    if (!exit_ok) REQUIRE(run.status != 0);
    if (!have_first) {
      first = run.output;
      have_first = true;
    } else if (exit_ok) {  // a failed assert's message differs between the C libraries' compilers
      CHECK(run.output == first);
    }
  }
  return first;
}

}  // namespace cbt
