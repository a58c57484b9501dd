// `gfec run`: the reference interpreter from the command line, as a user tries a chart.
#include "interpreter_support.h"
#include "support.h"

#include <catch2/catch.hpp>

using namespace gfec::test;

namespace {

const std::string gfec_exe = std::string(GFEC_BINARY_DIR) + "/gfec";
const std::string samples = std::string(GFEC_SOURCE_DIR) + "/samples";

}  // namespace

TEST_CASE("gfec run: the line follower over a CSV trace, every layer") {
  std::string dir = scratch_dir("gfec_run_trace");
  write_file(dir + "/lf.csv", "# the left sensor sees the line at tick 2\n"
                              "tick, Left_IR_Black, Left_IR_White\n"
                              "1, 0, 1\n"
                              "2, 1, 0\n");
  auto r = run_command(gfec_exe + " run " + samples + "/line_follower.sfc --inputs " + dir + "/lf.csv --hooks");
  CHECK(r.exit_code == 0);
  CHECK(r.out == std::string("tick 1\n"
                             "  entry LeftFw\n"
                             "  entry RightFw\n"
                             "  cond T0 = false\n"
                             "    call Left_IR_Black() = false\n"
                             "  cond T2 = false\n"
                             "    call Right_IR_Black() = false\n"
                             "  action LeftFw\n"
                             "    call Left_FW()\n"
                             "  action RightFw\n"
                             "    call Right_FW()\n"
                             "  av 1 0 1 0\n"
                             "tick 2\n") +
                     kLineFollowerLeftSeesLine);
}

TEST_CASE("gfec run: --observable prints what an engine's caller sees, --ticks") {
  auto r = run_command(gfec_exe + " run " + samples + "/cleanup.fsm --ticks 2 --observable");
  CHECK(r.exit_code == 0);
  CHECK(r.out ==
        "tick 1\ncall Arrived() = false\ncall Stuck() = false\ncall DriveToItem()\nav 1 0 0 0 0 0\nstate Z0 running\n"
        "tick 2\ncall Arrived() = false\ncall Stuck() = false\ncall DriveToItem()\nav 1 0 0 0 0 0\nstate Z0 running\n");
}

TEST_CASE("gfec run: errors in the trace, undefined behaviour and usage") {
  std::string dir = scratch_dir("gfec_run_errors");
  write_file(dir + "/bad.csv", "Left_IR_Blak\n1\n");
  auto bad = run_command(gfec_exe + " run " + samples + "/line_follower.sfc --inputs " + dir + "/bad.csv");
  CHECK(bad.exit_code == 1);
  CHECK(bad.out.find("bad.csv:1:1: error: no interface function 'Left_IR_Blak' for this column [trace]") !=
        std::string::npos);

  write_file(dir + "/ub.sfc", "interface I { void Show(int n); }\n"
                              "sfc Grow { var int n = 1; initial place A { n = n * 1000; Show(n); } }\n");
  auto ub = run_command(gfec_exe + " run " + dir + "/ub.sfc --observable");
  CHECK(ub.exit_code == 1);
  CHECK(ub.out.find("call Show(1000000000)\nav 1\ntick 4\n") != std::string::npos);
  CHECK(ub.out.find("ub.sfc:2:49: error: int overflow: 1000000000 * 1000 (undefined behaviour in C) during tick 4 "
                    "[runtime]") != std::string::npos);

  CHECK(run_command(gfec_exe + " run").exit_code == 2);
  CHECK(run_command(gfec_exe + " run " + dir + "/missing.sfc").exit_code == 2);
  CHECK(run_command(gfec_exe + " run " + samples + "/wall_follow.plan").exit_code == 2);
}

TEST_CASE("gfec run: a team machine runs every agent, with columns per agent") {
  std::string dir = scratch_dir("gfec_run_team");
  write_file(dir + "/fetch.fsm", R"(interface Bot { bool Arrived(); bool Holding(); void PickUp(); }
fsm Fetch {
  team 3;
  initial state Go;
  state Grab { PickUp(); }
  success state Got;
  Go -> Grab when Arrived() && team(Grab) == 0;
  Grab -> Got when Holding();
}
)");
  write_file(dir + "/in.csv", "tick, Arrived, Arrived@0, Holding@2\n"
                              "1, 0, 1, 0\n"
                              "2, 1, 1, 1\n");
  auto r = run_command(gfec_exe + " run " + dir + "/fetch.fsm --inputs " + dir + "/in.csv --observable");
  CHECK(r.exit_code == 0);
  CHECK(r.out == "tick 1\n"
                 "agent 0\ncall Arrived() = true\ncall PickUp()\nav 0 1 0\nstate Grab running\n"  // its own column
                 "agent 1\ncall Arrived() = false\nav 1 0 0\nstate Go running\n"                  // the shared one
                 "agent 2\ncall Arrived() = false\nav 1 0 0\nstate Go running\n"
                 "tick 2\n"
                 "agent 0\ncall Holding() = false\ncall PickUp()\nav 0 1 0\nstate Grab running\n"  // no Holding@0: 0
                 "agent 1\ncall Arrived() = true\nav 1 0 0\nstate Go running\n"                    // team(Grab) is 1
                 "agent 2\ncall Arrived() = true\nav 1 0 0\nstate Go running\n");

  auto two = run_command(gfec_exe + " run " + dir + "/fetch.fsm --agents 2 --ticks 1 --observable");
  CHECK(two.exit_code == 0);
  CHECK(two.out == "tick 1\nagent 0\ncall Arrived() = false\nav 1 0 0\nstate Go running\n"
                   "agent 1\ncall Arrived() = false\nav 1 0 0\nstate Go running\n");

  auto too_many = run_command(gfec_exe + " run " + dir + "/fetch.fsm --agents 4");
  CHECK(too_many.exit_code == 2);
  CHECK(too_many.out == "gfec: error: --agents 4: 'Fetch' is a team of 1 to 3 agents\n");

  auto bad_column = run_command(gfec_exe + " run " + dir + "/fetch.fsm --agents 2 --inputs " + dir + "/in.csv");
  CHECK(bad_column.exit_code == 1);
  CHECK(bad_column.out.find("in.csv:1:27: error: 'Holding@2' names no agent of this run (agents 0 to 1) [trace]") !=
        std::string::npos);
}
