// gfec monitor CHART: reads the trace an engine built with --trace writes (stdin, --serial,
// --tcp) and shows the run. The decoding is monitor/'s; this file parses the options, compiles
// the chart for the frame's layout and connects the source to what shows the run.
#include "monitor_command.h"

#include "byte_source.h"
#include "commands.h"
#include "diagnostic_report.h"
#include "driver.h"
#include "escape.h"
#include "external_tool.h"
#include "live_page.h"
#include "live_recording.h"
#include "live_server.h"
#include "tee_sink.h"
#include "log_sink.h"
#include "options.h"
#include "plan_decoder.h"
#include "plan_log_sink.h"
#include "plan_trace_format.h"
#include "pipeline/compilation.h"
#include "runnable_chart.h"
#include "trace_decoder.h"
#include "trace_format.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>
#include <ostream>
#include <unistd.h>

namespace gfec {

namespace {

/// The monitor's options, all declared in add_options: one place to add another way to show the
/// run.
struct MonitorOptions {
  std::string input;
  std::string chart;
  bool log = false;    ///< print the observable log
  std::string serial;  ///< a serial port's device
  long baud = 115200;
  std::string tcp;     ///< HOST:PORT to connect to
  double silence = 0;  ///< report silence after this many seconds (0: never)
  bool silence_given = false;
  std::string http;          ///< HOST:PORT of the live page ("" = none)
  bool http_remote = false;  ///< serve it on an address that is not loopback
  int robots = 1;            ///< --tcp connections, one per robot of a team (--http only)
  Options report;            ///< -I, -x, -W..., -f...: as gfec's
};

void add_options(CLI::App &app, MonitorOptions &o, FrontEndFlags &front_end) {
  app.add_option("chart", o.input, "The chart the engine was built from, or the plan of an afp::LinkTrace")->required();
  app.add_option("--chart", o.chart, "The chart, when the file declares several")->type_name("NAME");
  app.add_flag("--log", o.log,
               "Print the decoded run as 'gfec run --observable' does (tick, agent, av, state); the monitor's "
               "own lines (loss, silence) begin with '#'");
  app.add_option("--serial", o.serial, "Read the trace from a serial port, e.g. /dev/ttyACM0 (raw, 8N1)")
      ->type_name("DEV");
  app.add_option("--baud", o.baud, "The serial port's rate (default 115200)")->type_name("N");
  app.add_option("--tcp", o.tcp, "Connect to HOST:PORT (the robot or simulator listens) and read the trace")
      ->type_name("HOST:PORT");
  app.add_option("--silence", o.silence, "Report when nothing has arrived for S seconds (default: never)")
      ->type_name("S")
      ->check(CLI::Range(0.0, 86400.0));
  app.add_option("--http", o.http,
                 "Serve the live page on HOST:PORT (loopback only; port 0: a free one, printed): the run viewer "
                 "with the chart lit as ticks arrive, or a plan's running actors as its events arrive "
                 "(docs/live.md)")
      ->type_name("HOST:PORT");
  app.add_flag("--http-remote", o.http_remote,
               "Serve the live page on an address that is not loopback too (it has no login: anyone who reaches "
               "it sees the run)");
  app.add_option("--robots", o.robots,
                 "With --tcp and --http: connect N times, one stream per robot (carbot-sim --trace-to serves "
                 "robot i to the i-th connection), all robots on one page, each in its colour")
      ->type_name("N")
      ->check(CLI::Range(1, 64));
  add_front_end_options(app, o.report, front_end);
}

/// A stream the chart or plan refuses (another chart's, another format version): an error
/// located at the chart's name or the plan, reported as every diagnostic is, so
/// -fdiagnostics-format=json|sarif carries it too.
void report_refusal(DiagnosticReport &report, const std::string &input, const pipeline::Compilation &c,
                    const SourceRange &at, const std::string &refusal) {
  Diagnostics diag;
  diag.error(at, ErrorKind::StreamRefused, text::printable(refusal));
  report.add(input, diag, c.sources);
}

/// Where the stream comes from, for the live page's subtitle.
std::string source_name(const MonitorOptions &o) {
  return !o.serial.empty() ? "serial " + o.serial : !o.tcp.empty() ? "tcp " + o.tcp : "stdin";
}

/// Reads the stream on `fd` to its end into `decoder`, whose sink is `sink`: a refused stream is
/// reported at `refused_at` and ends the page; otherwise the page is told how the stream ended and
/// `counts` (the decoder's figures) is printed. Returns the command's exit code.
int read_to_end(const std::string &input, int fd, double silence, monitor::RunSink &sink, monitor::FrameStream &decoder,
                live::LiveRecording *page, DiagnosticReport &report, const pipeline::Compilation &c,
                const SourceRange &refused_at, const std::function<std::string()> &counts, std::ostream &err) {
  const std::string read_error = monitor::read_stream(
      fd, silence, sink, [&](const unsigned char *data, std::size_t n) { decoder.feed(data, n); },
      [&] { return decoder.refused(); });
  if (fd != 0) ::close(fd);
  decoder.finish();
  if (decoder.refused()) {
    report_refusal(report, input, c, refused_at, decoder.refusal());
    if (page) page->ended(decoder.refusal());
    return kExitInputError;
  }
  if (page) page->ended(read_error.empty() ? "the end of the stream" : "reading the trace: " + read_error);
  err << "gfec monitor: " << counts() << '\n';
  if (!read_error.empty()) {
    report.tool_error(input, "reading the trace: " + read_error, false);
    return kExitUsageOrIo;
  }
  return kExitOk;
}

/// Where decoded frames go: the log, the live page, or both through `both` (which it fills).
/// `Sink` is the decoder's sink interface (monitor::RunSink for charts, monitor::PlanSink for
/// plans); the page and the tee implement both.
template <class Sink, class Log>
Sink &pick_sink(Log &log, live::LiveRecording *page, bool want_log, std::unique_ptr<live::TeeSink> &both) {
  if (want_log && page) both = std::make_unique<live::TeeSink>(static_cast<Sink &>(log), *page);
  if (both) return *both;
  if (page) return *page;
  return log;
}

/// The source's file descriptor (0 for stdin), or -1 with `why` set.
int open_source(const MonitorOptions &o, std::string &why) {
  if (!o.serial.empty()) return monitor::open_serial(o.serial, o.baud, why);
  if (!o.tcp.empty()) return monitor::open_tcp(o.tcp, why);
  return 0;
}

/// A plan's stream (afp::LinkTrace, docs/live.md "Plans"): its events as a log, on the live page
/// or both.
int monitor_plan(const MonitorOptions &o, const pipeline::Compilation &c, model::PlanId plan, DiagnosticReport &report,
                 std::ostream &out, std::ostream &err) {
  const trace::PlanLayout layout = trace::plan_layout_of(c.model, plan);
  std::string why;
  const int fd = open_source(o, why);
  if (fd < 0) {
    report.tool_error(o.input, why, false);
    return kExitUsageOrIo;
  }
  std::unique_ptr<live::LiveRecording> page;
  if (!o.http.empty()) {
    try {
      page = std::make_unique<live::LiveRecording>(live_plan(c.model, layout, o.input, source_name(o)));
    } catch (const ToolTimeLimit &e) {
      if (fd != 0) ::close(fd);
      report.tool_error(o.input, e.what(), false);
      return kExitInputError;
    }
  }
  monitor::PlanLogSink log(c.model, layout, out);
  std::unique_ptr<live::TeeSink> both;
  monitor::PlanSink &sink = pick_sink<monitor::PlanSink>(log, page.get(), o.log, both);
  monitor::PlanTraceDecoder decoder(c.model, layout, sink);
  const double silence = page && !o.silence_given ? 1.0 : o.silence;
  auto read = [&]() -> int {
    return read_to_end(
        o.input, fd, silence, sink, decoder, page.get(), report, c, c.model.plans.at(plan).range,
        [&] {
          return fmt::format("{} frame{} decoded ({} event{}), {} lost, {} byte{} garbled", decoder.frames_shown(),
                             decoder.frames_shown() == 1 ? "" : "s", decoder.events_shown(),
                             decoder.events_shown() == 1 ? "" : "s", decoder.events_lost(), decoder.bytes_garbled(),
                             decoder.bytes_garbled() == 1 ? "" : "s");
        },
        err);
  };
  if (!page) return read();
  return serve_live_page(
      *page, o.http, o.http_remote, [&] { read(); }, err);
}

int monitor_with(const MonitorOptions &o, DiagnosticReport &report, std::ostream &out, std::ostream &err) {
  const RunnableChart loaded = load_runnable_chart(o.report, o.input, o.chart, "monitor", report,
                                                   pipeline::kSfc | pipeline::kFsm | pipeline::kPlan);
  if (loaded.exit_code != kExitOk) return loaded.exit_code;
  const pipeline::Compilation &c = *loaded.compilation;
  if (loaded.plan) {
    if (o.robots > 1) {
      report.tool_error(o.input, "--robots: the live page shows one plan's stream (one gfec monitor per robot's plan)",
                        false);
      return kExitUsageOrIo;
    }
    return monitor_plan(o, c, loaded.plan, report, out, err);
  }
  const model::ChartId chart = loaded.chart;
  const trace::Layout layout = trace::layout_of(c.model, chart);

  std::string why;
  int fd = open_source(o, why);
  if (fd < 0) {
    report.tool_error(o.input, why, false);
    return kExitUsageOrIo;
  }
  // --http: the live page's recording, fed beside (or instead of) the log.
  std::unique_ptr<live::LiveRecording> page;
  if (!o.http.empty()) {
    try {
      page = std::make_unique<live::LiveRecording>(live_chart(c.model, chart, o.input, source_name(o)),
                                                   static_cast<std::size_t>(o.robots));
    } catch (const ToolTimeLimit &e) {
      report.tool_error(o.input, e.what(), false);
      return kExitInputError;
    }
  }
  monitor::LogSink log(c.model, chart, out);
  std::unique_ptr<live::TeeSink> both;
  monitor::RunSink &sink = pick_sink<monitor::RunSink>(log, page.get(), o.log, both);
  monitor::TraceDecoder decoder(c.model, layout, sink);
  // The page's silence banner needs silence reported: after a second unless --silence says.
  const double silence = page && !o.silence_given ? 1.0 : o.silence;
  auto read = [&]() -> int {
    return read_to_end(
        o.input, fd, silence, sink, decoder, page.get(), report, c, c.model.charts.at(chart).name_range,
        [&] {
          return fmt::format("{} tick{} decoded, {} lost, {} byte{} garbled", decoder.ticks_shown(),
                             decoder.ticks_shown() == 1 ? "" : "s", decoder.ticks_lost(), decoder.bytes_garbled(),
                             decoder.bytes_garbled() == 1 ? "" : "s");
        },
        err);
  };
  if (!page) return read();
  if (o.robots > 1) {
    // A team: the other robots' connections (robot i is the i-th), each read and decoded on a
    // thread of its own into the one page (LiveRecording takes a lock per call).
    std::vector<int> fds{fd};
    for (int i = 1; i < o.robots; ++i) {
      const int more = monitor::open_tcp(o.tcp, why);
      if (more < 0) {
        for (int f : fds) ::close(f);
        report.tool_error(o.input, fmt::format("robot {}: {}", i, why), false);
        return kExitUsageOrIo;
      }
      fds.push_back(more);
    }
    auto read_team = [&] {
      std::vector<std::unique_ptr<monitor::TraceDecoder>> decoders;
      for (std::size_t i = 0; i < fds.size(); ++i)
        decoders.push_back(std::make_unique<monitor::TraceDecoder>(c.model, layout, *page, i));
      std::mutex err_mutex;
      std::vector<std::thread> readers;
      for (std::size_t i = 0; i < fds.size(); ++i)
        readers.emplace_back([&, i] {
          monitor::TraceDecoder &d = *decoders[i];
          const std::string read_error = monitor::read_stream(
              fds[i], silence, *page, [&](const unsigned char *data, std::size_t n) { d.feed(data, n); },
              [&] { return d.refused(); });
          ::close(fds[i]);
          d.finish();
          std::lock_guard<std::mutex> lock(err_mutex);
          if (d.refused()) err << fmt::format("gfec monitor: robot {}: {}\n", i, text::printable(d.refusal()));
          err << fmt::format("gfec monitor: robot {}: {} ticks decoded, {} lost, {} bytes garbled{}\n", i,
                             d.ticks_shown(), d.ticks_lost(), d.bytes_garbled(),
                             read_error.empty() ? "" : "; reading: " + read_error);
        });
      for (std::thread &t : readers) t.join();
      page->ended("the end of the robots' streams");
    };
    return serve_live_page(*page, o.http, o.http_remote, read_team, err);
  }
  // The page stays up after the stream ends, until the monitor is stopped; only a server that
  // cannot listen returns.
  return serve_live_page(
      *page, o.http, o.http_remote, [&] { read(); }, err);
}

}  // namespace

int monitor_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err) {
  MonitorOptions o;
  CLI::App app{"gfec monitor - decodes the live trace of a C engine built with --trace, or of a plan's "
               "afp::LinkTrace (docs/live.md)",
               "gfec monitor"};
  app.footer("The trace comes from stdin, a serial port (--serial) or a TCP connection (--tcp). A frame\n"
             "that cannot be decoded exactly is never shown: the loss is reported and the monitor is\n"
             "exact again from the next full frame.\n"
             "Exit status: 0 the stream ended, 1 errors in the chart or a stream of another chart,\n"
             "2 usage or I/O error.\n" +
             documentation_line("live.md"));
  FrontEndFlags front_end;
  add_options(app, o, front_end);
  if (auto code = parse_subcommand(app, argc, argv, out, err, "monitor")) return *code;
  o.silence_given = app.get_option("--silence")->count() > 0;
  o.report.line_numbers = false;
  std::string why = front_end.apply(o.report);
  if (why.empty() && !o.serial.empty() && !o.tcp.empty()) why = "--serial and --tcp: give one source";
  if (why.empty() && !o.log && o.http.empty()) why = "nothing to show: give --log or --http HOST:PORT";
  if (why.empty() && !o.http.empty()) {
    // The address is checked before the chart is compiled and drawn or a source opened.
    std::string host;
    int port = 0;
    why = live::parse_address(o.http, host, port);
    if (why.empty()) why = live::refuse_host(host, o.http_remote);
    if (!why.empty()) why = "--http " + o.http + ": " + why;
  }
  if (why.empty() && o.robots > 1 && (o.tcp.empty() || o.http.empty() || o.log))
    why = "--robots: several robots' streams come over --tcp and show on one --http page (no --log)";
  if (!why.empty()) {
    err << "gfec: error: " << text::printable(why) << "\nRun 'gfec monitor --help' for the options.\n";
    return kExitUsageOrIo;
  }
  auto report = make_report(o.report, err);
  return finish_report(*report, monitor_with(o, *report, out, err), err);
}

}  // namespace gfec
