#include "test_engine.h"

#include "backend_registry.h"
#include "c_harness.h"
#include "child_process.h"
#include "interpreter/value.h"
#include "scenario/snapshot.h"

#include <fmt/format.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <cerrno>
#include <fcntl.h>
#include <unistd.h>

namespace gfec {

namespace {

namespace fs = std::filesystem;

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

/// A pipe's read end as an input stream: the harness's records are parsed as they arrive, so
/// its output is never stored (docs/testing-charts.md).
class PipeReader : public std::streambuf {
public:
  explicit PipeReader(int fd) : fd_(fd) {}

protected:
  int_type underflow() override {
    ssize_t n;
    do n = ::read(fd_, buffer_, sizeof buffer_);
    while (n < 0 && errno == EINTR);
    if (n <= 0) return traits_type::eof();
    setg(buffer_, buffer_, buffer_ + n);
    return traits_type::to_int_type(buffer_[0]);
  }

private:
  int fd_;
  char buffer_[65536];
};

/// A compiler command split at blanks, as make splits $CC ("ccache gcc").
std::vector<std::string> words_of(const std::string &command) {
  std::istringstream words(command);
  std::vector<std::string> out;
  for (std::string w; words >> w;) out.push_back(w);
  if (out.empty()) out.push_back("cc");
  return out;
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

/// An input's value as the harness reads it (strtoll, strtoull, strtof, strtod): a bool 1 or 0,
/// a time its milliseconds, a number as gfec run prints it.
std::string harness_number(model::Type t, const std::string &value) {
  const interp::Value v = scenario::parse_value(value, t);
  if (t == model::Type::Bool) return v.b ? "1" : "0";
  if (t == model::Type::Time) return constant::decimal(v);
  return interp::format_value(v);
}

/// The program `gfec test` runs: the steps on stdin, the records on stdout (test_engine.h).
c_backend::HarnessOptions harness_options(int agents) {
  c_backend::HarnessOptions o;
  o.inputs = c_backend::HarnessInputs::Steps;
  o.log = c_backend::HarnessLog::Records;
  o.header = "engine.h";
  o.agents = std::max(agents, 1);
  return o;
}

}  // namespace

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

bool EngineBuilds::choose_compiler(std::vector<std::string> &notes) {
  std::vector<std::pair<std::string, std::string>> candidates;  // (compiler, where it came from)
  for (const char *var : {"HOST_CC", "CC"})
    if (const char *v = std::getenv(var); v && *v) candidates.emplace_back(v, fmt::format("${}", var));
  candidates.emplace_back("cc", "the default");
  const fs::path probe = fs::path(folder_) / "probe";
  if (!write_file(probe.string() + ".c", "int main(void) { return 0; }\n")) return false;
  std::vector<std::string> tried;
  for (const auto &[cc, from] : candidates) {
    if (std::find_if(tried.begin(), tried.end(), [&](const std::string &t) { return t == cc; }) != tried.end())
      continue;
    tried.push_back(cc);
    const std::string log = probe.string() + ".log";
    child_process::Spawn build;
    build.argv = words_of(cc);
    for (const std::string &part : {std::string("-std=c99"), std::string("-o"), probe.string(), probe.string() + ".c"})
      build.argv.push_back(part);
    build.stdout_path = log;
    build.stderr_path = "&1";
    const child_process::Result built = child_process::run(build);
    if (!built.ok()) {
      std::string out = head(read_file(log));
      notes.push_back(fmt::format("'{}' ({}) {}{}", cc, from,
                                  built.how == child_process::Result::How::NotStarted
                                      ? "could not be started (" + built.error + ")"
                                      : child_process::describe(built),
                                  out.empty() ? "" : ":\n" + out));
      continue;
    }
    child_process::Spawn run;
    run.argv = {probe.string()};
    run.stdout_path = "/dev/null";
    run.stderr_path = "&1";
    if (!child_process::run(run).ok()) {
      notes.push_back(fmt::format("'{}' ({}) builds programs this machine does not run (a cross compiler?)", cc, from));
      continue;
    }
    cc_ = cc;
    return true;
  }
  return false;
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
  const c_backend::HarnessOptions harness_o = harness_options(agents);
  for (model::FunctionId f : c_backend::engine_functions(model, chart))
    for (const std::string &name : c_backend::harness_library_names(harness_o))
      if (model.functions[f].name == name)
        return {"", fmt::format("the test harness cannot stand in for interface function '{}': it calls the C "
                                "library's '{}' itself (run this chart's tests with --reference-only)",
                                name, name)};
  const c_backend::HarnessSources harness = c_backend::write_harness(model, chart, o, harness_o);
  const std::string &cc = cc_;
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
    // A child in its own process group, stopped with what it started if gfec test is stopped
    // (support/child_process.h).
    child_process::Spawn compile;
    compile.argv = words_of(cc);
    for (const char *part : {"-std=c99", "-o"}) compile.argv.push_back(part);
    for (const char *part : {"harness", "engine.c", "glue.c", "harness.c"})
      compile.argv.push_back((dir / part).string());
    compile.stdout_path = (dir / "build.log").string();
    compile.stderr_path = "&1";
    const child_process::Result r = child_process::run(compile);
    if (r.ok()) b.program = (dir / "harness").string();
    else if (r.how == child_process::Result::How::NotStarted)
      b.error = fmt::format("the C compiler '{}' could not be started ({})", cc, r.error);
    else
      b.error = fmt::format("the C compiler '{}' {} on the generated engine:\n{}", cc, child_process::describe(r),
                            head(read_file(compile.stdout_path)));
  }
  builds_[hash] = b;
  return b;
}

scenario::Run EngineBuilds::run(const Build &build, const model::Model &model, const scenario::Test &test, int id,
                                scenario::KeptTicks keep) {
  scenario::Run run;
  std::string steps;
  for (const scenario::Step &s : test.steps) {
    if (s.kind == scenario::Step::Kind::Set && s.input)
      steps += fmt::format("input {} {} {}\n", s.agent, s.input.index(),
                           harness_number(model.charts[test.chart].vars[s.input].type, s.value));
    else if (s.kind == scenario::Step::Kind::Set)
      steps += fmt::format("set {} {} {}\n", s.agent, s.function.index(), s.value);
    if (s.kind == scenario::Step::Kind::Tick)
      for (unsigned long i = 0; i < s.count; ++i) steps += "tick\n";
  }
  fs::path in = fs::path(folder_) / fmt::format("steps-{}.txt", id);
  if (!write_file(in, steps)) {
    run.error = fmt::format("cannot write '{}'", in.string());
    return run;
  }
  // The records come through a pipe and are parsed as they arrive: a long test's output is
  // never stored in TMPDIR nor held in memory (docs/testing-charts.md).
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) {
    run.error = fmt::format("cannot create a pipe: {}", std::strerror(errno));
    return run;
  }
  child_process::Spawn harness;
  harness.argv = {build.program};
  harness.stdin_path = in.string();
  harness.stdout_fd = pipe_fds[1];
  harness.stderr_path = "&1";
  std::string error;
  const int pid = child_process::start(harness, error);
  ::close(pipe_fds[1]);
  child_process::Result r;
  if (pid >= 0) {
    PipeReader reader(pipe_fds[0]);
    std::istream text(&reader);
    parse_output(text, model, test, keep, run);
    r = child_process::wait(pid);
  } else {
    r.error = error;
  }
  ::close(pipe_fds[0]);
  std::uint64_t expected = scenario::total_ticks(test) + 1;
  // One record after _init, then one per tick: with n records, tick n did not finish.
  if (!r.ok() || run.recorded() != expected) {
    const std::string how = !r.ok() ? child_process::describe(r) : "stopped";
    run.error = run.recorded() == 0 ? fmt::format("the C engine's harness {} before its first tick", how)
                                    : fmt::format("the C engine's harness {} in tick {}", how, run.recorded());
  }
  std::error_code ec;
  fs::remove(in, ec);
  return run;
}

}  // namespace gfec
