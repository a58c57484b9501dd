#include "fuzz_support.h"

#include "analysis/activation_bounds.h"
#include "analysis/analysis.h"
#include "diagnostic_printer.h"
#include "interpreter/engine.h"
#include "loader.h"
#include "validate.h"
#ifdef GFEC_FUZZ_C_BACKEND
#include "c_backend.h"
#endif
#ifdef GFEC_FUZZ_JSON_BACKEND
#include "json_backend.h"
#endif
#ifdef GFEC_FUZZ_DOT_BACKEND
#include "dot_backend.h"
#endif
#ifdef GFEC_FUZZ_CPP_BACKEND
#include "cpp_backend.h"
#endif

#include <cstdio>
#include <functional>
#include <memory>

namespace gfec::fuzz {

namespace {

void expect(bool ok, const char *promise) {
  if (ok) return;
  std::fprintf(stderr, "fuzz: broken promise: %s\n", promise);
  __builtin_trap();
}

void check_range(const SourceManager &sources, const SourceRange &r, const char *what) {
  expect(r.file < sources.size(), what);
  if (r.file >= sources.size()) return;
  expect(r.begin <= r.end && r.end <= sources.file(r.file).text().size(), what);
}

/// Indices the back ends and the interpreter follow without checking.
class ModelCheck {
public:
  explicit ModelCheck(const model::Model &m) : m_(m) {}

  void expr(const model::Expr &e, const model::Chart *chart) {
    using K = model::Expr::Kind;
    auto n = e.args.size();
    switch (e.kind) {
    case K::Var: expect(chart && in(e.index, chart->vars.size()), "a var index in range"); break;
    case K::Const: expect(in(e.index, m_.consts.size()), "a const index in range"); break;
    case K::Call:
      expect(in(e.index, m_.functions.size()), "a function index in range");
      if (in(e.index, m_.functions.size()))
        expect(n == m_.functions[static_cast<std::size_t>(e.index)].params.size(), "as many arguments as parameters");
      break;
    case K::Elapsed: expect(chart && in(e.index, chart->places.size()), "an elapsed() place in range"); break;
    case K::Succeeded:
    case K::Failed: {
      bool ok = chart && in(e.index, chart->places.size());
      expect(ok, "a succeeded()/failed() place in range");
      if (!ok) break;
      int runs = chart->places[static_cast<std::size_t>(e.index)].runs;
      expect(in(runs, m_.charts.size()) && m_.charts[static_cast<std::size_t>(runs)].kind == model::Chart::Kind::Fsm,
             "succeeded()/failed() read a place that runs an fsm");
      break;
    }
    case K::Active: {
      // Each step names a place of the chart the previous one runs.
      expect(!e.path.empty(), "active() has a path");
      const model::Chart *at = chart;
      for (std::size_t k = 0; k < e.path.size() && at; ++k) {
        bool ok = in(e.path[k], at->places.size());
        expect(ok, "an active() path step in range");
        if (!ok) break;
        int runs = at->places[static_cast<std::size_t>(e.path[k])].runs;
        if (k + 1 < e.path.size())
          expect(in(runs, m_.charts.size()), "an active() path goes through a place that runs a chart");
        at = in(runs, m_.charts.size()) ? &m_.charts[static_cast<std::size_t>(runs)] : nullptr;
      }
      break;
    }
    case K::Unary:
    case K::Paren: expect(n == 1, "one operand"); break;
    case K::Binary: expect(n == 2, "two operands"); break;
    default: break;
    }
    for (const auto &a : e.args) expr(a, chart);
  }

  void block(const std::vector<model::Stmt> &b, const model::Chart &chart) {
    for (const auto &s : b) {
      if (s.kind == model::Stmt::Kind::Call) {
        expect(s.expr.kind == model::Expr::Kind::Call, "a call statement holds a call");
        expr(s.expr, &chart);
      } else if (s.kind == model::Stmt::Kind::Assign) {
        expect(in(s.var, chart.vars.size()), "an assigned var in range");
        expr(s.expr, &chart);
      }
    }
  }

