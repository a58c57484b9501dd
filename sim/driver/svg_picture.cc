// The picture of a run: the floor to scale, what stands on it, and the path the robot took.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/carbot_model.h"
#include "core/geometry.h"
#include "driver/engine_log.h"
#include "driver/reports.h"
#include "recording.h"
#include "xml_text.h"

namespace carbot::driver {
namespace {

// Colours chosen to read on screen and in print: dark line, warm solids, one blue path.
constexpr const char* kPage = "#fbfaf7";
constexpr const char* kFloor = "#ece8de";
constexpr const char* kGrid = "#dcd6c8";
constexpr const char* kLineInk = "#26262b";
constexpr const char* kWallInk = "#5a4636";
constexpr const char* kBoxFill = "#c49a5c";
constexpr const char* kBoxEdge = "#7a5a30";
constexpr const char* kPath = "#1f6fd1";
constexpr const char* kItem = "#e8772e";
constexpr const char* kDest = "#2e9e5b";
constexpr const char* kBump = "#d62839";
constexpr const char* kText = "#2b2b2b";
constexpr const char* kMuted = "#6b6b6b";

/// World metres -> picture pixels (y up in the world, down in SVG).
struct Frame {
  double scale = 100;  ///< px per metre
  double ox = 0, oy = 0;
  double x(double wx) const { return ox + wx * scale; }
  double y(double wy) const { return oy - wy * scale; }
  double len(double m) const { return m * scale; }
};

class Svg {
 public:
  template <typename... A>
  void add(fmt::format_string<A...> f, A&&... args) {
    text_ += fmt::format(f, std::forward<A>(args)...);
    text_ += '\n';
  }
  std::string& text() { return text_; }

 private:
  std::string text_;
};

std::string status_phrase(const RunReport& r) {
  const double t = r.sim.time();
  if (r.run.status == "running") return fmt::format("still running at the {:.0f} s limit", t);
  return fmt::format("{} after {:.1f} s", r.run.status, t);
}

void draw_floor(Svg& s, const Frame& f, const World& w) {
  const double hw = w.size.x / 2, hh = w.size.y / 2;
  s.add(R"(<rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" rx="4" fill="{}" stroke="{}"/>)", f.x(-hw),
        f.y(hh), f.len(w.size.x), f.len(w.size.y), kFloor, kGrid);
  s.add(R"(<g stroke="{}" stroke-width="0.8">)", kGrid);
  for (double gx = std::ceil(-hw / 0.5) * 0.5; gx < hw; gx += 0.5)
    s.add(R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}"/>)", f.x(gx), f.y(hh), f.x(gx), f.y(-hh));
  for (double gy = std::ceil(-hh / 0.5) * 0.5; gy < hh; gy += 0.5)
    s.add(R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}"/>)", f.x(-hw), f.y(gy), f.x(hw), f.y(gy));
  s.add("</g>");
}

void draw_line(Svg& s, const Frame& f, const Line& line) {
  if (line.points.empty()) return;
  std::string pts;
  for (const Vec2& p : line.points) pts += fmt::format("{:.1f},{:.1f} ", f.x(p.x), f.y(p.y));
  s.add(
      R"(<{} points="{}" fill="none" stroke="{}" stroke-width="{:.1f}" stroke-linejoin="round" stroke-linecap="round"/>)",
      line.closed ? "polygon" : "polyline", pts, kLineInk, f.len(line.width));
}

/// A box lower than the sonar is invisible to it: drawn paler, with a dashed edge.
bool low(const Box& b) { return b.height < model::kSonarZ; }

void draw_solids(Svg& s, const Frame& f, const World& w) {
  for (const Box& b : w.boxes)
    s.add(
        R"(<rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" rx="2" fill="{}" fill-opacity="{}" stroke="{}" stroke-width="1.5"{}/>)",
        f.x(b.center.x - b.size.x / 2), f.y(b.center.y + b.size.y / 2), f.len(b.size.x), f.len(b.size.y), kBoxFill,
        low(b) ? "0.45" : "1", kBoxEdge, low(b) ? R"( stroke-dasharray="5 3")" : "");
  for (const Wall& wl : w.walls)
    s.add(
        R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}" stroke-width="{:.1f}" stroke-linecap="square"/>)",
        f.x(wl.from.x), f.y(wl.from.y), f.x(wl.to.x), f.y(wl.to.y), kWallInk, f.len(wl.thickness));
}

