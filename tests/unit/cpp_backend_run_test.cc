// Compile-and-run tests of the cpp back end: samples/wall_follow.plan, samples/square.plan and
// tests/golden/cpp/formulas.plan go through the real front end and the back end, and the
// wiring is built with g++ and clang++ (kStrictFlags) together with a scripted test toolbox
// (tests/run/cpp/*_toolbox.h), the run harness (tests/run/cpp/run_plan.cc) and the afp runtime,
// then run on the stepped executor, one 10 ms step per script line. Each expected log was
// written by hand from the plan and docs/runtime.md (never copied from a run): which actor
// started, finished in which state or was interrupted by which supervisor, what each started
// component read from its formulas, and the configuration at the end. Both compilers must give
// the same log. Scratch files: <build>/test-scratch/cpp_backend/run-<plan>/.
#include "../run/cpp_backend_support.h"

using namespace cppt;

namespace {

struct Harnesses {
  std::vector<std::string> executables;  ///< one per compiler
};

/// Generates the plan's wiring and builds the harness once per compiler and test process.
const Harnesses &harness(const std::map<std::string, std::string> &files, const std::string &main,
                         const std::string &plan_name, const std::string &env) {
  static std::map<std::string, Harnesses> built;
  auto it = built.find(main);
  if (it != built.end()) return it->second;
  std::string stem = fs::path(main).stem().string();
  auto compiled = compile(files, main, stem + ".cpp");
  INFO(compiled->errors);
  REQUIRE(!compiled->diag.has_errors());
  // ctest runs each test case in its own process, side by side: each builds in its own folder.
  std::string dir = write_all(
      fmt::format("run-{}-{:x}", stem, std::hash<std::string>{}(Catch::getResultCapture().getCurrentTestName())),
      compiled->files);
  if (cxx_compilers().size() < 2) WARN("clang++ is not installed: the generated C++ is tested with g++ only");
  Harnesses h;
  for (const auto &cxx : runtime_linking_compilers())
    h.executables.push_back(build_harness(cxx, dir, stem, plan_name, env));
  return built.emplace(main, std::move(h)).first->second;
}

/// Runs the script with every compiler's harness; all must print `expected`.
void check_run(const Harnesses &h, const std::string &script, const std::string &expected,
               const std::string &args = "") {
  for (const auto &exe : h.executables) {
    std::string log = run_script(exe, script, args);
    INFO(exe << "\n" << first_difference(expected, log) << "\nwhole log:\n" << log);
    CHECK(log == expected);
  }
}

std::map<std::string, std::string> golden_files() { return chart_files(kGoldenDir); }

/// A stepped log without its plan times ("60 finish ..." -> "finish ..."): what the threaded
/// executor prints for a run in which no supervisor fires.
std::string untimed(const std::string &log) {
  std::string out;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);) {
    std::size_t digits = line.find_first_not_of("0123456789");
    if (digits > 0 && digits != std::string::npos && line[digits] == ' ') line.erase(0, digits + 1);
    out += line + "\n";
  }
  return out;
}

}  // namespace