  void chart(const model::Chart &c) {
    bool fsm = c.kind == model::Chart::Kind::Fsm;
    int initial = 0;
    for (const auto &p : c.places) {
      initial += p.initial;
      expect(p.runs == -1 || in(p.runs, m_.charts.size()), "a place runs a chart in range, or none");
      expect(p.runs == -1 || p.terminal == model::Terminal::None, "a terminal state runs nothing");
      block(p.action, c);
      if (p.entry) block(*p.entry, c);
      if (p.exit) block(*p.exit, c);
      if (p.post) expr(*p.post, &c);
    }
    expect(fsm ? initial == 1 : initial >= 1, "the initial places the language requires");
    for (const auto &t : c.transitions) {
      for (int p : t.inputs) expect(in(p, c.places.size()), "a transition input in range");
      for (int p : t.outputs) expect(in(p, c.places.size()), "a transition output in range");
      if (fsm) expect(t.inputs.size() == 1 && t.outputs.size() == 1, "an fsm transition has one source and one target");
      if (t.condition) expr(*t.condition, &c);
    }
    for (const auto &v : c.vars)
      if (v.init) expr(*v.init, &c);
    for (int f : c.functions) expect(in(f, m_.functions.size()), "a chart's function in range");
  }

  void plan(const model::Plan &p) {
    expect(in(p.start, p.actors.size()), "a plan's start in range");
    auto rules = [&](const std::vector<model::Rule> &rs) {
      for (const auto &r : rs)
        if (r.target.kind == model::Target::Kind::Actor)
          expect(in(r.target.actor, p.actors.size()), "a rule target in range");
    };
    for (const auto &a : p.actors) {
      expect(a.templ >= 0 ? in(a.templ, m_.templates.size()) : in(a.subplan, m_.plans.size()),
             "an actor's template in range");
      rules(a.rules);
      for (const auto &s : a.supervisors) rules(s.rules);
    }
    for (const auto &s : p.globals) rules(s.rules);
  }

private:
  static bool in(int i, std::size_t n) { return i >= 0 && static_cast<std::size_t>(i) < n; }
  const model::Model &m_;
};

/// Inputs that vary with the tick and the function, so runs take different paths.
class WobblyEnv : public interp::Environment {
public:
  explicit WobblyEnv(const model::Model &m) : m_(m) {}
  interp::Value call(int function, const std::vector<interp::Value> &, std::uint64_t tick) override {
    std::uint64_t h = (tick * 2654435761u) ^ static_cast<std::uint64_t>(function * 40503);
    switch (m_.functions.at(static_cast<std::size_t>(function)).result) {
    case model::Type::Bool: return interp::Value::of_bool((h >> 3) & 1);
    case model::Type::Float: return interp::Value::of_float(static_cast<float>(h % 7) - 3);
    case model::Type::Double: return interp::Value::of_double(static_cast<double>(h % 5) / 4);
    default: return interp::Value::of_int(static_cast<std::int32_t>(h % 11) - 5);
    }
  }

private:
  const model::Model &m_;
};

void run_interpreter(const model::Model &m, int chart) {
  WobblyEnv env(m);
  interp::EngineOptions options;
  options.check_post = true;
  try {
    interp::Engine engine(m, chart, options);
    interp::EventLog log;
    for (int t = 0; t < 12; ++t) engine.run(env, &log);
    log.render({true, true, true});
  } catch (const interp::RuntimeError &e) {
    expect(e.range.file < m.sources->size(), "a run-time error has a location");
  }
}

/// A back end never rejects a validated model, and gives the same output every time.
void emit_twice(const Backend &backend, const model::Model &m, EmitOptions o) {
  o.output_path = "out/engine.c";
  o.source_name = "fuzz.sfc";
  auto first = emit_to_memory(backend, m, o);
  auto second = emit_to_memory(backend, m, o);
  expect(first.size() == second.size(), "a back end writes the same files every time");
  for (std::size_t i = 0; i < first.size() && i < second.size(); ++i)
    expect(first[i].contents == second[i].contents, "a back end is deterministic");
}

void run_back_ends(const model::Model &m) {
  std::vector<std::unique_ptr<Backend>> charts, plans;
#ifdef GFEC_FUZZ_C_BACKEND
  charts.push_back(make_c_backend());
#endif
#ifdef GFEC_FUZZ_JSON_BACKEND
  charts.push_back(make_json_backend());
  plans.push_back(make_json_backend());
#endif
#ifdef GFEC_FUZZ_DOT_BACKEND
  charts.push_back(make_dot_backend());
  plans.push_back(make_dot_backend());
#endif
#ifdef GFEC_FUZZ_CPP_BACKEND
  plans.push_back(make_cpp_backend());
#endif
  for (std::size_t c = 0; c < m.charts.size(); ++c) {
    if (!m.charts[c].in_main_file) continue;
    EmitOptions o;
    o.chart = static_cast<int>(c);
    for (const auto &b : charts) emit_twice(*b, m, o);
  }
#ifdef GFEC_FUZZ_CPP_BACKEND
  for (std::size_t t = 0; t < m.toolboxes.size(); ++t) {
    if (m.toolboxes[t].range.file != m.main_file) continue;
    EmitOptions o;
    o.toolbox = static_cast<int>(t);
    emit_twice(*make_toolbox_skeleton_backend(), m, o);
  }
#endif
  for (std::size_t p = 0; p < m.plans.size(); ++p) {
    if (!m.plans[p].in_main_file) continue;
    EmitOptions o;
    o.plan = static_cast<int>(p);
    for (const auto &b : plans) emit_twice(*b, m, o);
  }
}

}  // namespace

std::string check_one(const std::string &input) {
  MemoryFileSystem fs;
  const std::string separator = "\n%%%\n";
  auto split = input.find(separator);
  fs.add("fuzz.sfc", input.substr(0, split));
  if (split != std::string::npos) fs.add("b.sfc", input.substr(split + separator.size()));

  SourceManager sources;
  WarningOptions all;
  for (int i = 0; i < static_cast<int>(Warning::Count_); ++i) all.set(static_cast<Warning>(i), true);
  Diagnostics diag(all, 1000);
  LoadResult loaded = load_program("fuzz.sfc", {}, fs, sources, diag);
  model::Model m;
  std::string printed;
  bool validated = false;
  if (!diag.has_errors()) {
    m = validate(loaded.program, sources, diag);
    validated = !diag.has_errors();
    // The facts the pipeline records for the back ends (compiler/pipeline/compilation.cc).
    if (validated) analysis::record_activation_bounds(m);
  }
  for (const Diagnostic &d : diag.all()) {
    check_range(sources, d.range, "a diagnostic's range lies in its file");
    for (const auto &n : d.notes)
      if (n.has_range) check_range(sources, n.range, "a note's range lies in its file");
    expect(!d.message.empty() && !d.check().empty(), "a diagnostic has a message and a check name");
    printed += render_text(d, sources);
  }
  if (!validated) return printed;

  ModelCheck check(m);
  for (const auto &c : m.charts) check.chart(c);
  for (const auto &p : m.plans) check.plan(p);
  for (std::size_t c = 0; c < m.charts.size(); ++c) run_interpreter(m, static_cast<int>(c));
  // Every analysis, with small limits so that one input stays fast; its warnings are located.
  analysis::Limits limits;
  limits.max_states = 2000;
  limits.max_outcomes = 20000;
  Diagnostics analysis_diag(all, 1000);
  analysis::analysis_report(m, analysis_diag, limits);
  for (const Diagnostic &d : analysis_diag.all()) {
    check_range(sources, d.range, "an analysis warning lies in its file");
    for (const auto &n : d.notes)
      if (n.has_range) check_range(sources, n.range, "an analysis note lies in its file");
    render_text(d, sources);
  }
  run_back_ends(m);
  return printed;
}

}  // namespace gfec::fuzz
