// The C-harness writer's table inputs and observable log (backends/c/c_harness.h): what a target
// runner builds. The program is compiled at the strict flags and run; its log must be the
// interpreter's observable log (with -DX_HOOKS, and its hooks layer) for the same inputs, line
// for line, whether it prints with printf or through a character function of the user's.
#include "../run/c_backend_support.h"

#include "interpreter/run_chart.h"

#include <catch2/catch.hpp>

using namespace cbt;

namespace {

/// Inputs that vary by function, tick and agent, the same for the interpreter and the table;
/// `special` values stress the character output's number formatting.
interp::Value input(const model::Model &m, model::FunctionId f, std::uint64_t tick, int agent) {
  static const double special[] = {0.1,  -0.3,   1e-7,        5e-324, 1.5e300, -0.0,    123456789.0,
                                   0.5,  2.5e-5, 1e16,        1e17,   99999.5, 1.0 / 3, 4503599627370497.0,
                                   1e-4, 1e-5,   0.000123456, 1e21,   7.0,     2.0e-308};
  static const float special_float[] = {0.1f, -0.3f, 1e-7f, 1.4e-45f, 3.4e38f, -0.0f,
                                        1e8f, 0.75f, 7.0f,  1e-4f,    1e-5f,   16777217.0f};
  const std::size_t k = f.index() * 7 + tick * 3 + static_cast<std::size_t>(agent) * 5;
  switch (m.functions[f].result) {
  case Type::Bool: return interp::Value::of_bool((k / 2) % 3 == 0);
  case Type::Int: return interp::Value::of_int(static_cast<std::int32_t>(k % 11) - 5);
  case Type::Float: return interp::Value::of_float(special_float[k % 12]);
  default: return interp::Value::of_double(special[(k + 3) % 20]);
  }
}

/// What the caller sets input variable `v` to before `tick` (docs/language.md §14): values that
/// vary by tick and variable, and every fourth tick nothing, so that an input keeps its value.
std::optional<interp::Value> input_var(const model::Var &v, std::uint64_t tick) {
  const std::size_t k = v.name.size() * 5 + tick * 3;
  if (tick % 4 == 3) return std::nullopt;
  switch (v.type) {
  case Type::Bool: return interp::Value::of_bool((k / 2) % 3 != 0);
  case Type::Int: return interp::Value::of_int(static_cast<std::int32_t>(k % 13) * 10 - 20);
  case Type::Float: return interp::Value::of_float(static_cast<float>(k % 9) * 0.25f);
  default: return interp::Value::of_double(static_cast<double>(k % 7) / 3);
  }
}

class TableEnvironment : public interp::Environment {
public:
  TableEnvironment(const model::Model &m, int agent) : m_(m), agent_(agent) {}
  interp::Value call(model::FunctionId f, const std::vector<interp::Value> &, std::uint64_t tick) override {
    return ::input(m_, f, tick, agent_);
  }
  std::optional<interp::Value> input(const model::Var &v, std::uint64_t tick) override { return input_var(v, tick); }

private:
  const model::Model &m_;
  int agent_;
};

/// The interpreter's observable log of `ticks` ticks (every agent of a team machine).
std::string reference(const Compiled &c, std::uint64_t ticks, int agents, bool hooks) {
  std::vector<TableEnvironment> envs;
  for (int a = 0; a < agents; ++a) envs.emplace_back(c.model, a);
  Diagnostics diag;
  interp::RunResult r;
  if (agents > 1) {
    std::vector<interp::Environment *> list;
    for (auto &e : envs) list.push_back(&e);
    r = interp::run_team(c.model, c.chart, list, ticks, {}, diag);
  } else {
    r = interp::run_chart(c.model, c.chart, envs[0], ticks, {}, diag);
  }
  REQUIRE(r.completed);
  interp::RenderOptions o;
  o.hooks = hooks;
  return r.log.render(o);
}

/// Builds the program for the engine in `c` with table inputs, runs it and returns its log.
std::string run_table_harness(const std::string &test, const Compiled &c, std::uint64_t ticks, int agents,
                              c_backend::HarnessOutput output, const std::string &defines) {
  c_backend::HarnessOptions o;
  o.inputs = c_backend::HarnessInputs::Table;
  o.log = c_backend::HarnessLog::Observable;
  o.output = output;
  o.header = "engine.h";
  o.agents = agents;
  o.table.ticks = ticks;
  o.table.value = [&](model::FunctionId f, std::uint64_t tick, int agent) { return input(c.model, f, tick, agent); };
  o.table.input = input_var;
  EmitOptions emit;
  emit.chart = c.chart;
  const c_backend::HarnessSources h = c_backend::write_harness(c.model, c.chart, emit, o);
  fs::path dir = scratch_dir(test);
  for (const auto &f : c.files) write_file(dir / base_name(f.path), f.contents);
  write_file(dir / "glue.c", h.glue);
  std::string sources = "glue.c engine.c";
  if (output == c_backend::HarnessOutput::Putc) {
    // No C library: the program includes no header of it and calls only the user's function.
    CHECK(h.main.empty());
    CHECK(h.glue.find("#include <") == std::string::npos);
    write_file(dir / "uart.c", "#include <stdio.h>\nint harness_putc(int c);\n"
                               "int harness_putc(int c)\n{\n    return putchar(c);\n}\n");
    sources += " uart.c";
    // glue.c alone, freestanding.
    auto alone = run_command(
        fmt::format("cd '{}' && cc {} -ffreestanding -c glue.c -o glue.o", dir.string(), kStrictFlags), dir / "fs.log");
    INFO(alone.output);
    CHECK(alone.status == 0);
  } else {
    write_file(dir / "harness.c", h.main);
    sources += " harness.c";
  }
  auto build = run_command(fmt::format("cd '{}' && cc {} {} {} -o run", dir.string(), kStrictFlags, defines, sources),
                           dir / "build.log");
  INFO(build.output);
  REQUIRE(build.status == 0);
  auto run = run_command(fmt::format("'{}'", (dir / "run").string()), dir / "run.log");
  REQUIRE(run.status == 0);
  return run.output;
}

/// Sample `name`, with every chart and interface of samples/ it may import.
std::unique_ptr<Compiled> compile_sample(const std::string &name) {
  std::map<std::string, std::string> files;
  for (const auto &f : fs::directory_iterator(fs::path(GFEC_SOURCE_DIR) / "samples")) {
    const std::string ext = f.path().extension().string();
    if (ext == ".sfc" || ext == ".fsm" || ext == ".iface") files[f.path().filename().string()] = read_file(f.path());
  }
  auto c = compile_chart(files, name, "engine.c", false);
  INFO(c->errors);
  REQUIRE(!c->diag.has_errors());
  return c;
}

void check_against_interpreter(const std::string &test, const Compiled &c, std::uint64_t ticks, int agents = 1) {
  for (auto output : {c_backend::HarnessOutput::Putc, c_backend::HarnessOutput::Stdio})
    for (bool hooks : {false, true}) {
      const std::string name = fmt::format("{}_{}{}", test, output == c_backend::HarnessOutput::Putc ? "putc" : "stdio",
                                           hooks ? "_hooks" : "");
      const std::string defines = hooks ? fmt::format("-D{}_HOOKS", c.the_chart().name) : "";
      const std::string log = run_table_harness(name, c, ticks, agents, output, defines);
      CHECK(log == reference(c, ticks, agents, hooks));
    }
}

}  // namespace

