#include "driver/chart_build.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "driver/engine_abi.h"
#include "driver/engine_cache.h"
#include "driver/process.h"
#include "chart_nodes.h"
#include "recording.h"

namespace carbot::driver {
namespace {

void run_tool(const std::vector<std::string>& argv, const std::string& what, Exit on_failure) {
  std::string error;
  const int rc = run_process(argv, error);
  if (rc < 0) throw BuildError(fmt::format("{}: {}", what, error), kUsage);
  if (rc != 0) throw BuildError(fmt::format("{} failed (exit {}): {}", what, rc, show_command(argv)), on_failure);
}

/// gfec prints its own diagnostics; ours only says what that means for the run.
void run_gfec(const std::vector<std::string>& argv, const std::string& chart) {
  std::string error;
  const int rc = run_process(argv, error);
  if (rc < 0) throw BuildError(fmt::format("cannot run gfec: {}", error), kUsage);
  if (rc == 1) throw BuildError(fmt::format("{}: gfec rejected the chart (its messages are above)", chart), kBadInput);
  if (rc != 0) throw BuildError(fmt::format("gfec failed (exit {}): {}", rc, show_command(argv)), kBadInput);
}

void read_viewer_info(const nlohmann::json& model, ChartInfo& info);

ChartInfo read_chart_info(const std::string& model_path) {
  std::ifstream in(model_path);
  nlohmann::json model;
  try {
    in >> model;
  } catch (const std::exception& e) {
    throw BuildError(fmt::format("{}: gfec's model is not JSON: {}", model_path, e.what()), kUsage);
  }
  auto text = [&](const char* key) {
    if (!model.is_object() || !model.contains(key) || !model[key].is_string())
      throw BuildError(fmt::format("{}: gfec's model has no string \"{}\"", model_path, key), kUsage);
    return model[key].get<std::string>();
  };
  ChartInfo info;
  info.name = text("name");
  info.kind = text("kind");
  if (model.contains("files") && model["files"].is_array())
    for (const auto& f : model["files"])
      if (f.is_string()) info.files.push_back(f.get<std::string>());
  if (info.kind != "sfc" && info.kind != "fsm" && info.kind != "plan")
    throw BuildError(fmt::format("{}: unknown chart kind '{}'", model_path, info.kind), kBadInput);
  // Optional parts of the model: carbot-sim runs without them.
  if (model.contains("period_ms") && model["period_ms"].is_number())
    info.period = model["period_ms"].get<double>() / 1000;
  if (model.contains("team") && model["team"].is_number_integer()) info.team = model["team"].get<int>();
  if (info.kind == "fsm" && model.contains("states") && model["states"].is_array()) {
    for (const auto& st : model["states"]) {
      std::string label = st.value("name", "?");
      if (st.contains("action") && st["action"].is_array() && !st["action"].empty() && st["action"][0].is_object()) {
        std::string call = st["action"][0].value("text", "");
        if (!call.empty() && call.back() == ';') call.pop_back();
        if (!call.empty()) label += " " + call;
      }
      info.states.push_back(label);
    }
  }
  read_viewer_info(model, info);
  return info;
}

/// The places (sfc) or states (fsm) of `chart`, a model JSON chart, or null.
const nlohmann::json* places_of(const nlohmann::json& chart) {
  const char* key = chart.value("kind", "") == "fsm" ? "states" : "places";
  return chart.contains(key) && chart[key].is_array() ? &chart[key] : nullptr;
}

/// The chart of `model` (gfec's JSON) and its sub-charts as the run viewer's outline: charts[0]
/// the chart, charts[1 + i] the model's subcharts[i]; a place runs the sub-chart it names.
gfec::viewer::ChartOutline chart_outline(const nlohmann::json& model, const nlohmann::json& subcharts) {
  gfec::viewer::ChartOutline outline;
  std::vector<const nlohmann::json*> charts{&model};
  for (const nlohmann::json& c : subcharts) charts.push_back(&c);
  for (const nlohmann::json* c : charts) {
    gfec::viewer::ChartOutline::Chart chart{c->value("name", "?"), {}};
    if (const nlohmann::json* places = places_of(*c))
      for (const nlohmann::json& pl : *places) {
        gfec::viewer::ChartOutline::Place place{pl.value("name", "?"),
                                                pl.contains("terminal") && pl["terminal"].is_string(), -1};
        if (pl.contains("runs") && pl["runs"].is_string())
          for (std::size_t i = 0; i < subcharts.size(); ++i)
            if (subcharts[i].value("name", "") == pl["runs"].get<std::string>() && places_of(subcharts[i]))
              place.runs = static_cast<int>(i + 1);
        chart.places.push_back(place);
      }
    outline.charts.push_back(std::move(chart));
  }
  return outline;
}

/// What the run viewer needs from the model: the timeline's rows and their picture nodes (the
/// ids gfec's DOT back end gives them, support/chart_nodes.h: places and states "pN", actors
/// "aN", supervisors "sN_M" and global ones "gN"), and the interface functions with their C types.
void read_viewer_info(const nlohmann::json& model, ChartInfo& info) {
  auto array = [&](const char* key) {
    return model.contains(key) && model[key].is_array() ? model[key] : nlohmann::json::array();
  };
  if (info.kind != "plan") {
    // The places or states, then the sub-chart instances' rows (the viewer's one walk of them).
    std::vector<gfec::viewer::Row> rows;
    std::vector<gfec::viewer::Instance> instances;
    const gfec::viewer::ChartOutline outline = chart_outline(model, array("subcharts"));
    gfec::viewer::outline_rows(outline, rows, instances);
    info.own_rows = outline.charts.front().places.size();
    for (const gfec::viewer::Row& r : rows) info.rows.push_back({r.name, r.node, r.terminal, r.group});
    for (const gfec::viewer::Instance& in : instances)
      info.instances.push_back({in.path, in.chart, in.first, in.count, in.parent_row});
  } else {
    const nlohmann::json actors = array("actors");
    for (std::size_t i = 0; i < actors.size(); ++i) {
      const nlohmann::json& r = actors[i];
      ChartInfo::Row row{r.value("name", "?"), gfec::chart_nodes::actor(i), false, ""};
      row.terminal = r.contains("terminal") && r["terminal"].is_string();
      if (r.contains("supervisors") && r["supervisors"].is_array())
        for (std::size_t s = 0; s < r["supervisors"].size(); ++s)
          info.supervisor_nodes[row.name + "/" + r["supervisors"][s].value("name", "?")] =
              gfec::chart_nodes::supervisor(i, s);
      info.rows.push_back(row);
    }
    info.own_rows = info.rows.size();
    const nlohmann::json globals = array("supervisors");
    for (std::size_t g = 0; g < globals.size(); ++g)
      info.supervisor_nodes[globals[g].value("name", "?")] = gfec::chart_nodes::global_supervisor(g);
  }
  // The functions the chart calls, and those its sub-charts call (each once): all are wrapped.
  std::vector<nlohmann::json> function_lists = {array("functions")};
  for (const nlohmann::json& sub : array("subcharts"))
    if (sub.contains("functions") && sub["functions"].is_array()) function_lists.push_back(sub["functions"]);
  for (const nlohmann::json& list : function_lists)
    for (const nlohmann::json& f : list) {
      ChartInfo::Function fn{f.value("name", ""), f.value("result", "void"), {}, f.value("interface", "")};
      if (f.contains("params") && f["params"].is_array())
        for (const nlohmann::json& p : f["params"]) fn.params.push_back(p.value("type", "int"));
      const bool known = std::any_of(info.functions.begin(), info.functions.end(),
                                     [&](const ChartInfo::Function& g) { return g.name == fn.name; });
      if (!fn.name.empty() && !known) info.functions.push_back(fn);
    }
}

/// The C spelling of a model type in a function signature, or "" for one the recorder does not
/// know (that function is then left unwrapped: it runs, unrecorded).
std::string c_type(const std::string& t) {
  if (t == "bool" || t == "int" || t == "float" || t == "double" || t == "void") return t;
  return "";
}

bool recordable(const ChartInfo::Function& f) {
  if (c_type(f.result).empty()) return false;
  for (const std::string& p : f.params)
    if (c_type(p).empty() || p == "void") return false;
  return true;
}

/// Runs a compile unless the cache has its result. The key leaves out the folder the engine is
/// built in (a fresh one every run) wherever it appears.
void compile(const std::vector<std::string>& command, const std::vector<std::string>& inputs,
             const std::vector<std::string>& header_dirs, const Options& o, const std::string& output,
             const char* what) {
  const EngineCache cache(o.cache_dir);
  const std::string key = EngineCache::key(command, inputs, header_dirs, header_dirs.front());
  if (cache.fetch(key, output)) {
    if (!o.quiet) std::fprintf(stderr, "carbot-sim: %s: taken from the cache (entry %s)\n", what, key.c_str());
    return;
  }
  run_tool(command, what, kBadInput);
  cache.store(key, output);
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw BuildError(fmt::format("{}: cannot write", path), kUsage);
}

}  // namespace

std::string c_shim(const ChartInfo& c, bool traced) {
  const std::string& n = c.name;
  // An sfc never ends by itself; an fsm reports 1 (succeeded) or -1 (failed).
  const std::string status =
      c.kind == "fsm" ? fmt::format("return {}_status((const {} *)m);", n, n) : std::string("(void)m;\n  return 0;");
  // An fsm also tells its current state, so the run can log and draw its phases.
  std::string state =
      c.kind == "fsm" ? fmt::format("int {}(const void *m) {{ return {}_state((const {} *)m); }}\n", kEngineState, n, n)
                      : std::string();
  // A team machine takes its agent number and the others' states (docs/c-engine.md "Team machines").
  if (c.team > 0)
    state += fmt::format(
        "void {0}(void *m, int agent) {{ {2}_set_agent(({2} *)m, agent); }}\n"
        "void {1}(void *m, int agent, int state) {{ {2}_report(({2} *)m, agent, state); }}\n",
        kEngineSetAgent, kEngineReport, n);
  // A chart with sub-charts: where each instance is, for the run viewer (gfec's reader of them,
  // docs/c-engine.md "Sub-charts"; the instances numbered as ChartInfo::instances).
  if (!c.instances.empty())
    state += fmt::format(
        "unsigned {0}(const void *m, int instance, int place) {{\n"
        "  return {1}_instance_activation((const {1} *)m, instance, place);\n}}\n",
        kEngineInstanceActivation, n);
  // gfec --trace: the engine's frames go to carbot-sim, which sends them to the selected robot's link.
  if (traced)
    state += fmt::format(
        "void carbot_sim_trace(const unsigned char *data, unsigned len);\n"
        "void {0}_trace_write(const unsigned char *data, unsigned len) {{ carbot_sim_trace(data, len); }}\n",
        n);
  return fmt::format(R"(/* Generated by carbot-sim: fixed entry points for the engine of {kind} {n}. */
#include <stddef.h>
#include "engine.h"

size_t {size}(void) {{ return sizeof({n}); }}
void {init}(void *m) {{ {n}_init(({n} *)m); }}
/* The instance context: the robot every interface call of this engine is for. */
void {set_context}(void *m, struct CarbotRobot *robot) {{ {n}_set_context(({n} *)m, robot); }}
void {run}(void *m) {{ {n}_run(({n} *)m); }}
int {status}(const void *m) {{
  {body}
}}
{state}
/* The activation API, for the run viewer's recording: read after each tick, never written. */
int {places}(void) {{ return {n}_PLACE_COUNT; }}
unsigned {activation}(const void *m, int p) {{ return {n}_activation((const {n} *)m, p); }}
)",
                     fmt::arg("kind", c.kind), fmt::arg("n", n), fmt::arg("size", kEngineSize),
                     fmt::arg("init", kEngineInit), fmt::arg("set_context", kEngineSetContext),
                     fmt::arg("run", kEngineRun), fmt::arg("status", kEngineStatus), fmt::arg("body", status),
                     fmt::arg("state", state), fmt::arg("places", kEnginePlaces),
                     fmt::arg("activation", kEngineActivation));
}

