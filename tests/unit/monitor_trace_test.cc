// The live trace end to end (docs/live.md): engines built with --trace run on random inputs in
// the run harness, whose observable log is the engine's own view of the run; the frames they
// wrote, decoded by gfec monitor's decoder, must give that log exactly (without the call lines,
// which the frames do not carry). Then the same frames garbled, cut short or read against
// another chart: the decoder never shows a wrong tick, says what it lost, is exact again by the
// next full frame, and refuses a stream of another chart.
#include "../run/c_backend_support.h"
#include "random_sfc.h"

#include "byte_source.h"
#include "log_sink.h"
#include "trace_decoder.h"
#include "trace_format.h"

#include <catch2/catch.hpp>

#include <random>

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

using namespace cbt;

namespace {

struct TracedRun {
  std::unique_ptr<Compiled> compiled;
  std::string log;    ///< the engine's observable log, call lines removed
  std::string bytes;  ///< what it handed X_trace_write
};

std::map<std::string, std::string> sample_files(const std::vector<std::string> &names) {
  std::map<std::string, std::string> files;
  for (const auto &n : names) files[n] = read_file(fs::path(GFEC_SOURCE_DIR) / "samples" / n);
  return files;
}

/// Random script lines: each sensing bool function named with a probability of its own.
std::string random_script(const model::Model &m, unsigned seed, int ticks) {
  std::mt19937 rng(seed);
  std::vector<std::pair<std::string, unsigned>> bools;
  for (const auto &f : m.functions)
    if (f.result == model::Type::Bool) bools.emplace_back(f.name, 5 + rng() % 40);
  std::string s;
  for (int t = 0; t < ticks; ++t) {
    std::string line;
    for (const auto &[name, percent] : bools)
      if (rng() % 100 < percent) line += (line.empty() ? "" : " ") + name;
    s += line + "\n";
  }
  return s;
}

TracedRun traced_run(const std::string &test, const std::map<std::string, std::string> &files, const std::string &main,
                     unsigned seed, int ticks, unsigned full_every = 32, EngineForm form = EngineForm::Auto) {
  TracedRun r;
  r.compiled = compile_chart(files, main, "engine.c");
  INFO(r.compiled->errors);
  REQUIRE(!r.compiled->diag.has_errors());
  const model::Model &m = r.compiled->model;
  EmitOptions o;
  o.output_path = "engine.c";
  o.source_name = main;
  o.engine = form;
  auto options = std::make_shared<c_backend::CEngineOptions>();
  options->trace = true;
  options->trace_full_every = full_every;
  o.backend = options;
  o.chart = r.compiled->chart;
  const std::vector<OutputFile> engine = emit_to_memory(*make_c_backend(), m, o);
  fs::path dir = scratch_dir("trace_" + test);
  for (const auto &f : engine) write_file(dir / f.path, f.contents);
  c_backend::HarnessOptions h;
  h.inputs = c_backend::HarnessInputs::Script;
  h.log = c_backend::HarnessLog::Observable;
  h.header = "engine.h";
  const c_backend::HarnessSources harness = c_backend::write_harness(m, o.chart, o, h);
  write_file(dir / "glue.c", harness.glue);
  write_file(dir / "harness.c", harness.main);
  const std::string &name = r.compiled->the_chart().name;
  write_file(dir / "trace_out.c", fmt::format("#include <stdio.h>\n"
                                              "void {}_trace_write(const unsigned char *data, unsigned len);\n"
                                              "void {}_trace_write(const unsigned char *data, unsigned len)\n"
                                              "{{\n"
                                              "    static FILE *out = NULL;\n"
                                              "    if (out == NULL) out = fopen(\"trace.bin\", \"wb\");\n"
                                              "    (void)fwrite(data, 1, len, out);\n"
                                              "    (void)fflush(out);\n"
                                              "}}\n",
                                              name, name));
  write_file(dir / "script.txt", random_script(m, seed, ticks));
  auto build = run_command(fmt::format("cd '{}' && gcc {} -Wconversion glue.c harness.c engine.c trace_out.c -o run",
                                       dir.string(), kStrictFlags),
                           dir / "build.log");
  INFO(build.output);
  REQUIRE(build.status == 0);
  auto run = run_command(fmt::format("cd '{}' && ./run < script.txt", dir.string()), dir / "run.log");
  REQUIRE(run.status == 0);
  std::istringstream lines(run.output);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("call ", 0) != 0) r.log += line + "\n";
  r.bytes = read_file(dir / "trace.bin");
  return r;
}

