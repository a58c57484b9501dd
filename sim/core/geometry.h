// Small plane geometry shared by the sensors, the robot libraries' helpers and the tests.
#pragma once

#include <cmath>

#include "core/world.h"

namespace carbot {

constexpr double kPi = 3.14159265358979323846;

inline double deg(double rad) { return rad * 180.0 / kPi; }
inline double rad(double deg) { return deg * kPi / 180.0; }

/// The angle a, wrapped into (-pi, pi].
inline double wrap_angle(double a) {
  a = std::fmod(a + kPi, 2 * kPi);
  if (a <= 0) a += 2 * kPi;
  return a - kPi;
}

inline double distance(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

/// Where a point lies relative to a polyline: how far from it, and how far along it.
struct LinePosition {
  double distance = 1e300;  ///< to the nearest point of the polyline, metres
  double along = 0;         ///< arc length from points[0] to that nearest point, metres
};

/// Nearest point of `line` (closed lines include the last-to-first segment).
LinePosition locate_on_line(const Line& line, Vec2 p);

/// Total arc length of `line`.
double line_length(const Line& line);

}  // namespace carbot
