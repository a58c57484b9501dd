// Hostile inputs to the real gfec (docs/security.md): long flat operator chains in every place an
// expression goes, NUL in import paths, numbers out of range. Never a crash: a located error
// (exit 1), or a compile.
#include "support.h"

#include <fmt/format.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <string>
#include <vector>

using namespace gfec;
using namespace gfec::test;

namespace {

const std::string gfec_exe = std::string(GFEC_BINARY_DIR) + "/gfec";

/// `term op term op ...`, `n` terms.
std::string chain(const std::string &term, const std::string &op, int n) {
  std::string out;
  out.reserve(static_cast<std::size_t>(n) * (term.size() + op.size() + 2));
  for (int i = 0; i < n; ++i) out += (i ? " " + op + " " : "") + term;
  return out;
}

struct Place {
  std::string name, file;
};

/// Every place an expression goes, with a chain of `n` terms of `op` in it. Arithmetic chains
/// are ints, the others bools, so short chains type-check.
std::vector<Place> places(const std::string &op, int n) {
  bool logical = op == "||" || op == "&&" || op == "==";
  std::string term = logical ? "b" : "x";
  std::string c = chain(term, op, n);
  std::string iface = "interface I { bool B(); void Act(int v); void Flag(bool v); }\n";
  std::string call = logical ? "Flag(" + c + ");" : "Act(" + c + ");";
  std::string cond = logical ? c : "(" + c + ") > 0";
  std::string vars = "  var int x = 1;\n  var bool b = true;\n";
  std::vector<Place> p = {
      {"condition",
       iface + "sfc X {\n" + vars + "  initial place A;\n  place B;\n  A -> B when " + cond + ";\n  B -> A;\n}\n"},
      {"action", iface + "sfc X {\n" + vars + "  initial place A { " + term + " = " + c + "; }\n}\n"},
      {"call argument", iface + "fsm X {\n" + vars + "  initial state A { " + call + " }\n}\n"},
      {"constant", iface + "const " + (logical ? "bool K = " + chain("true", op, n) : "int K = " + chain("1", op, n)) +
                       ";\nsfc X {\n  initial place A { Act(0); }\n}\n"},
  };
  if (!logical)
    p.push_back({"plan formula", "import \"" + std::string(GFEC_SOURCE_DIR) +
                                     "/samples/carbot.toolbox\";\n"
                                     "plan P {\n  config { float length = 50; }\n  start f;\n"
                                     "  actor f: Forward(" +
                                     chain("length", op, n) + ") { FORWARD_OK -> terminate; }\n}\n"});
  return p;
}

}  // namespace

TEST_CASE("hardening: a flat chain of thousands of operators is a located error, never a crash", "[hardening]") {
  std::string dir = scratch_dir("hardening_chains");
  for (std::string op : {"+", "-", "*", "||", "&&", "=="}) {
    for (int n : {15000, 100000}) {
      for (const auto &place : places(op, n)) {
        INFO(op << " x " << n << " in a " << place.name);
        std::string file = dir + "/chain.sfc";
        if (place.name == "plan formula") file = dir + "/chain.plan";
        else if (place.name == "call argument") file = dir + "/chain.fsm";
        write_file(file, place.file);
        CommandResult r = run_command(gfec_exe + " --check " + file);
        CHECK(r.exit_code == 1);
        // The error points at the operator that went past the limit, in the chain's line.
        CHECK(r.out.find("error: expression nested too deeply (more than 256 levels") != std::string::npos);
        CHECK(r.out.find("[nesting]") != std::string::npos);
        CHECK(r.out.find(file + ":") != std::string::npos);
      }
    }
  }
}

TEST_CASE("hardening: chains of 200 terms still compile with every back end", "[hardening]") {
  std::string dir = scratch_dir("hardening_short_chains");
  for (std::string op : {"+", "-", "*", "||", "&&", "=="}) {
    for (const auto &place : places(op, 200)) {
      INFO(op << " in a " << place.name);
      bool plan = place.name == "plan formula";
      std::string file = dir + (plan ? "/c.plan" : place.name == "call argument" ? "/c.fsm" : "/c.sfc");
      write_file(file, place.file);
      for (std::string emit : {plan ? "cpp" : "c", "json", "dot"}) {
        INFO("--emit=" << emit);
        CommandResult r = run_command(gfec_exe + " --emit=" + emit + " " + file + " -o " + dir + "/out." + emit);
        CHECK(r.exit_code == 0);
        CHECK(r.out == "");
      }
      // The static analyses and the reference interpreter walk the expressions too.
      CommandResult a = run_command(gfec_exe + " --analyze " + file);
      CHECK(a.exit_code == 0);
      if (!plan) {
        CommandResult run = run_command(gfec_exe + " run " + file + " --ticks 3");
        CHECK(run.exit_code == 0);
      }
    }
  }
}

