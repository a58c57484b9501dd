// The Action Flow Plans wall follower (samples/wall_follow.plan, unchanged) with the C++
// Carbot toolbox on the simulated Carbot.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "core/geometry.h"
#include "support.h"

namespace {

/// Distance from a point to the nearest wall face or box side, metres.
double clearance(const carbot::World &w, double x, double y) {
  double best = 1e9;
  for (const carbot::Wall &wall : w.walls) {
    const double dx = wall.to.x - wall.from.x, dy = wall.to.y - wall.from.y;
    const double t = std::clamp(((x - wall.from.x) * dx + (y - wall.from.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    best = std::min(best, std::hypot(x - wall.from.x - t * dx, y - wall.from.y - t * dy) - wall.thickness / 2);
  }
  for (const carbot::Box &b : w.boxes) {
    const double dx = std::max(std::fabs(x - b.center.x) - b.size.x / 2, 0.0);
    const double dy = std::max(std::fabs(y - b.center.y) - b.size.y / 2, 0.0);
    best = std::min(best, std::hypot(dx, dy));
  }
  return best;
}

struct Interval {
  double from, to;
};

/// When the plan's actor `actor` ran (from result.json's plan_log).
std::vector<Interval> intervals(const nlohmann::json &result, const std::string &actor) {
  std::vector<Interval> out;
  double since = -1;
  for (const auto &e : result["plan_log"]) {
    const std::string text = e["event"];
    const double t = e["t"];
    if (since >= 0) out.push_back({since, t}), since = -1;
    if (text == "start WallFollow." + actor) since = t;
  }
  if (since >= 0) out.push_back({since, result["sim_time_s"].get<double>()});
  return out;
}

bool logged(const nlohmann::json &result, const std::string &text) {
  for (const auto &e : result["plan_log"])
    if (e["event"] == text) return true;
  return false;
}

/// Runs the plan in `world_file` (whose escape event comes at 110 s) and checks what every
/// room must show: it followed walls inside the band, and escape ended it.
e2e::SimRun check_follows_walls(const char *world_file, double min_following_s) {
  e2e::SimRun run = e2e::run_sim("samples/wall_follow.plan", world_file, 120);
  INFO(run.output);
  if (e2e::skipped_for_missing_backend(run)) return run;
  REQUIRE(run.exit_code == 0);

  // Escape (at 110 s) terminates the plan, and the run ends there.
  CHECK(run.result["status"] == "terminated");
  CHECK(run.result["sim_time_s"].get<double>() == Approx(110).margin(0.05));
  CHECK(logged(run.result, "WallFollow.followWall interrupted by escape"));

  // Following: once settled (3 s after followWall starts), the robot's centre stays within
  // the plan's band walldist +- 5 cm = [25, 35] cm, give or take 5 cm, of the wall.
  const carbot::World w = e2e::world(world_file);
  double following = 0;
  double lo = 1e9, hi = 0;
  for (const Interval &iv : intervals(run.result, "followWall")) {
    for (const auto &r : run.trace) {
      if (r.t < iv.from + 3 || r.t > iv.to) continue;
      const double d = clearance(w, r.x, r.y);
      lo = std::min(lo, d), hi = std::max(hi, d);
      following += 0.01;
    }
  }
  INFO("followed walls for " << following << " s at " << lo << " .. " << hi << " m");
  CHECK(following >= min_following_s);
  CHECK(lo >= 0.20);
  CHECK(hi <= 0.40);
  return run;
}

}  // namespace

TEST_CASE("wall follow: finds a wall, follows it in the band, backs off a bump, stops on escape", "[e2e][plan]") {
  const e2e::SimRun run = check_follows_walls("sim/worlds/room.json", 40);
  if (run.exit_code != 0) return;
  INFO(run.output);

  // The low crate is invisible to the sonar: the robot bumps it, and CheckTouch sends it back
  // 30 cm (backupCollision), then it looks for a wall.
  REQUIRE(run.result["bump_log"].size() >= 1);
  const double bump_t = run.result["bump_log"][0]["t"];
  CHECK(logged(run.result, "WallFollow.searchFirstWall interrupted by touch"));
  CHECK(logged(run.result, "start WallFollow.backupCollision"));
  CHECK(logged(run.result, "start WallFollow.findWallAngle"));
  const auto at = [&](double t) {
    return *std::find_if(run.trace.begin(), run.trace.end(), [&](const auto &r) { return r.t >= t - 1e-6; });
  };
  const auto before = at(bump_t), after = at(bump_t + 2.5);
  const double h = carbot::rad(before.heading);
  const double moved = (after.x - before.x) * std::cos(h) + (after.y - before.y) * std::sin(h);
  CHECK(moved == Approx(-0.30).margin(0.05));
}

TEST_CASE("wall follow: the same plan follows the walls of an L-shaped room", "[e2e][plan]") {
  check_follows_walls("sim/worlds/room_l.json", 30);
}