std::string robot_names(const ChartInfo& c) {
  std::string out = fmt::format(
      "/* Generated by carbot-sim: {}'s calls go to carbot-sim's robot libraries, whose functions carry\n"
      "   their interface's name (sim/robots/robots.h). */\n",
      c.name);
  for (const ChartInfo::Function& f : c.functions)
    if (!f.interface.empty()) out += fmt::format("#define {0} {1}_{0}\n", f.name, f.interface);
  return out;
}

std::string record_renames(const ChartInfo& c) {
  std::string out =
      fmt::format("/* Generated by carbot-sim: the calls of {} go through recording wrappers. */\n", c.name);
  for (const ChartInfo::Function& f : c.functions)
    if (recordable(f)) out += fmt::format("#define {0} carbot_rec_{0}\n", f.name);
  return out;
}

std::string record_wrappers(const ChartInfo& c) {
  std::string out =
      fmt::format(R"(/* Generated by carbot-sim: records each call of {} and its result for the run viewer. */
#include <stdbool.h>
#include <stdio.h>

struct CarbotRobot;
void carbot_sim_call(const char *text);
)",
                  c.name);
  for (const ChartInfo::Function& f : c.functions) {
    if (!recordable(f)) continue;
    // The instance context first (kContextType), forwarded: the call reaches its own robot.
    std::string params = std::string(kContextType) + "ctx", args = "ctx", formats, values;
    for (std::size_t i = 0; i < f.params.size(); ++i) {
      const std::string& t = f.params[i];
      params += fmt::format(", {} a{}", t, i);
      args += fmt::format(", a{}", i);
      formats += i ? ", " : "";
      formats += t == "bool" ? "%s" : t == "int" ? "%d" : "%g";
      values += t == "bool"  ? fmt::format(", a{} ? \"true\" : \"false\"", i)
                : t == "int" ? fmt::format(", a{}", i)
                             : fmt::format(", (double)a{}", i);
    }
    const std::string& signature = params;
    const bool is_void = f.result == "void";
    const std::string result_format = is_void              ? ""
                                      : f.result == "bool" ? " = %s"
                                      : f.result == "int"  ? " = %d"
                                                           : " = %g";
    const std::string result_value = is_void              ? ""
                                     : f.result == "bool" ? ", r ? \"true\" : \"false\""
                                     : f.result == "int"  ? ", r"
                                                          : ", (double)r";
    out += fmt::format("\n{res} {name}({sig});\n{res} carbot_rec_{name}({sig}) {{\n  char text[256];\n",
                       fmt::arg("res", f.result), fmt::arg("name", f.name), fmt::arg("sig", signature));
    out +=
        is_void ? fmt::format("  {}({});\n", f.name, args) : fmt::format("  {} r = {}({});\n", f.result, f.name, args);
    out += fmt::format("  snprintf(text, sizeof text, \"{}({}){}\"{}{});\n  carbot_sim_call(text);\n", f.name, formats,
                       result_format, values, result_value);
    out += is_void ? "}\n" : "  return r;\n}\n";
  }
  return out;
}