TEST_CASE("hardening: a flat else-if chain is not nesting, a nested if is", "[hardening]") {
  std::string dir = scratch_dir("hardening_else_if");
  // A place whose entry block is `if (x == 0) {...} else if (x == 1) {...} ...`, n branches, or
  // n ifs each inside the one before.
  auto chart = [](int n, bool nested) {
    std::string body;
    for (int i = 0; i < n; ++i) body += fmt::format("{}if (x == {}) {{ Act({}); ", i && !nested ? "} else " : "", i, i);
    body += nested ? std::string(static_cast<std::size_t>(n), '}') : "}";
    return "interface I { void Act(int v); }\nsfc X {\n  var int x = 1;\n  initial place A { x = x + 1; " + body +
           " }\n  place B;\n  A -> B when x > 2;\n  B -> A;\n}\n";
  };
  // 255 branches were "expression nested too deeply" (each `else if` counted one level); 1024
  // go through every back end, the analyses and the interpreter.
  for (int n : {255, 1024}) {
    INFO(n << " branches");
    write_file(dir + "/chain.sfc", chart(n, false));
    for (std::string emit : {"c", "json", "dot", "chart"}) {
      INFO("--emit=" << emit);
      CommandResult r = run_command(gfec_exe + " --emit=" + emit + " " + dir + "/chain.sfc -o " + dir + "/out." + emit);
      CHECK(r.exit_code == 0);
      CHECK(r.out == "");
    }
    CHECK(run_command(gfec_exe + " --analyze " + dir + "/chain.sfc").exit_code == 0);
    CommandResult run = run_command(gfec_exe + " run " + dir + "/chain.sfc --ticks 3");
    CHECK(run.exit_code == 0);
    CHECK(run.out.find("Act(2)") != std::string::npos);
  }
  write_file(dir + "/chain.sfc", chart(1025, false));
  CommandResult longer = run_command(gfec_exe + " --check " + dir + "/chain.sfc");
  CHECK(longer.exit_code == 1);
  CHECK(longer.out.find("chain.sfc:4:") != std::string::npos);
  CHECK(longer.out.find("error: an 'else if' chain longer than 1024 branches [nesting]") != std::string::npos);
  // Nesting is still bounded: 300 ifs each inside the one before.
  write_file(dir + "/nested.sfc", chart(300, true));
  CommandResult nested = run_command(gfec_exe + " --check " + dir + "/nested.sfc");
  CHECK(nested.exit_code == 1);
  CHECK(nested.out.find("error: expression nested too deeply (more than 256 levels) [nesting]") != std::string::npos);
}

TEST_CASE("hardening: --emit=chart writes extreme constants so that they read back", "[hardening]") {
  // INT_MIN has no literal; a float folded to -FLT_MAX is shortest as -3.4028235e+38, a double
  // past FLT_MAX; durations below a tick and past the timers. The chart written must compile to
  // the same engine as the chart it came from, and write itself again unchanged.
  std::string dir = scratch_dir("hardening_chart_round_trip");
  run_command("mkdir -p " + dir + "/a " + dir + "/b");
  write_file(dir + "/a/s.sfc",
             "interface I { void Act(int v); void F(float f); }\n"
             "const int LOW = -2147483647 - 1;\nconst int HIGH = 2147483647;\n"
             "const float BIG = -3.4028234e38;\nconst float SMALL = 1e-38;\n"
             "sfc S {\n  period 10ms;\n  var int x = -2147483647 - 1;\n  var float f = -0.0;\n"
             "  initial place A { Act(LOW); Act(x); Act(HIGH); Act(-(LOW + 1)); F(BIG); F(SMALL); F(f); Act(- -5); }\n"
             "  place B;\n"
             "  A -> B when elapsed(A) >= 1e-9ms && x == -2147483647 - 1 || elapsed(A) > 4294967295000ms;\n"
             "  B -> A when elapsed(B) >= 0.1s;\n}\n");
  CommandResult to_chart = run_command(gfec_exe + " --emit=chart " + dir + "/a/s.sfc -o " + dir + "/b/s.sfc");
  REQUIRE(to_chart.exit_code == 0);
  CHECK(read_file(dir + "/b/s.sfc").find("const int LOW = (-2147483647 - 1);") != std::string::npos);
  CommandResult again = run_command(gfec_exe + " --emit=chart " + dir + "/b/s.sfc -o " + dir + "/again.sfc");
  CHECK(again.out == "");
  REQUIRE(again.exit_code == 0);
  std::string written = read_file(dir + "/b/s.sfc"), rewritten = read_file(dir + "/again.sfc");
  CHECK(written.substr(written.find('\n')) == rewritten.substr(rewritten.find('\n')));  // all but "from FILE"
  for (std::string side : {"a", "b"})
    CHECK(run_command("cd " + dir + "/" + side + " && " + gfec_exe + " s.sfc --no-line-directives -o e.c").exit_code ==
          0);
  CHECK(read_file(dir + "/a/e.c") == read_file(dir + "/b/e.c"));
  CHECK(read_file(dir + "/a/e.h") == read_file(dir + "/b/e.h"));
}

