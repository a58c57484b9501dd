// The GFE line follower (samples/line_follower.sfc, unchanged) on the simulated Carbot.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include "core/geometry.h"
#include "support.h"

namespace {

struct LineStats {
  double max_error = 0;  ///< largest distance of the robot centre from the line, m
  double rms_error = 0;
  double laps = 0;  ///< signed progress along the line / its length (+ = drawing order)
};

LineStats line_stats(const carbot::World &w, const std::vector<e2e::TraceRow> &trace) {
  LineStats s;
  const double length = carbot::line_length(w.line);
  double sum2 = 0, progress = 0, last = 0;
  for (size_t i = 0; i < trace.size(); ++i) {
    const auto at = carbot::locate_on_line(w.line, {trace[i].x, trace[i].y});
    s.max_error = std::max(s.max_error, at.distance);
    sum2 += at.distance * at.distance;
    if (i > 0) {
      double step = at.along - last;  // unwrap across the start of a closed line
      if (step > length / 2) step -= length;
      if (step < -length / 2) step += length;
      progress += step;
    }
    last = at.along;
  }
  s.rms_error = trace.empty() ? 0 : std::sqrt(sum2 / trace.size());
  s.laps = progress / length;
  return s;
}

void check_follows(const char *world_file, double seconds, double min_laps) {
  const e2e::SimRun run = e2e::run_sim("samples/line_follower.sfc", world_file, seconds);
  INFO(run.output);
  if (e2e::skipped_for_missing_backend(run)) return;
  REQUIRE(run.exit_code == 0);
  CHECK(run.result["status"] == "running");
  CHECK(run.result["bumps"] == 0);
  CHECK(run.result["left_floor"] == false);
  // The picture: a titled SVG with the line (a closed polygon) and the robot's path.
  CHECK(run.svg.rfind("<svg", 0) == 0);
  CHECK(run.svg.find("LineFollower (sfc) on ") != std::string::npos);
  CHECK(run.svg.find("<polygon points=") != std::string::npos);
  CHECK(run.svg.find("<polyline points=") != std::string::npos);
  CHECK(run.svg.find("robot path") != std::string::npos);
  REQUIRE(run.trace.size() == static_cast<size_t>(std::lround(seconds / 0.01)) + 1);

  const LineStats s = line_stats(e2e::world(world_file), run.trace);
  INFO("laps " << s.laps << ", max lateral error " << s.max_error << " m, rms " << s.rms_error << " m");
  CHECK(s.laps >= min_laps);
  CHECK(s.max_error < 0.04);  // the IR sensors are 7 cm apart: the line never got away
  CHECK(s.rms_error < 0.02);
}

}  // namespace

TEST_CASE("line follower: laps the oval without losing the line", "[e2e][line]") {
  check_follows("sim/worlds/oval.json", 75, 1.5);
}

TEST_CASE("line follower: the same chart follows the rounded square", "[e2e][line]") {
  check_follows("sim/worlds/rounded_square.json", 75, 1.5);
}

// The measures must be able to fail: a robot put down beside the line, facing away from it,
// sees only white and drives straight on; the same statistics show that.
TEST_CASE("line follower: off the line, the measures show it lost", "[e2e][line]") {
  e2e::TempDir dir;
  const std::string world_file = dir.file("beside.json");
  std::ofstream(world_file) << R"({"size": [8, 8],
    "line": {"width": 0.05, "closed": true, "points": [[-1, -1], [1, -1], [1, 1], [-1, 1]]},
    "start": {"pose": [0, -1.3, -90]}})";
  const e2e::SimRun run = e2e::run_sim("samples/line_follower.sfc", world_file, 15);
  INFO(run.output);
  if (e2e::skipped_for_missing_backend(run)) return;
  REQUIRE(run.exit_code == 0);
  const LineStats s = line_stats(e2e::world(world_file), run.trace);
  CHECK(std::fabs(s.laps) < 0.2);
  CHECK(s.max_error > 0.5);
}
