#include "support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace e2e {
namespace {

std::string slurp(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string quote(const std::string &s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::vector<TraceRow> parse_trace(const std::string &text) {
  std::vector<TraceRow> rows;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    TraceRow r{};
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &r.t, &r.x, &r.y, &r.heading) == 4) rows.push_back(r);
  }
  return rows;
}

}  // namespace

std::string source(const std::string &relative) {
  return relative.empty() || relative[0] == '/' ? relative : std::string(GFEC_SOURCE_DIR) + "/" + relative;
}

TempDir::TempDir() {
  std::string templ = (fs::temp_directory_path() / "gfec-e2e-XXXXXX").string();
  if (!mkdtemp(templ.data())) throw std::runtime_error("mkdtemp failed");
  path_ = templ;
}

TempDir::~TempDir() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

SimRun run_sim(const std::string &chart, const std::string &world, double seconds, const std::string &extra) {
  TempDir dir;
  const std::string trace = dir.file("trace.csv"), json = dir.file("result.json"), svg = dir.file("path.svg");
  const std::string log = dir.file("output.txt");
  const std::string cmd = std::string(CARBOT_SIM) + " " + quote(source(chart)) + " --world " + quote(source(world)) +
                          " --seconds " + std::to_string(seconds) + " --trace " + quote(trace) + " --json " +
                          quote(json) + " --svg " + quote(svg) + " " + extra + " >" + quote(log) + " 2>&1";
  const int status = std::system(cmd.c_str());
  SimRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.output = slurp(log);
  if (fs::exists(trace)) {
    run.trace_text = slurp(trace);
    run.trace = parse_trace(run.trace_text);
  }
  if (fs::exists(json)) run.result = nlohmann::json::parse(slurp(json));
  if (fs::exists(svg)) run.svg = slurp(svg);
  return run;
}

bool skipped_for_missing_backend(const SimRun &run) {
  if (run.exit_code == 0 || run.output.find("unknown back end") == std::string::npos) return false;
  std::printf("E2E-SKIP: gfec cannot generate this engine yet:\n%s\n", run.output.c_str());
  return true;
}

carbot::World world(const std::string &relative) { return carbot::load_world(source(relative)); }

}  // namespace e2e
