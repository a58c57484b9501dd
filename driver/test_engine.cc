#include "test_engine.h"

#include "backend_registry.h"
#include "c_context.h"
#include "interpreter/value.h"
#include "roots.h"
#include "scenario/snapshot.h"

#include <fmt/format.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string_view>
#include <sys/wait.h>

namespace gfec {

namespace {

namespace fs = std::filesystem;
using model::Type;

/// The value a `set` line stored for the agent that runs, as the function's type; 0 (false)
/// until set. harness.c keeps the values: glue.c asks it.
std::string result_of(Type t, model::FunctionId f) {
  switch (t) {
  case Type::Bool: return fmt::format("@H@bool(@H@agent, {}) != 0", f.index());
  case Type::Int: return fmt::format("@H@int(@H@agent, {})", f.index());
  case Type::Float: return fmt::format("@H@float(@H@agent, {})", f.index());
  default: return fmt::format("@H@double(@H@agent, {})", f.index());
  }
}

void function(std::string &s, const model::Function &f, model::FunctionId id) {
  std::string params, format, args;
  for (std::size_t i = 0; i < f.params.size(); ++i) {
    params += fmt::format("{}{} a{}", i ? ", " : "", model::type_name(f.params[i].type), i);
    auto [fmt_, arg] = interp::c_printf_of(f.params[i].type, fmt::format("a{}", i));
    format += (i ? ", " : "") + fmt_;
    args += ", " + arg;
  }
  s += fmt::format("{} {}({})\n{{\n", model::type_name(f.result), f.name, params.empty() ? "void" : params);
  s += fmt::format("    (void)@H@printf(\"call {}({})\\n\"{});\n", f.name, format, args);
  if (f.result != Type::Void) s += fmt::format("    return {};\n", result_of(f.result, id));
  s += "}\n\n";
}

std::string quote(const std::string &path) {
  std::string out = "'";
  for (char c : path) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string read_file(const fs::path &p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool write_file(const fs::path &p, const std::string &text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
  return static_cast<bool>(out);
}

/// The first lines of a compiler's or program's output, for a message.
std::string head(const std::string &text, int lines = 8) {
  std::string out;
  std::istringstream in(text);
  std::string line;
  for (int i = 0; i < lines && std::getline(in, line); ++i) out += (out.empty() ? "" : "\n") + line;
  return out;
}

/// How a program std::system ran through the shell ended. The shell reports a child killed by
/// signal N as exit status 128 + N; both are named as the signal (SIGFPE: an integer division
/// by zero in the engine).
std::string exit_status(int status) {
  if (status == -1) return "could not be started";
  int signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  if (WIFEXITED(status) && WEXITSTATUS(status) > 128 && WEXITSTATUS(status) < 128 + 64)
    signal = WEXITSTATUS(status) - 128;
  if (signal != 0) return fmt::format("was killed by signal {} ({})", signal, strsignal(signal));
  return fmt::format("exited with status {}", WIFEXITED(status) ? WEXITSTATUS(status) : status);
}

/// One harness output line `call F(a, b)` as a Call.
scenario::Call parse_call(const std::string &text, const model::Model &m) {
  scenario::Call c;
  c.text = text;
  std::size_t open = text.find('(');
  std::string name = text.substr(0, open);
  for (model::FunctionId i : m.functions.ids())
    if (m.functions[i].name == name) c.function = i;
  if (open == std::string::npos || text.size() < open + 2) return c;
  std::string list = text.substr(open + 1, text.size() - open - 2);
  std::size_t from = 0;
  while (!list.empty() && from <= list.size()) {
    std::size_t comma = list.find(", ", from);
    c.args.push_back(list.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
    if (comma == std::string::npos) break;
    from = comma + 2;
  }
  return c;
}

/// The records in a harness's output, after _init and after every tick (one per agent), into
/// `run`: read line by line, so a long test is never held whole.
void parse_output(std::istream &in, const model::Model &m, const scenario::Test &test, scenario::KeptTicks keep,
                  scenario::Run &run) {
  const model::Chart &c = m.charts[test.chart];
  const std::vector<scenario::Instance> instances = scenario::instances_of(m, test.chart);
  const std::size_t n = static_cast<std::size_t>(std::max(test.agents, 1));
  std::vector<scenario::Snapshot> agents;
  std::size_t agent = 0;  // whose lines these are
  auto reset = [&] {
    agents.assign(n, scenario::Snapshot{});
    for (std::size_t a = 0; a < n; ++a) {
      scenario::Snapshot &cur = agents[a];
      cur.tick = run.recorded();
      cur.agent = static_cast<int>(a);
      cur.activation.assign(c.places.size(), 0);
      cur.timers.assign(c.places.size(), 0);
      for (const auto &v : c.vars) cur.vars.push_back(interp::Value::zero(v.type));
      for (const auto &in : instances) cur.instances.emplace_back(m.charts[in.chart].places.size(), 0u);
    }
    agent = 0;
  };
  reset();
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string word;
    words >> word;
    scenario::Snapshot &cur = agents[agent];
    if (word == "tick") {
      reset();
    } else if (word == "agent") {
      std::size_t a = 0;
      words >> a;
      if (a < n) agent = a;
    } else if (word == "call") {
      cur.calls.push_back(parse_call(line.substr(5), m));
    } else if (word == "av") {
      for (model::PlaceId p : c.places.ids()) words >> cur.activation[p];
    } else if (word == "inst") {
      std::size_t k = 0;
      words >> k;
      if (k < cur.instances.size())
        for (unsigned &v : cur.instances[k]) words >> v;
    } else if (word == "state") {
      long state = -1;  // the engine's number, -1 for none
      words >> state >> cur.status;
      cur.state = state >= 0 ? model::PlaceId(static_cast<std::size_t>(state)) : model::PlaceId::none();
    } else if (word == "var") {
      std::size_t i = 0;
      std::string v;
      words >> i >> v;
      if (i < c.vars.size()) cur.vars[model::VarId(i)] = scenario::parse_value(v, c.vars[i].type);
    } else if (word == "timer") {
      std::size_t p = 0;
      std::uint32_t t = 0;
      words >> p >> t;
      if (p < c.places.size()) cur.timers[model::PlaceId(p)] = t;
    } else if (word == "end") {
      scenario::settle_tick(agents, instances, c);
      run.record(std::move(agents), keep, m, test.chart);
      reset();
    }
  }
}

/// The interface functions the engine's header declares: those of the chart and of every chart
/// its places run (sub-charts), in model order.
std::vector<model::FunctionId> engine_functions(const model::Model &model, model::ChartId root) {
  const IdMap<model::ChartId, bool> tree = charts_in_tree(model, root);
  IdMap<model::FunctionId, bool> used(model.functions.size());
  for (model::ChartId c : tree.ids())
    if (tree[c])
      for (model::FunctionId f : model.charts[c].functions) used[f] = true;
  std::vector<model::FunctionId> out;
  for (model::FunctionId f : used.ids())
    if (used[f]) out.push_back(f);
  return out;
}

}  // namespace

const std::vector<std::string> &harness_library_names() {
  // What harness.c calls of the C library (and main): an interface function of the same name
  // would stand in for it when the harness is linked.
  static const std::vector<std::string> names = {"main",   "vprintf", "scanf",  "strcmp", "strcpy",
                                                 "strtol", "strtof",  "strtod", "fflush"};
  return names;
}

/// What glue.c and harness.c call of each other, declared in both (neither includes the other's
/// headers: that is the point of two files).
constexpr std::string_view kHarnessCalls = "int @H@printf(const char *format, ...);\n"
                                           "int @H@bool(int agent, int function);\n"
                                           "int @H@int(int agent, int function);\n"
                                           "float @H@float(int agent, int function);\n"
                                           "double @H@double(int agent, int function);\n"
                                           "void @H@init(void);\n"
                                           "void @H@tick(void);\n\n";

HarnessSources harness_source(const model::Model &model, model::ChartId chart, const EmitOptions &options,
                              const std::string &header, int agents) {
  // The engine's field and function names as the C back end chose them for this chart.
  const auto fields = c_backend::make_context(model, model.charts.at(chart), options);
  const model::Chart &c = model.charts[chart];
  const std::string &t = c.name;
  const bool team = c.team > 0;
  const int n = std::max(agents, 1);
  const std::size_t functions = model.functions.size() + 1;

  // glue.c: the engine's side. It includes the engine's header, which declares the interface
  // functions, and no header of the C library (an interface function may be called `remove`).
  std::string g =
      fmt::format("/* Generated by gfec test: the interface of {0} as a test sets it, and the engines of the\n"
                  "   test run by the steps harness.c reads (docs/testing-charts.md). */\n"
                  "#include \"{1}\"\n\n"
                  "/* harness.c: output, and the values `set` gave each agent's sensing functions. */\n"
                  "{3}"
                  "/* The engines, one per agent, and the agent whose engine runs: its calls read its values. */\n"
                  "static {0} @H@m[{2}];\n"
                  "static int @H@agent;\n\n",
                  t, header, n, kHarnessCalls);
  for (model::FunctionId f : engine_functions(model, chart)) function(g, model.functions[f], f);
  g += fmt::format("static void @H@dump(const {} *m)\n{{\n    int p;\n    (void)@H@printf(\"av\");\n", t);
  g += fmt::format("    for (p = 0; p < {0}_PLACE_COUNT; ++p) {{\n"
                   "        (void)@H@printf(\" %u\", {0}_activation(m, p));\n    }}\n"
                   "    (void)@H@printf(\"\\n\");\n",
                   t);
  // Each sub-chart instance's activation, numbered as X_instance numbers them.
  const std::vector<scenario::Instance> instances = scenario::instances_of(model, chart);
  for (std::size_t k = 0; k < instances.size(); ++k)
    g += fmt::format("    (void)@H@printf(\"inst {0}\");\n    for (p = 0; p < {1}; ++p) {{\n"
                     "        (void)@H@printf(\" %u\", {2}(m, {0}, p));\n    }}\n"
                     "    (void)@H@printf(\"\\n\");\n",
                     k, model.charts[instances[k].chart].places.size(), fields->instance_activation_fn);
  if (c.kind == model::Chart::Kind::Fsm)
    g += fmt::format("    (void)@H@printf(\"state %d %d\\n\", (int){0}_state(m), {0}_status(m));\n", t);
  for (model::VarId i : c.vars.ids()) {
    auto [f, a] = interp::c_printf_of(c.vars[i].type, "m->" + fields->var_field[i]);
    g += fmt::format("    (void)@H@printf(\"var {} {}\\n\", {});\n", i.index(), f, a);
  }
  for (model::PlaceId p : c.places.ids())
    if (c.places[p].timed)
      g += fmt::format("    (void)@H@printf(\"timer {} %lu\\n\", (unsigned long)m->{});\n", p.index(),
                       fields->timer_field[p]);
  g += "}\n\n";
  // Every agent's state, then the end of the record.
  g += fmt::format("static void @H@dump_all(void)\n{{\n    int a;\n    for (a = 0; a < {}; ++a) {{\n", n);
  if (team) g += "        (void)@H@printf(\"agent %d\\n\", a);\n";
  g += "        @H@dump(&@H@m[a]);\n    }\n    (void)@H@printf(\"end\\n\");\n}\n\n";
  g += fmt::format("void @H@init(void)\n{{\n    int a;\n    for (a = 0; a < {}; ++a) {{\n"
                   "        {}_init(&@H@m[a]);\n",
                   n, t);
  if (team) g += fmt::format("        {}(&@H@m[a], a);\n", fields->set_agent_fn);
  g += "    }\n    @H@dump_all();\n}\n\n";
  g += fmt::format("void @H@tick(void)\n{{\n    int a;\n    (void)@H@printf(\"tick\\n\");\n"
                   "    for (a = 0; a < {}; ++a) {{\n",
                   n);
  if (team) g += "        (void)@H@printf(\"agent %d\\n\", a);\n";
  g += fmt::format("        @H@agent = a;\n        {}_run(&@H@m[a]);\n    }}\n", t);
  if (team)
    g += fmt::format("    /* The reference exchange (docs/language.md \"Teams\"): every agent's state to every "
                     "other. */\n"
                     "    for (a = 0; a < {0}; ++a) {{\n        int b;\n"
                     "        for (b = 0; b < {0}; ++b) {{\n"
                     "            {1}(&@H@m[b], a, (int){2}_state(&@H@m[a]));\n        }}\n    }}\n",
                     n, fields->report_fn, t);
  g += "    @H@dump_all();\n}\n";

  // harness.c: the C library's side, which never sees the engine's header.
  std::string h = fmt::format(
      "/* Generated by gfec test: reads the steps of a test on stdin and prints what the engines did\n"
      "   (docs/testing-charts.md). The engines and the interface are in glue.c. */\n"
      "#include <stdarg.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n\n"
      "{2}"
      "/* By agent and function (its index in the model): what `set` gave it; \"\" is false/0. */\n"
      "static char @H@value[{0}][{1}][64];\n\n"
      "int @H@printf(const char *format, ...)\n{{\n    int n;\n    va_list args;\n"
      "    va_start(args, format);\n    n = vprintf(format, args);\n    va_end(args);\n    return n;\n}}\n\n"
      "int @H@bool(int agent, int function)\n{{\n"
      "    return strcmp(@H@value[agent][function], \"true\") == 0;\n}}\n\n"
      "int @H@int(int agent, int function)\n{{\n"
      "    return (int)strtol(@H@value[agent][function], NULL, 10);\n}}\n\n"
      "float @H@float(int agent, int function)\n{{\n"
      "    return strtof(@H@value[agent][function], NULL);\n}}\n\n"
      "double @H@double(int agent, int function)\n{{\n"
      "    return strtod(@H@value[agent][function], NULL);\n}}\n\n",
      n, functions, kHarnessCalls);
  // Each record is flushed as it is complete: an engine that dies of a signal in tick n leaves
  // the records before it, so that the message can name the tick.
  h += fmt::format("int main(void)\n{{\n    char word[16];\n    @H@init();\n    (void)fflush(stdout);\n"
                   "    while (scanf(\"%15s\", word) == 1) {{\n"
                   "        if (strcmp(word, \"tick\") == 0) {{\n            @H@tick();\n"
                   "            (void)fflush(stdout);\n"
                   "        }} else if (strcmp(word, \"set\") == 0) {{\n"
                   "            int who;\n            int f;\n            int a;\n            char v[64];\n"
                   "            if (scanf(\"%d %d %63s\", &who, &f, v) != 3 || who < -1 || who >= {0} || f < 0 || "
                   "f >= {1}) {{\n"
                   "                return 2;\n            }}\n"
                   "            for (a = 0; a < {0}; ++a) {{\n"
                   "                if (who < 0 || who == a) {{\n"
                   "                    strcpy(@H@value[a][f], v);\n                }}\n            }}\n"
                   "        }}\n    }}\n    return 0;\n}}\n",
                   n, functions);
  // The harness's own names: a prefix that begins no name of the interface.
  std::string prefix = "gfec_h_";
  for (bool clash = true; clash;) {
    clash = false;
    for (model::FunctionId f : engine_functions(model, chart))
      clash = clash || model.functions[f].name.rfind(prefix, 0) == 0;
    if (clash) prefix.insert(prefix.size() - 1, "_");
  }
  for (std::string *text : {&g, &h})
    for (std::size_t at = text->find("@H@"); at != std::string::npos; at = text->find("@H@", at))
      text->replace(at, 3, prefix);
  return {std::move(g), std::move(h)};
}

EngineBuilds::EngineBuilds() {
  const char *tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/gfec-test-XXXXXX";
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  if (mkdtemp(buf.data())) folder_ = buf.data();
}

EngineBuilds::~EngineBuilds() {
  if (folder_.empty()) return;
  std::error_code ec;
  fs::remove_all(folder_, ec);
}

EngineBuilds::Build EngineBuilds::get(const model::Model &model, model::ChartId chart, const std::string &source_name,
                                      int agents) {
  auto backend = make_backend("c");
  if (!backend) return {"", "gfec was built without its C back end"};
  EmitOptions o;
  o.output_path = "engine.c";
  o.source_name = source_name;
  o.chart = chart;
  std::vector<OutputFile> files;
  try {
    files = emit_to_memory(*backend, model, o);
  } catch (const std::exception &e) { return {"", e.what()}; }
  for (model::FunctionId f : engine_functions(model, chart))
    for (const std::string &name : harness_library_names())
      if (model.functions[f].name == name)
        return {"", fmt::format("the test harness cannot stand in for interface function '{}': it calls the C "
                                "library's '{}' itself (run this chart's tests with --reference-only)",
                                name, name)};
  HarnessSources harness = harness_source(model, chart, o, "engine.h", agents);
  const char *cc_env = std::getenv("CC");
  std::string cc = cc_env && *cc_env ? cc_env : "cc";
  std::string all = cc + '\0' + harness.glue + '\0' + harness.main;
  for (const auto &f : files) all += '\0' + f.path + '\0' + f.contents;
  std::size_t hash = std::hash<std::string>{}(all);

  std::lock_guard<std::mutex> lock(mutex_);
  if (auto it = builds_.find(hash); it != builds_.end()) return it->second;
  Build b;
  fs::path dir = fs::path(folder_) / fmt::format("{:016x}", hash);
  std::error_code ec;
  fs::create_directories(dir, ec);
  bool written = !ec && write_file(dir / "glue.c", harness.glue) && write_file(dir / "harness.c", harness.main);
  for (const auto &f : files) written = written && write_file(dir / f.path, f.contents);
  if (!written) {
    b.error = fmt::format("cannot write the engine into '{}'", dir.string());
  } else {
    std::string log = (dir / "build.log").string();
    std::string cmd = fmt::format("{} -std=c99 -o {} {} {} {} > {} 2>&1", cc, quote((dir / "harness").string()),
                                  quote((dir / "engine.c").string()), quote((dir / "glue.c").string()),
                                  quote((dir / "harness.c").string()), quote(log));
    int status = std::system(cmd.c_str());
    if (status == 0) b.program = (dir / "harness").string();
    else
      b.error = fmt::format("the C compiler '{}' {} on the generated engine:\n{}", cc, exit_status(status),
                            head(read_file(log)));
  }
  builds_[hash] = b;
  return b;
}

scenario::Run EngineBuilds::run(const Build &build, const model::Model &model, const scenario::Test &test, int id,
                                scenario::KeptTicks keep) {
  scenario::Run run;
  std::string steps;
  for (const scenario::Step &s : test.steps) {
    if (s.kind == scenario::Step::Kind::Set)
      steps += fmt::format("set {} {} {}\n", s.agent, s.function.index(), s.value);
    if (s.kind == scenario::Step::Kind::Tick)
      for (unsigned long i = 0; i < s.count; ++i) steps += "tick\n";
  }
  fs::path in = fs::path(folder_) / fmt::format("steps-{}.txt", id);
  fs::path out = fs::path(folder_) / fmt::format("out-{}.txt", id);
  if (!write_file(in, steps)) {
    run.error = fmt::format("cannot write '{}'", in.string());
    return run;
  }
  std::string cmd = fmt::format("{} < {} > {} 2>&1", quote(build.program), quote(in.string()), quote(out.string()));
  int status = std::system(cmd.c_str());
  {
    std::ifstream text(out, std::ios::binary);
    parse_output(text, model, test, keep, run);
  }
  std::uint64_t expected = scenario::total_ticks(test) + 1;
  // One record after _init, then one per tick: with n records, tick n did not finish.
  if (status != 0 || run.recorded() != expected) {
    const std::string how = status != 0 ? exit_status(status) : "stopped";
    run.error = run.recorded() == 0 ? fmt::format("the C engine's harness {} before its first tick", how)
                                    : fmt::format("the C engine's harness {} in tick {}", how, run.recorded());
  }
  std::error_code ec;
  fs::remove(in, ec);
  fs::remove(out, ec);
  return run;
}

}  // namespace gfec
