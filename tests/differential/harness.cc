#include "harness.h"
#include "prepared.h"
#include "scratch_io.h"

#include "c_backend.h"
#include "c_driver.h"
#include "diagnostic_printer.h"
#include "file_system.h"
#include "interpreter/input_trace.h"
#include "interpreter/run_chart.h"
#include "pipeline/compilation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <sys/wait.h>

namespace gfec::diff {

namespace fs = std::filesystem;

namespace {

std::string printed(const Diagnostics &diag, const SourceManager &sources) {
  std::string out;
  for (const auto &d : diag.all()) out += render_text(d, sources);
  return out;
}

std::string engine_name(const Case &c) { return fmt::format("case_{}.c", c.id); }

std::string hooks_defines(const std::vector<Case *> &batch, const Config &config) {
  std::string d;
  if (config.hooks)
    for (const Case *c : batch) d += fmt::format(" -D{}_HOOKS", c->chart.name);
  return d;
}

/// The program's output cut at its `case <id>` lines.
std::map<int, std::string> sections(const std::string &out) {
  std::map<int, std::string> by_case;
  int current = -1;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("case ", 0) == 0) current = std::atoi(line.c_str() + 5);
    if (current >= 0) by_case[current] += line + "\n";
  }
  return by_case;
}

}  // namespace

const char *verdict_name(Verdict v) {
  switch (v) {
  case Verdict::Pass: return "pass";
  case Verdict::Invalid: return "invalid chart";
  case Verdict::Undefined: return "undefined behaviour";
  case Verdict::Mismatch: return "mismatch";
  case Verdict::CompileError: return "compile error";
  case Verdict::Lint: return "cppcheck finding";
  case Verdict::Crash: return "crash";
  case Verdict::TooBig: return "does not fit the target";
  case Verdict::NotRefused: return "compiled where double must be refused";
  }
  return "?";
}

std::vector<Config> default_configs(const std::vector<std::string> &compilers) {
  const std::string strict = "-Wall -Wextra -Wpedantic -Werror";
  std::vector<Config> configs;
  for (const auto &cc : compilers) {
    if (cc == "gcc") {
      configs.push_back({"gcc -O0 -std=c99 hooks", "gcc -std=c99 -O0 " + strict, true});
      configs.push_back({"gcc -O2 -std=c11", "gcc -std=c11 -O2 " + strict, false});
    } else if (cc == "clang") {
      configs.push_back({"clang -O0 -std=c11 hooks asan+ubsan",
                         "clang -std=c11 -O0 -g " + strict + " -fsanitize=address,undefined -fno-sanitize-recover=all",
                         true});
      configs.push_back({"clang -O2 -std=c99", "clang -std=c99 -O2 " + strict, false});
    } else {
      configs.push_back({cc + " -O2", cc + " -O2 " + strict, false});
    }
  }
  return configs;
}

// By blocks of six: main.cc makes case k an fsm when k % 3 == 2, and a team machine when
// k % 6 == 5, so every kind of chart comes in both forms.
bool scalable_form(const Case &c) { return (c.id / 6) % 2 == 1; }

Harness::Harness(std::string work, bool verbose) : work_(std::move(work)), verbose_(verbose) {
  fs::create_directories(work_);
}

