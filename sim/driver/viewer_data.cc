// The run viewer's recording of a carbot-sim run (docs/viewer.md): the world, the path, the
// chart's picture, activation and calls per tick (as change lists) and the events, as JSON.
#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/carbot_model.h"
#include "core/geometry.h"
#include "driver/engine_log.h"
#include "driver/reports.h"
#include "recording.h"
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

/// The builder of a recording of one robot or of several: the chart, its picture, the world
/// and the robots' size. The frames come with the ticks added.
gfec::viewer::RecordingBuilder builder(const RunReport& r, const std::string& chart_svg, const std::string& svg_note) {
  gfec::viewer::RecordingBuilder rec("carbot-sim", r.chart.name, r.chart.kind, r.chart_file,
                                     r.sim.config().control_period);
  rec.set_picture(chart_svg, svg_note);
  rec.set("world", world_json(r.sim.world()));
  rec.set("robot", {{"length", model::kLength}, {"width", model::kWidth}, {"gripper", model::kGripX}});
  return rec;
}

/// A run with several robots (docs/viewer.md, "Several robots"): the chart's rows once per robot
/// (`robot 1/Grab`, grouped under `robot 1`), each robot's path, calls and status; the items
/// with the robot holding them; the robots' contacts as events.
json team_viewer_data(const RunReport& r, const std::string& chart_svg, const std::string& svg_note) {
  const Simulation& sim = r.sim;
  const Recording& rec = r.run.recording;
  const std::vector<RobotRun>& robots = r.run.robots;
  const double period = sim.config().control_period;
  const long frames = static_cast<long>(robots.front().trace.size());
  auto frame_of = [&](double t) { return std::clamp(std::lround(t / period), 0L, std::max(0L, frames - 1)); };
  auto robot_name = [](std::size_t i) { return fmt::format("robot {}", i); };
  gfec::viewer::RecordingBuilder out = builder(r, chart_svg, svg_note);

  // The chart's own rows (a team machine is never a sub-chart; its own sub-charts' rows are
  // left out), once per robot: robot i's row j is i * own + j.
  std::vector<const ChartInfo::Row*> own;
  for (const ChartInfo::Row& row : r.chart.rows)
    if (row.group.empty()) own.push_back(&row);
  const std::size_t per = own.size();
  json bumps = json::array();
  for (std::size_t i = 0; i < robots.size(); ++i) {
    const RobotRun& robot = robots[i];
    for (const ChartInfo::Row* row : own)
      out.add_row({robot_name(i) + "/" + row->name, row->node, row->terminal, robot_name(i), static_cast<int>(i)});
    const std::size_t id = out.add_robot(robot_name(i), robot_colour(i), i * per, per);
    out.set_robot(id, "pose", pose_json(robot.trace));
    for (long k = 0; k < frames; ++k)
      out.record_calls(id, k, k < static_cast<long>(robot.calls.size()) ? robot.calls[k] : std::vector<std::string>());
    for (const Bump& b : robot.bump_log) {
      out.add_event(frame_of(b.t), "bump", fmt::format("{}: bump at ({:.2f}, {:.2f})", robot_name(i), b.at.x, b.at.y));
      bumps.push_back({frame_of(b.t), r4(b.at.x), r4(b.at.y), i});
    }
    for (const EngineEvent& e : robot.state_log)
      out.add_event(frame_of(e.t), "state", fmt::format("{}: {}", robot_name(i), e.text));
    out.record_status(id, 0, "running");
    if (robot.status != "running") {
      const long end = robot.ended >= 0 ? robot.ended : frames - 1;
      out.record_status(id, end, robot.status);
      out.add_event(end, "status", fmt::format("{}: {}", robot_name(i), robot.status));
    }
  }

  for (long k = 0; k < frames; ++k) {
    std::vector<std::size_t> on;
    for (std::size_t i = 0; i < robots.size(); ++i)
      if (k < static_cast<long>(robots[i].active.size()))
        for (int a : robots[i].active[k])
          if (a >= 0 && static_cast<std::size_t>(a) < per) on.push_back(i * per + static_cast<std::size_t>(a));
    out.add_tick(on);
  }

  json contacts = json::array();
  for (const RobotContact& c : sim.robot_contacts()) {
    out.add_event(frame_of(c.t), "contact",
                  fmt::format("robots {} and {} touch at ({:.2f}, {:.2f})", c.a, c.b, c.at.x, c.at.y));
    contacts.push_back({frame_of(c.t), c.a, c.b, r4(c.at.x), r4(c.at.y)});
  }
  for (const SimNote& n : sim.notes()) out.add_event(frame_of(n.t), "note", n.text);
  json items = json::array();
  const std::vector<ItemState>& first = rec.items.empty() ? sim.items() : rec.items.front();
  for (std::size_t i = 0; i < first.size(); ++i) {
    gfec::viewer::ChangeList track;
    int held_by = -1;
    for (long k = 0; k < static_cast<long>(rec.items.size()); ++k) {
      const ItemState& it = rec.items[k][i];
      const int holder = it.held && k < static_cast<long>(rec.holders.size()) ? rec.holders[k][i] : -1;
      if (holder != held_by)
        out.add_event(k, "item",
                      holder >= 0 ? fmt::format("{} picked up by robot {}", it.name, holder)
                                  : fmt::format("{} released by robot {}", it.name, held_by));
      held_by = holder;
      // While held the item is drawn at its robot's gripper, from that robot's pose.
      track.record(k, holder >= 0 ? json::array({1, holder}) : json::array({0, r4(it.at.x), r4(it.at.y)}));
    }
    items.push_back(item_json(first[i], track));
  }
  out.record_status(0, "running");
  if (r.run.status != "running") {
    long end = 0;
    for (const RobotRun& robot : robots) end = std::max(end, robot.ended >= 0 ? robot.ended : frames - 1);
    out.record_status(end, r.run.status);
    out.add_event(end, "status", "the team: " + r.run.status);
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
  out.set_title(fmt::format("{} ({}) on {}, {} robots: {} at {:.2f} s", r.chart.name, r.chart.kind, sim.world().name,
                            robots.size(), r.run.status, sim.time()),
                fmt::format("carbot-sim {} --world {} \u00b7 {} ticks of {:g} ms \u00b7 {} bump{} \u00b7 {} robot "
                            "contact{}{}",
                            r.chart_file, sim.world().path, frames, period * 1000, bump_count,
                            bump_count == 1 ? "" : "s", touches, touches == 1 ? "" : "s", exchange));
  out.set("calls_note", "");
  out.set("pose", nullptr);
  out.set("items", items);
  out.set("bumps", bumps);
  out.set("contacts", contacts);
  return out.data();
}

}  // namespace

