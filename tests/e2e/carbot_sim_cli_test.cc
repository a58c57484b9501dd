// carbot-sim as a command: how runs end, and what it says when a chart cannot run.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

#include "support.h"

namespace {

/// The oval, plus whatever else a test needs, written into `dir`.
std::string oval_with(const e2e::TempDir &dir, const std::string &extra_fields) {
  const carbot::World oval = e2e::world("sim/worlds/oval.json");
  std::string points;
  for (const auto &p : oval.line.points)
    points += (points.empty() ? "" : ", ") + ("[" + std::to_string(p.x) + ", " + std::to_string(p.y) + "]");
  const std::string path = dir.file("oval_plus.json");
  std::ofstream(path) << R"({"size": [4, 2.6], "line": {"width": 0.05, "closed": true, "points": [)" << points
                      << R"(]}, "start": {"pose": [-0.4, -0.7, 0]})" << extra_fields << "}";
  return path;
}

}  // namespace

TEST_CASE("carbot-sim: the escape button stops an sfc run", "[e2e][cli]") {
  e2e::TempDir dir;
  const std::string world = oval_with(dir, R"(, "events": [{"at": 12.5, "press": "escape"}])");
  const e2e::SimRun run = e2e::run_sim("samples/line_follower.sfc", world, 60);
  INFO(run.output);
  if (e2e::skipped_for_missing_backend(run)) return;
  REQUIRE(run.exit_code == 0);
  CHECK(run.result["status"] == "terminated");
  CHECK(run.result["sim_time_s"].get<double>() == Approx(12.5).margin(0.011));
  CHECK(run.result["escape_presses"] == 1);
  REQUIRE(!run.trace.empty());
  CHECK(run.trace.back().t == Approx(12.5).margin(0.011));
}

TEST_CASE("carbot-sim: a chart calling a function the Carbot lacks is refused by name", "[e2e][cli]") {
  e2e::TempDir dir;
  std::ofstream(dir.file("beeper.sfc")) << R"(interface Beeper { void Beep(); }
sfc Beeps {
  period 10ms;
  initial place Beeping { Beep(); }
}
)";
  const e2e::SimRun run = e2e::run_sim(dir.file("beeper.sfc"), "sim/worlds/oval.json", 1);
  INFO(run.output);
  if (e2e::skipped_for_missing_backend(run)) return;
  CHECK(run.exit_code == 1);
  CHECK(run.output.find("Beep") != std::string::npos);
  CHECK(run.output.find("cannot load the engine") != std::string::npos);
  CHECK(run.trace.empty());
}

TEST_CASE("carbot-sim: a chart gfec rejects stops it with gfec's diagnostics", "[e2e][cli]") {
  e2e::TempDir dir;
  std::ofstream(dir.file("broken.sfc")) << "import \"" << e2e::source("samples/linebot.iface") << R"(";
sfc Broken {
  initial place A { Left_FWD(); }
}
)";
  const e2e::SimRun run = e2e::run_sim(dir.file("broken.sfc"), "sim/worlds/oval.json", 1);
  INFO(run.output);
  CHECK(run.exit_code == 1);
  CHECK(run.output.find("Left_FWD") != std::string::npos);  // gfec's own message
  CHECK(run.output.find("broken.sfc: gfec rejected the chart") != std::string::npos);
}

