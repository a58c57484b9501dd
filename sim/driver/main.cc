// carbot-sim: run a chart on the simulated Carbot in a world (docs/sim.md).
//   carbot-sim CHART --world W.json [--seconds S] [--trace t.csv] [--json r.json] [--svg p.svg]
#include <unistd.h>

#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <fstream>
#include <sstream>
#include <mutex>
#include <thread>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "carbot_sim_paths.h"
#include "core/world.h"
#include "driver/chart_build.h"
#include "driver/engine_loader.h"
#include "driver/options.h"
#include "driver/trace_link.h"
#include "driver/process.h"
#include "driver/reports.h"
#include "driver/run.h"
#include "child_process.h"
#include "safe_output.h"
#include "viewer_page.h"

namespace fs = std::filesystem;
using namespace carbot;
using namespace carbot::driver;

namespace {

std::string env_or(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v && *v ? v : fallback;
}

/// Set by the watchdog when it stops the run: it reports and ends the process itself.
std::atomic<bool> g_stopping{false};

int fail(Exit code, const std::string& message) {
  // A child killed by the watchdog makes its step fail here: the watchdog's word is the one.
  while (g_stopping) pause();
  std::fprintf(stderr, "carbot-sim: error: %s\n", message.c_str());
  return code;
}

/// The private scratch folder the engine is built in (mkdtemp: fresh, mode 0700), removed when
/// the run ends. --work-dir gets a copy of what was built (keep_copy), written as outputs are:
/// a file or symlink planted there is replaced, never written through (docs/security.md).
class WorkDir {
 public:
  WorkDir() {
    std::string templ = (fs::temp_directory_path() / "carbot-sim-XXXXXX").string();
    if (!mkdtemp(templ.data())) throw std::runtime_error("cannot create a temporary folder");
    path_ = templ;
  }
  ~WorkDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const std::string& path() const { return path_; }

  /// Copies every regular file built so far into `keep` (created if missing); "" or why not.
  std::string keep_copy(const std::string& keep, const std::vector<std::string>& inputs) const {
    std::error_code ec;
    fs::create_directories(keep, ec);
    if (ec) return fmt::format("--work-dir {}: {}", keep, ec.message());
    std::vector<gfec::safe_output::File> files;
    for (const auto& entry : fs::directory_iterator(path_, ec)) {
      if (!entry.is_regular_file(ec)) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::ostringstream bytes;
      bytes << in.rdbuf();
      files.push_back({(fs::path(keep) / entry.path().filename()).string(), bytes.str()});
    }
    return gfec::safe_output::write_all(files, inputs);
  }