json viewer_data(const RunReport& r, const std::string& chart_svg, const std::string& svg_note) {
  if (!r.run.robots.empty()) return team_viewer_data(r, chart_svg, svg_note);
  const Simulation& sim = r.sim;
  const Recording& rec = r.run.recording;
  const double period = sim.config().control_period;
  const long frames = static_cast<long>(r.run.trace.size());
  auto frame_of = [&](double t) { return std::clamp(std::lround(t / period), 0L, std::max(0L, frames - 1)); };
  gfec::viewer::RecordingBuilder out = builder(r, chart_svg, svg_note);

  // The chart's rows, then its sub-chart instances' when the engine told their activation; for
  // a plan, its actors, then the sub-plans' actors grouped by the actor that ran them (in the
  // order they first ran; `remap` takes their recorded numbers to their rows).
  const bool nested = !r.chart.instances.empty();
  std::size_t rows = 0;
  for (const ChartInfo::Row& row : r.chart.rows) {
    if (!nested && !row.group.empty()) continue;
    out.add_row({row.name, row.node, row.terminal, row.group});
    ++rows;
  }
  if (nested)
    for (const ChartInfo::Instance& in : r.chart.instances) out.add_instance({in.path, in.chart, in.first, in.count});
  std::map<int, int> remap;
  std::vector<std::string> groups;
  for (const ChartInfo::Row& row : rec.sub_rows)
    if (std::find(groups.begin(), groups.end(), row.group) == groups.end()) groups.push_back(row.group);
  for (const std::string& g : groups) {
    const std::size_t first = rows;
    for (std::size_t i = 0; i < rec.sub_rows.size(); ++i) {
      if (rec.sub_rows[i].group != g) continue;
      remap[static_cast<int>(r.chart.rows.size() + i)] = static_cast<int>(rows);
      out.add_row({rec.sub_rows[i].name, "", false, g});
      ++rows;
    }
    std::string plan;
    for (std::size_t i = 0; i < rec.sub_rows.size() && plan.empty(); ++i)
      if (rec.sub_rows[i].group == g && i < rec.sub_plans.size()) plan = rec.sub_plans[i];
    out.add_instance({g, plan, first, rows - first});
  }

  for (long k = 0; k < frames; ++k) {
    std::vector<std::size_t> on;
    if (k < static_cast<long>(rec.active.size()))
      for (int row : rec.active[k]) on.push_back(static_cast<std::size_t>(row));
    if (k < static_cast<long>(rec.instances_active.size()))
      for (int row : rec.instances_active[k])
        if (nested || remap.count(row)) on.push_back(static_cast<std::size_t>(remap.count(row) ? remap.at(row) : row));
    out.add_tick(on);
    out.record_calls(k, k < static_cast<long>(rec.calls.size()) ? rec.calls[k] : std::vector<std::string>());
  }

  json bumps = json::array();
  for (const Bump& b : sim.bump_log()) {
    out.add_event(frame_of(b.t), "bump", fmt::format("bump at ({:.2f}, {:.2f})", b.at.x, b.at.y));
    bumps.push_back({frame_of(b.t), r4(b.at.x), r4(b.at.y)});
  }
  for (const SimNote& n : sim.notes()) out.add_event(frame_of(n.t), "note", n.text);
  for (std::size_t i = 0; i < engine_log().size() && i < rec.log_frames.size(); ++i) {
    const std::string& text = engine_log()[i].text;
    const std::string kind = text.rfind("state ", 0) == 0                         ? "state"
                             : text.rfind("start ", 0) == 0                       ? "actor"
                             : text.find(" interrupted by ") != std::string::npos ? "supervisor"
                                                                                  : "note";
    out.add_event(rec.log_frames[i], kind, text);
  }
  json items = json::array();
  const std::vector<ItemState>& first = rec.items.empty() ? sim.items() : rec.items.front();
  for (std::size_t i = 0; i < first.size(); ++i) {
    gfec::viewer::ChangeList track;
    bool held = false;
    for (long k = 0; k < static_cast<long>(rec.items.size()); ++k) {
      const ItemState& it = rec.items[k][i];
      if (it.held != held) out.add_event(k, "item", fmt::format("{} {}", it.name, it.held ? "picked up" : "released"));
      held = it.held;
      // While held the item is drawn at the gripper, from the pose: no entry per tick.
      track.record(k, it.held ? json::array({1}) : json::array({0, r4(it.at.x), r4(it.at.y)}));
    }
    items.push_back(item_json(first[i], track));
  }
  out.record_status(0, "running");
  if (r.run.status != "running") {
    out.record_status(frames - 1, r.run.status);
    out.add_event(frames - 1, "status", r.run.status);
  }
  for (const Recording::Fired& f : rec.fired) out.add_fired(f.frame, f.node, f.text);

  out.set_title(
      fmt::format("{} ({}) on {}: {} at {:.2f} s", r.chart.name, r.chart.kind, sim.world().name, r.run.status,
                  sim.time()),
      fmt::format("carbot-sim {} --world {} \u00b7 {} ticks of {:g} ms \u00b7 {:.2f} m driven \u00b7 {} bump{}",
                  r.chart_file, sim.world().path, frames, period * 1000, sim.odometer(), sim.bumps(),
                  sim.bumps() == 1 ? "" : "s"));
  out.set("calls_note", r.chart.kind == "plan" ? "A plan's actors and supervisors are C++ classes of the toolbox: "
                                                 "their calls are not recorded; the events list their starts and "
                                                 "interruptions."
                                               : "");
  out.set("pose", pose_json(r.run.trace));
  out.set("items", items);
  out.set("bumps", bumps);
  return out.data();
}

}  // namespace carbot::driver
