#include "core/geometry.h"

#include <algorithm>

namespace carbot {
namespace {

size_t segment_count(const Line& line) {
  if (line.points.size() < 2) return 0;
  return line.closed ? line.points.size() : line.points.size() - 1;
}

Vec2 segment_end(const Line& line, size_t i) { return line.points[(i + 1) % line.points.size()]; }

}  // namespace

LinePosition locate_on_line(const Line& line, Vec2 p) {
  LinePosition best;
  double walked = 0;
  for (size_t i = 0; i < segment_count(line); ++i) {
    const Vec2 a = line.points[i], b = segment_end(line, i);
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0);
    const Vec2 q{a.x + t * dx, a.y + t * dy};
    const double d = distance(p, q);
    if (d < best.distance) best = {d, walked + t * std::sqrt(len2)};
    walked += std::sqrt(len2);
  }
  return best;
}

double line_length(const Line& line) {
  double total = 0;
  for (size_t i = 0; i < segment_count(line); ++i) total += distance(line.points[i], segment_end(line, i));
  return total;
}

}  // namespace carbot
