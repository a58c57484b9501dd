#include "wall_fit.h"

#include <cmath>

namespace carbot::toolbox {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kOffLine = 0.03;  ///< m: a point further from the run's line starts a new run
constexpr double kGap = 0.40;      ///< m: so does a jump between neighbouring echoes
constexpr double kMaxRms = 0.02;   ///< m: a run straighter than this is a wall

struct Point {
  double x, y;
};

/// A least-squares line: centroid, unit direction, rms distance of the points from it.
struct FitLine {
  Point c{0, 0};
  Point u{1, 0};
  double rms = 0;
};

FitLine fit(const std::vector<Point>& pts) {
  FitLine l;
  for (const Point& p : pts) l.c.x += p.x / pts.size(), l.c.y += p.y / pts.size();
  double sxx = 0, syy = 0, sxy = 0;
  for (const Point& p : pts) {
    const double dx = p.x - l.c.x, dy = p.y - l.c.y;
    sxx += dx * dx, syy += dy * dy, sxy += dx * dy;
  }
  const double a = 0.5 * std::atan2(2 * sxy, sxx - syy);  // principal axis
  l.u = {std::cos(a), std::sin(a)};
  double sum2 = 0;
  for (const Point& p : pts) {
    const double d = (p.x - l.c.x) * -l.u.y + (p.y - l.c.y) * l.u.x;
    sum2 += d * d;
  }
  l.rms = std::sqrt(sum2 / pts.size());
  return l;
}

double off_line(const FitLine& l, Point p) { return std::fabs((p.x - l.c.x) * -l.u.y + (p.y - l.c.y) * l.u.x); }

std::vector<std::vector<Point>> straight_runs(const std::vector<Point>& pts) {
  std::vector<std::vector<Point>> runs;
  std::vector<Point> run;
  auto close = [&] {
    if (run.size() >= 3 && fit(run).rms < kMaxRms) runs.push_back(run);
    run.clear();
  };
  for (const Point& p : pts) {
    if (!run.empty()) {
      const Point& last = run.back();
      const bool jump = std::hypot(p.x - last.x, p.y - last.y) > kGap;
      const bool bends = run.size() >= 2 && off_line(fit(run), p) > kOffLine;
      if (jump || bends) {
        const Point keep = run.back();  // a corner point may start the next wall too
        close();
        if (!jump) run.push_back(keep);
      }
    }
    run.push_back(p);
  }
  close();
  return runs;
}

/// Where driving straight on (along +x from the centre) meets the run, or a negative number.
double ahead(const FitLine& l, const std::vector<Point>& run) {
  if (std::fabs(l.u.y) < 0.2) return -1;  // nearly parallel: never met
  const double s = -l.c.y / l.u.y;        // along the line to y = 0
  double lo = 1e9, hi = -1e9;             // the run's extent along its line, plus a margin
  for (const Point& p : run) {
    const double t = (p.x - l.c.x) * l.u.x + (p.y - l.c.y) * l.u.y;
    lo = std::fmin(lo, t), hi = std::fmax(hi, t);
  }
  if (s < lo - 0.3 || s > hi + 0.3) return -1;
  return l.c.x + s * l.u.x;
}

}  // namespace

WallFit fit_wall(const std::vector<SonarSample>& sweep, double sonar_x, double max_range) {
  std::vector<Point> pts;
  for (const SonarSample& s : sweep)
    if (s.range < max_range - 1e-6) pts.push_back({sonar_x + s.range * std::cos(s.angle), s.range * std::sin(s.angle)});
  WallFit best;
  double best_ahead = 1e9, best_near = 1e9;
  bool best_is_ahead = false;
  for (const auto& run : straight_runs(pts)) {
    const FitLine l = fit(run);
    const double a = ahead(l, run);
    const double near = std::fabs(l.c.x * -l.u.y + l.c.y * l.u.x);  // centre to line
    const bool take = a > 0 ? (!best_is_ahead || a < best_ahead) : (!best_is_ahead && near < best_near);
    if (!take) continue;
    best_is_ahead = a > 0;
    best_ahead = a > 0 ? a : best_ahead;
    best_near = near;
    // Parallel headings: along u or against it; the wall must end up on the right, i.e. the
    // line's nearest point q on the right of the new heading h: h x q < 0.
    const double qx = -l.u.y * (l.c.x * -l.u.y + l.c.y * l.u.x), qy = l.u.x * (l.c.x * -l.u.y + l.c.y * l.u.x);
    double h = std::atan2(l.u.y, l.u.x);
    if (std::cos(h) * qy - std::sin(h) * qx > 0) h += kPi;
    best.found = true;
    best.turn = std::atan2(std::sin(h), std::cos(h));
    best.distance = near;
  }
  return best;
}

}  // namespace carbot::toolbox
