// WallForward: follow the wall on the right at a distance, with the sonar looking right and
// glancing ahead now and then.
#include <algorithm>
#include <cmath>

#include "carbot_toolbox.h"

namespace carbot::toolbox {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSide = -kPi / 2;     ///< mount angle looking right
constexpr double kSpeed = 0.20;        ///< m/s
constexpr double kSegment = 0.50;      ///< m driven per FORWARD_OK
constexpr double kLookEvery = 0.6;     ///< s between glances ahead
constexpr double kAheadMargin = 0.15;  ///< m added to dist before the lane counts as blocked
constexpr double kLostMargin = 0.25;   ///< m beyond maxDist that counts as no wall
constexpr double kGain = 2.5;          ///< rad/s per m off the target distance
constexpr double kDamping = 3.0;       ///< rad/s per m/s of drift towards or away from the wall
constexpr double kMaxTurn = 0.6;       ///< rad/s

}  // namespace

WallForward::WallForward(Environment& ee, afp::In<float> dist, afp::In<float> minDist, afp::In<float> maxDist)
    : ee_(ee), dist_(std::move(dist)), min_dist_(std::move(minDist)), max_dist_(std::move(maxDist)) {}

void WallForward::start(afp::Context& ctx) {
  target_ = dist_.read(ctx) / 100.0;
  low_ = min_dist_.read(ctx) / 100.0;
  high_ = max_dist_.read(ctx) / 100.0;
  x0_ = ee_.x(), y0_ = ee_.y();
  glancing_ = false;
  side_since_ = ee_.time();
  last_side_ = -1;
  rate_ = 0;
  turn_ = 0;
  misses_ = 0;
  ee_.aim_sonar(kSide);
}

afp::StepResult WallForward::step(afp::Context&) {
  if (std::hypot(ee_.x() - x0_, ee_.y() - y0_) >= kSegment) return FORWARD_OK;
  return glancing_ ? look_ahead() : follow();
}

// While the mount swings ahead and back, the robot keeps its last steering, halved.
afp::StepResult WallForward::look_ahead() {
  ee_.drive(kSpeed, turn_ * 0.5);
  if (!ee_.sonar_at(0)) return afp::running;
  if (ee_.sonar_range() < target_ + kAheadMargin) {
    ee_.halt();
    return LANE_NOT_FREE;
  }
  glancing_ = false;
  last_side_ = -1;  // the drift estimate restarts after the gap
  ee_.aim_sonar(kSide);
  return afp::running;
}

afp::StepResult WallForward::follow() {
  if (!ee_.sonar_at(kSide)) {  // still swinging back: keep going as before
    ee_.drive(kSpeed, turn_ * 0.5);
    side_since_ = ee_.time();
    return afp::running;
  }
  const double now = ee_.time();
  const double d = ee_.sonar_range();
  if (d > high_ + kLostMargin) {
    if (++misses_ >= 3) {
      ee_.halt();
      return WALL_LOST;
    }
  } else {
    misses_ = 0;
    if (last_side_ >= 0 && now > last_side_t_) rate_ = 0.7 * rate_ + 0.3 * (d - last_side_) / (now - last_side_t_);
    last_side_ = d, last_side_t_ = now;
    // Wall on the right: too far (or drifting away) turns right, i.e. negative.
    const double gain = (d < low_ || d > high_) ? 1.5 * kGain : kGain;
    turn_ = std::clamp(gain * (target_ - d) - kDamping * rate_, -kMaxTurn, kMaxTurn);
  }
  ee_.drive(kSpeed, turn_);
  if (now - side_since_ >= kLookEvery) {
    glancing_ = true;
    ee_.aim_sonar(0);
  }
  return afp::running;
}

void WallForward::stop() { ee_.halt(); }

}  // namespace carbot::toolbox