void draw_destination(Svg& s, const Frame& f, Vec2 d) {
  const double x = f.x(d.x), y = f.y(d.y), r = std::max(6.0, f.len(0.10));
  s.add(
      R"(<g stroke="{}" fill="none" stroke-width="2"><circle cx="{:.1f}" cy="{:.1f}" r="{:.1f}"/>)"
      R"(<circle cx="{:.1f}" cy="{:.1f}" r="{:.1f}" stroke-dasharray="4 3"/>)"
      R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}"/><line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}"/></g>)",
      kDest, x, y, r * 0.45, x, y, r, x - r * 0.7, y, x + r * 0.7, y, x, y - r * 0.7, x, y + r * 0.7);
}

void draw_item(Svg& s, const Frame& f, Vec2 at, bool ghost) {
  const double r = std::max(5.0, f.len(0.045));
  if (ghost)
    s.add(
        R"(<circle cx="{:.1f}" cy="{:.1f}" r="{:.1f}" fill="none" stroke="{}" stroke-width="1.5" stroke-dasharray="3 2"/>)",
        f.x(at.x), f.y(at.y), r, kItem);
  else
    s.add(R"(<circle cx="{:.1f}" cy="{:.1f}" r="{:.1f}" fill="{}" stroke="#8a3f10" stroke-width="1.2"/>)", f.x(at.x),
          f.y(at.y), r, kItem);
}

void draw_items(Svg& s, const Frame& f, const RunReport& r) {
  const World& w = r.sim.world();
  for (size_t i = 0; i < w.items.size(); ++i) {
    const Item& spec = w.items[i];
    const ItemState& now = r.sim.items()[i];
    draw_destination(s, f, spec.destination);
    s.add(
        R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}" stroke-width="1" stroke-dasharray="2 4"/>)",
        f.x(spec.at.x), f.y(spec.at.y), f.x(spec.destination.x), f.y(spec.destination.y), kMuted);
    draw_item(s, f, spec.at, true);
    draw_item(s, f, now.at, false);
    s.add(R"(<text x="{:.1f}" y="{:.1f}" font-size="13" fill="{}">{}</text>)", f.x(now.at.x) + 9, f.y(now.at.y) - 9,
          kText, gfec::text::xml_escape(now.name));
  }
}

/// Which actor of a plan (or state of an fsm) drove each stretch of the path: (start time,
/// name) in time order, from the engine log. Empty for sfc runs.
std::vector<std::pair<double, std::string>> actor_spans() {
  std::vector<std::pair<double, std::string>> spans;
  for (const EngineEvent& e : engine_log()) {
    if (e.text.rfind("state ", 0) == 0) {  // an fsm's "state Z1 PickUp()"
      spans.emplace_back(e.t, e.text.substr(6));
    } else if (e.text.rfind("start ", 0) == 0) {  // a plan's "start WallFollow.followWall"
      const size_t dot = e.text.find('.');
      spans.emplace_back(e.t, e.text.substr(dot == std::string::npos ? 6 : dot + 1));
    }
  }
  return spans;
}