TEST_CASE("c harness: a table-driven program prints the interpreter's observable log", "[c_harness][run]") {
  SECTION("sfc with a fork, a join, timers and float arguments") {
    auto c = compile_sample("work_cell.sfc");
    check_against_interpreter("harness_work_cell", *c, 80);
  }
  SECTION("sfc line follower") {
    auto c = compile_sample("line_follower.sfc");
    check_against_interpreter("harness_line_follower", *c, 12);
  }
  SECTION("fsm") {
    auto c = compile_sample("mission.fsm");
    check_against_interpreter("harness_mission", *c, 15);
  }
  SECTION("a team machine of three agents") {
    auto c = compile_sample("fetch_team.fsm");
    check_against_interpreter("harness_fetch_team", *c, 15, 3);
  }
}

TEST_CASE("c harness: a chart's inputs and outputs, set and read around each tick", "[c_harness][run][iec]") {
  // docs/language.md §14: the caller sets `in` fields before a tick and reads `out` fields after;
  // the observable log's `out NAME = VALUE` lines are the interpreter's, in both engine forms.
  const std::string chart = "sfc Mixer {\n"
                            "  period 100ms;\n"
                            "  in bool Start;\n  in int Level = 5;\n  in double Rate;\n"
                            "  out bool Valve;\n  out int Batches = 1;\n  out float Mix = 0.5;\n"
                            "  out double Flow;\n  var int kept;\n"
                            "  initial place Idle { Valve = false; }\n"
                            "  place Filling { Valve = Level < 80; Flow = Rate * 2.0; kept += 1; }\n"
                            "  place Settle { Batches += Level; Mix = Mix / 2.0; }\n"
                            "  Idle -> Filling when Start;\n"
                            "  Filling -> Settle when Level >= 40 || !Start;\n"
                            "  Settle -> Idle when elapsed(Settle) >= 200ms;\n"
                            "}\n";
  for (EngineForm form : {EngineForm::Readable, EngineForm::Scalable}) {
    auto c = compile_chart({{"mixer.sfc", chart}}, "mixer.sfc", "engine.c", false, form);
    INFO(c->errors);
    REQUIRE(!c->diag.has_errors());
    const std::string name = form == EngineForm::Readable ? "harness_io_readable" : "harness_io_scalable";
    for (auto output : {c_backend::HarnessOutput::Putc, c_backend::HarnessOutput::Stdio}) {
      const std::string log = run_table_harness(name, *c, 30, 1, output, "");
      CHECK(log == reference(*c, 30, 1, false));
      CHECK(log.find("out Batches = ") != std::string::npos);
      CHECK(log.find("out Valve = true") != std::string::npos);  // an input reached the chart
    }
  }
}

