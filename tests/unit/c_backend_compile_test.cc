// The golden engines (tests/golden/c) as a C compiler and cppcheck see them: warning-free with
// gcc and clang at -std=c99 and -std=c11, -Wall -Wextra -Wpedantic -Werror, with and without
// the hooks and the checks; the header usable from C++; every `#line` back to the engine naming
// the line that follows it.
#include "../run/c_backend_support.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace cbt;

namespace {

const fs::path kGoldenDir = fs::path(GFEC_SOURCE_DIR) / "tests" / "golden" / "c";

struct GoldenEngine {
  std::string stem;   ///< "line_follower"
  std::string chart;  ///< "LineFollower": the prefix of the macros
};

/// The golden cases, each with its chart's name (from the header's hooks macro).
std::vector<GoldenEngine> golden_engines() {
  std::vector<GoldenEngine> engines;
  for (const auto &entry : fs::directory_iterator(kGoldenDir)) {
    if (entry.path().extension() != ".h") continue;
    std::string header = read_file(entry.path());
    auto at = header.find("_HOOKS\n");
    REQUIRE(at != std::string::npos);
    auto begin = header.rfind("#ifdef ", at) + 7;
    engines.push_back({entry.path().stem().string(), header.substr(begin, at - begin)});
  }
  std::sort(engines.begin(), engines.end(), [](const auto &a, const auto &b) { return a.stem < b.stem; });
  return engines;
}

fs::path copy_engine(const GoldenEngine &e, const std::string &test) {
  fs::path dir = scratch_dir(test + "_" + e.stem);
  for (const char *ext : {".c", ".h"}) fs::copy_file(kGoldenDir / (e.stem + ext), dir / (e.stem + ext));
  return dir;
}

}  // namespace

TEST_CASE("c engine compile: golden engines are warning-free in every configuration", "[c_backend][compile]") {
  auto engines = golden_engines();
  REQUIRE(engines.size() >= 4);
  if (!have_tool("clang")) WARN("clang is not installed: the generated code is compiled with gcc only");
  for (const auto &e : engines) {
    fs::path dir = copy_engine(e, "warnings");
    for (const auto &cc : c_compilers())
      for (const char *std : {"c99", "c11"})
        for (const auto &defines : std::vector<std::string>{"", "-D" + e.chart + "_HOOKS", "-D" + e.chart + "_CHECKS",
                                                            "-D" + e.chart + "_HOOKS -D" + e.chart + "_CHECKS"}) {
          auto r =
              run_command(fmt::format("cd '{}' && {} -std={} -Wall -Wextra -Wpedantic -Werror {} -c {}.c -o /dev/null",
                                      dir.string(), cc, std, defines, e.stem),
                          dir / "build.log");
          INFO(e.stem << ": " << cc << " -std=" << std << " " << defines << "\n" << r.output);
          CHECK(r.status == 0);
        }
  }
}

TEST_CASE("c engine compile: the header is valid C++", "[c_backend][compile]") {
  for (const auto &e : golden_engines()) {
    fs::path dir = copy_engine(e, "cplusplus");
    write_file(dir / "user.cpp", fmt::format("#include \"{}.h\"\nint main() {{ {} m; {}_init(&m); return 0; }}\n",
                                             e.stem, e.chart, e.chart));
    auto r =
        run_command(fmt::format("cd '{}' && g++ -std=c++17 -Wall -Wextra -Wpedantic -Werror -D{}_HOOKS -c user.cpp "
                                "-o /dev/null",
                                dir.string(), e.chart),
                    dir / "build.log");
    INFO(e.stem << "\n" << r.output);
    CHECK(r.status == 0);
  }
}

TEST_CASE("c engine compile: the header declares the API as the language writes its prototypes",
          "[c_backend][compile]") {
  // A caller may declare the functions itself (or take their addresses) exactly as
  // docs/language.md §5.2 and §7 write them: any other return or parameter type is a
  // "conflicting types" error.
  for (const auto &e : golden_engines()) {
    fs::path dir = copy_engine(e, "prototypes");
    std::string header = read_file(dir / (e.stem + ".h"));
    const std::string &x = e.chart;
    std::string user = fmt::format("#include \"{0}.h\"\n"
                                   "void {1}_init({1} *m);\n"
                                   "void {1}_run({1} *m);\n"
                                   "unsigned {1}_activation(const {1} *m, int place);\n",
                                   e.stem, x);
    const bool fsm = header.find(x + "_status(") != std::string::npos;
    if (fsm)
      user += fmt::format("int {0}_state(const {0} *m);\nint {0}_status(const {0} *m);\n"
                          "int (*state_of)(const {0} *) = {0}_state;\n",
                          x);
    user += fmt::format("unsigned (*activation_of)(const {0} *, int) = {0}_activation;\n", x);
    write_file(dir / "user.c", user);
    for (const auto &cc : c_compilers()) {
      auto r = run_command(fmt::format("cd '{}' && {} {} -c user.c -o /dev/null", dir.string(), cc, kStrictFlags),
                           dir / "build.log");
      INFO(e.stem << " (" << (fsm ? "fsm" : "sfc") << "): " << cc << "\n" << user << r.output);
      CHECK(r.status == 0);
    }
  }
}

TEST_CASE("c engine compile: cppcheck finds nothing", "[c_backend][compile]") {
  if (!have_tool("cppcheck")) {
    WARN("cppcheck is not installed: skipped");
    return;
  }
  for (const auto &e : golden_engines()) {
    fs::path dir = copy_engine(e, "cppcheck");
    for (const auto &defines : std::vector<std::string>{"", "-D" + e.chart + "_HOOKS -D" + e.chart + "_CHECKS"}) {
      auto r =
          run_command(fmt::format("cd '{}' && cppcheck -q --std=c99 --enable=warning,style,performance,portability "
                                  "--suppress=missingIncludeSystem --error-exitcode=1 {} {}.c",
                                  dir.string(), defines, e.stem),
                      dir / "cppcheck.log");
      INFO(e.stem << " " << defines << "\n" << r.output);
      CHECK(r.status == 0);
      CHECK(r.output.empty());
    }
  }
}

TEST_CASE("c engine compile: each #line back to the engine names the line after it", "[c_backend][compile]") {
  for (const auto &e : golden_engines()) {
    std::istringstream in(read_file(kGoldenDir / (e.stem + ".c")));
    std::string line, back = fmt::format("\"{}.c\"", e.stem);
    long expected = -1;
    for (long number = 1; std::getline(in, line); ++number) {
      if (expected >= 0) {
        INFO(e.stem << ".c line " << number);
        CHECK(number == expected);
        expected = -1;
      }
      if (line.rfind("#line ", 0) == 0 && line.size() > back.size() &&
          line.compare(line.size() - back.size(), back.size(), back) == 0)
        expected = std::stol(line.substr(6));
    }
  }
}
