#include "fuzz_support.h"

#include "analysis/analysis.h"
#include "diagnostic_printer.h"
#include "format/format_source.h"
#include "lexer.h"
#include "interpreter/machine.h"
#include "pipeline/compilation.h"
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

#include <cstdint>
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

/// The ids the back ends and the interpreter follow without checking.
class ModelCheck {
public:
  explicit ModelCheck(const model::Model &m) : m_(m) {}

  void expr(const model::Expr &e, const model::Chart *chart) {
    using K = model::Expr::Kind;
    auto n = e.args.size();
    switch (e.kind) {
    case K::Var: expect(chart && chart->vars.contains(e.var()), "a var index in range"); break;
    case K::Const: expect(m_.consts.contains(e.constant()), "a const index in range"); break;
    case K::Call:
      expect(m_.functions.contains(e.function()), "a function index in range");
      if (m_.functions.contains(e.function()))
        expect(n == m_.functions[e.function()].params.size(), "as many arguments as parameters");
      break;
    case K::Elapsed: expect(chart && chart->places.contains(e.place()), "an elapsed() place in range"); break;
    case K::Succeeded:
    case K::Failed: {
      bool ok = chart && chart->places.contains(e.place());
      expect(ok, "a succeeded()/failed() place in range");
      if (!ok) break;
      model::ChartId runs = chart->places[e.place()].runs;
      expect(m_.charts.contains(runs) && m_.charts[runs].kind == model::Chart::Kind::Fsm,
             "succeeded()/failed() read a place that runs an fsm");
      break;
    }
    case K::Active: {
      // Each step names a place of the chart the previous one runs.
      expect(!e.path.empty(), "active() has a path");
      const model::Chart *at = chart;
      for (std::size_t k = 0; k < e.path.size() && at; ++k) {
        bool ok = at->places.contains(e.path[k]);
        expect(ok, "an active() path step in range");
        if (!ok) break;
        model::ChartId runs = at->places[e.path[k]].runs;
        if (k + 1 < e.path.size())
          expect(m_.charts.contains(runs), "an active() path goes through a place that runs a chart");
        at = m_.charts.contains(runs) ? &m_.charts[runs] : nullptr;
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
        expect(chart.vars.contains(s.var), "an assigned var in range");
        expr(s.expr, &chart);
      }
    }
  }

  void chart(const model::Chart &c) {
    bool fsm = c.kind == model::Chart::Kind::Fsm;
    int initial = 0;
    for (const auto &p : c.places) {
      initial += p.initial;
      expect(!p.runs || m_.charts.contains(p.runs), "a place runs a chart in range, or none");
      expect(!p.runs || p.terminal == model::Terminal::None, "a terminal state runs nothing");
      block(p.action, c);
      if (p.entry) block(*p.entry, c);
      if (p.exit) block(*p.exit, c);
      if (p.post) expr(*p.post, &c);
    }
    expect(fsm ? initial == 1 : initial >= 1, "the initial places the language requires");
    for (const auto &t : c.transitions) {
      for (model::PlaceId p : t.inputs) expect(c.places.contains(p), "a transition input in range");
      for (model::PlaceId p : t.outputs) expect(c.places.contains(p), "a transition output in range");
      if (fsm) expect(t.inputs.size() == 1 && t.outputs.size() == 1, "an fsm transition has one source and one target");
      if (t.condition) expr(*t.condition, &c);
    }
    for (const auto &v : c.vars)
      if (v.init) expr(*v.init, &c);
    for (model::FunctionId f : c.functions) expect(m_.functions.contains(f), "a chart's function in range");
  }

  void plan(const model::Plan &p) {
    expect(p.actors.contains(p.start), "a plan's start in range");
    auto rules = [&](const std::vector<model::Rule> &rs) {
      for (const auto &r : rs)
        if (r.target.kind == model::RuleTarget::Kind::Actor)
          expect(p.actors.contains(r.target.actor), "a rule target in range");
    };
    for (const auto &a : p.actors) {
      expect(a.templ ? m_.templates.contains(a.templ) : m_.plans.contains(a.subplan), "an actor's template in range");
      rules(a.rules);
      for (const auto &s : a.supervisors) rules(s.rules);
    }
    for (const auto &s : p.globals) rules(s.rules);
  }

private:
  const model::Model &m_;
};

/// Inputs that vary with the tick and the function, so runs take different paths.
class WobblyEnv : public interp::Environment {
public:
  explicit WobblyEnv(const model::Model &m) : m_(m) {}
  interp::Value call(model::FunctionId function, const std::vector<interp::Value> &, std::uint64_t tick) override {
    std::uint64_t h = (tick * 2654435761u) ^ (function.index() * 40503);
    switch (m_.functions.at(function).result) {
    case model::Type::Bool: return interp::Value::of_bool((h >> 3) & 1);
    case model::Type::Float: return interp::Value::of_float(static_cast<float>(h % 7) - 3);
    case model::Type::Double: return interp::Value::of_double(static_cast<double>(h % 5) / 4);
    default: return interp::Value::of_int(static_cast<std::int32_t>(h % 11) - 5);
    }
  }

private:
  const model::Model &m_;
};

void run_interpreter(const model::Model &m, model::ChartId chart) {
  WobblyEnv env(m);
  interp::MachineOptions options;
  options.check_post = true;
  try {
    interp::Machine engine(m, chart, options);
    interp::EventLog log;
    for (int t = 0; t < 12; ++t) engine.run(env, &log);
    log.render({true, true, true});
  } catch (const interp::RuntimeError &e) {
    expect(e.range.file < m.sources().size(), "a run-time error has a location");
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
  for (model::ChartId c : m.charts.ids()) {
    if (!m.charts[c].in_main_file) continue;
    EmitOptions o;
    o.chart = c;
    for (const auto &b : charts) emit_twice(*b, m, o);
  }
#ifdef GFEC_FUZZ_CPP_BACKEND
  for (model::ToolboxId t : m.toolboxes.ids()) {
    if (m.toolboxes[t].range.file != m.main_file) continue;
    EmitOptions o;
    o.toolbox = t;
    emit_twice(*make_toolbox_skeleton_backend(), m, o);
  }
#endif
  for (model::PlanId p : m.plans.ids()) {
    if (!m.plans[p].in_main_file) continue;
    EmitOptions o;
    o.plan = p;
    for (const auto &b : plans) emit_twice(*b, m, o);
  }
}

/// The tokens (kind and spelling) and the comments of a text, one string.
std::string lexed(const std::string &text) {
  SourceManager sources;
  Diagnostics diag(WarningOptions{}, 1000);
  FileId id = sources.add("t.sfc", text);
  std::vector<SourceRange> comments;
  Lexer lexer(sources, id, diag);
  lexer.record_comments(&comments);
  std::string out;
  for (Token t = lexer.next(); t.kind != Tok::End; t = lexer.next())
    out.append(std::to_string(static_cast<int>(t.kind))).append(" ").append(t.text).append("\n");
  for (const SourceRange &r : comments) {
    std::string c = text.substr(r.begin, r.end - r.begin);
    if (c.rfind("//", 0) == 0) c.erase(c.find_last_not_of(" \t\f\v") + 1);  // gfec fmt drops trailing blanks
    out.append(c).append("\n");
  }
  return out;
}

/// gfec fmt's promises (docs/formatting.md): it refuses only text with errors, keeps every token
/// and comment, and formatting its result changes nothing.
void check_format(const std::string &text) {
  SourceManager sources;
  Diagnostics diag(WarningOptions{}, 1000);
  auto once = format_source(sources, sources.add("fuzz.sfc", text), diag);
  if (!once) {
    expect(diag.has_errors(), "the formatter refuses only text with errors");
    return;
  }
  expect(lexed(text) == lexed(*once), "formatting keeps every token and comment");
  SourceManager again;
  Diagnostics again_diag(WarningOptions{}, 1000);
  auto twice = format_source(again, again.add("fuzz.sfc", *once), again_diag);
  expect(twice && *twice == *once, "formatting formatted text changes nothing");
}

}  // namespace

std::string mutate(const std::string &text, unsigned seed) {
  std::uint64_t x = seed * 0x9E3779B97F4A7C15ull + 1;
  auto next = [&x](std::size_t n) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    return n == 0 ? std::size_t(0) : static_cast<std::size_t>(x % n);
  };
  std::string t = text;
  const std::size_t edits = 1 + next(4);
  for (std::size_t e = 0; e < edits; ++e) {
    const std::size_t at = next(t.size() + 1), len = 1 + next(16);
    switch (next(4)) {
    case 0: t.resize(at); break;
    case 1: t.erase(at, len); break;
    case 2: t.insert(at, t.substr(next(t.size() + 1), len)); break;
    default:
      for (std::size_t k = at; k < t.size() && k < at + len; ++k) t[k] = static_cast<char>(next(256));
      break;
    }
  }
  return t;
}

