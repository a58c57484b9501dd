// A case on an emulated target (tests/targets/targets.txt): the program is the one harness
// writer's (backends/c/c_harness.h) with the trace compiled in as a table and the log written a
// character at a time through the target's harness_putc, so the log is the interpreter's
// observable log byte for byte, whatever the target's C library can print.
#include "harness.h"
#include "prepared.h"
#include "scratch_io.h"

#include "c_harness.h"
#include "file_system.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace gfec::diff {

namespace fs = std::filesystem;

namespace {

/// Stack and the C library's own data: what RAM needs besides .data and .bss.
constexpr long kStackReserve = 256;

/// Whether the program declares a double anywhere (an interface function, a constant, a var):
/// where `double` is not binary64 its engine must refuse to compile.
bool declares_double(const model::Model &m) {
  for (const auto &f : m.functions) {
    if (f.result == model::Type::Double) return true;
    for (const auto &p : f.params)
      if (p.type == model::Type::Double) return true;
  }
  for (const auto &k : m.consts)
    if (k.type == model::Type::Double) return true;
  for (const auto &c : m.charts)
    for (const auto &v : c.vars)
      if (v.type == model::Type::Double) return true;
  return false;
}

/// The program's two generated files: the engine's header name and glue.c.
c_backend::HarnessSources program(const Case &c) {
  const Prepared &p = *c.prepared;
  c_backend::HarnessOptions o;
  o.inputs = c_backend::HarnessInputs::Table;
  o.log = c_backend::HarnessLog::Observable;
  o.output = c_backend::HarnessOutput::Putc;
  o.header = base_name(p.engine.at(1).path);
  o.agents = std::max(1, c.chart.agents);
  o.table.ticks = static_cast<std::uint64_t>(c.trace.ticks);
  o.table.value = [&p](model::FunctionId f, std::uint64_t tick, int agent) { return p.inputs->value(f, tick, agent); };
  return c_backend::write_harness(p.model, p.root, p.emit, o);
}

std::string engine_source(const Case &c) { return base_name(c.prepared->engine.at(0).path); }

std::string build_command(const Case &c, const Config &config, const std::string &dir) {
  const targets::Target &t = *config.target;
  return fmt::format("{}{} -I{} -o {}/prog.elf {}/glue.c {}/{} {}/{} {}", config.command,
                     config.hooks ? fmt::format(" -D{}_HOOKS", c.chart.name) : "", dir, dir, dir, dir, engine_source(c),
                     config.target_folder, t.support, t.link);
}

std::string run_command(const Config &config, const std::string &elf) {
  return targets::expand(config.target->run, {{"elf", elf}, {"bin", config.bin}});
}

}  // namespace

Config target_config(const targets::Target &t, const std::string &folder, const std::string &bin) {
  Config c;
  c.name = fmt::format("{}: {} {}", t.name, t.cc, t.flags);
  c.command = fmt::format("{} {} -Wall -Wextra -Werror", t.cc, t.flags);
  c.target = &t;
  c.target_folder = folder;
  c.bin = bin;
  return c;
}

Outcome Harness::run_on_target(Case &c, const Config &config, const std::string &tag) const {
  const Prepared &p = *c.prepared;
  const targets::Target &t = *config.target;
  const std::string dir = work_ + "/" + tag;
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const auto &f : p.engine) write(dir + "/" + base_name(f.path), f.contents);
  try {
    write(dir + "/glue.c", program(c).glue);
  } catch (const std::exception &e) {
    return {Verdict::Crash, fmt::format("the harness writer threw: {}", e.what()), ""};
  }
  const std::string expected = config.hooks ? p.expected_hooks : p.expected_plain;
  const bool must_refuse = t.double_bits < 64 && declares_double(p.model);
  auto done = [&](Outcome o) {
    if (!verbose_ && o.verdict == Verdict::Pass) fs::remove_all(dir);
    return o;
  };

  if (shell(build_command(c, config, dir) + fmt::format(" > {}/build.log 2>&1", dir)) != 0) {
    const std::string log = read(dir + "/build.log");
    // Where double is binary32 an engine may refuse what it cannot compute as the interpreter
    // does (a chart declaring a double must be refused): the refusal names the type.
    if (t.double_bits < 64 && log.find("#error") != std::string::npos && log.find("double") != std::string::npos) {
      Outcome o;
      o.refused = true;
      return done(o);
    }
    if (log.find("overflowed by") != std::string::npos || log.find("will not fit in region") != std::string::npos)
      return done({Verdict::TooBig, log, expected});
    return done({Verdict::CompileError, log, expected});
  }
  if (must_refuse)
    return done({Verdict::NotRefused,
                 fmt::format("{}'s double has {} bits, and the engine of a chart declaring a double compiled\n", t.name,
                             t.double_bits),
                 expected});
  // Berkeley size: text (code and what stays in flash), data (copied from flash to RAM), bss.
  long text = 0, data = 0, bss = 0;
  {
    const std::string sizes = dir + "/size.txt";
    shell(fmt::format("{} {}/prog.elf > {} 2>&1", t.size_tool(), dir, sizes));
    std::istringstream in(read(sizes));
    std::string header;
    std::getline(in, header);
    in >> text >> data >> bss;
  }
  if (text + data > t.flash || data + bss + kStackReserve > t.ram)
    return done({Verdict::TooBig,
                 fmt::format("flash {} B of {}, RAM {} B (+{} B of stack) of {}\n", text + data, t.flash, data + bss,
                             kStackReserve, t.ram),
                 expected});
  const int status =
      shell(fmt::format("cd {} && timeout 120 {} > out.txt 2> err.txt", dir, run_command(config, dir + "/prog.elf")));
  const std::string out = read(dir + "/out.txt");
  if (status != 0)
    return done({Verdict::Crash, out + fmt::format("[exit status {}]\n{}", status, read(dir + "/err.txt")), expected});
  if (out != expected) return done({Verdict::Mismatch, out, expected});
  return done({});
}

void save_target_program(const Case &c, const Config &config, const std::string &dir) {
  for (const auto &f : c.prepared->engine) write(dir + "/" + base_name(f.path), f.contents);
  write(dir + "/glue.c", program(c).glue);
  write(dir + "/README",
        fmt::format("target: {}\nbuild: {}\nrun: {}\nreference: gfec run {} --inputs trace.csv --observable\n",
                    config.target->name, build_command(c, config, "."), run_command(config, "prog.elf"),
                    c.given ? c.file : fmt::format("r{}.sfc", c.id)));
}

}  // namespace gfec::diff
