// The deepest hierarchy gfec compiles (200 levels of sub-chart instances, compiler/validate/
// subcharts.cc) through every stage that descends into the instances one level at a time: the C
// engine, the DOT picture, the analyses and `gfec run`. Before the depth had a limit, a chain of
// 30,000 charts overflowed the stack of `--emit=dot` and `gfec run`.
#include "support.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

using namespace gfec::test;

namespace {

const std::string gfec_exe = std::string(GFEC_BINARY_DIR) + "/gfec";

/// Charts C0 .. C{levels}, each running the next from its one place: C0's instances nest
/// `levels` deep. Every chart acts, so each level has code in the engine.
/// `place` names the place that runs the next chart (its length is the instance path's per level).
std::string chain(int levels, const std::string &place = "A") {
  std::string s = "interface Bot { bool Go(); void Act(int i); }\n";
  for (int i = 0; i < levels; ++i)
    s += "sfc C" + std::to_string(i) + " { period 10ms; initial place " + place + " runs C" + std::to_string(i + 1) +
         "; place B { Act(" + std::to_string(i) + "); } " + place + " -> B when Go(); B -> " + place +
         " when Go(); }\n";
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

TEST_CASE("sub-chart instances: the path of names to an instance is bounded", "[subcharts]") {
  // The engine names an instance after its path, and each level repeats the levels above: 200
  // levels of 4,000-character names wrote 972 MB of C in 3.4 GB of memory. The path, the root's
  // name and a place name and a byte per level, is at most 4,096 bytes.
  const std::string dir = scratch_dir("subchart-path");
  const std::string file = dir + "/long.sfc";
  // 200 levels of a 4,000-character place name: refused at the root, at once, before any back end.
  write_file(file, chain(200, "P" + std::string(3999, 'p')));
  CommandResult over = run_command(gfec_exe + " --chart C0 " + file + " -o " + dir + "/over.c");
  CHECK(over.exit_code == 1);
  CHECK(over.out.find("long.sfc:2:5: error: sfc 'C0' has sub-chart instances whose path of names is 800202 bytes "
                      "long, more than the 4096 gfec compiles (the engine names an instance after its path) "
                      "[subchart-depth]") != std::string::npos);
  CHECK(over.out.find("note: place 'P") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/over.c"));
  // At the bound (2 + 200 * (19 + 1) = 4002 bytes) every back end and gfec run still go.
  write_file(file, chain(200, "P" + std::string(18, 'p')));
  for (const char *emit : {"c", "json"}) {
    INFO("--emit=" << emit);
    CommandResult r = run_command(gfec_exe + " --chart C0 --emit=" + emit + " " + file + " -o " + dir + "/out." + emit);
    CHECK(r.exit_code == 0);
    CHECK(r.out == "");
  }
  CHECK(run_command(gfec_exe + " run --chart C0 " + file + " --ticks 2").exit_code == 0);
  // 21 + 1 bytes a level is 4402: refused.
  write_file(file, chain(200, "P" + std::string(20, 'p')));
  CHECK(run_command(gfec_exe + " --check --chart C0 " + file).out.find("path of names is 4402 bytes long") !=
        std::string::npos);
}