TEST_CASE("hardening: a NUL in an import path is an error at the string", "[hardening]") {
  FrontEnd fe({{"m.sfc", "import \"a.iface\\0.sfc\";\n"}, {"a.iface", "interface A { void Go(); }\n"}});
  CHECK(fe.text() == "m.sfc:1:8: error: an import path cannot contain a NUL character [import]\n"
                     " import \"a.iface\\0.sfc\";\n"
                     "        ^~~~~~~~~~~~~~~\n");
  CHECK(fe.loaded.paths == std::vector<std::string>{"m.sfc"});
}

TEST_CASE("hardening: one rule for numbers, in actions, arguments and plan formulas as in constants", "[hardening]") {
  std::string dir = scratch_dir("hardening_numbers");
  struct Case {
    std::string action, message;
  };
  // Each would be undefined behaviour or a -Woverflow error in the generated C.
  std::vector<Case> cases = {
      {"x = 2147483647 + 1;", ":4:29: error: integer overflow in constant expression [not-constant]"},
      {"x = 2147483648;", ":4:29: error: integer constant '2147483648' is too large for 'int' [not-constant]"},
      {"g(3000000000);", ":4:27: error: integer constant '3000000000' is too large for 'int' [not-constant]"},
      {"f = 1e999;", ":4:29: error: floating constant '1e999' is too large for 'double' [not-constant]"},
      {"f = 1e308 * 10;", ":4:29: error: floating-point overflow in constant expression [not-constant]"},
      {"x = 3e9;", ":4:29: error: value 3000000000 does not fit in 'int' [not-constant]"},
      {"h(1e39);", ":4:27: error: value 1e+39 is too large for 'float' [not-constant]"},
      {"g(-2147483647 - 2);", ":4:27: error: integer overflow in constant expression [not-constant]"},
      {"x = 7 % 0;", ":4:29: error: division by zero in constant expression [not-constant]"},
  };
  for (const auto &c : cases) {
    INFO(c.action);
    // The action on line 4: its value at column 29, an argument at 27.
    write_file(dir + "/n.sfc", "interface I { void g(int v); void h(float v); }\n"
                               "sfc N {\n  var int x = 1; var float f = 1;\n"
                               "  initial place Place { " +
                                   c.action + " }\n}\n");
    CommandResult r = run_command(gfec_exe + " --check " + dir + "/n.sfc");
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("n.sfc" + c.message) != std::string::npos);
  }
  // What stays legal: the extremes themselves, and arithmetic the robot does at run time.
  write_file(dir + "/ok.sfc", "interface I { void g(int v); void h(float v); int Count(); }\n"
                              "sfc N {\n  var int x = 1; var float f = 1;\n"
                              "  initial place A { x = -2147483647 - 1; x = 2147483647; g(x + 2147483647); "
                              "h(3.4e38); f = 1e308 / 1e300; g(Count() * 3); }\n}\n");
  CommandResult ok = run_command(gfec_exe + " --check " + dir + "/ok.sfc");
  CHECK(ok.exit_code == 0);
  CHECK(ok.out == "");

  // Plan formulas follow the same rule.
  for (std::string arg : {"1e999", "2147483647 + 1", "3000000000", "length * 2 + 1e308 * 10"}) {
    INFO(arg);
    write_file(dir + "/p.plan", "import \"" + std::string(GFEC_SOURCE_DIR) +
                                    "/samples/carbot.toolbox\";\n"
                                    "plan P {\n  config { float length = 50; }\n  start f;\n"
                                    "  actor f: Forward(" +
                                    arg + ") { FORWARD_OK -> terminate; }\n}\n");
    CommandResult r = run_command(gfec_exe + " --check " + dir + "/p.plan");
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("p.plan:5:") != std::string::npos);
    CHECK(r.out.find("[not-constant]") != std::string::npos);
  }
}