TEST_CASE("cpp run: wall_follow, lane not free, touch, formulas over a changed entry, escape", "[cpp_backend][run]") {
  const auto &h = harness(sample_files(), "wall_follow.plan", "WallFollow", "Carbot");
  // The lane closes (CheckLane, watching searchFirstWall) -> findWallAngle finds a wall at 15
  // degrees and writes wallangle, which parallelToWall reads. The application sets walldist to
  // 40 while followWall runs: the next actors read it (-walldist, walldist -+ 5, CheckLane).
  // A touch interrupts searchFirstWall -> backupCollision drives back 40 cm (4 steps). Escape,
  // a global supervisor, ends the plan from followWall.
  const std::string script = "\n"         // before the start
                             "\n"         // 10 ms: searchFirstWall drives
                             "lane=25\n"  // 20: 25 < walldist 30
                             "wall=15\n"  // 30
                             "\n"         // 40: the turn ends
                             "set:walldist=40\n"
                             "blocked\n"   // 60: WallForward's own LANE_NOT_FREE
                             "\n"          // 70: no wall -> turnAfterWallLost
                             "\n"          // 80
                             "touch\n"     // 90: touch is checked before lane
                             "\n\n\n\n"    // 100-130: backing up 40 cm
                             "wall=-20\n"  // 140
                             "\n"          // 150
                             "escape\n";   // 160
  check_run(h, script,
            "0 start WallFollow.searchFirstWall\n"
            "  Forward distance=100000\n"
            "  CheckLane dist=30\n"
            "  Forward stop\n"
            "20 interrupt WallFollow.searchFirstWall by lane event 0\n"
            "20 start WallFollow.findWallAngle\n"
            "30 finish WallFollow.findWallAngle state 0\n"
            "30 start WallFollow.parallelToWall\n"
            "  Turn angle=15\n"
            "40 finish WallFollow.parallelToWall state 0\n"
            "40 start WallFollow.followWall\n"
            "  WallForward dist=30 min=25 max=35\n"
            "set walldist=40\n"
            "60 finish WallFollow.followWall state 1\n"
            "60 start WallFollow.findWallAngle\n"
            "70 finish WallFollow.findWallAngle state 1\n"
            "70 start WallFollow.turnAfterWallLost\n"
            "  Turn angle=-60\n"
            "80 finish WallFollow.turnAfterWallLost state 0\n"
            "80 start WallFollow.searchFirstWall\n"
            "  Forward distance=100000\n"
            "  CheckLane dist=40\n"
            "  Forward stop\n"
            "90 interrupt WallFollow.searchFirstWall by touch event 0\n"
            "90 start WallFollow.backupCollision\n"
            "  Forward distance=-40\n"
            "  Forward stop\n"
            "130 finish WallFollow.backupCollision state 0\n"
            "130 start WallFollow.findWallAngle\n"
            "140 finish WallFollow.findWallAngle state 0\n"
            "140 start WallFollow.parallelToWall\n"
            "  Turn angle=-20\n"
            "150 finish WallFollow.parallelToWall state 0\n"
            "150 start WallFollow.followWall\n"
            "  WallForward dist=40 min=35 max=45\n"
            "160 interrupt WallFollow.followWall by escape event 0\n"
            "160 end WallFollow interrupted\n"
            "status interrupted\n"
            "config wallangle=-20\n"
            "config walldist=40\n");
}

TEST_CASE("cpp run: wall_follow, following the wall: a new run per FORWARD_OK, wallTouch, WALL_LOST",
          "[cpp_backend][run]") {
  const auto &h = harness(sample_files(), "wall_follow.plan", "WallFollow", "Carbot");
  const std::string script = "\n"
                             "lane=20 wall=10\n"  // 10: lane interrupts; the actor does not step
                             "wall=10\n"          // 20
                             "\n"                 // 30: followWall starts
                             "\n\n\n"             // 40-60: FORWARD_OK at its third step -> followWall again
                             "touch\n"            // 70: followWall's own wallTouch
                             "\n\n\n"             // 80-100: backing up 30 cm
                             "wall=5\n"           // 110
                             "\n"                 // 120
                             "lost\n"             // 130: WALL_LOST
                             "\n"                 // 140
                             "escape\n";          // 150
  check_run(h, script,
            "0 start WallFollow.searchFirstWall\n"
            "  Forward distance=100000\n"
            "  CheckLane dist=30\n"
            "  Forward stop\n"
            "10 interrupt WallFollow.searchFirstWall by lane event 0\n"
            "10 start WallFollow.findWallAngle\n"
            "20 finish WallFollow.findWallAngle state 0\n"
            "20 start WallFollow.parallelToWall\n"
            "  Turn angle=10\n"
            "30 finish WallFollow.parallelToWall state 0\n"
            "30 start WallFollow.followWall\n"
            "  WallForward dist=30 min=25 max=35\n"
            "60 finish WallFollow.followWall state 0\n"
            "60 start WallFollow.followWall\n"
            "  WallForward dist=30 min=25 max=35\n"
            "70 interrupt WallFollow.followWall by wallTouch event 0\n"
            "70 start WallFollow.backupCollision\n"
            "  Forward distance=-30\n"
            "  Forward stop\n"
            "100 finish WallFollow.backupCollision state 0\n"
            "100 start WallFollow.findWallAngle\n"
            "110 finish WallFollow.findWallAngle state 0\n"
            "110 start WallFollow.parallelToWall\n"
            "  Turn angle=5\n"
            "120 finish WallFollow.parallelToWall state 0\n"
            "120 start WallFollow.followWall\n"
            "  WallForward dist=30 min=25 max=35\n"
            "130 finish WallFollow.followWall state 2\n"
            "130 start WallFollow.turnAfterWallLost\n"
            "  Turn angle=-60\n"
            "140 finish WallFollow.turnAfterWallLost state 0\n"
            "140 start WallFollow.searchFirstWall\n"
            "  Forward distance=100000\n"
            "  CheckLane dist=30\n"
            "  Forward stop\n"
            "150 interrupt WallFollow.searchFirstWall by escape event 0\n"
            "150 end WallFollow interrupted\n"
            "status interrupted\n"
            "config wallangle=5\n"
            "config walldist=30\n");
}

