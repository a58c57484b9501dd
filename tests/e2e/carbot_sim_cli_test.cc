// carbot-sim as a command: how runs end, and what it says when a chart cannot run.
#include <catch2/catch.hpp>

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

TEST_CASE("carbot-sim: command-line numbers are finite and in range; the run has budgets", "[e2e][cli]") {
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

TEST_CASE("carbot-sim: --timeout stops a chart that loops forever; no temporary folder is left", "[e2e][cli]") {
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
