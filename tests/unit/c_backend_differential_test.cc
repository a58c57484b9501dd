// The C engine against the reference interpreter (compiler/interpreter): engines and the
// interpreter must agree tick for tick (docs/language.md). Each chart runs on random scripts (fixed
// seeds) once as a compiled engine with the run harness (-DX_HOOKS) and once in the interpreter,
// whose calls, hooks and activation are printed in the harness's log format; the logs must match.
#include "../run/c_backend_support.h"
#include "random_sfc.h"

#include "c_layout.h"
#include "interpreter/machine.h"
#include "interpreter/event_log.h"
#include "roots.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <algorithm>
#include <random>

using namespace cbt;

namespace {

/// One tick's inputs: function name -> value (absent: 0).
using Tick = std::map<std::string, double>;

std::string script_text(const std::vector<Tick> &ticks) {
  std::string s;
  for (const auto &tick : ticks) {
    std::string line;
    for (const auto &[name, value] : tick) line += fmt::format("{}{}={}", line.empty() ? "" : " ", name, value);
    s += line + "\n";
  }
  return s;
}

/// Random inputs for every sensing function of the chart: bools true with a probability that
/// differs per function, numbers from a few exactly representable values.
std::vector<Tick> random_script(const model::Model &m, const model::Chart &chart, unsigned seed, int length) {
  std::mt19937 rng(seed);
  std::vector<Tick> ticks(static_cast<std::size_t>(length));
  // The chart's own functions first, then those only its sub-charts call (docs/language.md
  // "Sub-charts"), each once.
  std::vector<model::FunctionId> functions = chart.functions;
  const auto tree = charts_in_tree(m, m.charts.id_of(chart));
  for (model::ChartId c : m.charts.ids())
    if (tree[c])
      for (model::FunctionId f : m.charts[c].functions)
        if (std::find(functions.begin(), functions.end(), f) == functions.end()) functions.push_back(f);
  for (model::FunctionId f : functions) {
    const auto &fn = m.functions[f];
    if (fn.result == Type::Void) continue;
    unsigned percent = 10 + rng() % 80;
    for (auto &tick : ticks) {
      if (fn.result == Type::Bool) {
        if (rng() % 100 < percent) tick[fn.name] = 1;
      } else {
        tick[fn.name] =
            fn.result == Type::Int ? static_cast<double>(rng() % 5) : static_cast<double>(rng() % 8) * 0.25 - 0.5;
      }
    }
  }
  return ticks;
}

std::string printf_g(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

/// What the harness prints for a value of type `t`: %d for bool and int, %g for floats.
std::string harness_value(const interp::Value &v) {
  switch (v.type) {
  case Type::Bool: return v.b ? "1" : "0";
  case Type::Float:
  case Type::Double: return printf_g(v.f);
  default: return std::to_string(v.i);
  }
}

/// The interpreter's side: answers calls from the script and writes them as the harness does.
class ScriptEnvironment : public interp::Environment {
public:
  ScriptEnvironment(const model::Model &m, const std::vector<Tick> &ticks) : model_(m), ticks_(ticks) {}

  interp::Value call(model::FunctionId function, const std::vector<interp::Value> &args, std::uint64_t tick) override {
    const auto &fn = model_.functions.at(function);
    std::string list;
    for (const auto &a : args) list += (list.empty() ? "" : ", ") + harness_value(a);
    if (fn.result == Type::Void) {
      lines.push_back("act " + fn.name + (args.empty() ? "" : "(" + list + ")"));
      return interp::Value::zero(Type::Int);
    }
    std::string call = args.empty() ? "" : "call " + fn.name + "(" + list + ")\n";
    const Tick &row = ticks_.at(static_cast<std::size_t>(tick - 1));
    auto it = row.find(fn.name);
    double raw = it == row.end() ? 0 : it->second;
    interp::Value v = fn.result == Type::Bool    ? interp::Value::of_bool(raw != 0)
                      : fn.result == Type::Int   ? interp::Value::of_int(static_cast<std::int32_t>(raw))
                      : fn.result == Type::Float ? interp::Value::of_float(static_cast<float>(raw))
                                                 : interp::Value::of_double(raw);
    lines.push_back(call + "cond " + fn.name + " -> " + harness_value(v));
    return v;
  }

  std::vector<std::string> lines;  ///< each call's lines, in call order, as the harness prints them

private:
  const model::Model &model_;
  const std::vector<Tick> &ticks_;
};

/// The interpreter's run in the harness's format: its event log gives the order of calls, hooks
/// and the end of each tick; the calls' text comes from the environment.
std::string interpreter_log(const model::Model &m, model::ChartId root, const std::vector<Tick> &ticks) {
  const auto &chart = m.charts.at(root);
  interp::Machine engine(m, root);
  ScriptEnvironment env(m, ticks);
  interp::EventLog log;
  for (std::size_t i = 0; i < ticks.size(); ++i) engine.run(env, &log);
  std::string out;
  std::size_t next_call = 0;
  auto name = [&](const std::string &text) { return text.substr(text.find(' ') + 1); };
  for (const auto &e : log.events()) {
    switch (e.kind) {
    case interp::EventKind::Tick: out += e.text + "\n"; break;
    case interp::EventKind::Call: out += env.lines.at(next_call++) + "\n"; break;
    case interp::EventKind::Lost: out += "hook lost " + name(e.text) + "\n"; break;
    case interp::EventKind::Gained: out += "hook gained " + name(e.text) + "\n"; break;
    case interp::EventKind::Enabled: out += "hook enabled " + name(e.text) + "\n"; break;
    case interp::EventKind::Av:
      if (chart.kind == model::Chart::Kind::Sfc) {
        std::istringstream counts(e.text.substr(2));
        std::string line = "av";
        unsigned n = 0;
        for (std::size_t p = 0; counts >> n; ++p)
          if (n == 1) line += " " + chart.places[p].name;
          else if (n > 1) line += fmt::format(" {}:{}", chart.places[p].name, n);
        out += line + "\n";
      }
      break;
    case interp::EventKind::State: {  // "state Z1 running"
      std::istringstream words(e.text);
      std::string word, state, status;
      words >> word >> state >> status;
      out += fmt::format("state {} status {}\n", state, status == "running" ? 0 : status == "succeeded" ? 1 : -1);
      break;
    }
    default: break;
    }
  }
  return out;
}

/// The charts: every golden case and the extra charts under tests/run (*.sfc, *.fsm).
std::vector<std::pair<std::string, std::map<std::string, std::string>>> charts() {
  std::vector<std::pair<std::string, std::map<std::string, std::string>>> all;
  for (const char *folder : {"tests/golden/c", "tests/run"}) {
    std::map<std::string, std::string> files;
    fs::path dir = fs::path(GFEC_SOURCE_DIR) / folder;
    for (const auto &entry : fs::directory_iterator(dir)) {
      auto ext = entry.path().extension();
      if (ext == ".sfc" || ext == ".fsm" || ext == ".iface")
        files[entry.path().filename().string()] = read_file(entry.path());
    }
    for (const auto &[name, text] : files) {
      auto ext = fs::path(name).extension();
      if (ext == ".sfc" || ext == ".fsm") all.emplace_back(name, files);
    }
  }
  return all;
}

/// A sequential chart of `places` places, large enough for the split form (c_layout.h): each place
/// goes on to the next, some jump far (to other parts), some have timers, entry, exit and action
/// blocks, so every switch of the form has cases in many parts.
std::string large_sequential_sfc(int places) {
  std::string s = "interface RandomBot {\n  bool B0();\n  bool B1();\n  bool B2();\n  int Level();\n"
                  "  void Act(int n);\n  void Beep();\n}\n\nsfc Large {\n  period 10ms;\n  var int n = 0;\n";
  for (int p = 0; p < places; ++p) {
    std::string body;
    if (p % 5 == 1) body += " entry { Beep(); }";
    if (p % 7 == 2) body += " exit { n += 1; }";
    if (p % 2 == 0) body += fmt::format(" Act({});", p);
    if (p % 11 == 3) body += " Act(n);";
    s += fmt::format("  {}place P{} {{{} }}\n", p == 0 ? "initial " : "", p, body);
  }
  for (int p = 0; p < places; ++p) {
    if (p % 3 == 0) s += fmt::format("  transition P{} -> P{} when B1() && !B2();\n", p, (p * 397 + 131) % places);
    if (p % 13 == 4) s += fmt::format("  transition P{} -> P{} when elapsed(P{}) >= 20ms;\n", p, (p + 1) % places, p);
    else s += fmt::format("  transition P{} -> P{} when B0();\n", p, (p + 1) % places);
  }
  return s + "}\n";
}

/// An fsm of `states` states, large enough for its switches to be split (c_layout.h): each state
/// goes on to the next, some jump far (to other parts), some tries several transitions or one
/// without a condition, some have timers, entry, exit and action blocks; success and failure
/// states (one with a postcondition) are spread over the parts, and many states can reach one.
std::string large_fsm(int states) {
  // S8 and S40 (which S3 jumps to) each try one transition, into a terminal state: the split
  // form moves those in the case, status included.
  auto terminal = [](int s) { return s == 9 || s % 97 == 50 ? "success " : s == 41 || s % 89 == 60 ? "failure " : ""; };
  std::string s = "interface RandomBot {\n  bool B0();\n  bool B1();\n  bool B2();\n  int Level();\n"
                  "  void Act(int n);\n  void Beep();\n}\n\nfsm Huge {\n  period 10ms;\n  var int n = 0;\n";
  for (int p = 0; p < states; ++p) {
    if (*terminal(p)) {
      s += fmt::format("  {}state S{}{};\n", terminal(p), p, p == 50 ? " post Level() >= 0" : "");
      continue;
    }
    std::string body;
    if (p % 5 == 1) body += " entry { Beep(); }";
    if (p % 7 == 2) body += " exit { n += 1; }";
    if (p % 2 == 0) body += fmt::format(" Act({});", p);
    if (p % 13 == 4) body += fmt::format(" if (elapsed(S{}) >= 20ms) {{ Act(n); }}", p);
    s += fmt::format("  {}state S{} {{{} }}\n", p == 0 ? "initial " : "", p, body);
  }
  for (int p = 0; p < states; ++p) {
    if (*terminal(p)) continue;
    const int next = (p + 1) % states, jump = p == 3 ? 40 : (p * 397 + 131) % states, end = 50 + 97 * (p % 11);
    if (p % 3 == 0 && jump != next) s += fmt::format("  S{} -> S{} when B1() && !B2();\n", p, jump);
    if (p % 10 == 9 && end != next && end != jump)
      s += fmt::format("  S{} -> S{} when B2() && Level() == 4;\n", p, end);
    if (p % 13 == 4) s += fmt::format("  S{} -> S{} when elapsed(S{}) >= 20ms;\n", p, next, p);
    else if (p % 17 == 5) s += fmt::format("  S{} -> S{};\n", p, next);
    else s += fmt::format("  S{} -> S{} when B0();\n", p, next);
  }
  return s + "}\n";
}

/// One chart in every engine form against the interpreter, on `scripts` random scripts.
void check_forms(const std::string &name, const std::map<std::string, std::string> &files, int scripts,
                 const std::vector<EngineForm> &forms = {EngineForm::Readable, EngineForm::Scalable}) {
  for (auto form : forms) {
    const char *form_name = form == EngineForm::Readable ? "readable" : "scalable";
    auto compiled = compile_chart(files, name, "engine.c", true, form);
    INFO(form_name << " engine of " << name << "\n" << compiled->errors);
    REQUIRE(!compiled->diag.has_errors());
    const auto &chart = compiled->the_chart();
    for (unsigned seed = 1; seed <= static_cast<unsigned>(scripts); ++seed) {
      auto ticks = random_script(compiled->model, chart, seed * 7919u + static_cast<unsigned>(name.size()), 60);
      std::string expected = interpreter_log(compiled->model, compiled->chart, ticks);
      std::string actual =
          compile_and_run(fmt::format("differential_{}_{}_{}", fs::path(name).stem().string(), form_name, seed),
                          compiled->files, compiled->model, chart, script_text(ticks), "-D" + chart.name + "_HOOKS");
      INFO("seed " << seed << ", script:\n" << script_text(ticks));
      CHECK(actual == expected);
    }
  }
}

}  // namespace

TEST_CASE("c engine agrees with the reference interpreter tick for tick", "[c_backend][run][differential]") {
  auto all = charts();
  REQUIRE(all.size() >= 6);
  for (const auto &[name, files] : all) {
    DYNAMIC_SECTION(name) { check_forms(name, files, 3); }
  }
}

TEST_CASE("c engine: both forms agree with the interpreter on random charts", "[c_backend][run][differential]") {
  // Fixed seeds; each chart in the readable and the scalable form, against the interpreter.
  for (unsigned seed = 1; seed <= 24; ++seed) {
    std::string text = random_sfc(seed);
    DYNAMIC_SECTION("random chart " << seed) {
      INFO(text);
      check_forms(fmt::format("random{}.sfc", seed), {{fmt::format("random{}.sfc", seed), text}}, 1);
    }
  }
}

TEST_CASE("c engine: the split sequential form of a large chart agrees with the interpreter",
          "[c_backend][run][differential]") {
  // Above kSplitAbovePlaces places each switch of the sequential form is written in parts
  // called through tables (docs/c-engine.md, "Large charts"); hooks on (the harness's -DX_HOOKS).
  const int places = static_cast<int>(gfec::c_backend::kSplitAbovePlaces) + 100;
  std::string text = large_sequential_sfc(places);
  auto compiled = compile_chart({{"large.sfc", text}}, "large.sfc", "engine.c", true, EngineForm::Scalable);
  REQUIRE(!compiled->diag.has_errors());
  REQUIRE(!compiled->files.empty());
  CHECK(compiled->files.front().contents.find("Large_update_parts[m->current / ") != std::string::npos);
  // A place with one transition to try only says that it fired; X_run moves it by the table.
  CHECK(compiled->files.front().contents.find("m->current = Large_moves[m->current];") != std::string::npos);
  check_forms("large.sfc", {{"large.sfc", text}}, 3, {EngineForm::Scalable});
}

TEST_CASE("c engine: an fsm's switches, whole and in parts, agree with the interpreter",
          "[c_backend][run][differential]") {
  // The scalable form of an fsm is a switch on the state; above kSplitAbovePlaces states each
  // switch is written in parts called through tables (docs/c-engine.md, "Large fsms"); hooks on.
  const int states = static_cast<int>(gfec::c_backend::kSplitAbovePlaces) + 100;
  std::string text = large_fsm(states);
  auto compiled = compile_chart({{"huge.fsm", text}}, "huge.fsm", "engine.c", true, EngineForm::Auto);
  INFO(compiled->errors);
  REQUIRE(!compiled->diag.has_errors());
  REQUIRE(!compiled->files.empty());
  const std::string &engine = compiled->files.front().contents;
  CHECK(engine.find("Huge_update_parts[(uint16_t)m->state / 256u](m, (uint16_t)m->state)") != std::string::npos);
  // A state whose one transition leads to a plain state only says that it fired; one that enters
  // a terminal state also sets the status, in its own case.
  CHECK(engine.find("m->state = Huge_moves[m->state];") != std::string::npos);
  CHECK(engine.find("m->status = 1;") != std::string::npos);
  CHECK(engine.find("m->status = -1;") != std::string::npos);
  CHECK(engine.find("else if (") == std::string::npos);  // no chain of tests on the state
  check_forms("huge.fsm", {{"huge.fsm", text}}, 4, {EngineForm::Scalable});
  // At the size the split begins: one switch per part of the tick, no parts.
  std::string whole = large_fsm(static_cast<int>(gfec::c_backend::kSplitAbovePlaces));
  auto one = compile_chart({{"whole.fsm", whole}}, "whole.fsm", "engine.c", true, EngineForm::Auto);
  REQUIRE(!one->diag.has_errors());
  CHECK(one->files.front().contents.find("_parts[") == std::string::npos);
  CHECK(one->files.front().contents.find("switch ((int)m->state) {") != std::string::npos);
  check_forms("whole.fsm", {{"whole.fsm", whole}}, 2, {EngineForm::Scalable});
}

TEST_CASE("c engine: every integer type, time and the conversions agree with the interpreter",
          "[c_backend][run][differential]") {
  // Values stay in range for any script (the interpreter would stop at an overflow, the engine
  // not): the point is that both compute, store and print each type alike, in both forms, with
  // gcc and clang -Werror.
  const std::string text = R"(interface TypesBot {
  bool B0();
  int Level();
  void Act(int n);
}
sfc Types {
  period 10ms;
  var int8 a = -5;
  var int16 b = 300;
  var int64 c = 3000000000;
  var uint8 d = 200;
  var uint16 e = 60000;
  var uint32 f = 4000000000;
  var uint64 g = 900000000000000000;
  var time t = 1s;
  var double x = 0.5;
  var float y = 2.5;
  const int16 HALF = 2;
  initial place A {
    a = int8(Level() % 100);
    b = b / HALF + a;
    c = c + b * 3;
    d = uint8(d / 3 + 10);
    e = e - uint16(d);
    f = f / 2 + e;
    g = g + f;
    t = t + elapsed(A) * 2;
    if (t > 3s) { t = 0ms; }
    x = x * 0.5 + 1;
    Act(int(b) + int(time(c % 7) / 2));
  }
  place B {
    a = int8(x * -10.0);
    b = int16(y * 100.0);
    y += 0.25;
    t -= 10ms;
    Act(int(t) + int(a));
  }
  A -> B when B0() && elapsed(A) >= 30ms;
  B -> A when elapsed(B) >= 20ms || t <= elapsed(B);
}
)";
  check_forms("types.sfc", {{"types.sfc", text}}, 3);
}