TEST_CASE("cpp run: square, the sub-plan Side counted by the computation CountDown", "[cpp_backend][run]") {
  const auto &h = harness(sample_files(), "square.plan", "Square", "Carbot");
  // A side: Forward 50 cm (5 steps), Turn (1 step), then Side ends OK and CountDown computes
  // at its start and reports at its first step.
  const std::string two_sides = "set sides=2\n"
                                "0 start Square.side\n"
                                "0 start Side.forward\n"
                                "  Forward distance=50\n"
                                "  Forward stop\n"
                                "50 finish Side.forward state 0\n"
                                "50 start Side.turn\n"
                                "  Turn angle=90\n"
                                "60 finish Side.turn state 0\n"
                                "60 end Side succeeded\n"
                                "60 finish Square.side state 0\n"
                                "60 start Square.count\n"
                                "  CountDown n=2\n"
                                "70 finish Square.count state 0\n"
                                "70 start Square.side\n"
                                "70 start Side.forward\n"
                                "  Forward distance=50\n"
                                "  Forward stop\n"
                                "120 finish Side.forward state 0\n"
                                "120 start Side.turn\n"
                                "  Turn angle=90\n"
                                "130 finish Side.turn state 0\n"
                                "130 end Side succeeded\n"
                                "130 finish Square.side state 0\n"
                                "130 start Square.count\n"
                                "  CountDown n=1\n"
                                "140 finish Square.count state 1\n"
                                "140 end Square succeeded\n"
                                "status succeeded\n"
                                "config length=50\n"
                                "config sides=0\n";
  SECTION("two sides set by the application, then DONE") {
    check_run(h, "set:sides=2\n" + std::string(14, '\n'), two_sides);
  }
  SECTION("the threaded executor runs the same plan to the same end") {
    // No supervisor fires, so only the times (real time there) differ from the stepped run.
    check_run(h, "set:sides=2\n", untimed(two_sides), "threaded");
  }
  SECTION("four sides by default") {
    std::string log = run_script(h.executables.front(), std::string(40, '\n'));
    CHECK(log.find("  CountDown n=4\n") != std::string::npos);
    CHECK(log.find("  CountDown n=1\n") != std::string::npos);
    CHECK(log.find("280 end Square succeeded\nstatus succeeded\n") != std::string::npos);
  }
  SECTION("a bump ends the side INTERRUPTED; Square backs off length / 2") {
    check_run(h, "\n\n\ntouch\n\n\n\n\n",
              "0 start Square.side\n"
              "0 start Side.forward\n"
              "  Forward distance=50\n"
              "  Forward stop\n"
              "30 interrupt Side.forward by bump event 0\n"
              "30 end Side interrupted\n"
              "30 finish Square.side state 1\n"
              "30 start Square.backOff\n"
              "  Forward distance=-25\n"
              "  Forward stop\n"
              "60 finish Square.backOff state 0\n"
              "60 end Square succeeded\n"
              "status succeeded\n"
              "config length=50\n"
              "config sides=4\n");
  }
  SECTION("escape, global in Square, stops the side from outside") {
    check_run(h, "\n\n\nescape\n",
              "0 start Square.side\n"
              "0 start Side.forward\n"
              "  Forward distance=50\n"
              "  Forward stop\n"
              "30 end Side stopped\n"
              "30 interrupt Square.side by escape event 0\n"
              "30 end Square interrupted\n"
              "status interrupted\n"
              "config length=50\n"
              "config sides=4\n");
  }
}