Outcome Harness::prepare(Case &c) const {
  if (!c.given) {
    c.text = chart_text(c.chart);
    c.csv = trace_csv(c.chart, c.trace);
  }
  auto p = std::make_shared<Prepared>();
  MemoryFileSystem files;
  const std::string chart_file = c.given ? c.file : fmt::format("r{}.sfc", c.id);
  files.add(chart_file, c.text);
  p->c.front_end(chart_file, files);
  if (p->diag.has_errors()) {
    // Near the limits, a generated expression of constants may overflow: gfec refuses it at
    // compile time, as the interpreter refuses it at run time (docs/language.md): no test.
    const std::string why = printed(p->diag, p->sources);
    if (!c.given && why.find("[not-constant]") != std::string::npos && why.find("overflow") != std::string::npos)
      return {Verdict::Undefined, why, ""};
    return {Verdict::Invalid, why, ""};
  }
  // The compiled chart: the root (a hierarchical program also declares its sub-charts; a given
  // file's root is its last chart).
  model::ChartId root;
  for (model::ChartId i : p->model.charts.ids())
    if (c.given ? p->model.charts[i].in_main_file : p->model.charts[i].name == c.chart.name) root = i;
  if (c.given && root) c.chart.name = p->model.charts[root].name;
  if (!root || (!c.given && p->model.charts.size() != 1 + c.chart.pool.size()))
    return {Verdict::Invalid, "the model does not hold the generated charts\n" + printed(p->diag, p->sources), ""};

  Diagnostics trace_diag;
  FileId csv = p->sources.add(fmt::format("r{}.csv", c.id), c.csv);
  const int agents = std::max(1, c.chart.agents);
  p->inputs = std::make_unique<interp::InputTrace>(p->model, p->sources, csv, trace_diag, agents);
  interp::InputTrace &trace = *p->inputs;
  if (trace_diag.has_errors()) return {Verdict::Invalid, printed(trace_diag, p->sources), ""};
  if (c.given && c.trace.ticks == 0) c.trace.ticks = static_cast<int>(trace.rows());
  Diagnostics run_diag;
  const auto ticks = static_cast<std::uint64_t>(c.trace.ticks);
  interp::RunResult r;
  if (c.chart.agents > 0) {
    // A team machine: every agent's engine in lockstep under the reference exchange.
    std::vector<interp::InputTrace::Agent> inputs;
    for (int k = 0; k < agents; ++k) inputs.emplace_back(trace, k);
    std::vector<interp::Environment *> envs;
    for (auto &in : inputs) envs.push_back(&in);
    r = interp::run_team(p->model, root, envs, ticks, {}, run_diag);
  } else {
    r = interp::run_chart(p->model, root, trace, ticks, {}, run_diag);
  }
  if (!r.completed) return {Verdict::Undefined, printed(run_diag, p->sources), ""};
  p->expected_plain = r.log.render({false, false, false});
  p->expected_hooks = r.log.render({true, false, false});

  EmitOptions o;
  o.output_path = engine_name(c);
  o.source_name = chart_file;
  o.chart = root;
  // Random charts are small, so `auto` would always pick the readable form: half the cases take
  // the scalable one (an fsm's: a switch on the state), so both forms answer to the interpreter.
  o.engine = scalable_form(c) ? EngineForm::Scalable : EngineForm::Readable;
  p->root = root;
  p->emit = o;
  try {
    p->engine = emit_to_memory(*make_c_backend(), p->model, o);
  } catch (const std::exception &e) { return {Verdict::Crash, fmt::format("the C back end threw: {}", e.what()), ""}; }
  const model::Chart &compiled = p->model.charts[root];
  for (const auto &pl : compiled.places) p->places.push_back(pl.name.str());
  for (const auto &t : compiled.transitions) p->transitions.push_back(t.name.str());
  c.prepared = p;
  return {};
}

std::vector<Outcome> Harness::run_batch(const std::vector<Case *> &batch, const Config &config,
                                        const std::string &tag) const {
  std::vector<Outcome> outcomes(batch.size());
  if (batch.empty()) return outcomes;
  if (config.target) {  // a program per case: a small part holds one engine and its trace at a time
    for (std::size_t i = 0; i < batch.size(); ++i)
      outcomes[i] = run_on_target(*batch[i], config, fmt::format("{}t{}", tag, i));
    return outcomes;
  }
  const std::string dir = work_ + "/" + tag;
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<DriverCase> driver;
  std::string sources;
  for (Case *c : batch) {
    for (const auto &f : c->prepared->engine) write(dir + "/" + f.path, f.contents);
    sources += " " + dir + "/" + engine_name(*c);
    driver.push_back({c->id, &c->chart, &c->trace, base_name(c->prepared->engine.at(1).path), c->prepared->places,
                      c->prepared->transitions});
  }
  write(dir + "/driver.c", driver_source(driver));
  const std::string build = fmt::format("{}{} -I{} -o {}/prog{} {}/driver.c > {}/build.log 2>&1", config.command,
                                        hooks_defines(batch, config), dir, dir, sources, dir, dir);
  if (shell(build) != 0) {
    // Which engines do not compile on their own? The others are built again without them.
    std::vector<Case *> rest;
    std::vector<std::size_t> rest_at;
    for (std::size_t i = 0; i < batch.size(); ++i) {
      std::string log = fmt::format("{}/{}.log", dir, batch[i]->id);
      std::string one = fmt::format("{}{} -I{} -c -o /dev/null {}/{} > {} 2>&1", config.command,
                                    hooks_defines({batch[i]}, config), dir, dir, engine_name(*batch[i]), log);
      if (shell(one) != 0) {
        outcomes[i] = {Verdict::CompileError, read(log), ""};
      } else {
        rest.push_back(batch[i]);
        rest_at.push_back(i);
      }
    }
    if (rest.size() == batch.size()) {  // every engine compiles: the driver or the headers do not
      for (auto &o : outcomes) o = {Verdict::CompileError, read(dir + "/build.log"), ""};
      return outcomes;
    }
    auto again = run_batch(rest, config, tag + "b");
    for (std::size_t k = 0; k < rest.size(); ++k) outcomes[rest_at[k]] = again[k];
    return outcomes;
  }
  int status = shell(fmt::format("cd {} && timeout 60 ./prog > out.txt 2> err.txt", dir));
  auto by_case = sections(read(dir + "/out.txt"));
  std::vector<Case *> unrun;
  std::vector<std::size_t> unrun_at;
  bool crashed_seen = false;
  for (std::size_t i = 0; i < batch.size(); ++i) {
    const Case &c = *batch[i];
    std::string expected =
        fmt::format("case {}\n", c.id) + (config.hooks ? c.prepared->expected_hooks : c.prepared->expected_plain);
    auto it = by_case.find(c.id);
    if (it == by_case.end()) {
      if (status != 0 && crashed_seen) {  // never reached: the program died before it
        unrun.push_back(batch[i]);
        unrun_at.push_back(i);
        continue;
      }
      outcomes[i] = {Verdict::Crash, fmt::format("exit status {}\n{}", status, read(dir + "/err.txt")), expected};
      crashed_seen = true;
      continue;
    }
    if (it->second == expected) continue;
    // The last case printed is the one that died, if the program died.
    bool last = std::next(it) == by_case.end();
    if (status != 0 && last) {
      outcomes[i] = {Verdict::Crash, it->second + fmt::format("[exit status {}]\n{}", status, read(dir + "/err.txt")),
                     expected};
      crashed_seen = true;
    } else {
      outcomes[i] = {Verdict::Mismatch, it->second, expected};
    }
  }
  if (!unrun.empty()) {
    auto again = run_batch(unrun, config, tag + "r");
    for (std::size_t k = 0; k < unrun.size(); ++k) outcomes[unrun_at[k]] = again[k];
  }
  if (!verbose_) fs::remove_all(dir);
  return outcomes;
}