namespace {

/// Runs carbot-sim with `args` (already quoted), returns the exit code and what it printed.
int run_cli(const std::string &args, std::string &output, const e2e::TempDir &dir) {
  const std::string log = dir.file("cli_output.txt");
  const int status = std::system((std::string(CARBOT_SIM) + " " + args + " >'" + log + "' 2>&1").c_str());
  std::ifstream in(log);
  output.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string q(const std::string &s) { return "'" + s + "'"; }

}  // namespace

// docs/security.md: the outputs are written as gfec writes its own, as one set.
TEST_CASE("carbot-sim: never writes over the world, the chart, a FIFO or one file twice", "[e2e][cli]") {
  e2e::TempDir dir;
  const std::string world = dir.file("w.json"), chart = dir.file("lf.sfc");
  {
    std::ifstream w(e2e::source("sim/worlds/oval.json")), c(e2e::source("samples/line_follower.sfc")),
        i(e2e::source("samples/linebot.iface"));
    std::ofstream(world) << w.rdbuf();
    std::ofstream(chart) << c.rdbuf();
    std::ofstream(dir.file("linebot.iface")) << i.rdbuf();
  }
  const std::string fifo = dir.file("fifo");
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  const std::string base = q(chart) + " --world " + q(world) + " --seconds 0.05 -q";
  std::string out;
  const std::string trace = dir.file("t.csv");
  const auto world_size = std::filesystem::file_size(world);

  CHECK(run_cli(base + " --trace " + q(trace) + " --json " + q(world), out, dir) == 2);
  CHECK(out.find("refusing to write") != std::string::npos);
  CHECK(std::filesystem::file_size(world) == world_size);
  CHECK_FALSE(std::filesystem::exists(trace));  // the set is refused whole, before anything is written

  CHECK(run_cli(base + " --trace " + q(trace) + " --svg " + q(fifo), out, dir) == 2);
  CHECK(out.find("not a regular file") != std::string::npos);
  CHECK(std::filesystem::is_fifo(fifo));
  CHECK_FALSE(std::filesystem::exists(trace));

  CHECK(run_cli(base + " --json " + q(trace) + " --svg " + q(trace), out, dir) == 2);
  CHECK(out.find("twice") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(trace));

  CHECK(run_cli(base + " --trace " + q(chart), out, dir) == 2);
  // Nor over a file the chart imports (the model's "files").
  const std::string iface = dir.file("linebot.iface");
  const auto iface_size = std::filesystem::file_size(iface);
  CHECK(run_cli(base + " --json " + q(iface), out, dir) == 2);
  CHECK(out.find("refusing to write") != std::string::npos);
  CHECK(std::filesystem::file_size(iface) == iface_size);
  INFO(out);
  CHECK(run_cli(base + " --trace " + q(trace) + " --json " + q(dir.file("r.json")), out, dir) == 0);
  CHECK(std::filesystem::exists(trace));
  for (const auto &entry : std::filesystem::directory_iterator(std::filesystem::path(trace).parent_path()))
    CHECK(entry.path().filename().string().find("tmp") == std::string::npos);
}

TEST_CASE("carbot-sim: command-line numbers are finite and in range, the run has budgets", "[e2e][cli]") {
  e2e::TempDir dir;
  const std::string base =
      q(e2e::source("samples/line_follower.sfc")) + " --world " + q(e2e::source("sim/worlds/oval.json")) + " -q";
  std::string out;
  // nan and 1e17 once ran zero ticks and exited 0; 1e300 overflowed the tick count.
  for (std::string_view bad : {"--seconds nan", "--seconds 1e17", "--seconds -1", "--period 1e300", "--period inf",
                               "--physics-step 0", "--physics-step nan", "--timeout -1", "--seconds 5x"}) {
    INFO(bad);
    CHECK(run_cli(base + " " + std::string(bad), out, dir) == 2);
    CHECK(out.find(bad.substr(0, bad.find(' '))) != std::string::npos);  // names the option
  }
  // The tick budget: 1e5 s at a 10 us physics step is 1e10 steps.
  CHECK(run_cli(base + " --seconds 100000 --physics-step 0.00001", out, dir) == 2);
  CHECK(out.find("physics steps; the budget is") != std::string::npos);
}

TEST_CASE("carbot-sim: --timeout stops a chart that loops forever, no temporary folder is left", "[e2e][cli]") {
  e2e::TempDir dir;
  const std::string tmp = dir.file("tmp");
  std::filesystem::create_directories(tmp);
  {
    std::ifstream i(e2e::source("samples/linebot.iface"));
    std::ofstream(dir.file("linebot.iface")) << i.rdbuf();
    std::ofstream(dir.file("loop.sfc"))
        << "import \"linebot.iface\";\n"
           "sfc Loop {\n  period 10ms;\n  initial place A { Left_FW(); %{ for (;;) {} %} }\n}\n";
  }
  const std::string env = "TMPDIR=" + q(tmp) + " CARBOT_SIM_CACHE= ";
  const std::string sim = std::string(CARBOT_SIM) + " " + q(dir.file("loop.sfc")) + " --world " +
                          q(e2e::source("sim/worlds/oval.json")) + " -q";
  const std::string cmd = env + sim;
  std::string out;
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system((cmd + " --timeout 2 >" + q(dir.file("out.txt")) + " 2>&1").c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 3);
  CHECK(seconds < 30);
  std::ifstream log(dir.file("out.txt"));
  out.assign(std::istreambuf_iterator<char>(log), std::istreambuf_iterator<char>());
  CHECK(out.find("longer than --timeout 2 s") != std::string::npos);
  CHECK(std::filesystem::is_empty(tmp));

  // SIGTERM while the engine loops: the temporary work folder goes too.
  const int term = std::system((env + "timeout -s TERM 3 " + sim + " >/dev/null 2>&1").c_str());
  CHECK(WEXITSTATUS(term) == 124);  // timeout(1): the command was killed
  CHECK(std::filesystem::is_empty(tmp));
}

// Issue 42 (docs/security.md): a hostile work folder, world or chart, and a run stopped with
// children still running. Every run is under timeout(1) and `ulimit -v`, so a regression fails
// the test instead of taking the machine down.
namespace {

/// `text` as a file in `dir`, for a stand-in tool.
std::string script(const e2e::TempDir &dir, const std::string &name, const std::string &text) {
  const std::string path = dir.file(name);
  std::ofstream(path) << text;
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
  return path;
}

std::string slurp_file(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Every pid written to `pids` has ended (each is killed if not, so a failure leaves none).
bool none_alive(const std::string &pids) {
  std::ifstream in(pids);
  bool none = true;
  for (long pid; in >> pid;)
    if (::kill(static_cast<pid_t>(pid), 0) == 0) {
      ::kill(static_cast<pid_t>(pid), SIGKILL);
      none = false;
    }
  return none;
}

/// Runs carbot-sim with `args` under 3 GB of address space and a 120 s limit, `env` (shell
/// words: "export X=1; ") first; returns the exit code and what it printed.
int run_limited(const std::string &env, const std::string &args, std::string &output, const e2e::TempDir &dir) {
  const std::string log = dir.file("cli_output.txt");
  const std::string command = "(ulimit -v 3000000; " + env + "timeout 120 " + CARBOT_SIM + " " + args + ")";
  const int status = std::system((command + " >'" + log + "' 2>&1").c_str());
  output = slurp_file(log);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("carbot-sim: --work-dir never writes through planted symlinks", "[e2e][cli]") {
  e2e::TempDir dir;
  const std::string work = dir.file("work");
  std::filesystem::create_directories(work);
  // One victim per name (a shared one is refused as "one file twice"): each must stay as it is.
  const std::vector<std::string> names = {"shim.c",   "robot_names.h", "record.c",  "record.h",  "engine_rec.c",
                                          "engine.c", "engine.h",      "engine.so", "model.json"};
  for (const std::string &n : names) {
    std::ofstream(dir.file("victim_" + n)) << "precious " << n << "\n";
    std::filesystem::create_symlink(dir.file("victim_" + n), work + "/" + n);
  }
  std::string out;
  const int code =
      run_cli(q(e2e::source("samples/line_follower.sfc")) + " --world " + q(e2e::source("sim/worlds/oval.json")) +
                  " --seconds 0.05 -q --cache '' --record " + q(dir.file("rec.json")) + " --work-dir " + q(work),
              out, dir);
  INFO(out);
  CHECK(code == 0);
  for (const std::string &n : names) {
    INFO(n);
    CHECK(slurp_file(dir.file("victim_" + n)) == "precious " + n + "\n");
    // The copy replaced the symlink itself.
    CHECK(std::filesystem::is_regular_file(std::filesystem::symlink_status(work + "/" + n)));
  }
  CHECK(slurp_file(work + "/record.c").find("carbot_rec_") != std::string::npos);
}

TEST_CASE("carbot-sim: a world that is a device, a FIFO, too large or too full is refused at once", "[e2e][cli]") {
  e2e::TempDir dir;
  const std::string zero = dir.file("zero.json"), fifo = dir.file("fifo.json");
  std::filesystem::create_symlink("/dev/zero", zero);
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  {
    std::ofstream big(dir.file("big.json"));  // 5 MB of spaces before a valid world
    big << std::string(5u << 20, ' ') << R"({"size": [4, 3], "start": {"pose": [0, 0, 0]}})";
    std::ofstream walls(dir.file("walls.json"));  // 100,000 walls: seconds per simulated second
    walls << R"({"size": [4, 3], "start": {"pose": [0, -1, 0]}, "walls": [)";
    for (int i = 0; i < 100000; ++i) walls << (i ? "," : "") << R"({"from":[0,0],"to":[0.1,0.1]})";
    walls << "]}";
  }
  const std::string chart = q(e2e::source("samples/line_follower.sfc"));
  struct Case {
    std::string world, message;
  };
  for (const Case &c :
       {Case{zero, "cannot read the world file: not a regular file (a character device)"},
        Case{fifo, "cannot read the world file: not a regular file (a FIFO)"},
        Case{dir.file("big.json"), "cannot read the world file: larger than 4 MiB, the most a world may be"},
        Case{dir.file("walls.json"),
             "walls: a world holds at most 1000 walls, boxes and items in all; this one has at least "
             "100000"}}) {
    INFO(c.world);
    std::string out;
    const auto start = std::chrono::steady_clock::now();
    CHECK(run_limited("", "--cache '' " + chart + " --world " + q(c.world) + " --seconds 1 -q", out, dir) == 1);
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(20));
    CHECK(out.find(c.world + ": " + c.message) != std::string::npos);
    INFO(out);
  }
}

TEST_CASE("carbot-sim: after --timeout no compiler, gfec or dot survives, and TMPDIR is clean", "[e2e][cli]") {
  e2e::TempDir dir;
  const std::string tmp = dir.file("tmp"), pids = dir.file("pids"), bin = dir.file("bin");
  std::filesystem::create_directories(tmp);
  std::filesystem::create_directories(bin);
  // Slow stand-ins: a C compiler, and a dot on PATH, each writing its pid and sleeping.
  const std::string slow = "#!/bin/sh\necho $$ >> " + q(pids) + "\nexec sleep 300\n";
  const std::string cc = script(dir, "slow_cc", slow);
  script(dir, "bin/dot", slow);
  const std::string env = "export TMPDIR=" + q(tmp) + " PATH=" + q(bin) + ":\"$PATH\"; ";
  const std::string run = q(e2e::source("samples/line_follower.sfc")) + " --world " +
                          q(e2e::source("sim/worlds/oval.json")) + " --seconds 0.05 -q --cache '' --timeout 3";
  std::string out;
  // The compiler is still running at the time limit.
  CHECK(run_limited(env, run + " --cc " + q(cc), out, dir) == 3);
  INFO(out);
  CHECK(std::filesystem::exists(pids));
  CHECK(none_alive(pids));
  CHECK(std::filesystem::is_empty(tmp));
  // With --html, gfec is drawing the chart with dot at the time limit.
  std::filesystem::remove(pids);
  CHECK(run_limited(env, run + " --html " + q(dir.file("run.html")), out, dir) == 3);
  CHECK(std::filesystem::exists(pids));
  CHECK(none_alive(pids));
  CHECK(std::filesystem::is_empty(tmp));
  CHECK_FALSE(std::filesystem::exists(dir.file("run.html")));
}

TEST_CASE("carbot-sim: the engine cache hits on a second identical run and keeps at most 64 engines", "[e2e][cli]") {
  e2e::TempDir dir;
  const std::string cache = dir.file("cache"), calls = dir.file("calls");
  // A C compiler that counts its runs: a cache hit runs none.
  const std::string cc = script(dir, "counting_cc", "#!/bin/sh\necho run >> " + q(calls) + "\nexec cc \"$@\"\n");
  const std::string run = q(e2e::source("samples/line_follower.sfc")) + " --world " +
                          q(e2e::source("sim/worlds/oval.json")) + " --seconds 0.05 --cache " + q(cache) + " --cc " +
                          q(cc);
  auto entries = [&] {
    std::size_t n = 0;
    for (const auto &e : std::filesystem::directory_iterator(cache)) n += e.path().extension() == ".so";
    return n;
  };
  auto compiles = [&] {
    std::ifstream in(calls);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
  };
  std::string out;
  REQUIRE(run_cli(run, out, dir) == 0);
  CHECK(compiles() == 1);
  CHECK(entries() == 1);
  REQUIRE(run_cli(run, out, dir) == 0);
  INFO(out);
  CHECK(compiles() == 1);  // the second run compiled nothing
  CHECK(entries() == 1);
  CHECK(out.find("taken from the cache") != std::string::npos);
  // 70 older entries: one run later, the 64 most recently used remain, its own among them.
  const auto old = std::filesystem::file_time_type::clock::now() - std::chrono::hours(24);
  for (int i = 0; i < 70; ++i) {
    const std::string stale = cache + "/stale" + std::to_string(i) + ".so";
    std::ofstream(stale) << "x";
    std::filesystem::last_write_time(stale, old - std::chrono::minutes(i));
  }
  std::filesystem::remove(calls);
  REQUIRE(run_cli(run + " --record " + q(dir.file("rec.json")), out, dir) == 0);  // another build: a store
  CHECK(compiles() == 1);
  CHECK(entries() == 64);
  CHECK_FALSE(std::filesystem::exists(cache + "/stale69.so"));  // the least recently used went first
}