TEST_CASE("hardening: a duration beyond what timers count is never reached, however long", "[hardening]") {
  std::string dir = scratch_dir("hardening_durations");
  // 1e18s once became 0 ticks (a double past 2^64 converted to an integer): "always".
  for (std::string d : {"1e17s", "1e18s", "1e300s", "4294967296s"}) {
    INFO(d);
    write_file(dir + "/d.sfc", "sfc D {\n  period 1ms;\n  initial place A;\n  place B;\n"
                               "  A -> B when elapsed(A) >= " +
                                   d + ";\n  B -> A when elapsed(B) < " + d + ";\n}\n");
    CommandResult r = run_command(gfec_exe + " " + dir + "/d.sfc -o " + dir + "/d.c");
    REQUIRE(r.exit_code == 0);
    std::string c = read_file(dir + "/d.c");
    CHECK(c.find("(false /* never") != std::string::npos);  // A -> B
    CHECK(c.find("(true /* always") != std::string::npos);  // B -> A
    CHECK(c.find("(true /* always") > c.find("(false /* never"));
  }
}

TEST_CASE("hardening: did-you-mean stays fast on hostile names, and still helps on real typos", "[hardening]") {
  std::string dir = scratch_dir("hardening_suggest");
  // A 40,000-character name and its typo: the edit distance once took seconds per candidate.
  std::string name(40000, 'a');
  write_file(dir + "/long.sfc",
             "interface I { void " + name + "(); }\nsfc X { initial place A { " + name.substr(1) + "b(); } }\n");
  auto start = std::chrono::steady_clock::now();
  CommandResult r = run_command(gfec_exe + " --check " + dir + "/long.sfc");
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("unknown function") != std::string::npos);
  CHECK(r.out.find("did you mean") == std::string::npos);  // past 64 characters: no suggestion
  CHECK(seconds < 5);
  // Names up to 64 characters still get one, and a name far longer than the typo is skipped.
  std::string n64 = "Drive_" + std::string(58, 'x');
  write_file(dir + "/typo.sfc", "interface I { void " + n64 +
                                    "(); void Forwards_and_then_some_more(); }\n"
                                    "sfc X { initial place A { " +
                                    n64.substr(0, 63) + "y(); Forwrd(); } }\n");
  CommandResult t = run_command(gfec_exe + " --check " + dir + "/typo.sfc");
  CHECK(t.exit_code == 1);
  CHECK(t.out.find("note: did you mean '" + n64 + "'?") != std::string::npos);
  CHECK(t.out.find("did you mean 'Forwards_and_then_some_more'") == std::string::npos);
  // A thousand near-identical 64-character names, each called misspelt: every search compared
  // every name in full, also for the errors past -fmax-errors that are never printed (24.8 s).
  // Now those get no search, and a search stops at the first candidate it cannot beat.
  std::string iface = "interface I {\n", calls;
  for (int i = 0; i < 1000; ++i) {
    std::string f = fmt::format("F{:04}_{}", i, std::string(58, 'x'));
    iface += "  void " + f + "();\n";
    calls += " " + f.substr(0, 63) + "z();";
  }
  write_file(dir + "/many.sfc", iface + "}\nsfc X { initial place A {" + calls + " } }\n");
  start = std::chrono::steady_clock::now();
  CommandResult many = run_command(gfec_exe + " --check " + dir + "/many.sfc");
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(many.exit_code == 1);
  CHECK(many.out.find("note: did you mean 'F0049_" + std::string(58, 'x') + "'?") != std::string::npos);
  CHECK(many.out.find("compilation terminated due to -fmax-errors=50.") != std::string::npos);
  CHECK(seconds < 10);
}

