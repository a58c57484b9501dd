#include "test_command.h"

#include "commands.h"
#include "escape.h"
#include "diagnostic_printer.h"
#include "diagnostic_report.h"
#include "driver.h"
#include "output_files.h"
#include "pipeline/compilation.h"
#include "scenario/reference_run.h"
#include "scenario/scenario.h"
#include "scenario/snapshot.h"
#include "child_process.h"
#include "test_engine.h"
#include "xml_text.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <pthread.h>
#include <unistd.h>
#include <memory>
#include <ostream>
#include <set>
#include <thread>

namespace gfec {

namespace {

struct TestOptions {
  std::vector<std::string> files;
  std::string junit;
  std::string filter;
  bool engine_only = false;
  bool reference_only = false;
  bool verbose = false;
  unsigned jobs = 1;
  Options report;  ///< -I, -x, -W..., -f...: as gfec's (add_front_end_options)
};

pipeline::FrontEndOptions test_front_end(const TestOptions &o) {
  pipeline::FrontEndOptions f = front_end_options(o.report);
  f.analyze = false;  // the tests say what the chart must do; the analyses are gfec's business
  return f;
}

/// One test file through the front end (pipeline/compilation.h).
struct TestFile {
  explicit TestFile(const TestOptions &o) : c(test_front_end(o)) {}
  std::string path;
  pipeline::Compilation c;
  SourceManager &sources = c.sources;
  Diagnostics &diag = c.diag;
  LoadResult &loaded = c.loaded;
  model::Model &model = c.model;
  scenario::Suite suite;
  bool unreadable = false;
  std::string unreadable_why;  ///< "cannot read 'x.test': ...", when unreadable
  /// What the file stands for in the results when it cannot run: each `test` block written in
  /// it that --filter selects, or the file itself when it declares none.
  std::vector<std::string> broken_tests(const std::string &filter) const {
    if (suite.written.empty()) return {path};
    std::vector<std::string> out;
    for (const std::string &name : suite.written)
      if (filter.empty() || name.find(filter) != std::string::npos) out.push_back(name);
    return out;
  }
};

/// What one test gave.
struct Outcome {
  TestFile *file = nullptr;
  const scenario::Test *test = nullptr;
  Diagnostics diag{WarningOptions{}, static_cast<std::size_t>(-1)};
  double seconds = 0;
  bool passed() const { return !diag.has_errors(); }
};

/// The text a range covers, on one line: an expectation as the user wrote it.
std::string text_of(const SourceManager &sources, SourceRange r) {
  const std::string &text = sources.file(r.file).text();
  std::string out;
  bool space = false;
  for (std::uint32_t i = r.begin; i < r.end && i < text.size(); ++i) {
    char c = text[i];
    if (c == '\n' || c == '\r' || c == '\t' || c == ' ') {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    out += c;
  }
  return out;
}

/// Whether an expectation asks about calls (its failure then lists the tick's calls).
bool reads_calls(const scenario::Expect &e) {
  if (e.kind == scenario::Expect::Kind::Called || e.kind == scenario::Expect::Kind::Calls) return true;
  for (const auto &a : e.args)
    if (reads_calls(a)) return true;
  return false;
}

/// The `called` and `calls` operands of an expectation, in source order.
void call_operands(const scenario::Expect &e, std::vector<const scenario::Expect *> &out) {
  if (e.kind == scenario::Expect::Kind::Called || e.kind == scenario::Expect::Kind::Calls) out.push_back(&e);
  for (const auto &a : e.args) call_operands(a, out);
}

/// The range of the `tick` step that ran tick `tick` (counted from 1).
SourceRange tick_step(const scenario::Test &test, std::uint64_t tick) {
  std::uint64_t seen = 0;
  for (const scenario::Step &s : test.steps) {
    if (s.kind != scenario::Step::Kind::Tick) continue;
    seen += s.count;
    if (seen >= tick) return s.range;
  }
  return test.range;
}

class TestRunner {
public:
  TestRunner(const TestOptions &o, EngineBuilds &builds) : o_(o), builds_(builds) {}

  void run(Outcome &out, int id) {
    auto start = std::chrono::steady_clock::now();
    const scenario::Test &test = *out.test;
    TestFile &file = *out.file;
    const model::Model &m = file.model;
    std::optional<scenario::Run> ref, eng;
    const std::set<std::uint64_t> keep = scenario::expectation_ticks(test);
    if (!o_.engine_only) ref = scenario::run_reference(m, test, &keep);
    EngineBuilds::Build b;
    if (!o_.reference_only) {
      b = builds_.get(m, test.chart, chart_file(file, test.chart), test.agents);
      if (b.program.empty()) {
        auto &d = out.diag.error(test.range, ErrorKind::TestEngine,
                                 fmt::format("cannot build the C engine for '{}'", m.charts[test.chart].name));
        // The compiler's output, a note a line: a message is printed on one line, its line
        // breaks escaped (a line of its own could forge a diagnostic or a CI command).
        for (std::size_t at = 0, nl; at < b.error.size(); at = nl + 1) {
          nl = b.error.find('\n', at);
          if (nl == std::string::npos) nl = b.error.size();
          if (nl > at) d.note(b.error.substr(at, nl - at));
        }
      } else {
        eng = builds_.run(b, m, test, id, &keep);
      }
    }
    stopped(out, ref, "the reference interpreter");
    stopped(out, eng, "the C engine");
    if (ref && eng) disagreement(out, *ref, *eng, b, id);
    expectations(out, ref ? &*ref : nullptr, eng ? &*eng : nullptr);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

private:
  static std::string chart_file(const TestFile &file, model::ChartId chart) {
    SourceRange r = file.model.charts[chart].range;
    return file.sources.file(r.file).path();
  }

  void stopped(Outcome &out, const std::optional<scenario::Run> &run, const char *who) {
    if (!run || run->error.empty()) return;
    SourceRange at = run->error_located ? run->error_range : out.test->range;
    out.diag.error(at, ErrorKind::TestRun, fmt::format("{} stopped: {}", who, run->error))
        .note(fmt::format("in test \"{}\"", out.test->name));
  }

  /// The first tick at which the two runs differ, and the first difference in it. The runs
  /// kept digests of most ticks: the records of a tick whose digests differ are made again by
  /// running both once more, keeping that tick (both are deterministic).
  void disagreement(Outcome &out, const scenario::Run &ref, const scenario::Run &eng, const EngineBuilds::Build &b,
                    int id) {
    const model::Model &m = out.file->model;
    const scenario::Test &test = *out.test;
    const std::uint64_t n = std::min(ref.recorded(), eng.recorded());
    for (std::uint64_t k = 0; k < n; ++k) {
      if (ref.digests[k] == eng.digests[k]) continue;
      std::optional<scenario::Run> ref_again, eng_again;
      const std::set<std::uint64_t> just{k};
      const scenario::Run *x = &ref, *y = &eng;
      if (!x->at(k)) x = &ref_again.emplace(scenario::run_reference(m, test, &just));
      if (!y->at(k)) y = &eng_again.emplace(builds_.run(b, m, test, id, &just));
      if (!x->at(k) || !y->at(k)) continue;
      const std::vector<scenario::Snapshot> &rx = *x->at(k), &ry = *y->at(k);
      std::string diff;
      std::size_t agent = 0;
      for (; agent < rx.size() && agent < ry.size() && diff.empty(); ++agent)
        diff = scenario::compare(rx[agent], ry[agent], m, test.chart, "reference", "engine");
      if (diff.empty()) continue;
      SourceRange at = k == 0 ? out.test->range : tick_step(*out.test, k);
      std::string what = k == 0 ? "after _init" : fmt::format("at tick {}", k);
      if (out.test->agents > 1) what += fmt::format(" (agent {})", agent - 1);
      bool call = diff.rfind("call ", 0) == 0;
      out.diag
          .error(at, ErrorKind::TestDisagreement,
                 fmt::format("the reference interpreter and the C engine disagree {}: {}", what,
                             call ? "first differing " + diff : diff))
          .note("a verbatim %{ %} block runs only in the C engine; otherwise this is a bug in gfec")
          .note(fmt::format("in test \"{}\"", out.test->name));
      return;
    }
  }

  void expectations(Outcome &out, const scenario::Run *ref, const scenario::Run *eng) {
    const scenario::Test &test = *out.test;
    const TestFile &file = *out.file;
    std::uint64_t tick = 0;
    for (const scenario::Step &s : test.steps) {
      if (s.kind == scenario::Step::Kind::Tick) tick += s.count;
      if (s.kind != scenario::Step::Kind::Expect) continue;
      struct Side {
        const char *who;
        std::optional<scenario::Verdict> verdict;
      } sides[2] = {{"the reference interpreter", std::nullopt}, {"the C engine", std::nullopt}};
      const scenario::Run *runs[2] = {ref, eng};
      const std::size_t agent = static_cast<std::size_t>(s.expect_agent());
      for (int i = 0; i < 2; ++i)
        if (runs[i] && runs[i]->at(tick) && agent < runs[i]->at(tick)->size())
          sides[i].verdict = scenario::evaluate(s.expect, runs[i]->at(tick)->at(agent), file.model, test.chart);
      auto failed = [](const Side &x) { return x.verdict && (!x.verdict->holds || !x.verdict->error.empty()); };
      if (!failed(sides[0]) && !failed(sides[1])) continue;
      const Side &bad = failed(sides[0]) ? sides[0] : sides[1];
      const scenario::Run &bad_run = *runs[&bad == &sides[0] ? 0 : 1];
      auto &d = out.diag.error(s.range, ErrorKind::Expectation,
                               fmt::format("expectation failed: {}", text_of(file.sources, s.expect.range)));
      if (!bad.verdict->error.empty()) d.note(fmt::format("it has no defined value: {}", bad.verdict->error));
      std::vector<std::string> said;  // an operand written twice is told once
      for (const scenario::Operand &op : bad.verdict->operands) {
        std::string note = fmt::format("'{}' is {}", text_of(file.sources, op.range), op.value);
        if (std::find(said.begin(), said.end(), note) != said.end()) continue;
        d.note(note);
        said.push_back(std::move(note));
      }
      if (reads_calls(s.expect)) {
        std::string calls;
        for (const scenario::Call &c : bad_run.at(tick)->at(agent).calls) calls += (calls.empty() ? "" : ", ") + c.text;
        d.note(calls.empty() ? std::string("no function was called in the last tick")
                             : fmt::format("the calls of the last tick: {}", calls));
        last_calls(d, test, file, s.expect, agent, tick);
      }
      if (sides[0].verdict && sides[1].verdict && failed(sides[0]) != failed(sides[1]))
        d.note(
            fmt::format("it fails on {} only; it holds on {}", bad.who, (&bad == &sides[0] ? sides[1] : sides[0]).who));
      d.note(test.agents > 1 ? fmt::format("in test \"{}\", agent {}, after tick {}", test.name, agent, tick)
                             : fmt::format("in test \"{}\", after tick {}", test.name, tick));
    }
  }

  /// When each function the expectation asks about was last called (on the reference run): a
  /// call expected at the wrong tick is the usual mistake (the first tick of an initial place).
  static void last_calls(Diagnostic &d, const scenario::Test &test, const TestFile &file, const scenario::Expect &e,
                         std::size_t agent, std::uint64_t tick) {
    constexpr std::uint64_t kWindow = 100000;  // a longer look back would keep too many records
    if (tick == 0) return;                     // before the first tick nothing was called
    std::vector<const scenario::Expect *> operands;
    call_operands(e, operands);
    std::vector<std::string> said;  // an operand written twice is told once
    for (const scenario::Expect *op : operands) {
      const model::Function &fn = file.model.functions.at(op->function);
      std::string name = std::string(fn.name);
      if (op->call_args) {  // `Led(false)` as the test wrote it
        const std::string written = text_of(file.sources, op->range);
        const std::size_t at = written.find(name);
        if (at != std::string::npos) name = written.substr(at);
      }
      if (std::find(said.begin(), said.end(), name) != said.end()) continue;
      said.push_back(name);
      const auto last = scenario::last_call(file.model, test, op->function, op->call_args, agent, tick, kWindow);
      if (last && last->tick == tick) continue;  // the calls of the last tick are listed already
      if (last) d.note(fmt::format("'{}' was last called in tick {}: {}", name, last->tick, last->text));
      else if (tick <= kWindow) d.note(fmt::format("'{}' was not called in any tick so far (1 ... {})", name, tick));
      else d.note(fmt::format("'{}' was not called in the {} ticks up to tick {}", name, kWindow, tick));
    }
  }

  const TestOptions &o_;
  EngineBuilds &builds_;
};

void load(TestFile &f) {
  RealFileSystem fs;
  f.c.front_end(f.path, fs, &f.suite);
  if (f.c.unreadable()) {
    f.unreadable = true;
    f.unreadable_why = f.c.cannot_read_main(f.path);
  }
  // A file with nothing to run is a mistake of the command line a CI step must not pass green
  // (a glob that picked the charts instead of their tests).
  else if (!f.diag.has_errors() && f.suite.written.empty())
    f.diag.error({f.model.main_file, 0, 0}, ErrorKind::Test, fmt::format("'{}' declares no test", f.path))
        .note("a file given to 'gfec test' holds 'test \"NAME\" of CHART { ... }' blocks (docs/testing-charts.md)");
}

/// JUnit XML: a testsuite per file, a testcase per test; the tests of a file that does not
/// compile are failed testcases (the file's errors in each), and a file without tests that
/// cannot run is one failed testcase named after the file: the totals are the summary line's.
std::string junit(const std::vector<std::unique_ptr<TestFile>> &files,
                  const std::vector<std::unique_ptr<Outcome>> &outcomes, const std::string &filter) {
  std::size_t total = 0, failures = 0;
  std::string suites;
  for (const auto &f : files) {
    std::string cases;
    std::size_t n = 0, failed = 0;
    double time = 0;
    auto failure = [&](const std::string &name, const Diagnostics &diag, const SourceManager &sources, double seconds) {
      std::string first, all;
      for (const auto &d : diag.all()) {
        if (d.severity != Severity::Error) continue;
        std::string text = render_text(d, sources);
        if (first.empty()) first = text.substr(0, text.find('\n'));
        all += text;
      }
      ++n;
      time += seconds;
      cases += fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"{:.3f}\"", text::xml_escape(name),
                           text::xml_escape(f->path), seconds);
      if (first.empty()) {
        cases += "/>\n";
        return;
      }
      ++failed;
      cases += fmt::format(">\n      <failure message=\"{}\" type=\"expectation\">{}</failure>\n    </testcase>\n",
                           text::xml_escape(first), text::xml_escape(all));
    };
    if (f->unreadable) {
      ++n;
      ++failed;
      cases += fmt::format("    <testcase name=\"{0}\" classname=\"{0}\" time=\"0.000\">\n      <failure "
                           "message=\"cannot read '{0}'\" type=\"io\"/>\n    </testcase>\n",
                           text::xml_escape(f->path));
    } else if (f->diag.has_errors()) {
      for (const std::string &name : f->broken_tests(filter)) failure(name, f->diag, f->sources, 0);
    }
    for (const auto &o : outcomes)
      if (o->file == f.get()) failure(o->test->name, o->diag, f->sources, o->seconds);
    suites += fmt::format(
        "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.3f}\">\n{}  </testsuite>\n",
        text::xml_escape(f->path), n, failed, time, cases);
    total += n;
    failures += failed;
  }
  return fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"gfec test\" tests=\"{}\" "
                     "failures=\"{}\" errors=\"0\">\n{}</testsuites>\n",
                     total, failures, suites);
}

/// For the lifetime of a `gfec test` run, SIGINT, SIGTERM and SIGHUP are held back in every
/// thread and taken by one watcher, which stops the C compilers and harnesses still running
/// (their process groups), removes the build folder, then lets the signal act: a stopped run
/// leaves nothing in TMPDIR and no child behind (docs/security.md).
class StopOnSignal {
public:
  explicit StopOnSignal(std::string folder) : folder_(std::move(folder)) {
    sigemptyset(&set_);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set_, s);
    pthread_sigmask(SIG_BLOCK, &set_, &old_);  // before any worker starts: they inherit it
    watcher_ = std::thread([this] {
      while (!done_) take(100);
    });
  }
  ~StopOnSignal() {
    done_ = true;
    watcher_.join();
    take(0);  // one that came as the watcher ended
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  StopOnSignal(const StopOnSignal &) = delete;
  StopOnSignal &operator=(const StopOnSignal &) = delete;

private:
  void take(long wait_ms) {
    timespec wait{0, wait_ms * 1000000L};
    const int sig = sigtimedwait(&set_, nullptr, &wait);
    if (sig <= 0) return;
    child_process::stop_all(1.0);
    std::error_code ignored;
    if (!folder_.empty()) std::filesystem::remove_all(folder_, ignored);
    // The signal's own action now, in this thread: safe_output's handler while the JUnit file
    // is being written (it removes its temporary), else the default, which ends gfec.
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, sig);
    pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
    raise(sig);
    _exit(128 + sig);
  }

