// The wall-following plan (samples/wall_follow.plan) wired the way the
// C++ back end is to emit it (see docs/runtime.md), over a scripted Carbot
// toolbox: proves the API is easy to target and that the plan runs as drawn.
#include <afp/afp.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "fakes.h"

using namespace std::chrono_literals;

namespace {

// The execution environment `ee`: a robot whose sensors the test scripts.
struct Env {
  bool touching = false;
  bool escape = false;
  bool wall_visible = false;
  float wall_angle = 0;
  float obstacle_distance = 1000;
  float heading = 0;
  float position = 0;
};

// ---- The Carbot toolbox, as a toolbox developer would write it ----

class Forward : public afp::Actor {
 public:
  enum State { FORWARD_OK };
  Forward(Env& ee, afp::In<float> distance) : ee_(ee), distance_(std::move(distance)) {}
  void start(afp::Context& ctx) override { remaining_ = distance_.read(ctx); }
  afp::StepResult step(afp::Context&) override {
    float move = std::clamp(remaining_, -10.0f, 10.0f);  // at most 10 units per step
    ee_.position += move;
    remaining_ -= move;
    return remaining_ == 0 ? afp::StepResult(FORWARD_OK) : afp::running;
  }

 private:
  Env& ee_;
  afp::In<float> distance_;
  float remaining_ = 0;
};

class Turn : public afp::Actor {
 public:
  enum State { TURN_OK };
  Turn(Env& ee, afp::In<float> angle) : ee_(ee), angle_(std::move(angle)) {}
  void start(afp::Context& ctx) override { angle_now_ = angle_.read(ctx); }
  afp::StepResult step(afp::Context&) override {
    ee_.heading += angle_now_;
    return TURN_OK;
  }

 private:
  Env& ee_;
  afp::In<float> angle_;
  float angle_now_ = 0;
};

class SearchWall : public afp::Actor {
 public:
  enum State { WALL_FOUND, NO_WALL_FOUND };
  SearchWall(Env& ee, afp::Out<float> angle) : ee_(ee), angle_(std::move(angle)) {}
  afp::StepResult step(afp::Context& ctx) override {
    if (!ee_.wall_visible) return NO_WALL_FOUND;
    angle_.write(ctx, ee_.wall_angle);
    return WALL_FOUND;
  }

 private:
  Env& ee_;
  afp::Out<float> angle_;
};

class WallForward : public afp::Actor {
 public:
  enum State { FORWARD_OK, LANE_NOT_FREE, WALL_LOST };
  WallForward(Env& ee, afp::In<float> dist, afp::In<float> min_dist, afp::In<float> max_dist)
      : ee_(ee), dist_(std::move(dist)), min_dist_(std::move(min_dist)), max_dist_(std::move(max_dist)) {}
  void start(afp::Context& ctx) override { band_ = {dist_.read(ctx), min_dist_.read(ctx), max_dist_.read(ctx)}; }
  afp::StepResult step(afp::Context&) override {
    if (ee_.obstacle_distance < band_[0]) return LANE_NOT_FREE;
    if (!ee_.wall_visible) return WALL_LOST;
    return afp::running;
  }

 private:
  Env& ee_;
  afp::In<float> dist_, min_dist_, max_dist_;
  std::vector<float> band_;  // dist, minDist, maxDist as read at start
};

class CheckTouch : public afp::Supervisor {
 public:
  enum Event { TOUCHED };
  explicit CheckTouch(Env& ee) : ee_(ee) {}
  afp::CheckResult check(afp::Context&) override { return ee_.touching ? afp::CheckResult(TOUCHED) : afp::no_event; }

 private:
  Env& ee_;
};

class CheckLane : public afp::Supervisor {
 public:
  enum Event { LANE_NOT_FREE };
  CheckLane(Env& ee, afp::In<float> dist) : afp::Supervisor(10ms), ee_(ee), dist_(std::move(dist)) {}
  void start(afp::Context& ctx) override { limit_ = dist_.read(ctx); }
  afp::CheckResult check(afp::Context&) override {
    return ee_.obstacle_distance < limit_ ? afp::CheckResult(LANE_NOT_FREE) : afp::no_event;
  }

 private:
  Env& ee_;
  afp::In<float> dist_;
  float limit_ = 0;
};

class CheckEscape : public afp::Supervisor {
 public:
  enum Event { ESCAPE };
  explicit CheckEscape(Env& ee) : ee_(ee) {}
  afp::CheckResult check(afp::Context&) override { return ee_.escape ? afp::CheckResult(ESCAPE) : afp::no_event; }

