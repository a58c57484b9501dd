// The command table (driver/commands.h) and the options every command shares
// (add_front_end_options): `gfec run` and `gfec test` read -I, -x, -W, -w and -f as gfec does.
#include "commands.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace gfec;

namespace {

struct Ran {
  int code = 0;
  std::string out, err;
  std::string first_err_line() const { return err.substr(0, err.find('\n')); }
};

/// `gfec ARGS...` as main runs it.
Ran run_gfec(std::vector<const char *> args) {
  args.insert(args.begin(), "gfec");
  std::ostringstream out, err;
  Ran r;
  r.code = dispatch(static_cast<int>(args.size()), args.data(), out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

/// A scratch folder holding a chart with one warning (an unreachable place) and a test of it;
/// the commands run with it as the current folder.
struct Charts {
  Charts() {
    char name[] = "/tmp/gfec_commands_XXXXXX";
    dir = mkdtemp(name);
    write("robot.iface", "interface Robot { bool Ready(); void Go(); }\n");
    write("warn.sfc", "import \"robot.iface\";\n"
                      "sfc Warn { initial place A { Go(); } place B; place Island; A -> B when Ready(); B -> A; }\n");
    write("warn.test", "import \"warn.sfc\";\ntest \"starts in A\" of Warn { tick; expect active(A); }\n");
    previous = std::filesystem::current_path();
    std::filesystem::current_path(dir);
  }
  ~Charts() {
    std::filesystem::current_path(previous);
    std::filesystem::remove_all(dir);
  }
  void write(const std::string &name, const std::string &text) const { std::ofstream(dir / name) << text; }
  std::filesystem::path dir, previous;
};

const char *kWarning = "warning: place 'Island' can never become active [-Wunreachable-place]";

}  // namespace

TEST_CASE("commands: main dispatches through the table, and gfec --help lists every command of it") {
  Ran help = run_gfec({"--help"});
  CHECK(help.code == 0);
  for (const Command &c : commands()) {
    CHECK(help.out.find(c.synopsis) != std::string::npos);
    CHECK(help.out.find(c.summary) != std::string::npos);
    if (c.name[0] == '\0') continue;
    CHECK(help.out.find(std::string("'gfec ") + c.name + " --help'") != std::string::npos);
    // `gfec NAME --help` reaches the command's own parser.
    Ran own = run_gfec({c.name, "--help"});
    CHECK(own.code == 0);
    CHECK(own.out.find(std::string("gfec ") + c.name + " - ") == 0);
  }
  // Anything that is not a command's name is the compiler's.
  CHECK(run_gfec({"--version"}).out.find("gfec ") == 0);
}

TEST_CASE("commands: gfec run and gfec test take gfec's front-end options, and --help says so") {
  for (const char *command : {"run", "test"}) {
    INFO(command);
    Ran help = run_gfec({command, "--help"});
    for (const char *option : {"-I DIR", "-x LANG", "-W NAME", "-w", "-f OPTION", "-fmax-errors=N"})
      CHECK(help.out.find(option) != std::string::npos);
  }
}

TEST_CASE("commands: -x is read by gfec run and gfec test as by gfec") {
  Charts charts;
  // Chart text in a file named as ALICA's: read as ALICA JSON unless -x gfec says otherwise.
  charts.write("chart.pml", "import \"robot.iface\";\nsfc Mover { initial place A { Go(); } place B; A -> B; }\n");
  charts.write("chart_test.pml", "import \"chart.pml\";\ntest \"moves on\" of Mover { tick 2; expect active(B); }\n");
  Ran check = run_gfec({"--check", "chart.pml"});
  Ran run = run_gfec({"run", "chart.pml"});
  CHECK(check.code == 1);
  CHECK(run.code == 1);
  CHECK(run.first_err_line() == check.first_err_line());
  CHECK(run_gfec({"--check", "-x", "gfec", "chart.pml"}).code == 0);
  Ran ran = run_gfec({"run", "-x", "gfec", "chart.pml", "--ticks", "2"});
  CHECK(ran.code == 0);
  CHECK(ran.err.empty());
  Ran tested = run_gfec({"test", "--reference-only", "-x", "gfec", "chart_test.pml"});
  CHECK(tested.code == 0);
  CHECK(tested.out == "1 passed, 0 failed\n");
  CHECK(run_gfec({"test", "--reference-only", "chart_test.pml"}).code == 1);

  // -x alica: chart text read as ALICA JSON fails alike everywhere.
  Ran alica_check = run_gfec({"--check", "-x", "alica", "warn.sfc"});
  Ran alica_run = run_gfec({"run", "-x", "alica", "warn.sfc"});
  Ran alica_test = run_gfec({"test", "--reference-only", "-x", "alica", "warn.test"});
  CHECK(alica_check.code == 1);
  CHECK(alica_run.code == 1);
  CHECK(alica_test.code == 1);
  CHECK(alica_run.first_err_line() == alica_check.first_err_line());
  CHECK(alica_test.first_err_line().find("warn.test:1:1: error:") == 0);

  // A language gfec does not know is the same usage error for each command.
  for (const char *command : {"run", "test"}) {
    Ran bad = run_gfec({command, "-x", "cobol", "warn.sfc"});
    CHECK(bad.code == 2);
    CHECK(bad.err.find("-x: cobol not in {alica,gfec,iec-st,plcopen}") != std::string::npos);
  }
  CHECK(run_gfec({"-x", "cobol", "warn.sfc"}).err.find("-x: cobol not in {alica,gfec,iec-st,plcopen}") !=
        std::string::npos);
}

TEST_CASE("commands: -W, -Werror, -Wno-NAME and -w act in gfec run and gfec test as in gfec") {
  Charts charts;
  Ran check = run_gfec({"--check", "warn.sfc"});
  CHECK(check.code == 0);
  CHECK(check.err.find(kWarning) != std::string::npos);

  Ran run = run_gfec({"run", "warn.sfc", "--ticks", "1"});
  CHECK(run.code == 0);
  CHECK(run.err.find(kWarning) != std::string::npos);
  Ran test = run_gfec({"test", "--reference-only", "warn.test"});
  CHECK(test.code == 0);
  CHECK(test.err.find(kWarning) != std::string::npos);

  SECTION("-Werror: the warning is an error, the chart has errors (exit 1)") {
    for (Ran r :
         {run_gfec({"--check", "-Werror", "warn.sfc"}), run_gfec({"run", "-Werror", "warn.sfc", "--ticks", "1"}),
          run_gfec({"test", "--reference-only", "-Werror", "warn.test"})}) {
      CHECK(r.code == 1);
      CHECK(r.err.find("error: place 'Island' can never become active [-Werror=unreachable-place]") !=
            std::string::npos);
    }
    Ran t = run_gfec({"test", "--reference-only", "-Werror=unreachable-place", "warn.test"});
    CHECK(t.code == 1);
    CHECK(t.out == "0 passed, 1 failed\n");
  }
  SECTION("-Wno-NAME and -w: no warning") {
    for (const char *off : {"-Wno-unreachable-place", "-w"}) {
      INFO(off);
      Ran c = run_gfec({"--check", off, "warn.sfc"});
      Ran r = run_gfec({"run", off, "warn.sfc", "--ticks", "1"});
      Ran t = run_gfec({"test", "--reference-only", off, "warn.test"});
      CHECK(c.code == 0);
      CHECK(c.err.empty());
      CHECK(r.code == 0);
      CHECK(r.err.empty());
      CHECK(t.code == 0);
      CHECK(t.err.empty());
      CHECK(t.out == "1 passed, 0 failed\n");
    }
  }
  SECTION("an unknown warning is the same usage error") {
    Ran c = run_gfec({"--check", "-Wno-unreachable-plase", "warn.sfc"});
    Ran r = run_gfec({"run", "-Wno-unreachable-plase", "warn.sfc"});
    Ran t = run_gfec({"test", "-Wno-unreachable-plase", "warn.test"});
    CHECK(c.code == 2);
    CHECK(r.code == 2);
    CHECK(t.code == 2);
    CHECK(c.first_err_line() == r.first_err_line());
    CHECK(c.first_err_line() == t.first_err_line());
    CHECK(c.first_err_line().find("did you mean '-Wno-unreachable-place'?") != std::string::npos);
  }
}

TEST_CASE("commands: -I and -f in gfec run and gfec test, as in gfec") {
  Charts charts;
  std::filesystem::create_directory(charts.dir / "lib");
  std::filesystem::rename(charts.dir / "robot.iface", charts.dir / "lib" / "robot.iface");
  CHECK(run_gfec({"run", "warn.sfc", "--ticks", "1"}).code == 1);  // the import is not found
  CHECK(run_gfec({"run", "-I", "lib", "-w", "warn.sfc", "--ticks", "1"}).code == 0);
  CHECK(run_gfec({"test", "--reference-only", "-Ilib", "-w", "warn.test"}).code == 0);
  Ran json = run_gfec({"test", "--reference-only", "-I", "lib", "-fdiagnostics-format=json", "warn.test"});
  CHECK(json.code == 0);
  CHECK(json.err.find("\"kind\":\"warning\"") != std::string::npos);
}