std::string cpp_shim(const ChartInfo& c, bool has_header, bool traced) {
  // The plan runs in the stepped executor, one step per control period; its actor changes go
  // to carbot-sim's plan log through an exported C function. With --trace-to an afp::LinkTrace
  // beside the log sends the plan's frames to carbot-sim's link, as a robot's program would.
  const std::string link =
      traced ? "extern \"C\" void carbot_sim_trace(const unsigned char* data, unsigned len);\n" : "";
  const std::string members = traced ? "  afp::LinkTrace link{*plan, [](const unsigned char* d, std::size_t n) {\n"
                                       "    carbot_sim_trace(d, static_cast<unsigned>(n));\n  }};\n"
                                       "  afp::TraceTee observers{&log, &link};\n"
                                       "  afp::SteppedExecutor exec{*plan, config, &observers};\n"
                                     : "  afp::SteppedExecutor exec{*plan, config, &log};\n";
  const std::string heartbeat = traced ? "  e->link.heartbeat(e->exec.now());\n" : "";
  return fmt::format(
      R"~(// Generated by carbot-sim: fixed entry points for plan {n}.
#include <afp/afp.h>
#include <cstddef>
#include <memory>
#include <new>
#include <string>
#include "carbot_toolbox.h"
{factory}

extern "C" double carbot_control_period(struct CarbotRobot* robot);
extern "C" void carbot_sim_plan_event(double t, const char* text);
{link}
namespace {{

double seconds(afp::Duration d) {{ return std::chrono::duration<double>(d).count(); }}

struct Log : afp::TraceObserver {{
  std::string last;
  void actor_started(const afp::Plan& plan, std::string_view actor, afp::Duration now) override {{
    std::string name = plan.name() + "." + std::string(actor);
    if (name != last) carbot_sim_plan_event(seconds(now), ("start " + name).c_str());
    last = name;
  }}
  void actor_interrupted(const afp::Plan& plan, std::string_view actor, std::string_view supervisor, int,
                         afp::Duration now) override {{
    carbot_sim_plan_event(seconds(now), (plan.name() + "." + std::string(actor) + " interrupted by " +
                                         std::string(supervisor)).c_str());
    last.clear();
  }}
  void component_failed(const afp::Plan& plan, std::string_view component, std::string_view what,
                        afp::Duration now) override {{
    carbot_sim_plan_event(seconds(now), (plan.name() + "." + std::string(component) + " failed: " +
                                         std::string(what)).c_str());
  }}
}};

// The plan starts at its first tick, once its robot is known (set_context comes after init).
struct Engine {{
  Env ee;
  afp::Configuration config;
  Log log;
  std::unique_ptr<afp::Plan> plan = make_{n}(ee);
{members}  afp::Duration period{{}};
  bool started = false;
}};

}}  // namespace

extern "C" std::size_t {size}(void) {{ return sizeof(Engine); }}
extern "C" void {init}(void* m) {{ new (m) Engine; }}
/* The instance context, as a C engine's: the robot the plan's toolbox drives. */
extern "C" void {set_context}(void* m, struct CarbotRobot* robot) {{
  auto* e = static_cast<Engine*>(m);
  e->ee.set_robot(robot);
  e->period = std::chrono::duration_cast<afp::Duration>(std::chrono::duration<double>(carbot_control_period(robot)));
}}
extern "C" void {run}(void* m) {{
  auto* e = static_cast<Engine*>(m);
  if (!e->started) e->exec.start();
  e->started = true;
  e->exec.step(e->period);
{heartbeat}}}
extern "C" void {fini}(void* m) {{ static_cast<Engine*>(m)->~Engine(); }}
extern "C" int {status}(const void* m) {{
  switch (static_cast<const Engine*>(m)->exec.status()) {{
    case afp::Status::Succeeded: return 1;
    case afp::Status::Failed: return -1;
    case afp::Status::Interrupted:
    case afp::Status::Stopped: return 2;
    default: return 0;
  }}
}}
)~",
      fmt::arg("n", c.name), fmt::arg("link", link), fmt::arg("members", members), fmt::arg("heartbeat", heartbeat),
      // gfec's header declares the factory; without one, declare it as docs/runtime.md shows.
      fmt::arg("factory", has_header ? std::string("#include \"engine.hpp\"")
                                     : fmt::format("std::unique_ptr<afp::Plan> make_{}(Env& ee);", c.name)),
      fmt::arg("size", kEngineSize), fmt::arg("init", kEngineInit), fmt::arg("set_context", kEngineSetContext),
      fmt::arg("run", kEngineRun), fmt::arg("fini", kEngineFini), fmt::arg("status", kEngineStatus));
}