  std::string folder_;
  sigset_t set_, old_;
  std::atomic<bool> done_{false};
  std::thread watcher_;
};

int test_with(const TestOptions &o, std::ostream &out, std::ostream &err) {
  auto report = make_report(o.report, err);
  std::vector<std::unique_ptr<TestFile>> files;
  std::vector<std::unique_ptr<Outcome>> outcomes;
  bool io_error = false;
  std::size_t broken = 0;  ///< tests in files that do not compile: each counts as failed
  for (const auto &path : o.files) {
    auto f = std::make_unique<TestFile>(o);
    f->path = path;
    load(*f);
    if (f->unreadable) {
      io_error = true;
      broken += 1;
    } else if (f->diag.has_errors()) {
      broken += f->broken_tests(o.filter).size();
    } else {
      for (const auto &t : f->suite.tests) {
        if (!o.filter.empty() && t.name.find(o.filter) == std::string::npos) continue;
        auto oc = std::make_unique<Outcome>();
        oc->file = f.get();
        oc->test = &t;
        outcomes.push_back(std::move(oc));
      }
    }
    files.push_back(std::move(f));
  }

  EngineBuilds builds;
  if (!o.reference_only && !builds.ok()) {
    report->tool_error("", "cannot create a temporary folder for the C engines", false);
    report->finish(kExitUsageOrIo);
    return kExitUsageOrIo;
  }
  StopOnSignal stop_on_signal(builds.folder());
  if (!o.reference_only && !outcomes.empty()) {
    // One clear error rather than every test failing on its own (docs/testing-charts.md).
    std::vector<std::string> notes;
    if (!builds.choose_compiler(notes)) {
      std::string message = "no C compiler builds programs for this machine, so the generated engines cannot run";
      for (const std::string &n : notes) message += "\n  tried " + n;
      message += "\n  install one (Debian: gcc), name it in $HOST_CC, or run only the reference interpreter with "
                 "'gfec test --reference-only'";
      report->tool_error("", message, false);
      report->finish(kExitUsageOrIo);
      return kExitUsageOrIo;
    }
    if (!notes.empty())
      err << fmt::format("gfec test: note: the engines are built with '{}': {}\n", builds.compiler(), notes.front());
  }
  TestRunner runner(o, builds);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i; (i = next++) < outcomes.size();) runner.run(*outcomes[i], static_cast<int>(i));
  };
  unsigned jobs = std::max(1u, std::min<unsigned>(o.jobs, static_cast<unsigned>(outcomes.size())));
  std::vector<std::thread> threads;
  for (unsigned j = 1; j < jobs; ++j) threads.emplace_back(worker);
  worker();
  for (auto &t : threads) t.join();

  std::size_t passed = 0, failed = broken;
  for (const auto &f : files) {
    if (f->unreadable) {
      report->tool_error(f->path, f->unreadable_why, false);
      continue;
    }
    report->add(f->path, f->diag, f->sources);
    for (const auto &oc : outcomes) {
      if (oc->file != f.get()) continue;
      report->add(f->path, oc->diag, f->sources);
      if (oc->passed()) ++passed;
      else ++failed;
      if (o.verbose)
        out << fmt::format("{} {}: {}\n", oc->passed() ? "PASS" : "FAIL", text::printable(f->path),
                           text::printable(oc->test->name));
    }
  }
  if (!o.junit.empty()) {
    // Never over a test file or anything it imports (docs/security.md).
    std::vector<std::string> inputs = o.files;
    for (const auto &f : files)
      for (FileId i = 0; i < f->sources.size(); ++i) inputs.push_back(f->sources.file(i).path());
    std::string failure = write_atomically({{o.junit, junit(files, outcomes, o.filter)}}, inputs);
    if (!failure.empty()) {
      report->tool_error(o.junit, failure, false);
      io_error = true;
    }
  }
  int code = io_error ? kExitUsageOrIo : failed > 0 ? kExitInputError : kExitOk;
  code = finish_report(*report, code, err);
  err << std::flush;
  out << fmt::format("{} passed, {} failed\n", passed, failed) << std::flush;
  return code;
}

}  // namespace

