// Forward and Turn: closed-loop moves on the overhead tracker's pose.
#include <algorithm>
#include <cmath>

#include "carbot_toolbox.h"

namespace carbot::toolbox {
namespace {

constexpr double kCruise = 0.25;      ///< m/s
constexpr double kCreep = 0.04;       ///< m/s, the slowest approach
constexpr double kDone = 0.005;       ///< m: Forward is done this close
constexpr double kStall = 2.0;        ///< s without 1 cm of progress: blocked, give up
constexpr double kProgress = 0.01;    ///< m
constexpr double kHeadingGain = 2.0;  ///< rad/s per rad of heading error
constexpr double kTurnGain = 2.5;     ///< rad/s per rad still to turn
constexpr double kTurnMax = 1.2;      ///< rad/s
constexpr double kTurnMin = 0.12;     ///< rad/s, so the last degrees do not take forever
constexpr double kTurnDone = 0.012;   ///< rad (~0.7 deg)

double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }

}  // namespace

Forward::Forward(Environment& ee, afp::In<float> distance) : ee_(ee), distance_(std::move(distance)) {}

void Forward::start(afp::Context& ctx) {
  goal_ = distance_.read(ctx) / 100.0;
  x0_ = ee_.x(), y0_ = ee_.y(), heading0_ = ee_.heading();
  best_ = 0;
  best_since_ = ee_.time();
}

afp::StepResult Forward::step(afp::Context&) {
  const double along = (ee_.x() - x0_) * std::cos(heading0_) + (ee_.y() - y0_) * std::sin(heading0_);
  const double left = goal_ - along;  // signed: same sign as goal_ until done
  // Done when there; also when blocked (backing into something the bumper cannot feel):
  // the toolbox gives Forward no other way to end.
  const double done = std::fabs(goal_) - std::fabs(left);
  if (done > best_ + kProgress) best_ = done, best_since_ = ee_.time();
  if (left * (goal_ < 0 ? -1 : 1) <= kDone || ee_.time() - best_since_ > kStall) {
    ee_.halt();
    return FORWARD_OK;
  }
  const double speed = std::clamp(std::fabs(left) * 1.5, kCreep, kCruise) * (left < 0 ? -1 : 1);
  ee_.drive(speed, kHeadingGain * wrap(heading0_ - ee_.heading()));
  return afp::running;
}

void Forward::stop() { ee_.halt(); }

Turn::Turn(Environment& ee, afp::In<float> angle) : ee_(ee), angle_(std::move(angle)) {}

void Turn::start(afp::Context& ctx) {
  goal_ = angle_.read(ctx) * 3.14159265358979323846 / 180.0;
  turned_ = 0;
  last_heading_ = ee_.heading();
  settled_ = 0;
}

afp::StepResult Turn::step(afp::Context&) {
  const double h = ee_.heading();
  turned_ += wrap(h - last_heading_);  // unwrapped, so turns beyond 180 degrees work
  last_heading_ = h;
  const double left = goal_ - turned_;
  if (std::fabs(left) < kTurnDone) {
    ee_.halt();
    if (++settled_ >= 3) return TURN_OK;  // wait for the wheels to stop before reporting
    return afp::running;
  }
  settled_ = 0;
  const double rate = std::clamp(kTurnGain * std::fabs(left), kTurnMin, kTurnMax);
  ee_.drive(0, left < 0 ? -rate : rate);
  return afp::running;
}

void Turn::stop() { ee_.halt(); }

}  // namespace carbot::toolbox