namespace {

/// A chart with named actions, its engine emitted in `form`.
std::unique_ptr<Compiled> compile_actions(const std::string &text, EngineForm form) {
  auto c = compile_chart({{"acts.sfc", text}}, "acts.sfc", "engine.c", false, form);
  INFO(c->errors);
  REQUIRE(!c->diag.has_errors());
  return c;
}

// The interpreter's hand-checked charts (tests/unit/interpreter_sfc_test.cc) and a cycle driven
// by inputs that holds every qualifier the engine runs, with durations of 0.
const char *const kActionCharts[] = {
    "sfc Acts {\n  var int k = 0;\n  out int hold = 0;\n  out int pulse = 0;\n  out int edge = 0;\n"
    "  action Hold { hold += 1; }\n  action Pulse { pulse += 1; }\n  action Edge { edge += 1; }\n"
    "  initial place Clock { k += 1; }\n  initial place A { P Pulse; P1 Edge; N Hold; }\n"
    "  place B { N Hold; P0 Edge; }\n  place C { N Hold; }\n  place E;\n  place F;\n"
    "  A -> (B, C) when k >= 1;\n  B -> E when k >= 2;\n  C -> F when k >= 3;\n}\n",
    "sfc Store {\n  var int k = 0;\n  out int lamp = 0;\n  action Lamp { lamp += 1; }\n"
    "  initial place Clock { k += 1; }\n  initial place A { S Lamp; }\n  place B;\n"
    "  place C { S Lamp; R Lamp; }\n  place D;\n"
    "  A -> B when k >= 1;\n  B -> C when k >= 2;\n  C -> D when k >= 3;\n}\n",
    "sfc Timed {\n  period 10ms;\n  out int brief = 0;\n  out int late = 0;\n"
    "  action Short { brief += 1; }\n  action Late { late += 1; }\n"
    "  initial place A { L Short 20ms; D Late 20ms; }\n}\n",
    "sfc Cycle {\n  period 10ms;\n  in bool Go;\n  in int Level;\n"
    "  out int n = 0;\n  out int p = 0;\n  out int e = 0;\n  out int s = 0;\n  out int l = 0;\n  out int d = 0;\n"
    "  action Run { n += 1; }\n  action Kick { p += 1; }\n  action Edge { e += 10; }\n"
    "  action Lamp { s += 1; }\n  action Brief { l += 1; }\n  action Late { d += 1; }\n  action Never { n = 0; }\n"
    "  initial place Idle { P1 Edge; S Lamp; N Run; }\n"
    "  place Fill { N Run; P Kick; L Brief 30ms; D Late 20ms; P0 Edge; }\n"
    "  place Hold { R Lamp; D Late 0ms; L Brief 0ms; P Kick; R Never; }\n"
    "  place Drain { S Lamp; N Run; }\n"
    "  Idle -> Fill when Go;\n  Fill -> Hold when Level > 20;\n  Hold -> Drain when !Go;\n"
    "  Drain -> Idle when elapsed(Drain) >= 30ms;\n}\n",
    // The sparse form with timers: L and D on places of a fork and its join.
    "sfc Fork {\n  period 10ms;\n  var int k = 0;\n  out int a = 0;\n  out int b = 0;\n"
    "  action Lim { a += 1; }\n  action Del { b += 1; }\n"
    "  initial place Clock { k += 1; }\n  initial place S { L Lim 30ms; }\n"
    "  place X { D Del 20ms; L Lim 10ms; }\n  place Y { D Del 0ms; }\n"
    "  S -> (X, Y) when k % 7 == 2;\n  (X, Y) -> S when k % 7 == 0;\n}\n",
    // Sub-charts: an instance's action control is its own, and starts clear when its place gains
    // activation again; the actions report through calls.
    "interface Io { void Hit(int i); bool Go(int i); }\n"
    "sfc Inner {\n  action Beat { Hit(1); }\n  action Once { Hit(2); }\n"
    "  initial place I { N Beat; P1 Once; }\n  place J { P Once; S Beat; }\n"
    "  I -> J when Go(1);\n  J -> I when Go(2);\n}\n"
    "sfc Outer {\n  action Mark { Hit(3); }\n  initial place A runs Inner { S Mark; }\n"
    "  place B runs Inner { R Mark; P0 Mark; }\n  A -> B when Go(3);\n  B -> A when Go(4);\n}\n",
    // SD, DS and SL (tests/unit/interpreter_sfc_test.cc checks each by hand): a set and its place
    // left before the delay, R before it, R in the tick of a set, DS left before its delay, SL
    // running out and set again after R, durations of 0 and beyond the timers' range.
    "sfc SdLeft {\n  period 10ms;\n  var int k = 0;\n  out int on = 0;\n  action Late { on += 1; }\n"
    "  initial place Clock { k += 1; }\n  initial place A { SD Late 30ms; }\n  place B;\n  place C { R Late; }\n"
    "  place D;\n  A -> B when k >= 1;\n  B -> C when k >= 6;\n  C -> D when k >= 7;\n}\n",
    "sfc SdReset {\n  period 10ms;\n  var int k = 0;\n  out int late = 0;\n  out int lamp = 0;\n"
    "  action Late { late += 1; }\n  action Lamp { lamp += 1; }\n  initial place Clock { k += 1; }\n"
    "  initial place A { SD Late 30ms; }\n  place B { R Late; }\n"
    "  place C { SD Late 30ms; R Late; SL Lamp 20ms; R Lamp; }\n  place D;\n"
    "  A -> B when k >= 1;\n  B -> C when k >= 2;\n  C -> D when k >= 3;\n}\n",
    "sfc Ds {\n  period 10ms;\n  var int k = 0;\n  out int a = 0;\n  out int b = 0;\n"
    "  action Early { a += 1; }\n  action Kept { b += 1; }\n  initial place Clock { k += 1; }\n"
    "  initial place A { DS Early 30ms; DS Kept 20ms; }\n  place B;\n  place C { R Kept; }\n"
    "  A -> B when k >= 2;\n  B -> C when k >= 5;\n}\n",
    "sfc Sl {\n  period 10ms;\n  var int k = 0;\n  out int l = 0;\n  out int z = 0;\n  out int y = 0;\n"
    "  out int w = 0;\n  out int v = 0;\n  out int u = 0;\n"
    "  action Lim { l += 1; }\n  action Zsd { z += 1; }\n  action Zds { y += 1; }\n  action Zsl { w += 1; }\n"
    "  action Far { v += 1; }\n  action Wide { u += 1; }\n"
    "  initial place Clock { k += 1; }\n  initial place A { SL Lim 30ms; SD Far 1e12s; SL Wide 1e12s; }\n"
    "  place B { SD Zsd 0ms; DS Zds 0ms; SL Zsl 0ms; DS Far 1e12s; }\n"
    "  place C { R Zsd; R Zds; R Lim; R Wide; }\n  place D { SL Lim 30ms; SL Wide 1e12s; }\n"
    "  A -> B when k >= 5;\n  B -> C when k >= 6;\n  C -> D when k >= 7;\n  D -> A when k % 13 == 0;\n}\n",
    // A sequential chart (its scalable form is the switch on the one active place) driven by
    // inputs: every stored form in one action, set and reset around a cycle.
    "sfc Cycle {\n  period 10ms;\n  in bool Go;\n  in int Level;\n  out int n = 0;\n  out int m = 0;\n"
    "  action Run { n += 1; }\n  action Mix { m += 1; }\n"
    "  initial place Idle { SD Run 40ms; R Mix; }\n  place Fill { SL Run 20ms; DS Mix 30ms; }\n"
    "  place Hold { SD Run 40ms; S Mix; SL Mix 50ms; }\n  place Drain { R Run; DS Run 10ms; }\n"
    "  Idle -> Fill when Go;\n  Fill -> Hold when Level > 20;\n  Hold -> Drain when !Go;\n"
    "  Drain -> Idle when elapsed(Drain) >= 30ms;\n}\n",
    // Sub-charts: an instance's SD, DS and SL flags and timers are its own, cleared as its place
    // gains activation again (Brief, set by DS in J, runs until then).
    "interface Io { void Hit(int i); }\n"
    "sfc Inner {\n  period 10ms;\n  var int j = 0;\n  action Slow { Hit(1); }\n  action Brief { Hit(2); }\n"
    "  initial place I { j += 1; SD Slow 30ms; SL Brief 20ms; }\n  place J { j += 1; DS Brief 20ms; R Slow; }\n"
    "  I -> J when j % 5 == 4;\n  J -> I when j % 5 == 2;\n}\n"
    "sfc Outer {\n  period 10ms;\n  var int k = 0;\n  action Mark { Hit(3); }\n"
    "  initial place A runs Inner { k += 1; SD Mark 20ms; }\n  place B runs Inner { k += 1; SL Mark 30ms; }\n"
    "  place C { k += 1; R Mark; }\n"
    "  A -> B when k % 11 == 7;\n  B -> C when k % 11 == 10;\n  C -> A when k % 11 == 0;\n}\n",
    // An initial place left in tick 1 falls in tick 1 (its P0 runs, the rest does not): in the
    // sequential form, and in instances, whose first tick follows each start.
    "sfc Seq {\n  var int k = 0;\n  out int n = 0;\n  out int r = 0;\n  out int f = 0;\n  out int p = 0;\n"
    "  action Run { n += 1; }\n  action Rise { r += 1; }\n  action Fall { f += 1; }\n  action Kick { p += 1; }\n"
    "  initial place A { k += 1; N Run; P1 Rise; P0 Fall; P Kick; }\n  place B { k += 1; P0 Fall; }\n"
    "  A -> B when k % 5 == 0;\n  B -> A when k % 5 == 3;\n}\n",
    "interface Io { void Hit(int i); bool Go(int i); }\n"
    "sfc Inner {\n  action Fall { Hit(1); }\n  action Rise { Hit(2); }\n  action Hold { Hit(4); }\n"
    "  initial place I { P0 Fall; P1 Rise; N Hold; }\n  place J { P0 Fall; }\n"
    "  I -> J when Go(1);\n  J -> I when Go(2);\n}\n"
    "sfc Outer {\n  action Mark { Hit(3); }\n  initial place A runs Inner { P0 Mark; }\n"
    "  place B runs Inner { P0 Mark; }\n  A -> B when Go(3);\n  B -> A when Go(4);\n}\n",
};

}  // namespace