std::vector<Outcome> Harness::lint_batch(const std::vector<Case *> &batch, const std::string &tag) const {
  std::vector<Outcome> outcomes(batch.size());
  const std::string dir = work_ + "/" + tag;
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string files;
  for (Case *c : batch) {
    for (const auto &f : c->prepared->engine) write(dir + "/" + f.path, f.contents);
    files += " " + engine_name(*c);
  }
  // One finding a line, starting with the file it is in.
  int status = shell(fmt::format("cd {} && cppcheck --enable=warning,style,performance,portability --quiet "
                                 "--std=c99 --template='{{file}}:{{line}}: {{severity}}: {{message}} [{{id}}]'{} "
                                 "> lint.txt 2>&1",
                                 dir, files));
  std::string found = read(dir + "/lint.txt");
  for (std::size_t i = 0; i < batch.size(); ++i) {
    std::string name = engine_name(*batch[i]), mine;
    std::istringstream in(found);
    for (std::string line; std::getline(in, line);)
      if (line.rfind(name + ":", 0) == 0 || line.rfind(fmt::format("case_{}.h:", batch[i]->id), 0) == 0)
        mine += line + "\n";
    if (!mine.empty()) outcomes[i] = {Verdict::Lint, mine, ""};
  }
  if (status != 0 && found.empty())
    for (auto &o : outcomes) o = {Verdict::Lint, fmt::format("cppcheck failed (exit status {})", status), ""};
  if (!verbose_) fs::remove_all(dir);
  return outcomes;
}

Outcome Harness::run_one(Case &c, const Config &config, const std::string &tag) const {
  return run_batch({&c}, config, tag).at(0);
}

void Harness::save(const Case &c, const Outcome &o, const Config &config, const std::string &dir) const {
  fs::create_directories(dir);
  write(dir + fmt::format("/r{}.sfc", c.id), c.text);
  write(dir + "/trace.csv", c.csv);
  write(dir + "/expected.log", o.expected);
  write(dir + "/actual.log", o.detail);
  if (c.prepared && config.target) {
    save_target_program(c, config, dir);
    return;
  }
  if (c.prepared) {
    for (const auto &f : c.prepared->engine) write(dir + "/" + f.path, f.contents);
    DriverCase d{c.id,
                 &c.chart,
                 &c.trace,
                 base_name(c.prepared->engine.at(1).path),
                 c.prepared->places,
                 c.prepared->transitions};
    write(dir + "/driver.c", driver_source({d}));
  }
  write(dir + "/README", fmt::format("verdict: {}\nbuild: {}{} -I. -o prog {} driver.c && ./prog\n"
                                     "reference: gfec run r{}.sfc --inputs trace.csv --observable{}{}\n",
                                     verdict_name(o.verdict), config.command,
                                     config.hooks ? fmt::format(" -D{}_HOOKS", c.chart.name) : "", engine_name(c), c.id,
                                     config.hooks ? " --hooks" : "",
                                     c.chart.agents > 0 ? fmt::format(" --agents {}", c.chart.agents) : ""));
}

}  // namespace gfec::diff
