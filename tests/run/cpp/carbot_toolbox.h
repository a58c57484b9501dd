// A scripted Carbot toolbox for compile-and-run tests of generated plans: the contract of
// docs/toolbox.md (classes, enums in declaration order, constructors taking the environment,
// then afp::In/afp::Out in parameter order) with made-up behaviour driven by the script
// (scripted_env.h). Every start logs the inputs it read, so a test sees formulas evaluated.
//
//   Forward      moves 10 cm per step; FORWARD_OK once |distance| is covered
//   Turn         TURN_OK at its first step
//   SearchWall   `wall=A`: writes A to its out parameter, WALL_FOUND; else NO_WALL_FOUND
//   WallForward  `blocked`: LANE_NOT_FREE; `lost`: WALL_LOST; else FORWARD_OK at its third step
//   CountDown    rest = n - 1; AGAIN while rest > 0, else DONE
//   CheckTouch   `touch`: TOUCHED          CheckEscape  `escape`: ESCAPE
//   CheckLane    `lane=D` with D < dist: LANE_NOT_FREE (period 10ms, as the toolbox says)
#ifndef CARBOT_TOOLBOX_H
#define CARBOT_TOOLBOX_H

#include <afp/afp.h>

#include <chrono>
#include <cmath>
#include <utility>

#include "scripted_env.h"

class Carbot : public ScriptedEnv {};
using Env = Carbot;

class Forward : public afp::Actor {
public:
  enum State { FORWARD_OK };
  Forward(Carbot &ee, afp::In<float> distance) : ee_(ee), distance_(std::move(distance)) {}
  void start(afp::Context &ctx) override {
    goal_ = distance_.read(ctx);
    moved_ = 0;
    ee_.out << "  Forward distance=" << goal_ << "\n";
  }
  afp::StepResult step(afp::Context &) override {
    moved_ += 10;
    return moved_ >= std::fabs(goal_) ? afp::StepResult(FORWARD_OK) : afp::running;
  }
  void stop() override { ee_.out << "  Forward stop\n"; }

private:
  Carbot &ee_;
  afp::In<float> distance_;
  float goal_ = 0, moved_ = 0;
};

class Turn : public afp::Actor {
public:
  enum State { TURN_OK };
  Turn(Carbot &ee, afp::In<float> angle) : ee_(ee), angle_(std::move(angle)) {}
  void start(afp::Context &ctx) override { ee_.out << "  Turn angle=" << angle_.read(ctx) << "\n"; }
  afp::StepResult step(afp::Context &) override { return TURN_OK; }

private:
  Carbot &ee_;
  afp::In<float> angle_;
};

class SearchWall : public afp::Actor {
public:
  enum State { WALL_FOUND, NO_WALL_FOUND };
  SearchWall(Carbot &ee, afp::Out<float> angle) : ee_(ee), angle_(std::move(angle)) {}
  afp::StepResult step(afp::Context &ctx) override {
    if (!ee_.has("wall")) return NO_WALL_FOUND;
    angle_.write(ctx, static_cast<float>(ee_.value("wall")));
    return WALL_FOUND;
  }

private:
  Carbot &ee_;
  afp::Out<float> angle_;
};

class WallForward : public afp::Actor {
public:
  enum State { FORWARD_OK, LANE_NOT_FREE, WALL_LOST };
  WallForward(Carbot &ee, afp::In<float> dist, afp::In<float> minDist, afp::In<float> maxDist)
      : ee_(ee), dist_(std::move(dist)), min_(std::move(minDist)), max_(std::move(maxDist)) {}
  void start(afp::Context &ctx) override {
    steps_ = 0;
    ee_.out << "  WallForward dist=" << dist_.read(ctx) << " min=" << min_.read(ctx) << " max=" << max_.read(ctx)
            << "\n";
  }
  afp::StepResult step(afp::Context &) override {
    if (ee_.has("blocked")) return LANE_NOT_FREE;
    if (ee_.has("lost")) return WALL_LOST;
    return ++steps_ == 3 ? afp::StepResult(FORWARD_OK) : afp::running;
  }

private:
  Carbot &ee_;
  afp::In<float> dist_, min_, max_;
  int steps_ = 0;
};

class CountDown : public afp::Computation {
public:
  enum State { AGAIN, DONE };
  CountDown(Carbot &ee, afp::In<int> n, afp::Out<int> rest) : ee_(ee), n_(std::move(n)), rest_(std::move(rest)) {}
  int compute(afp::Context &ctx) override {
    int n = n_.read(ctx);
    ee_.out << "  CountDown n=" << n << "\n";
    rest_.write(ctx, n - 1);
    return n - 1 > 0 ? AGAIN : DONE;
  }

private:
  Carbot &ee_;
  afp::In<int> n_;
  afp::Out<int> rest_;
};

class CheckTouch : public afp::Supervisor {
public:
  enum Event { TOUCHED };
  explicit CheckTouch(Carbot &ee) : ee_(ee) {}
  afp::CheckResult check(afp::Context &) override {
    return ee_.has("touch") ? afp::CheckResult(TOUCHED) : afp::no_event;
  }

private:
  Carbot &ee_;
};

class CheckLane : public afp::Supervisor {
public:
  enum Event { LANE_NOT_FREE };
  CheckLane(Carbot &ee, afp::In<float> dist)
      : afp::Supervisor(std::chrono::milliseconds(10)), ee_(ee), dist_(std::move(dist)) {}
  void start(afp::Context &ctx) override {
    limit_ = dist_.read(ctx);
    ee_.out << "  CheckLane dist=" << limit_ << "\n";
  }
  afp::CheckResult check(afp::Context &) override {
    return ee_.has("lane") && ee_.value("lane") < limit_ ? afp::CheckResult(LANE_NOT_FREE) : afp::no_event;
  }

private:
  Carbot &ee_;
  afp::In<float> dist_;
  float limit_ = 0;
};

class CheckEscape : public afp::Supervisor {
public:
  enum Event { ESCAPE };
  explicit CheckEscape(Carbot &ee) : ee_(ee) {}
  afp::CheckResult check(afp::Context &) override {
    return ee_.has("escape") ? afp::CheckResult(ESCAPE) : afp::no_event;
  }

private:
  Carbot &ee_;
};

#endif  // CARBOT_TOOLBOX_H