int test_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err) {
  TestOptions o;
  CLI::App app{"gfec test - runs the scenario tests of test files on the reference interpreter and on the "
               "generated C engine",
               "gfec test"};
  app.footer("Each test runs on both; it passes when every expectation holds on both and both saw the same\n"
             "calls. The last line is 'N passed, M failed'. The C engine is built with $CC (else cc).\n"
             "Exit status: 0 all passed, 1 a test failed or a file has errors, 2 usage or I/O error.\n" +
             documentation_line("testing-charts.md"));
  app.add_option("files", o.files, "Test files")->required();
  app.add_option("--junit", o.junit, "Also write the results as JUnit XML to FILE")->type_name("FILE");
  app.add_option("--filter", o.filter, "Run only the tests whose name contains TEXT")->type_name("TEXT");
  app.add_flag("--engine-only", o.engine_only, "Run the generated C engine only");
  app.add_flag("--reference-only", o.reference_only, "Run the reference interpreter only (no C compiler needed)");
  app.add_option("-j,--jobs", o.jobs, "Run N tests at once")->type_name("N")->check(CLI::Range(1u, 256u));
  app.add_flag("-v,--verbose", o.verbose, "Print PASS or FAIL and the name of every test");
  FrontEndFlags front_end;
  add_front_end_options(app, o.report, front_end);
  if (auto code = parse_subcommand(app, argc, argv, out, err, "test")) return *code;
  auto usage = [&](const std::string &message) {
    err << "gfec: error: " << text::printable(message) << "\nRun 'gfec test --help' for the options.\n";
    return kExitUsageOrIo;
  };
  if (o.engine_only && o.reference_only) return usage("--engine-only and --reference-only exclude each other");
  if (std::string why = front_end.apply(o.report); !why.empty()) return usage(why);
  return test_with(o, out, err);
}

}  // namespace gfec