/// A colour per actor, in order of first appearance (no red: red marks bumps).
std::vector<std::string> actor_names() {
  std::vector<std::string> names;
  for (const auto& [t, name] : actor_spans())
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

const char* actor_colour(const std::string& name) {
  static const char* const kPalette[] = {"#1f6fd1", "#2e9e5b", "#7b4fc9", "#e8772e",
                                         "#16a3a3", "#a0522d", "#d6409f", "#6b6b6b"};
  const auto names = actor_names();
  const size_t i = std::find(names.begin(), names.end(), name) - names.begin();
  return kPalette[i % (sizeof kPalette / sizeof kPalette[0])];
}

/// The robot to scale at `p`: its outline and an arrow for its heading.
void draw_robot_at(Svg& s, const Frame& f, const Pose& p, const char* colour) {
  const double hx = std::cos(p.heading), hy = std::sin(p.heading);
  auto corner = [&](double bx, double by) {
    return fmt::format("{:.1f},{:.1f}", f.x(p.x + hx * bx - hy * by), f.y(p.y + hy * bx + hx * by));
  };
  const double l = model::kLength / 2, w = model::kWidth / 2;
  s.add(R"(<polygon points="{} {} {} {}" fill="{}" fill-opacity="0.18" stroke="{}" stroke-width="2"/>)", corner(l, w),
        corner(l, -w), corner(-l, -w), corner(-l, w), colour, colour);
  s.add(R"(<polygon points="{} {} {}" fill="{}"/>)", corner(l - 0.02, 0), corner(l - 0.14, 0.07),
        corner(l - 0.14, -0.07), colour);
}

/// The path, thinned to points at least 5 mm apart (the picture cannot show finer), one
/// polyline per stretch driven by one actor (a single one for charts), and the robot drawn to
/// scale where it ended.
void draw_path(Svg& s, const Frame& f, const RunReport& r) {
  const auto& trace = r.run.trace;
  if (trace.empty()) return;
  const auto spans = actor_spans();
  size_t span = 0;
  std::string pts, colour = spans.empty() ? kPath : actor_colour(spans.front().second);
  Vec2 last{1e9, 1e9};
  auto flush = [&] {
    if (!pts.empty())
      s.add(
          R"(<polyline points="{}" fill="none" stroke="{}" stroke-width="2.2" stroke-opacity="0.85" stroke-linejoin="round"/>)",
          pts, colour);
  };
  for (size_t i = 0; i < trace.size(); ++i) {
    const Vec2 p{trace[i].x, trace[i].y};
    if (span + 1 < spans.size() && trace[i].t >= spans[span + 1].first - 1e-9) {
      while (span + 1 < spans.size() && trace[i].t >= spans[span + 1].first - 1e-9) ++span;
      pts += fmt::format("{:.1f},{:.1f} ", f.x(p.x), f.y(p.y));  // the new stretch starts where this ends
      flush();
      pts.clear();
      colour = actor_colour(spans[span].second);
      last = {1e9, 1e9};
    }
    if (i + 1 < trace.size() && distance(p, last) < 0.005) continue;
    pts += fmt::format("{:.1f},{:.1f} ", f.x(p.x), f.y(p.y));
    last = p;
  }
  flush();
  for (const Bump& b : r.sim.bump_log()) {
    const double x = f.x(b.at.x), y = f.y(b.at.y);
    s.add(R"(<path d="M{:.1f},{:.1f} l10,10 m0,-10 l-10,10" stroke="{}" stroke-width="3" stroke-linecap="round"/>)",
          x - 5, y - 5, kBump);
  }
  const TraceRow& a = trace.front();
  s.add(R"(<circle cx="{:.1f}" cy="{:.1f}" r="6" fill="#ffffff" stroke="{}" stroke-width="3"/>)", f.x(a.x), f.y(a.y),
        kPath);

  draw_robot_at(s, f, r.sim.pose(), kPath);
}

// --- Several robots (docs/sim.md, "Several robots") ------------------------------------------

}  // namespace

// A colour per robot (no red: red marks bumps; no orange or green: items and destinations);
// the run viewer's page uses the same (reports.h).
const char* robot_colour(std::size_t i) { return gfec::viewer::robot_colour(i); }

namespace {

constexpr const char* kContact = "#b8860b";

/// Every robot's path in its own colour, its start, the robot where it ended with its number
/// and final state, its bumps; and a diamond where two robots touched.
void draw_team(Svg& s, const Frame& f, const RunReport& r) {
  for (std::size_t i = 0; i < r.run.robots.size(); ++i) {
    const RobotRun& robot = r.run.robots[i];
    if (robot.trace.empty()) continue;
    std::string pts;
    Vec2 last{1e9, 1e9};
    for (std::size_t k = 0; k < robot.trace.size(); ++k) {
      const Vec2 p{robot.trace[k].x, robot.trace[k].y};
      if (k + 1 < robot.trace.size() && distance(p, last) < 0.005) continue;
      pts += fmt::format("{:.1f},{:.1f} ", f.x(p.x), f.y(p.y));
      last = p;
    }
    s.add(
        R"(<polyline points="{}" fill="none" stroke="{}" stroke-width="2.2" stroke-opacity="0.85" stroke-linejoin="round"/>)",
        pts, robot_colour(i));
    const TraceRow& a = robot.trace.front();
    s.add(R"(<circle cx="{:.1f}" cy="{:.1f}" r="6" fill="#ffffff" stroke="{}" stroke-width="3"/>)", f.x(a.x), f.y(a.y),
          robot_colour(i));
    draw_robot_at(s, f, robot.final_pose, robot_colour(i));
    for (const Bump& b : robot.bump_log)
      s.add(R"(<path d="M{:.1f},{:.1f} l10,10 m0,-10 l-10,10" stroke="{}" stroke-width="3" stroke-linecap="round"/>)",
            f.x(b.at.x) - 5, f.y(b.at.y) - 5, kBump);
    const std::string state =
        robot.state >= 0 && robot.state < static_cast<int>(r.chart.rows.size()) ? r.chart.rows[robot.state].name : "";
    s.add(R"(<text x="{:.1f}" y="{:.1f}" font-size="13" font-weight="bold" fill="{}">{}{}</text>)",
          f.x(robot.final_pose.x) + 14, f.y(robot.final_pose.y) + 26, robot_colour(i), i,
          gfec::text::xml_escape(state.empty() ? "" : " " + state));
  }
  for (const RobotContact& c : r.sim.robot_contacts())
    s.add(R"(<path d="M{:.1f},{:.1f} l7,-7 l7,7 l-7,7 z" fill="{}" stroke="#5c4305" stroke-width="1"/>)",
          f.x(c.at.x) - 7, f.y(c.at.y), kContact);
}

void draw_scale_bar(Svg& s, const Frame& f, double x, double y) {
  s.add(
      R"(<g stroke="{}" stroke-width="2"><line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}"/>)"
      R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}"/><line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}"/></g>)",
      kText, x, y, x + f.len(1), y, x, y - 5, x, y + 5, x + f.len(1), y - 5, x + f.len(1), y + 5);
  s.add(R"(<text x="{:.1f}" y="{:.1f}" font-size="12" fill="{}" text-anchor="middle">1 m</text>)", x + f.len(0.5),
        y - 8, kText);
}