std::string check_one(const std::string &input, const std::string &name) {
  MemoryFileSystem fs;
  // The reader is chosen by the saved input's extension: IEC structured text, PLCopen XML, or
  // chart text (which may hold a second file after a line %%%).
  auto ends_with = [&](const char *ext) {
    const std::size_t n = std::char_traits<char>::length(ext);
    return name.size() >= n && name.compare(name.size() - n, n, ext) == 0;
  };
  const bool chart_text = !ends_with(".st") && !ends_with(".xml");
  const std::string separator = "\n%%%\n";
  auto split = chart_text ? input.find(separator) : std::string::npos;
  const std::string main = chart_text ? "fuzz.sfc" : ends_with(".st") ? "fuzz.st" : "fuzz.xml";
  fs.add(main, input.substr(0, split));
  if (split != std::string::npos) fs.add("b.sfc", input.substr(split + separator.size()));

  // The pipeline gfec runs (compiler/pipeline/compilation.h), every warning on; the analyses
  // run below with small limits instead, so that one input stays fast.
  pipeline::FrontEndOptions options;
  for (int i = 0; i < static_cast<int>(Warning::Count_); ++i) options.warnings.set(static_cast<Warning>(i), true);
  options.error_limit = 1000;
  options.analyze = false;
  pipeline::Compilation compilation(options);
  const bool validated = compilation.front_end(main, fs);
  const SourceManager &sources = compilation.sources;
  const Diagnostics &diag = compilation.diag;
  const model::Model &m = compilation.model;
  const WarningOptions &all = options.warnings;
  std::string printed;
  for (const Diagnostic &d : diag.all()) {
    check_range(sources, d.range, "a diagnostic's range lies in its file");
    for (const auto &n : d.notes)
      if (n.has_range) check_range(sources, n.range, "a note's range lies in its file");
    expect(!d.message.empty() && !d.check().empty(), "a diagnostic has a message and a check name");
    printed += render_text(d, sources);
  }
  if (chart_text) check_format(input.substr(0, split));
  if (!validated) return printed;

  ModelCheck check(m);
  for (const auto &c : m.charts) check.chart(c);
  for (const auto &p : m.plans) check.plan(p);
  for (model::ChartId c : m.charts.ids()) run_interpreter(m, c);
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