 private:
  std::string path_;
};

/// gfec's SVG of the chart for the viewer page, or "" and `note` saying why there is none (the
/// run goes on without a diagram: Graphviz is optional).
std::string chart_svg(const Options& o, const std::string& dir, std::string& note) {
  const std::string path = dir + "/chart.svg";
  std::string error;
  const int rc = run_process({o.gfec, "--emit=svg", o.chart, "-o", path}, error);
  // Exit 1: the chart cannot be drawn in gfec's time limit for Graphviz (GFEC_TOOL_TIMEOUT,
  // docs/security.md): an error, as it is for gfec. Else Graphviz is optional: a page without it.
  if (rc == 1)
    throw BuildError(fmt::format("{}: gfec could not draw the chart (its message is above)", o.chart), kBadInput);
  if (rc != 0) {
    note = rc < 0 ? error : "no diagram: 'gfec --emit=svg' failed (it needs Graphviz's dot)";
    return "";
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A number option that must be finite and within [low, high]: CLI11's checks let "nan" and
/// "1e300" through, which ran zero ticks or overflowed the tick count.
CLI::Validator finite_in(double low, double high) {
  return CLI::Validator(
      [low, high](std::string& text) -> std::string {
        double v = 0;
        try {
          std::size_t used = 0;
          v = std::stod(text, &used);
          if (used != text.size()) return "not a number: " + text;
        } catch (const std::exception&) { return "not a number: " + text; }
        if (!std::isfinite(v) || v < low || v > high)
          return fmt::format("expected a number from {:g} to {:g}, got {}", low, high, text);
        return {};
      },
      fmt::format("NUMBER in [{:g}, {:g}]", low, high));
}

/// The private work folder, to remove if the run is stopped from outside.
std::string g_work_dir;
std::mutex g_work_dir_mutex;

/// SIGINT, SIGTERM and SIGHUP are blocked in every thread and taken by this one, which also
/// ends a run that outlives --timeout (a chart action looping forever cannot be interrupted
/// in its own thread): it removes the temporary work folder, then lets the signal act (or
/// exits with kTimeout), so no exit path leaves /tmp/carbot-sim-* behind.
void start_watchdog(double timeout_seconds) {
  sigset_t set;
  sigemptyset(&set);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, s);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  std::thread([set, timeout_seconds] {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
    for (;;) {
      timespec wait{1, 0};
      if (timeout_seconds > 0) {
        const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0) break;
        wait.tv_sec = static_cast<time_t>(std::min(left, 3600.0));
        wait.tv_nsec = static_cast<long>((std::min(left, 3600.0) - static_cast<double>(wait.tv_sec)) * 1e9);
      } else {
        wait.tv_sec = 3600;
      }
      const int sig = sigtimedwait(&set, nullptr, &wait);
      if (sig > 0) {
        // The compilers, gfec and dot first (their process groups), then their folder.
        g_stopping = true;
        gfec::child_process::stop_all(1.0);
        {
          std::lock_guard<std::mutex> lock(g_work_dir_mutex);
          std::error_code ignored;
          if (!g_work_dir.empty()) fs::remove_all(g_work_dir, ignored);
        }
        // The signal's own action now: safe_output's handler if outputs are being written
        // (it removes their temporaries), else the default, which ends the process.
        sigset_t one;
        sigemptyset(&one);
        sigaddset(&one, sig);
        pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
        raise(sig);
        _exit(128 + sig);
      }
    }
    g_stopping = true;
    gfec::child_process::stop_all(1.0);
    {
      std::lock_guard<std::mutex> lock(g_work_dir_mutex);
      std::error_code ignored;
      if (!g_work_dir.empty()) fs::remove_all(g_work_dir, ignored);
    }
    std::fprintf(stderr, "carbot-sim: error: the run took longer than --timeout %g s of wall-clock time; stopped\n",
                 timeout_seconds);
    std::fflush(stderr);
    _exit(kTimeout);
  }).detach();
}

}  // namespace

int run_main(int argc, char** argv);

int main(int argc, char** argv) {
  const int code = run_main(argc, argv);
  while (g_stopping) pause();  // the watchdog ends the process with its own status
  return code;
}