TEST_CASE("c harness: action control runs in both engine forms as in the interpreter", "[c_harness][run][iec]") {
  // docs/iec.md "Action control": the outputs count each action's runs, so the log of every tick
  // shows which ran; with hooks, the activation too.
  int k = 0;
  for (const char *chart : kActionCharts) {
    ++k;
    for (EngineForm form : {EngineForm::Readable, EngineForm::Scalable}) {
      auto c = compile_actions(chart, form);
      for (bool hooks : {false, true}) {
        const std::string name = fmt::format(
            "harness_actions{}_{}{}", k, form == EngineForm::Readable ? "readable" : "scalable", hooks ? "_hooks" : "");
        const std::string defines = hooks ? fmt::format("-D{}_HOOKS", c->the_chart().name) : "";
        const std::string log = run_table_harness(name, *c, 40, 1, c_backend::HarnessOutput::Stdio, defines);
        CHECK(log == reference(*c, 40, 1, hooks));
      }
    }
  }
}

TEST_CASE("c harness: the character output formats floats and doubles exactly as printf", "[c_harness][run]") {
  // Every sensing function's result is printed: `call F() = v`, each tick other values, among
  // them subnormals, halfway cases, the edges of %g's exponent form and negative zero.
  const std::string chart = "interface Probe { float F(); double D(); double E(); void Show(double x, float y); }\n"
                            "sfc Numbers {\n"
                            "  initial place A { Show(D() * 0.5, F() - 1.0); }\n"
                            "  transition A -> A when F() > 0.0 || E() < 0.0;\n"
                            "}\n";
  auto c = compile_chart({{"numbers.sfc", chart}}, "numbers.sfc", "engine.c", false);
  INFO(c->errors);
  REQUIRE(!c->diag.has_errors());
  const std::string log = run_table_harness("harness_numbers", *c, 40, 1, c_backend::HarnessOutput::Putc, "");
  CHECK(log == reference(*c, 40, 1, false));
  CHECK(log.find("e-324") != std::string::npos);  // the subnormal reached the log
}

TEST_CASE("c harness: the library names each kind of program calls", "[c_harness]") {
  c_backend::HarnessOptions o;
  o.inputs = c_backend::HarnessInputs::Steps;
  std::vector<std::string> steps = c_backend::harness_library_names(o);
  std::sort(steps.begin(), steps.end());
  // gfec test refuses a chart with an interface function of one of these names.
  CHECK(steps == std::vector<std::string>{"fflush", "main", "scanf", "strcmp", "strcpy", "strtod", "strtof", "strtol",
                                          "strtoll", "strtoull", "vprintf"});
  o.inputs = c_backend::HarnessInputs::Table;
  o.output = c_backend::HarnessOutput::Putc;
  CHECK(c_backend::harness_library_names(o) == std::vector<std::string>{"main", "harness_putc"});
  o.context = true;
  auto m = ChartBuilder("X", model::Chart::Kind::Sfc);
  m.place("A", true);
  EmitOptions emit;
  emit.chart = model::ChartId(0);
  CHECK_THROWS_AS(c_backend::write_harness(m.model(), model::ChartId(0), emit, o), std::invalid_argument);
}