TEST_CASE("hardening: the smaller input cases of the probe", "[hardening]") {
  std::string dir = scratch_dir("hardening_small");
  // A file that declares no chart is an error in the input (1), located, not a usage error (2).
  write_file(dir + "/only.iface", "interface I { void Go(); }\n");
  CommandResult none = run_command("cd " + dir + " && " + gfec_exe + " only.iface");
  CHECK(none.exit_code == 1);
  CHECK(none.out.find("only.iface:1:1: error: nothing to compile: the file declares no sfc, fsm or plan") !=
        std::string::npos);

  // A UTF-8 byte-order mark is not part of the text; CR-only line ends are line ends.
  write_file(dir + "/bom.sfc", "\xEF\xBB\xBFinterface I { void Go(); }\nsfc S { initial place A { Go(); } }\n");
  CHECK(run_command(gfec_exe + " --check " + dir + "/bom.sfc").exit_code == 0);
  write_file(dir + "/cr.sfc", "// a comment\rinterface I { void Go(); }\rsfc S { initial place A { Go(); } "
                              "place B; A -> B when x; }\r");
  CommandResult cr = run_command("cd " + dir + " && " + gfec_exe + " --check cr.sfc");
  CHECK(cr.exit_code == 1);
  CHECK(cr.out.find("cr.sfc:3:56: error: unknown name 'x'") != std::string::npos);

  // Names the C headers of an engine define would be replaced there: the C would not compile.
  write_file(dir + "/m.iface", "interface I { void NULL(); int UINT32_MAX(); void uint8_t(); void interval_t(); }\n");
  CommandResult m = run_command("cd " + dir + " && " + gfec_exe + " --check m.iface");
  CHECK(m.exit_code == 1);
  CHECK(m.out.find("m.iface:1:20: error: 'NULL' is a macro or type of the C headers") != std::string::npos);
  CHECK(m.out.find("'UINT32_MAX' is a macro") != std::string::npos);
  CHECK(m.out.find("'uint8_t' is a macro") != std::string::npos);
  CHECK(m.out.find("'interval_t' is a macro") == std::string::npos);  // only the headers' own names

  // One file by an absolute path and through a symlinked folder is read once.
  run_command("mkdir -p " + dir + "/real && ln -sfn real " + dir + "/link");
  write_file(dir + "/real/a.iface", "interface I { void Go(); }\n");
  write_file(dir + "/two.sfc", "import \"" + dir +
                                   "/real/a.iface\";\nimport \"link/a.iface\";\n"
                                   "sfc S { initial place A { Go(); } }\n");
  CommandResult two = run_command(gfec_exe + " --check " + dir + "/two.sfc");
  CHECK(two.exit_code == 0);
  CHECK(two.out == "");

  // Trigraphs in a file name reach #line escaped: "??-" would be '~' (and -Wtrigraphs) in C99.
  write_file(dir + "/tri?\?-.sfc", "interface I { void Go(); }\nsfc S { initial place A { Go(); } }\n");
  CommandResult tri = run_command("cd " + dir + " && " + gfec_exe +
                                  " 'tri?\?-.sfc' -o tri.c && "
                                  "cc -std=c99 -Wall -Wextra -Wpedantic -Werror -c tri.c -o tri.o");
  CHECK(tri.exit_code == 0);
  CHECK(read_file(dir + "/tri.c").find("#line 2 \"tri?\\?-.sfc\"") != std::string::npos);
  // What --check says of a chart that imports `path` and nothing else.
  auto importing = [&](const std::string &path) {
    write_file(dir + "/imports.sfc", "import \"" + path + "\";\nsfc S { initial place A; }\n");
    CommandResult r = run_command("cd " + dir + " && " + gfec_exe + " --check imports.sfc");
    CHECK(r.exit_code == 1);
    return r.out;
  };
  // An import of a device is refused with the reason, not "cannot find".
  CHECK(importing("/dev/zero")
            .find("imports.sfc:1:8: error: cannot read imported file '/dev/zero': not a regular "
                  "file") != std::string::npos);
  // /proc/self/mem, a regular file whose read(2) at offset 0 fails (a stream took it for an empty
  // file), is not even opened: no file of /proc is read (tests/cli/special_files.sh has the rest).
  CHECK(importing("/proc/self/mem")
            .find("imports.sfc:1:8: error: cannot read imported file '/proc/self/mem': a file of /proc, /sys or "
                  "another of the kernel's pseudo file systems; gfec reads none") != std::string::npos);
  // A megabyte-long import path beside a thousand files: refused by its length before it is split,
  // searched for or offered a did-you-mean (0.7 s and 190 MB before, for 'a/a/a/...').
  for (int i = 0; i < 1000; ++i)
    write_file(dir + "/f" + std::to_string(i) + ".iface", "interface I" + std::to_string(i) + " { }\n");
  std::string huge;
  for (int i = 0; i < 500000; ++i) huge += "a/";
  CHECK(importing(huge).find(
            "imports.sfc:1:8: error: an import path is at most 4096 bytes; this one has 1000000 [import]") !=
        std::string::npos);
  CHECK(importing(std::string(4097, 'f')).find("this one has 4097 [import]") != std::string::npos);
  CHECK(importing(std::string(4000, 'f')).find("cannot find imported file") != std::string::npos);
  CommandResult main_mem = run_command(gfec_exe + " --check /proc/self/mem");
  CHECK(main_mem.exit_code == 2);
}