int run_main(int argc, char** argv) {
  Options o;
  o.gfec = env_or("CARBOT_SIM_GFEC", kGfecPath);
  o.cc = env_or("CC", kCCompiler);
  o.cxx = env_or("CXX", kCxxCompiler);
  o.plans_supported = kPlansSupported;
  o.runtime_include = kRuntimeInclude;
  o.toolbox_include = kToolboxInclude;
  o.cache_dir = env_or("CARBOT_SIM_CACHE", kCacheDir);

  CLI::App app{
      "Runs a chart (.sfc, .fsm or .plan) on the ODE-simulated Carbot in a world, headless and deterministic."};
  app.add_option("chart", o.chart, "the chart file")->required();
  app.add_option("--world", o.world, "the world file (JSON, see docs/sim.md)")->required();
  app.add_option("--seconds", o.seconds, "simulated time limit")->capture_default_str()->check(finite_in(1e-3, 1e6));
  app.add_option("--trace", o.trace, "write t,x,y,heading per control tick (CSV)");
  app.add_option("--json", o.json, "write the result (JSON)");
  app.add_option("--svg", o.svg, "write a picture of the world and the path (SVG)");
  app.add_option("--html", o.html, "write the run viewer: one self-contained HTML page (docs/viewer.md)");
  app.add_option("--record", o.record, "write the run viewer's recording (JSON, docs/viewer.md)");
  app.add_option("--trace-to", o.trace_to,
                 "serve each robot's engine trace (gfec --trace) on this address, one connection per robot: "
                 "the run starts when `gfec monitor CHART --tcp HOST:PORT` has connected for each, and goes at "
                 "real time (docs/live.md)")
      ->type_name("tcp:HOST:PORT");
  app.add_option("--physics-step", o.physics_step, "physics step in seconds")
      ->capture_default_str()
      ->check(finite_in(1e-5, 0.1));
  auto* period_option =
      app.add_option("--period", o.period, "control period in seconds (default: the chart's period, else 0.01)")
          ->check(finite_in(1e-4, 10));
  app.add_option("--timeout", o.timeout, "stop the run after this many seconds of wall-clock time (0: no limit)")
      ->capture_default_str()
      ->check(finite_in(0, 1e7));
  app.add_option("--gfec", o.gfec, "the chart compiler (env CARBOT_SIM_GFEC)")->capture_default_str();
  app.add_option("--cc", o.cc, "C compiler for sfc/fsm engines (env CC)")->capture_default_str();
  app.add_option("--cxx", o.cxx, "C++ compiler for plan engines (env CXX)")->capture_default_str();
  app.add_option("--cache", o.cache_dir, "keep compiled engines here for reuse, '' for none (env CARBOT_SIM_CACHE)")
      ->capture_default_str();
  app.add_option("--work-dir", o.work_dir, "keep a copy of the generated engine's files here");
  app.add_flag("-q,--quiet", o.quiet, "no progress display and no summary");
  // Several robots running a team machine (docs/sim.md, "Several robots").
  app.add_flag("--no-exchange", o.no_exchange, "team machines: exchange no states (each robot runs alone)");
  app.add_option("--exchange-delay", o.exchange_delay, "team machines: reports arrive this many ticks late")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000));
  app.add_option("--exchange-loss", o.exchange_loss, "team machines: each report is lost with this probability")
      ->capture_default_str()
      ->check(finite_in(0, 1));
  app.add_option("--seed", o.seed, "team machines: seed of the lost reports")->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? kOk : kUsage;
  }

  const bool period_given = period_option->count() > 0;
  start_watchdog(o.timeout);

  // 1. The world: checked before anything is built, so a typo costs no compile.
  if (!fs::exists(o.world)) return fail(kUsage, fmt::format("{}: no such world file", o.world));
  if (!fs::exists(o.chart)) return fail(kUsage, fmt::format("{}: no such chart file", o.chart));
  World world;
  try {
    world = load_world(o.world);
  } catch (const WorldError& e) { return fail(kBadInput, e.what()); }

  try {
    // 2. The engine: gfec generates it, the C compiler makes it loadable, we load it.
    WorkDir dir;
    {
      std::lock_guard<std::mutex> lock(g_work_dir_mutex);
      g_work_dir = dir.path();
    }
    BuiltEngine built;
    try {
      built = build_engine(o, dir.path());
    } catch (const BuildError&) {
      if (!o.work_dir.empty()) dir.keep_copy(o.work_dir, {o.chart, o.world});  // for a look at what failed
      throw;
    }
    if (!o.work_dir.empty()) {
      std::vector<std::string> never = built.chart.files;
      never.push_back(o.chart);
      never.push_back(o.world);
      const std::string error = dir.keep_copy(o.work_dir, never);
      if (!error.empty()) return fail(kUsage, error);
    }
    const int robots = static_cast<int>(world.robots.size());
    if (robots > 1) {
      if (built.chart.kind == "plan")
        return fail(kUsage, fmt::format("{}: {} robots: carbot-sim runs several robots with sfc and fsm charts only",
                                        o.world, robots));
      if (built.chart.team > 0 && robots > built.chart.team)
        return fail(kBadInput, fmt::format("{}: {} robots, but {} is a team of at most {} agents", o.world, robots,
                                           built.chart.name, built.chart.team));
    }
    std::vector<std::unique_ptr<LoadedEngine>> engines;
    for (int i = 0; i < robots; ++i) engines.push_back(std::make_unique<LoadedEngine>(built.library));
    LoadedEngine& engine = *engines.front();

    // 3. The run.
    // The chart's own period, unless the command line gives one.
    const double period = period_given || built.chart.period <= 0 ? o.period : built.chart.period;
    // The tick budget: the trace keeps a row per control tick, and physics steps cost time.
    const double control_ticks = o.seconds / period, physics_steps = o.seconds / o.physics_step;
    if (control_ticks > kMaxControlTicks || physics_steps > kMaxPhysicsSteps)
      return fail(kUsage, fmt::format("--seconds {:g} is {:.3g} control ticks and {:.3g} physics steps; the budget is "
                                      "{:g} and {:g} (a shorter run, a longer --period or --physics-step)",
                                      o.seconds, control_ticks, physics_steps, kMaxControlTicks, kMaxPhysicsSteps));
    // The live trace: every robot connected before the first tick, or no run.
    if (!o.trace_to.empty()) {
      if (const std::string why = trace_links().open(o.trace_to, robots, period); !why.empty())
        return fail(kUsage, why);
    }
    Simulation sim(world, SimConfig{o.physics_step, period});
    RunResult result;
    if (robots == 1) {
      result = run_engine(sim, engine, built.chart, o.seconds, o.quiet);
    } else {
      std::vector<LoadedEngine*> each;
      for (auto& e : engines) each.push_back(e.get());
      Exchange exchange;
      exchange.enabled = !o.no_exchange;
      exchange.delay_ticks = o.exchange_delay;
      exchange.loss = o.exchange_loss;
      exchange.seed = o.seed;
      result = run_team(sim, each, built.chart, o.seconds, exchange);
    }

    // 4. What it leaves behind.
    const RunReport report{built.chart, o.chart, sim, result};
    std::vector<gfec::safe_output::File> outputs;
    if (!o.trace.empty()) outputs.push_back({o.trace, trace_csv(report)});
    if (!o.json.empty()) outputs.push_back({o.json, result_json(report)});
    if (!o.svg.empty()) outputs.push_back({o.svg, svg_picture(report)});
    if (o.recording()) {
      std::string note;
      const std::string svg = chart_svg(o, dir.path(), note);
      const nlohmann::json data = viewer_data(report, svg, note);
      if (!o.html.empty()) outputs.push_back({o.html, gfec::viewer::page(data)});
      if (!o.record.empty()) outputs.push_back({o.record, data.dump() + "\n"});
    }
    // Never over the chart, a file it imports or the world (docs/security.md).
    std::vector<std::string> inputs = built.chart.files;
    inputs.push_back(o.chart);
    inputs.push_back(o.world);
    while (g_stopping) pause();  // a child stopped by the watchdog: no outputs from a cut-short run
    const std::string error = gfec::safe_output::write_all(outputs, inputs);
    if (!error.empty()) return fail(kUsage, error);
    if (!o.quiet) {
      if (robots == 1) {
        std::printf("carbot-sim: %s (%s) on %s: %s at %.2f s, %.2f m driven, %d bump%s (%.2f s, %.0fx real time)\n",
                    built.chart.name.c_str(), built.chart.kind.c_str(), world.name.c_str(), result.status.c_str(),
                    sim.time(), sim.odometer(), sim.bumps(), sim.bumps() == 1 ? "" : "s", result.wall_seconds,
                    result.wall_seconds > 0 ? sim.time() / result.wall_seconds : 0.0);
      } else {
        std::printf(
            "carbot-sim: %s (%s) on %s, %d robots: %s at %.2f s, %zu robot contact%s (%.2f s, %.0fx real time)\n",
            built.chart.name.c_str(), built.chart.kind.c_str(), world.name.c_str(), robots, result.status.c_str(),
            sim.time(), sim.robot_contacts().size(), sim.robot_contacts().size() == 1 ? "" : "s", result.wall_seconds,
            result.wall_seconds > 0 ? sim.time() / result.wall_seconds : 0.0);
        for (int i = 0; i < robots; ++i) {
          const RobotRun& r = result.robots[static_cast<std::size_t>(i)];
          const std::string state = r.state >= 0 && r.state < static_cast<int>(built.chart.rows.size())
                                        ? " in " + built.chart.rows[static_cast<std::size_t>(r.state)].name
                                        : "";
          std::printf("  robot %d: %s%s, %.2f m driven, %d bump%s%s\n", i, r.status.c_str(), state.c_str(),
                      r.distance_m, r.bumps, r.bumps == 1 ? "" : "s",
                      r.held >= 0 ? (", holding " + sim.items()[static_cast<std::size_t>(r.held)].name).c_str() : "");
        }
      }
      for (const SimNote& n : sim.notes()) std::printf("  t=%.2f s: %s\n", n.t, n.text.c_str());
    }
    return kOk;
  } catch (const BuildError& e) { return fail(e.code, e.what()); } catch (const LoadError& e) {
    return fail(kBadInput, e.what());
  } catch (const std::exception& e) { return fail(kUsage, e.what()); }
}
