// The deepest hierarchy gfec compiles (200 levels of sub-chart instances, compiler/validate/
// subcharts.cc) through every stage that descends into the instances one level at a time: the C
// engine, the DOT picture, the analyses and `gfec run`. Before the depth had a limit, a chain of
// 30,000 charts overflowed the stack of `--emit=dot` and `gfec run`.
#include "support.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec::test;

namespace {

const std::string gfec_exe = std::string(GFEC_BINARY_DIR) + "/gfec";

/// Charts C0 .. C{levels}, each running the next from its one place: C0's instances nest
/// `levels` deep. Every chart acts, so each level has code in the engine.
std::string chain(int levels) {
  std::string s = "interface Bot { bool Go(); void Act(int i); }\n";
  for (int i = 0; i < levels; ++i)
    s += "sfc C" + std::to_string(i) + " { period 10ms; initial place A runs C" + std::to_string(i + 1) +
         "; place B { Act(" + std::to_string(i) + "); } A -> B when Go(); B -> A when Go(); }\n";
  return s + "sfc C" + std::to_string(levels) + " { period 10ms; initial place A { Act(-1); } }\n";
}

}  // namespace

TEST_CASE("sub-chart instances: 200 levels deep go through every back end and gfec run", "[subcharts]") {
  const std::string dir = scratch_dir("subchart-depth");
  const std::string file = dir + "/deep.sfc";
  write_file(file, chain(200));
  for (const char *emit : {"c", "dot", "json", "chart"}) {
    INFO("--emit=" << emit);
    CommandResult r = run_command(gfec_exe + " --chart C0 --emit=" + emit + " " + file + " -o " + dir + "/out." + emit);
    CHECK(r.exit_code == 0);
    CHECK(r.out == "");
  }
  CHECK(run_command(gfec_exe + " --analyze --chart C0 " + file).exit_code == 0);
  CommandResult run = run_command(gfec_exe + " run --chart C0 " + file + " --ticks 3");
  CHECK(run.exit_code == 0);

  // One level more is refused before any back end runs.
  write_file(file, chain(201));
  CommandResult over = run_command(gfec_exe + " --chart C0 " + file + " -o " + dir + "/over.c");
  CHECK(over.exit_code == 1);
  CHECK(over.out.find("nests sub-chart instances 201 levels deep, more than the 200 gfec compiles [subchart-depth]") !=
        std::string::npos);
}
