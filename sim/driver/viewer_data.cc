// The run viewer's recording of a carbot-sim run (docs/viewer.md): the world, the path, the
// chart's picture, activation and calls per tick (as change lists) and the events, as JSON.
#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/carbot_model.h"
#include "core/geometry.h"
#include "driver/engine_log.h"
#include "driver/reports.h"
#include "viewer_page.h"

namespace carbot::driver {
namespace {

using nlohmann::json;

double r4(double v) { return std::round(v * 1e4) / 1e4; }
json point(Vec2 p) { return json::array({r4(p.x), r4(p.y)}); }

/// The world with every default filled in, in the world file's shape.
json world_json(const World& w) {
  json line = nullptr;
  if (!w.line.points.empty()) {
    json pts = json::array();
    for (const Vec2& p : w.line.points) pts.push_back(point(p));
    line = {{"width", w.line.width}, {"closed", w.line.closed}, {"points", pts}};
  }
  json walls = json::array(), boxes = json::array();
  for (const Wall& wl : w.walls)
    walls.push_back(
        {{"from", point(wl.from)}, {"to", point(wl.to)}, {"thickness", wl.thickness}, {"height", wl.height}});
  for (const Box& b : w.boxes)
    boxes.push_back({{"center", point(b.center)}, {"size", point(b.size)}, {"height", b.height}});
  return {{"name", w.name}, {"file", w.path}, {"size", point(w.size)},
          {"line", line},   {"walls", walls}, {"boxes", boxes}};
}

/// An item of the world: where it starts, where it goes, and its track through the run.
json item_json(const ItemState& item, const gfec::viewer::ChangeList& track) {
  return {
      {"name", item.name}, {"at", point(item.at)}, {"destination", point(item.destination)}, {"track", track.json()}};
}

/// The path as delta-coded integers (mm and 0.01 degree): a 120 s run at 10 ms is 12,001 poses.
json pose_json(const std::vector<TraceRow>& trace) {
  json xs = json::array(), ys = json::array(), hs = json::array();
  long px = 0, py = 0, ph = 0;
  for (const TraceRow& t : trace) {
    const long x = std::lround(t.x * 1000), y = std::lround(t.y * 1000), h = std::lround(t.heading_deg * 100);
    xs.push_back(x - px);
    ys.push_back(y - py);
    hs.push_back(h - ph);
    px = x, py = y, ph = h;
  }
  return {{"scale", 1000}, {"heading_scale", 100}, {"x", xs}, {"y", ys}, {"h", hs}};
}

/// A run with several robots (docs/viewer.md, "Several robots"): the chart's rows once per robot
/// (`robot 1/Grab`, grouped under `robot 1`), each robot's path, calls and status; the items
/// with the robot holding them; the robots' contacts as events.
/// The events list: [frame, kind, text], in frame order (events of one frame as they came).
using Events = std::vector<std::tuple<long, std::string, std::string>>;
json events_json(Events& events) {
  std::stable_sort(events.begin(), events.end(),
                   [](const auto& a, const auto& b) { return std::get<0>(a) < std::get<0>(b); });
  json list = json::array();
  for (const auto& [k, kind, text] : events) list.push_back({k, kind, text});
  return list;
}

/// What a recording of one robot and one of several hold alike: the format, the chart and its
/// picture, the frames, the world and the robots' size.
json common_json(const RunReport& r, long frames, const std::string& chart_svg, const std::string& svg_note) {
  return {
      {"format", 1},
      {"tool", "carbot-sim"},
      {"chart", {{"name", r.chart.name}, {"kind", r.chart.kind}, {"file", r.chart_file}}},
      {"period", r.sim.config().control_period},
      {"frames", frames},
      {"svg", chart_svg},
      {"svg_note", svg_note},
      {"world", world_json(r.sim.world())},
      {"robot", {{"length", model::kLength}, {"width", model::kWidth}, {"gripper", model::kGripX}}},
  };
}

json team_viewer_data(const RunReport& r, const std::string& chart_svg, const std::string& svg_note) {
  const Simulation& sim = r.sim;
  const Recording& rec = r.run.recording;
  const std::vector<RobotRun>& robots = r.run.robots;
  const double period = sim.config().control_period;
  const long frames = static_cast<long>(robots.front().trace.size());
  auto frame_of = [&](double t) { return std::clamp(std::lround(t / period), 0L, std::max(0L, frames - 1)); };
  auto robot_name = [](std::size_t i) { return fmt::format("robot {}", i); };

  // The chart's own rows (a team machine is never a sub-chart; its own sub-charts' rows are
  // left out), once per robot: robot i's row j is i * own + j.
  std::vector<const ChartInfo::Row*> own;
  for (const ChartInfo::Row& row : r.chart.rows)
    if (row.group.empty()) own.push_back(&row);
  const std::size_t per = own.size();
  json rows = json::array(), robot_list = json::array();
  Events events;
  json bumps = json::array();
  for (std::size_t i = 0; i < robots.size(); ++i) {
    const RobotRun& robot = robots[i];
    for (const ChartInfo::Row* row : own)
      rows.push_back({{"name", robot_name(i) + "/" + row->name},
                      {"node", row->node},
                      {"terminal", row->terminal},
                      {"group", robot_name(i)},
                      {"robot", i}});
    gfec::viewer::CallRecorder calls;
    for (long k = 0; k < frames; ++k)
      calls.record(k, k < static_cast<long>(robot.calls.size()) ? robot.calls[k] : std::vector<std::string>());
    for (const Bump& b : robot.bump_log) {
      events.emplace_back(frame_of(b.t), "bump",
                          fmt::format("{}: bump at ({:.2f}, {:.2f})", robot_name(i), b.at.x, b.at.y));
      bumps.push_back({frame_of(b.t), r4(b.at.x), r4(b.at.y), i});
    }
    for (const EngineEvent& e : robot.state_log)
      events.emplace_back(frame_of(e.t), "state", fmt::format("{}: {}", robot_name(i), e.text));
    json status = json::array({json::array({0, "running"})});
    if (robot.status != "running") {
      const long end = robot.ended >= 0 ? robot.ended : frames - 1;
      status.push_back({end, robot.status});
      events.emplace_back(end, "status", fmt::format("{}: {}", robot_name(i), robot.status));
    }
    robot_list.push_back({{"name", robot_name(i)},
                          {"colour", robot_colour(i)},
                          {"first", i * per},
                          {"count", per},
                          {"pose", pose_json(robot.trace)},
                          {"calls", calls.json()},
                          {"status", status}});
  }

  gfec::viewer::ChangeList active;
  for (long k = 0; k < frames; ++k) {
    json on = json::array();
    for (std::size_t i = 0; i < robots.size(); ++i)
      if (k < static_cast<long>(robots[i].active.size()))
        for (int a : robots[i].active[k])
          if (a >= 0 && static_cast<std::size_t>(a) < per) on.push_back(i * per + static_cast<std::size_t>(a));
    active.record(k, on);
  }

  json contacts = json::array();
  for (const RobotContact& c : sim.robot_contacts()) {
    events.emplace_back(frame_of(c.t), "contact",
                        fmt::format("robots {} and {} touch at ({:.2f}, {:.2f})", c.a, c.b, c.at.x, c.at.y));
    contacts.push_back({frame_of(c.t), c.a, c.b, r4(c.at.x), r4(c.at.y)});
  }
  for (const SimNote& n : sim.notes()) events.emplace_back(frame_of(n.t), "note", n.text);
  json items = json::array();
  const std::vector<ItemState>& first = rec.items.empty() ? sim.items() : rec.items.front();
  for (std::size_t i = 0; i < first.size(); ++i) {
    gfec::viewer::ChangeList track;
    int held_by = -1;
    for (long k = 0; k < static_cast<long>(rec.items.size()); ++k) {
      const ItemState& it = rec.items[k][i];
      const int holder = it.held && k < static_cast<long>(rec.holders.size()) ? rec.holders[k][i] : -1;
      if (holder != held_by)
        events.emplace_back(k, "item",
                            holder >= 0 ? fmt::format("{} picked up by robot {}", it.name, holder)
                                        : fmt::format("{} released by robot {}", it.name, held_by));
      held_by = holder;
      // While held the item is drawn at its robot's gripper, from that robot's pose.
      track.record(k, holder >= 0 ? json::array({1, holder}) : json::array({0, r4(it.at.x), r4(it.at.y)}));
    }
    items.push_back(item_json(first[i], track));
  }
  json status = json::array({json::array({0, "running"})});
  if (r.run.status != "running") {
    long end = 0;
    for (const RobotRun& robot : robots) end = std::max(end, robot.ended >= 0 ? robot.ended : frames - 1);
    status.push_back({end, r.run.status});
    events.emplace_back(end, "status", "the team: " + r.run.status);
  }

  int bump_count = 0;
  for (const RobotRun& robot : robots) bump_count += robot.bumps;
  const std::size_t touches = sim.robot_contacts().size();
  std::string exchange;
  if (r.run.team_machine) {
    const Exchange& x = r.run.exchange;
    exchange = !x.enabled ? " \u00b7 no exchange"
               : x.delay_ticks > 0 || x.loss > 0
                   ? fmt::format(" \u00b7 exchange {} ticks late, {:g} lost", x.delay_ticks, x.loss)
                   : " \u00b7 reference exchange";
  }
  json doc = common_json(r, frames, chart_svg, svg_note);
  doc.update({
      {"title", fmt::format("{} ({}) on {}, {} robots: {} at {:.2f} s", r.chart.name, r.chart.kind, sim.world().name,
                            robots.size(), r.run.status, sim.time())},
      {"subtitle", fmt::format("carbot-sim {} --world {} \u00b7 {} ticks of {:g} ms \u00b7 {} bump{} \u00b7 {} robot "
                               "contact{}{}",
                               r.chart_file, sim.world().path, frames, period * 1000, bump_count,
                               bump_count == 1 ? "" : "s", touches, touches == 1 ? "" : "s", exchange)},
      {"rows", rows},
      {"instances", json::array()},
      {"robots", robot_list},
      {"active", active.json()},
      {"calls", nullptr},
      {"calls_note", ""},
      {"events", events_json(events)},
      {"fired", json::array()},
      {"status", status},
      {"pose", nullptr},
      {"items", items},
      {"bumps", bumps},
      {"contacts", contacts},
  });
  return doc;
}

}  // namespace

json viewer_data(const RunReport& r, const std::string& chart_svg, const std::string& svg_note) {
  if (!r.run.robots.empty()) return team_viewer_data(r, chart_svg, svg_note);
  const Simulation& sim = r.sim;
  const Recording& rec = r.run.recording;
  const double period = sim.config().control_period;
  const long frames = static_cast<long>(r.run.trace.size());
  auto frame_of = [&](double t) { return std::clamp(std::lround(t / period), 0L, std::max(0L, frames - 1)); };

  // The chart's rows, then its sub-chart instances' when the engine told their activation; for
  // a plan, its actors, then the sub-plans' actors grouped by the actor that ran them (in the
  // order they first ran; `remap` takes their recorded numbers to their rows).
  const bool nested = !r.chart.instances.empty();
  json rows = json::array(), instances = json::array();
  for (const ChartInfo::Row& row : r.chart.rows) {
    if (!nested && !row.group.empty()) continue;
    json j = {{"name", row.name}, {"node", row.node}, {"terminal", row.terminal}};
    if (!row.group.empty()) j["group"] = row.group;
    rows.push_back(j);
  }
  if (nested)
    for (const ChartInfo::Instance& in : r.chart.instances)
      instances.push_back({{"path", in.path}, {"chart", in.chart}, {"first", in.first}, {"count", in.count}});
  std::map<int, int> remap;
  std::vector<std::string> groups;
  for (const ChartInfo::Row& row : rec.sub_rows)
    if (std::find(groups.begin(), groups.end(), row.group) == groups.end()) groups.push_back(row.group);
  for (const std::string& g : groups) {
    const std::size_t first = rows.size();
    for (std::size_t i = 0; i < rec.sub_rows.size(); ++i) {
      if (rec.sub_rows[i].group != g) continue;
      remap[static_cast<int>(r.chart.rows.size() + i)] = static_cast<int>(rows.size());
      rows.push_back({{"name", rec.sub_rows[i].name}, {"node", ""}, {"terminal", false}, {"group", g}});
    }
    std::string plan;
    for (std::size_t i = 0; i < rec.sub_rows.size() && plan.empty(); ++i)
      if (rec.sub_rows[i].group == g && i < rec.sub_plans.size()) plan = rec.sub_plans[i];
    instances.push_back({{"path", g}, {"chart", plan}, {"first", first}, {"count", rows.size() - first}});
  }

  gfec::viewer::ChangeList active;
  gfec::viewer::CallRecorder calls;
  for (long k = 0; k < frames; ++k) {
    json on = k < static_cast<long>(rec.active.size()) ? json(rec.active[k]) : json::array();
    if (k < static_cast<long>(rec.instances_active.size()))
      for (int row : rec.instances_active[k])
        if (nested || remap.count(row)) on.push_back(remap.count(row) ? remap.at(row) : row);
    active.record(k, on);
    calls.record(k, k < static_cast<long>(rec.calls.size()) ? rec.calls[k] : std::vector<std::string>());
  }

  // Events: [frame, kind, text], in frame order.
  Events events;
  json bumps = json::array();
  for (const Bump& b : sim.bump_log()) {
    events.emplace_back(frame_of(b.t), "bump", fmt::format("bump at ({:.2f}, {:.2f})", b.at.x, b.at.y));
    bumps.push_back({frame_of(b.t), r4(b.at.x), r4(b.at.y)});
  }
  for (const SimNote& n : sim.notes()) events.emplace_back(frame_of(n.t), "note", n.text);
  for (std::size_t i = 0; i < engine_log().size() && i < rec.log_frames.size(); ++i) {
    const std::string& text = engine_log()[i].text;
    const std::string kind = text.rfind("state ", 0) == 0                         ? "state"
                             : text.rfind("start ", 0) == 0                       ? "actor"
                             : text.find(" interrupted by ") != std::string::npos ? "supervisor"
                                                                                  : "note";
    events.emplace_back(rec.log_frames[i], kind, text);
  }
  json items = json::array();
  const std::vector<ItemState>& first = rec.items.empty() ? sim.items() : rec.items.front();
  for (std::size_t i = 0; i < first.size(); ++i) {
    gfec::viewer::ChangeList track;
    bool held = false;
    for (long k = 0; k < static_cast<long>(rec.items.size()); ++k) {
      const ItemState& it = rec.items[k][i];
      if (it.held != held)
        events.emplace_back(k, "item", fmt::format("{} {}", it.name, it.held ? "picked up" : "released"));
      held = it.held;
      // While held the item is drawn at the gripper, from the pose: no entry per tick.
      track.record(k, it.held ? json::array({1}) : json::array({0, r4(it.at.x), r4(it.at.y)}));
    }
    items.push_back(item_json(first[i], track));
  }
  json status = json::array({json::array({0, "running"})});
  if (r.run.status != "running") {
    status.push_back({frames - 1, r.run.status});
    events.emplace_back(frames - 1, "status", r.run.status);
  }
  json fired = json::array();
  for (const Recording::Fired& f : rec.fired) fired.push_back({f.frame, f.node, f.text});

  json doc = common_json(r, frames, chart_svg, svg_note);
  doc.update({
      {"title", fmt::format("{} ({}) on {}: {} at {:.2f} s", r.chart.name, r.chart.kind, sim.world().name, r.run.status,
                            sim.time())},
      {"subtitle",
       fmt::format("carbot-sim {} --world {} \u00b7 {} ticks of {:g} ms \u00b7 {:.2f} m driven \u00b7 {} bump{}",
                   r.chart_file, sim.world().path, frames, period * 1000, sim.odometer(), sim.bumps(),
                   sim.bumps() == 1 ? "" : "s")},
      {"rows", rows},
      {"instances", instances},
      {"active", active.json()},
      {"calls", calls.json()},
      {"calls_note", r.chart.kind == "plan" ? "A plan's actors and supervisors are C++ classes of the toolbox: their "
                                              "calls are not recorded; the events list their starts and interruptions."
                                            : ""},
      {"events", events_json(events)},
      {"fired", fired},
      {"status", status},
      {"pose", pose_json(r.run.trace)},
      {"items", items},
      {"bumps", bumps},
  });
  return doc;
}

}  // namespace carbot::driver