TEST_CASE("cpp run: formulas evaluated and converted at run time", "[cpp_backend][run]") {
  const auto &h = harness(golden_files(), "formulas.plan", "Formulas", "Probe");
  // n / 2 is int division; f * (n - 1) is float; LAPS - BACK was folded to 3 - -2; " 12.5 " is
  // parsed into a float; "lap " + n converts the entry, (f + 1) is computed then converted.
  const std::string first_actors = "  Numbers half=4 scaled=20 negated=-0.25 folded=5 parsed=12.5\n"
                                   "10 finish Formulas.numbers state 0\n"
                                   "10 start Formulas.texts\n"
                                   "  Texts lap=\"lap 9\" where=\"robot at 3.5cm\" joined=\"ab\" empty=\"robot\"\n"
                                   "20 finish Formulas.texts state 0\n"
                                   "20 start Formulas.things\n";
  SECTION("n = 7: -n / (n - LAPS - 4) divides by zero, and the supervisor that reads it fails") {
    // An ignored TIMEOUT of the global Watch does not interrupt texts.
    check_run(h, "\n\ntimeout\n\n",
              "  Watch limit=21\n"
              "0 start Formulas.numbers\n"
              "  Numbers half=3 scaled=15 negated=-0.25 folded=5 parsed=12.5\n"
              "10 finish Formulas.numbers state 0\n"
              "10 start Formulas.texts\n"
              "  Texts lap=\"lap 7\" where=\"robot at 3.5cm\" joined=\"ab\" empty=\"robot\"\n"
              "20 finish Formulas.texts state 0\n"
              "20 start Formulas.things\n"
              "  Things thing=null on=true\n"
              "30 fail Formulas.ee: division by zero in a formula\n"
              "30 end Formulas failed\n"
              "status failed: ee: division by zero in a formula\n"
              "config d=0.25\n"
              "config f=2.5\n"
              "config label=\"\"\n"
              "config n=7\n"
              "config name=\"robot\"\n"
              "config number=\" 12.5 \"\n"
              "config on=true\n"
              "config seen=0\n"
              "config thing=null\n");
  }
  SECTION("n = 9: out parameters write an object and a string") {
    check_run(h, "set:n=9\n\n\n\n",
              "set n=9\n"
              "  Watch limit=27\n"
              "0 start Formulas.numbers\n" +
                  first_actors +
                  "  Things thing=null on=true\n"
                  "  Watch limit=-4\n"
                  "30 finish Formulas.things state 0\n"
                  "30 end Formulas succeeded\n"
                  "status succeeded\n"
                  "config d=0.25\n"
                  "config f=2.5\n"
                  "config label=\"made\"\n"
                  "config n=9\n"
                  "config name=\"robot\"\n"
                  "config number=\" 12.5 \"\n"
                  "config on=true\n"
                  "config seen=0\n"
                  "config thing=object 42\n");
  }
  SECTION("NOT_MADE loops back; the global Watch fires and its output is committed") {
    check_run(h, "set:n=9 set:on=false\n\n\n\nfire\n",
              "set n=9\n"
              "set on=false\n"
              "  Watch limit=27\n"
              "0 start Formulas.numbers\n" +
                  first_actors +
                  "  Things thing=null on=false\n"
                  "  Watch limit=-4\n"
                  "30 finish Formulas.things state 1\n"
                  "30 start Formulas.numbers\n"
                  "  Numbers half=4 scaled=20 negated=-0.25 folded=5 parsed=12.5\n"
                  "40 interrupt Formulas.numbers by Texts event 0\n"
                  "40 end Formulas interrupted\n"
                  "status interrupted\n"
                  "config d=0.25\n"
                  "config f=2.5\n"
                  "config label=\"\"\n"
                  "config n=9\n"
                  "config name=\"robot\"\n"
                  "config number=\" 12.5 \"\n"
                  "config on=false\n"
                  "config seen=27\n"
                  "config thing=null\n");
  }
  SECTION("a TIMEOUT the global Watch ignores terminates through the local one") {
    std::string log = run_script(h.executables.front(), "set:n=9\n\n\ntimeout\n");
    CHECK(log.find("30 interrupt Formulas.things by ee event 1\n30 end Formulas interrupted\n") != std::string::npos);
  }
}