/// Decodes `bytes` in chunks of `chunk` bytes and returns the log the monitor prints.
std::string decode(const TracedRun &r, const std::string &bytes, std::size_t chunk = 7,
                   std::string *refusal = nullptr) {
  std::ostringstream out;
  monitor::LogSink log(r.compiled->model, r.compiled->chart, out);
  monitor::TraceDecoder decoder(trace::layout_of(r.compiled->model, r.compiled->chart), log);
  const auto *data = reinterpret_cast<const std::uint8_t *>(bytes.data());
  for (std::size_t at = 0; at < bytes.size(); at += chunk) decoder.feed(data + at, std::min(chunk, bytes.size() - at));
  decoder.finish();
  if (refusal) *refusal = decoder.refusal();
  return out.str();
}

/// The log's ticks: tick number -> its lines.
std::map<std::uint32_t, std::string> ticks_of(const std::string &log) {
  std::map<std::uint32_t, std::string> ticks;
  std::istringstream lines(log);
  std::uint32_t tick = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("#", 0) == 0) continue;
    if (line.rfind("tick ", 0) == 0) tick = static_cast<std::uint32_t>(std::stoul(line.substr(5)));
    ticks[tick] += line + "\n";
  }
  return ticks;
}

/// Every tick the garbled stream shows is the clean run's tick, and a loss is reported.
void check_garbled(const TracedRun &r, const std::string &bytes, std::uint32_t exact_from) {
  const std::string log = decode(r, bytes, 5);
  INFO(log);
  CHECK(log.find("# lost") != std::string::npos);
  const auto clean = ticks_of(r.log);
  const auto shown = ticks_of(log);
  for (const auto &[tick, text] : shown) {
    REQUIRE(clean.count(tick) == 1);
    CHECK(text == clean.at(tick));
  }
  for (std::uint32_t t = exact_from; t <= clean.rbegin()->first; ++t) CHECK(shown.count(t) == 1);
}

}  // namespace

TEST_CASE("traced engines: the decoded frames give the engine's observable log", "[monitor][compile]") {
  struct Sample {
    std::vector<std::string> files;
    std::string main;
  };
  const Sample samples[] = {
      {{"line_follower.sfc", "linebot.iface"}, "line_follower.sfc"},
      {{"mission.fsm", "line_follower.sfc", "linebot.iface", "cleanup.fsm", "cleanbot.iface"}, "mission.fsm"},
      {{"fetch_team.fsm", "fetchbot.iface"}, "fetch_team.fsm"},
      {{"work_cell.sfc", "cellbot.iface"}, "work_cell.sfc"}};
  for (const auto &s : samples) {
    SECTION(s.main) {
      for (unsigned every : {32u, 1u, 5u}) {
        // Both engine forms write the same frames: they read the activation as X_activation does.
        const EngineForm form = every == 5 ? EngineForm::Scalable : EngineForm::Readable;
        const TracedRun r = traced_run(s.main, sample_files(s.files), s.main, 7 + every, 150, every, form);
        INFO(s.main << " every " << every << (form == EngineForm::Scalable ? " scalable" : " readable"));
        REQUIRE(!r.bytes.empty());
        CHECK(decode(r, r.bytes) == r.log);
        CHECK(decode(r, r.bytes, 1) == r.log);
        CHECK(decode(r, r.bytes, 4096) == r.log);
      }
    }
  }
}

TEST_CASE("traced random sfcs: the decoded frames give the engine's observable log", "[monitor][compile]") {
  // Joins, forks and self-loops pile up activation: values past 127 take several bytes.
  bool wide = false;
  for (unsigned seed = 1; seed <= 12; ++seed) {
    const std::map<std::string, std::string> files{{"random.sfc", random_sfc(seed)}};
    const EngineForm form = seed % 2 == 0 ? EngineForm::Scalable : EngineForm::Readable;
    const TracedRun r = traced_run(fmt::format("random{}", seed), files, "random.sfc", seed, 200, 1 + seed % 40, form);
    INFO("seed " << seed << "\n" << files.at("random.sfc"));
    CHECK(decode(r, r.bytes, 3) == r.log);
    wide = wide || r.log.find_first_of("0123456789") != std::string::npos &&
                       std::any_of(ticks_of(r.log).begin(), ticks_of(r.log).end(), [](const auto &t) {
                         std::istringstream words(t.second.substr(t.second.find("av")));
                         std::string w;
                         words >> w;
                         for (unsigned long v; words >> v;)
                           if (v > 127) return true;
                         return false;
                       });
  }
  CHECK(wide);
}