 private:
  Env& ee_;
};

// ---- What `gfec --emit=cpp wall_follow.plan` is to generate ----

std::unique_ptr<afp::Plan> make_WallFollow(Env& ee) {
  auto plan = std::make_unique<afp::Plan>("WallFollow");
  plan->declare("walldist", afp::Value(30.0f));
  plan->declare("wallangle", afp::Type::Float);

  // Actors
  auto* searchFirstWall = plan->add_actor("searchFirstWall", std::make_unique<Forward>(ee, afp::in<float>(100000)));
  auto* backupCollision = plan->add_actor(
      "backupCollision", std::make_unique<Forward>(
                             ee, afp::in<float>([](const afp::ConfigView& c) { return -c.get<float>("walldist"); })));
  auto* findWallAngle =
      plan->add_actor("findWallAngle", std::make_unique<SearchWall>(ee, afp::out<float>("wallangle")));
  auto* parallelToWall =
      plan->add_actor("parallelToWall", std::make_unique<Turn>(ee, afp::in<float>(afp::entry("wallangle"))));
  auto* followWall = plan->add_actor(
      "followWall", std::make_unique<WallForward>(
                        ee, afp::in<float>(afp::entry("walldist")),
                        afp::in<float>([](const afp::ConfigView& c) { return c.get<float>("walldist") - 5; }),
                        afp::in<float>([](const afp::ConfigView& c) { return c.get<float>("walldist") + 5; })));
  auto* turnAfterWallLost = plan->add_actor("turnAfterWallLost", std::make_unique<Turn>(ee, afp::in<float>(-60)));

  // Supervisors
  auto* escape = plan->add_supervisor("escape", std::make_unique<CheckEscape>(ee));
  auto* touch = plan->add_supervisor("touch", std::make_unique<CheckTouch>(ee));
  auto* lane = plan->add_supervisor("lane", std::make_unique<CheckLane>(ee, afp::in<float>(afp::entry("walldist"))));
  auto* wallTouch = plan->add_supervisor("wallTouch", std::make_unique<CheckTouch>(ee));

  // Rules
  plan->define_first_actor(searchFirstWall);
  plan->define_global_supervision(escape, CheckEscape::ESCAPE, afp::terminate);
  plan->define_subsequent(searchFirstWall, Forward::FORWARD_OK, searchFirstWall);
  plan->define_supervision(searchFirstWall, touch, CheckTouch::TOUCHED, backupCollision);
  plan->define_supervision(searchFirstWall, lane, CheckLane::LANE_NOT_FREE, findWallAngle);
  plan->define_subsequent(backupCollision, Forward::FORWARD_OK, findWallAngle);
  plan->define_subsequent(findWallAngle, SearchWall::WALL_FOUND, parallelToWall);
  plan->define_subsequent(findWallAngle, SearchWall::NO_WALL_FOUND, turnAfterWallLost);
  plan->define_subsequent(parallelToWall, Turn::TURN_OK, followWall);
  plan->define_subsequent(followWall, WallForward::FORWARD_OK, followWall);
  plan->define_subsequent(followWall, WallForward::LANE_NOT_FREE, findWallAngle);
  plan->define_subsequent(followWall, WallForward::WALL_LOST, turnAfterWallLost);
  plan->define_supervision(followWall, wallTouch, CheckTouch::TOUCHED, backupCollision);
  plan->define_subsequent(turnAfterWallLost, Turn::TURN_OK, searchFirstWall);
  return plan;
}

// The started actors of a trace, in order.
std::vector<std::string> started(const fakes::Recorder& trace) {
  const std::string prefix = "WallFollow: start ";
  std::vector<std::string> out;
  for (const auto& line : trace.lines)
    if (line.rfind(prefix, 0) == 0) out.push_back(line.substr(prefix.size()));
  return out;
}

}  // namespace

TEST_CASE("the wall-following plan runs as drawn", "[wallfollow]") {
  Env ee;
  auto plan = make_WallFollow(ee);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::SteppedExecutor exec(*plan, config, &trace);
  config.set("walldist", 25);  // the application sets walldist before the start
  exec.start();
  auto run_for = [&](int steps) {
    for (int i = 0; i < steps; ++i) exec.step(10ms);
  };

  run_for(3);                 // driving towards a wall
  ee.obstacle_distance = 20;  // the lane supervisor sees it
  ee.wall_visible = true;
  ee.wall_angle = 12;
  run_for(1);  // lane: LANE_NOT_FREE -> findWallAngle
  ee.obstacle_distance = 1000;
  run_for(3);  // WALL_FOUND -> parallelToWall -> followWall
  CHECK(config.get<float>("wallangle") == 12.0f);
  CHECK(ee.heading == 12.0f);
  ee.touching = true;
  run_for(1);  // wallTouch: TOUCHED -> backupCollision
  ee.touching = false;
  float before_backup = ee.position;
  run_for(3);  // backs up 25 in 3 steps, then findWallAngle
  CHECK(ee.position == before_backup - 25);
  ee.wall_visible = false;
  run_for(3);  // NO_WALL_FOUND -> turnAfterWallLost -> searchFirstWall
  CHECK(ee.heading == 12.0f - 60.0f);
  ee.escape = true;
  CHECK(exec.step(10ms) == afp::Status::Interrupted);

  CHECK(started(trace) == std::vector<std::string>{"searchFirstWall", "findWallAngle", "parallelToWall", "followWall",
                                                   "backupCollision", "findWallAngle", "turnAfterWallLost",
                                                   "searchFirstWall"});
  CHECK(trace.lines.back() == "WallFollow: end interrupted");
}