BuiltEngine build_engine(const Options& o, const std::string& dir) {
  BuiltEngine built;
  const std::string model = dir + "/model.json";
  run_gfec({o.gfec, "--emit=json", o.chart, "-o", model}, o.chart);
  built.chart = read_chart_info(model);
  built.library = dir + "/engine.so";

  if (built.chart.kind == "plan") {
    if (!o.plans_supported)
      throw BuildError(fmt::format("{}: plan '{}': this carbot-sim was built without the afp runtime, so it "
                                   "cannot run plans",
                                   o.chart, built.chart.name),
                       kUsage);
    run_gfec({o.gfec, o.chart, "-o", dir + "/engine.cc"}, o.chart);
    write_file(dir + "/shim.cc", cpp_shim(built.chart, std::ifstream(dir + "/engine.hpp").good(), !o.trace_to.empty()));
    compile({o.cxx, "-std=c++17", "-O1", "-fPIC", "-shared", "-I", dir, "-I", o.runtime_include, "-I",
             o.toolbox_include, "-o", built.library, dir + "/engine.cc", dir + "/shim.cc"},
            {dir + "/engine.cc", dir + "/shim.cc"}, {dir, o.runtime_include, o.toolbox_include}, o, built.library,
            "compiling the plan engine");
    return built;
  }
  // Each engine instance gets its robot as context (docs/sim.md "Several robots").
  std::vector<std::string> engine_command{o.gfec, std::string("--context-type=") + kContextType, o.chart, "-o",
                                          dir + "/engine.c"};
  if (!o.trace_to.empty()) engine_command.push_back("--trace");
  run_gfec(engine_command, o.chart);
  write_file(dir + "/shim.c", c_shim(built.chart, !o.trace_to.empty()));
  // The engine's calls (in a recording build, the wrappers' calls) are renamed to the robot
  // libraries' by a header.
  write_file(dir + "/robot_names.h", robot_names(built.chart));
  if (o.recording()) {
    // The same engine.c, its interface calls renamed to the recording wrappers.
    write_file(dir + "/record.h", record_renames(built.chart));
    write_file(dir + "/record.c", "#include \"robot_names.h\"\n" + record_wrappers(built.chart));
    write_file(dir + "/engine_rec.c", "#include \"record.h\"\n#include \"engine.c\"\n");
    compile({o.cc, "-std=c99", "-O2", "-fPIC", "-shared", "-I", dir, "-o", built.library, dir + "/engine_rec.c",
             dir + "/shim.c", dir + "/record.c"},
            {dir + "/engine.c", dir + "/engine.h", dir + "/shim.c", dir + "/record.h", dir + "/record.c",
             dir + "/engine_rec.c", dir + "/robot_names.h"},
            {dir}, o, built.library, "compiling the engine");
    return built;
  }
  compile({o.cc, "-std=c99", "-O2", "-fPIC", "-shared", "-I", dir, "-include", dir + "/robot_names.h", "-o",
           built.library, dir + "/engine.c", dir + "/shim.c"},
          {dir + "/engine.c", dir + "/shim.c", dir + "/robot_names.h"}, {dir}, o, built.library,
          "compiling the engine");
  return built;
}
}  // namespace carbot::driver