TEST_CASE("a garbled, cut or foreign trace: never a wrong tick, the loss said, exact again", "[monitor][compile]") {
  const auto files = sample_files({"line_follower.sfc", "linebot.iface"});
  const TracedRun r = traced_run("garbled", files, "line_follower.sfc", 3, 200);
  REQUIRE(decode(r, r.bytes) == r.log);
  // Where each frame begins: every frame is found by its sync bytes and its length.
  std::vector<std::size_t> starts;
  for (std::size_t at = 0; at + trace::kHeaderBytes <= r.bytes.size();) {
    starts.push_back(at);
    const std::size_t length = static_cast<unsigned char>(r.bytes[at + 4]) |
                               static_cast<std::size_t>(static_cast<unsigned char>(r.bytes[at + 5])) << 8;
    at += trace::kHeaderBytes + length + trace::kCrcBytes;
  }
  REQUIRE(starts.size() == 200);

  SECTION("a flipped bit in a frame of changes: that tick and those up to the next full frame are lost") {
    std::string bytes = r.bytes;
    bytes[starts[40] + 10] = static_cast<char>(bytes[starts[40] + 10] ^ 0x04);  // tick 41's tick number
    check_garbled(r, bytes, 65);
    CHECK(ticks_of(decode(r, bytes)).count(41) == 0);
  }
  SECTION("a flipped byte in every part of a frame: never a wrong tick") {
    for (std::size_t k = 0; k < 20; ++k) {
      std::string bytes = r.bytes;
      const std::size_t at = starts[70] + k % (starts[71] - starts[70]);
      bytes[at] = static_cast<char>(bytes[at] ^ (1 << (k % 8)));
      check_garbled(r, bytes, 97);
    }
  }
  SECTION("dropped bytes: resynchronised on the next frame") {
    std::string bytes = r.bytes;
    bytes.erase(starts[100] + 3, 9);
    check_garbled(r, bytes, 129);
  }
  SECTION("noise between frames and whole frames missing") {
    std::string bytes =
        r.bytes.substr(0, starts[10]) + std::string("\xA7\x5E\x01garbage\xA7", 11) + r.bytes.substr(starts[15]);
    const std::string log = decode(r, bytes);
    CHECK(log.find("# lost") != std::string::npos);
    check_garbled(r, bytes, 33);
  }
  SECTION("a stream cut inside a frame") {
    const std::string log = decode(r, r.bytes.substr(0, starts[150] + 6));
    CHECK(log.find("# lost: the stream ended inside a frame (6 bytes)") != std::string::npos);
    CHECK(ticks_of(log).size() == 150);
  }
  SECTION("a monitor that joins the run late waits for a full frame") {
    const std::string log = decode(r, r.bytes.substr(starts[50] + 1));
    CHECK(ticks_of(log).begin()->first == 65);
    CHECK(log.find("# lost 64 ticks") != std::string::npos);
  }
  SECTION("a stream of another chart is refused with both fingerprints") {
    const TracedRun other =
        traced_run("other", sample_files({"work_cell.sfc", "cellbot.iface"}), "work_cell.sfc", 3, 5);
    std::string refusal;
    const std::string log = decode(r, other.bytes, 64, &refusal);
    CHECK(log.empty());
    CHECK(refusal.find("another chart") != std::string::npos);
    CHECK(refusal.find(fmt::format("{:08x}", trace::layout_of(r.compiled->model, r.compiled->chart).fingerprint)) !=
          std::string::npos);
  }
}

namespace {

/// Collects what read_stream reports.
class CountingSink : public monitor::RunSink {
public:
  void started(std::size_t) override {}
  void tick(const monitor::DecodedTick &) override {}
  void lost(std::size_t, std::uint64_t, const std::string &) override {}
  void silent(double seconds) override { silences.push_back(seconds); }
  void ended(const std::string &) override {}
  std::vector<double> silences;
};

}  // namespace

TEST_CASE("a serial port: termios raw mode on a pseudo-terminal, the bytes as written", "[monitor]") {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  REQUIRE(master >= 0);
  REQUIRE(::grantpt(master) == 0);
  REQUIRE(::unlockpt(master) == 0);
  const std::string device = ::ptsname(master);
  std::string error;
  CHECK(monitor::open_serial(device, 12345, error) < 0);
  CHECK(error.find("not a rate") != std::string::npos);
  const int fd = monitor::open_serial(device, 115200, error);
  INFO(error);
  REQUIRE(fd >= 0);
  // Raw mode: bytes a terminal would treat (CR, ^C, ^D, 0xFF) arrive as they are.
  const std::string sent("\xA7\x5E\r\n\x03\x04\xFF\x11\x13", 9);
  REQUIRE(::write(master, sent.data(), sent.size()) == static_cast<ssize_t>(sent.size()));
  std::string got;
  CountingSink sink;
  const std::string why = monitor::read_stream(
      fd, 0.2, sink, [&](const unsigned char *d, std::size_t n) { got.append(reinterpret_cast<const char *>(d), n); },
      [&] { return got.size() >= sent.size() || !sink.silences.empty(); });
  CHECK(why.empty());
  CHECK(got == sent);
  ::close(fd);
  ::close(master);
  CHECK(monitor::open_serial("/dev/null", 115200, error) < 0);
  CHECK(error.find("not a serial port") != std::string::npos);
}