void draw_legend(Svg& s, double x, double y, double right, const RunReport& r) {
  const World& w = r.sim.world();
  struct Entry {
    std::string swatch;
    std::string label;
  };
  std::vector<Entry> entries;
  const bool team = !r.run.robots.empty();
  for (std::size_t i = 0; i < r.run.robots.size(); ++i)
    entries.push_back(
        {fmt::format(R"(<line x1="0" y1="0" x2="22" y2="0" stroke="{}" stroke-width="3"/>)", robot_colour(i)),
         fmt::format("robot {}", i)});
  if (team && !r.sim.robot_contacts().empty())
    entries.push_back({fmt::format(R"(<path d="M4,0 l7,-7 l7,7 l-7,7 z" fill="{}"/>)", kContact), "robots touched"});
  if (!team && actor_names().empty())
    entries.push_back(
        {fmt::format(R"(<line x1="0" y1="0" x2="22" y2="0" stroke="{}" stroke-width="3"/>)", kPath), "robot path"});
  for (const std::string& actor : team ? std::vector<std::string>() : actor_names())
    entries.push_back(
        {fmt::format(R"(<line x1="0" y1="0" x2="22" y2="0" stroke="{}" stroke-width="3"/>)", actor_colour(actor)),
         actor});
  entries.push_back(
      {fmt::format(R"(<circle cx="11" cy="0" r="5" fill="#fff" stroke="{}" stroke-width="3"/>)", kPath), "start"});
  entries.push_back(
      {fmt::format(
           R"(<rect x="3" y="-6" width="16" height="12" fill="{}" fill-opacity="0.18" stroke="{}" stroke-width="2"/>)",
           kPath, kPath),
       "robot at the end"});
  if (!w.line.points.empty())
    entries.push_back(
        {fmt::format(R"(<line x1="0" y1="0" x2="22" y2="0" stroke="{}" stroke-width="6"/>)", kLineInk), "line"});
  if (!w.walls.empty())
    entries.push_back(
        {fmt::format(R"(<line x1="0" y1="0" x2="22" y2="0" stroke="{}" stroke-width="6"/>)", kWallInk), "wall"});
  if (std::any_of(w.boxes.begin(), w.boxes.end(), [](const Box& b) { return !low(b); }))
    entries.push_back(
        {fmt::format(R"(<rect x="2" y="-7" width="18" height="14" fill="{}" stroke="{}"/>)", kBoxFill, kBoxEdge),
         "box"});
  if (std::any_of(w.boxes.begin(), w.boxes.end(), low))
    entries.push_back(
        {fmt::format(
             R"(<rect x="2" y="-7" width="18" height="14" fill="{}" fill-opacity="0.45" stroke="{}" stroke-dasharray="5 3"/>)",
             kBoxFill, kBoxEdge),
         "low box (under the sonar)"});
  if (!w.items.empty()) {
    entries.push_back({fmt::format(R"(<circle cx="11" cy="0" r="6" fill="{}"/>)", kItem), "item"});
    entries.push_back(
        {fmt::format(R"(<circle cx="11" cy="0" r="6" fill="none" stroke="{}" stroke-dasharray="3 2"/>)", kItem),
         "item at the start"});
    entries.push_back({fmt::format(R"(<circle cx="11" cy="0" r="7" fill="none" stroke="{}" stroke-width="2"/>)", kDest),
                       "destination"});
  }
  bool bumped = r.sim.bumps() > 0;
  for (const RobotRun& robot : r.run.robots) bumped = bumped || robot.bumps > 0;
  if (bumped)
    entries.push_back(
        {fmt::format(R"(<path d="M6,-5 l10,10 m0,-10 l-10,10" stroke="{}" stroke-width="3"/>)", kBump), "bump"});
  double cx = x;
  for (const Entry& e : entries) {
    const double w = 40 + 7.2 * e.label.size();
    if (cx > x && cx + w > right) cx = x, y += 24;  // wrap to a second row
    s.add(R"~(<g transform="translate({:.1f},{:.1f})">{}<text x="28" y="4" font-size="13" fill="{}">{}</text></g>)~",
          cx, y, e.swatch, kText, gfec::text::xml_escape(e.label));
    cx += w;
  }
}

}  // namespace

std::string svg_picture(const RunReport& r) {
  const World& w = r.sim.world();
  constexpr double kMargin = 28, kTitle = 84, kLegend = 80;
  Frame f;
  f.scale = std::min(900.0 / w.size.x, 640.0 / w.size.y);
  const std::string title = fmt::format("{} ({}) on {}{}", r.chart.name, r.chart.kind, w.name,
                                        r.run.robots.empty() ? "" : fmt::format(", {} robots", r.run.robots.size()));
  const std::string heading = fmt::format("{} — {}", title, status_phrase(r));
  // Wide enough for the floor and for the heading (bold 20 px: ~11.5 px a character).
  const double width = std::max({f.len(w.size.x) + 2 * kMargin, 760.0, 2 * kMargin + 11.5 * heading.size()});
  const double height = kTitle + f.len(w.size.y) + kLegend + kMargin;
  f.ox = width / 2;
  f.oy = kTitle + f.len(w.size.y) / 2;

  Svg s;
  s.add(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="{:.0f}" height="{:.0f}" viewBox="0 0 {:.0f} {:.0f}" font-family="DejaVu Sans, Helvetica, Arial, sans-serif">)",
      width, height, width, height);
  s.add("<title>{}</title>", gfec::text::xml_escape(title));
  s.add(R"(<rect width="100%" height="100%" fill="{}"/>)", kPage);
  s.add(R"(<text x="{:.0f}" y="28" font-size="20" font-weight="bold" fill="{}">{}</text>)", kMargin, kText,
        gfec::text::xml_escape(heading));
  std::string facts =
      fmt::format("{:.2f} m driven · {} bump{}", r.sim.odometer(), r.sim.bumps(), r.sim.bumps() == 1 ? "" : "s");
  if (!r.run.robots.empty()) {
    int bumps = 0;
    for (const RobotRun& robot : r.run.robots) bumps += robot.bumps;
    const std::size_t touches = r.sim.robot_contacts().size();
    facts = fmt::format("{} robots · {} bump{} · {} robot contact{}", r.run.robots.size(), bumps, bumps == 1 ? "" : "s",
                        touches, touches == 1 ? "" : "s");
    if (r.run.team_machine)
      facts += r.run.exchange.enabled
                   ? fmt::format(" · exchange: {} tick{} late, {:g}% lost", r.run.exchange.delay_ticks,
                                 r.run.exchange.delay_ticks == 1 ? "" : "s", r.run.exchange.loss * 100)
                   : std::string(" · no exchange");
  }
  for (const ItemState& it : r.sim.items())
    facts += fmt::format(" · {} {:.2f} m from its destination{}", it.name, distance(it.at, it.destination),
                         it.held ? " (held)" : "");
  facts += fmt::format(" · world {:.1f} × {:.1f} m", w.size.x, w.size.y);
  s.add(R"(<text x="{:.0f}" y="50" font-size="13" fill="{}">{}</text>)", kMargin, kMuted,
        gfec::text::xml_escape(facts));

  draw_floor(s, f, w);
  draw_line(s, f, w.line);
  draw_solids(s, f, w);
  draw_items(s, f, r);
  if (r.run.robots.empty()) draw_path(s, f, r);
  else draw_team(s, f, r);
  const double legend_y = kTitle + f.len(w.size.y) + 30;
  draw_legend(s, kMargin, legend_y, width - kMargin, r);
  draw_scale_bar(s, f, f.x(w.size.x / 2) - f.len(1), kTitle - 12);  // its own row, over the floor's right edge
  s.add("</svg>");
  return s.text();
}

}  // namespace carbot::driver
