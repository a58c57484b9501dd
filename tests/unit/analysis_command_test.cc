// `gfec --analyze` and the analyses inside an ordinary compile, as users see them.
#include "support.h"

#include <catch2/catch.hpp>

using namespace gfec::test;

namespace {

const std::string gfec_exe = std::string(GFEC_BINARY_DIR) + "/gfec";
const std::string samples = std::string(GFEC_SOURCE_DIR) + "/samples";

const char *kChoice = R"(interface Bot { bool Left(); }
sfc Choice {
  initial place S;
  place L;
  place R;
  place J;
  transition GoLeft: S -> L when Left();
  transition GoRight: S -> R when !Left();
  transition Both: (L, R) -> J;
}
)";

}  // namespace

TEST_CASE("gfec --analyze: a report per chart and plan, every analysis on") {
  auto r = run_command(gfec_exe + " --analyze " + samples + "/line_follower.sfc " + samples + "/cleanup.fsm");
  CHECK(r.exit_code == 0);
  CHECK(r.out == samples +
                     "/line_follower.sfc:\n"
                     "  sfc LineFollower: 4 places, 4 transitions\n"
                     "    activation states: 4 (all of them)\n"
                     "    safe: no place ever holds more than one activation\n"
                     "    deadlocks: none\n"
                     "    never active: 0 places; never firing: 0 transitions\n" +
                     samples +
                     "/cleanup.fsm:\n"
                     "  fsm CleanUp: 6 states (2 terminal), 8 transitions\n"
                     "    reachable states: 6 of 6\n"
                     "    states that can never finish: 0\n"
                     "    shadowed transitions: 0\n");
  auto plan = run_command(gfec_exe + " --analyze " + samples + "/wall_follow.plan");
  CHECK(plan.exit_code == 0);
  // -Wsupervisor-race is off by default, on under --analyze.
  CHECK(plan.out.find("wall_follow.plan:13:9: warning: 3 supervisors watch actor 'searchFirstWall' and can raise "
                      "events in the same step; 'escape' (global) wins [-Wsupervisor-race]") != std::string::npos);
  CHECK(run_command(gfec_exe + " --analyze " + samples + "/line_follower.sfc -o x.c").exit_code == 2);
}

TEST_CASE("gfec: the analyses run in every compile, as named warnings that -Werror and -Wno- control") {
  std::string dir = scratch_dir("analysis_command");
  write_file(dir + "/choice.sfc", kChoice);
  auto r = run_command(gfec_exe + " --check " + dir + "/choice.sfc");
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("choice.sfc:2:5: warning: sfc 'Choice' can reach a state in which nothing can fire any more: R "
                   "[-Wdeadlock]") != std::string::npos);
  CHECK(r.out.find("[-Wdead-join]") != std::string::npos);
  CHECK(run_command(gfec_exe + " --check -Werror " + dir + "/choice.sfc").exit_code == 1);
  auto quiet =
      run_command(gfec_exe + " --check -Wno-deadlock -Wno-dead-join -Wno-unreachable-place " + dir + "/choice.sfc");
  CHECK(quiet.exit_code == 0);
  CHECK(quiet.out == "");
}

TEST_CASE("the pipeline: the analyses run after the front end report what they report inside it, once", "[pipeline]") {
  // A language server publishes the front end's diagnostics before the analyses run
  // (Compilation::load_and_validate, then analyze()); gfec runs both in front_end().
  std::string with_unreachable = kChoice;
  with_unreachable.insert(with_unreachable.find("  place J;"), "  place X;\n");
  auto fs = files({{"choice.sfc", with_unreachable}});
  auto text = [](const gfec::pipeline::Compilation &c) {
    std::string out;
    for (const auto &d : c.diag.all()) out += gfec::render_text(d, c.sources);
    return out;
  };
  gfec::pipeline::FrontEndOptions options;
  gfec::pipeline::Compilation whole(options);
  CHECK(whole.front_end("choice.sfc", fs));
  gfec::pipeline::Compilation later(options);
  REQUIRE(later.load_and_validate("choice.sfc", fs));
  // The validator's own finding is there at once; the state space's wait for analyze().
  CHECK(text(later).find("place 'X' can never become active [-Wunreachable-place]") != std::string::npos);
  CHECK(text(later).find("[-Wdeadlock]") == std::string::npos);
  CHECK(later.analysis_pending());
  CHECK(later.analyze());
  CHECK(!later.analysis_pending());
  CHECK(later.analyze());
  CHECK(text(later) == text(whole));
  CHECK(text(later).find("[-Wdeadlock]") != std::string::npos);

  // Nothing pending without the analyses, or after a front end with errors.
  options.analyze = false;
  gfec::pipeline::Compilation off(options);
  CHECK(off.load_and_validate("choice.sfc", fs));
  CHECK(!off.analysis_pending());
  gfec::pipeline::Compilation broken(gfec::pipeline::FrontEndOptions{});
  auto bad = files({{"bad.sfc", "sfc Bad { initial place A; A -> Nowhere; }\n"}});
  CHECK(!broken.load_and_validate("bad.sfc", bad));
  CHECK(!broken.analysis_pending());
  CHECK(!broken.analyze());
}

TEST_CASE("gfec --analyze: the summary counts what the warnings above it report, a transition out of a place "
          "never active is dead") {
  std::string dir = scratch_dir("analysis_summary");
  // X and Y: no transition leads in (the validator's finding); C: only after an unconditional
  // transition declared first, so no reachable state holds it (the state space's).
  write_file(dir + "/never.sfc", R"(interface Bot { bool Go(); }
sfc Never {
  initial place A;
  place B;
  place C;
  place D;
  place X;
  place Y;
  A -> B;
  A -> C when Go();
  C -> D when Go();
  X -> Y when Go();
  Y -> X when Go();
}
)");
  auto r = run_command(gfec_exe + " --analyze " + dir + "/never.sfc");
  CHECK(r.out.find("never active: 4 places; never firing: 4 transitions") != std::string::npos);
  CHECK(r.out.find("place 'X' can never become active") != std::string::npos);
  CHECK(r.out.find("place 'C' can never become active") != std::string::npos);
  CHECK(r.out.find("transition 'T2' can never fire: its input place 'C' never becomes active") != std::string::npos);
  CHECK(r.out.find("transition 'T3' can never fire: its input place 'X' never becomes active") != std::string::npos);
  CHECK(r.out.find("transition 'T1' can never fire") != std::string::npos);
}
