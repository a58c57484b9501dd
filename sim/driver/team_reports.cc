// The trace and the result of a run with several robots (docs/sim.md, "Several robots"): the
// single-robot formats with every robot in them.
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/geometry.h"
#include "driver/reports.h"

namespace carbot::driver {
namespace {

double r4(double v) { return std::round(v * 1e4) / 1e4; }

nlohmann::json point(Vec2 p) { return nlohmann::json::array({r4(p.x), r4(p.y)}); }

std::string row_name(const ChartInfo& chart, int a) {
  return a >= 0 && a < static_cast<int>(chart.rows.size()) ? chart.rows[static_cast<std::size_t>(a)].name
                                                           : std::to_string(a);
}

}  // namespace

// `t,robot,x,y,heading,active`: per tick one row per robot, in robot order.
std::string team_trace_csv(const RunReport& r) {
  std::string out = "t,robot,x,y,heading,active\n";
  const std::vector<RobotRun>& robots = r.run.robots;
  const std::size_t rows = robots.front().trace.size();
  out.reserve(out.size() + rows * robots.size() * 50);
  for (std::size_t k = 0; k < rows; ++k)
    for (std::size_t i = 0; i < robots.size(); ++i) {
      const RobotRun& robot = robots[i];
      if (k >= robot.trace.size()) continue;
      const TraceRow& row = robot.trace[k];
      out += fmt::format("{:.3f},{},{:.4f},{:.4f},{:.2f},", row.t, i, row.x, row.y, row.heading_deg);
      if (k < robot.active.size())
        for (std::size_t j = 0; j < robot.active[k].size(); ++j) {
          out += j ? " " : "";
          out += row_name(r.chart, robot.active[k][j]);
        }
      out += '\n';
    }
  return out;
}

std::string team_result_json(const RunReport& r) {
  using nlohmann::json;
  const Simulation& sim = r.sim;
  json items = json::array();
  for (std::size_t i = 0; i < sim.items().size(); ++i) {
    const ItemState& it = sim.items()[i];
    const int holder = sim.holder(static_cast<int>(i));
    items.push_back({{"name", it.name},
                     {"at", point(it.at)},
                     {"destination", point(it.destination)},
                     {"held", it.held},
                     {"held_by", holder >= 0 ? json(holder) : json(nullptr)},
                     {"distance_to_destination_m", r4(distance(it.at, it.destination))}});
  }
  json robots = json::array();
  int bumps = 0;
  for (std::size_t i = 0; i < r.run.robots.size(); ++i) {
    const RobotRun& robot = r.run.robots[i];
    bumps += robot.bumps;
    json bump_log = json::array();
    for (const Bump& b : robot.bump_log) bump_log.push_back({{"t", r4(b.t)}, {"at", point(b.at)}});
    json state_log = json::array();
    for (const EngineEvent& e : robot.state_log) state_log.push_back({{"t", r4(e.t)}, {"event", e.text}});
    const Pose& p = robot.final_pose;
    json entry = {
        {"robot", i},
        {"status", robot.status},
        {"state", robot.state >= 0 ? json(row_name(r.chart, robot.state)) : json(nullptr)},
        {"holding", robot.held >= 0 ? json(sim.items()[static_cast<std::size_t>(robot.held)].name) : json(nullptr)},
        {"bumps", robot.bumps},
        {"bump_log", bump_log},
        {"distance_m", r4(robot.distance_m)},
        {"final_pose", {{"x", r4(p.x)}, {"y", r4(p.y)}, {"heading_deg", r4(deg(p.heading))}}},
        {"left_floor", robot.left_floor},
        {"lights", robot.lights},
        {"beeps", robot.beeps},
    };
    if (r.chart.kind == "fsm") entry["state_log"] = state_log;
    robots.push_back(entry);
  }
  json contacts = json::array();
  for (const RobotContact& c : sim.robot_contacts())
    contacts.push_back({{"t", r4(c.t)}, {"robots", {c.a, c.b}}, {"at", point(c.at)}});
  json notes = json::array();
  for (const SimNote& n : sim.notes()) notes.push_back({{"t", r4(n.t)}, {"text", n.text}});
  const Exchange& x = r.run.exchange;
  json doc = {
      {"chart", {{"file", r.chart_file}, {"name", r.chart.name}, {"kind", r.chart.kind}}},
      {"world", {{"file", sim.world().path}, {"name", sim.world().name}}},
      {"sim_time_s", r4(sim.time())},
      {"status", r.run.status},
      {"robot_count", r.run.robots.size()},
      {"robots", robots},
      {"bumps", bumps},
      {"robot_contacts", sim.robot_contacts().size()},
      {"robot_contact_log", contacts},
      {"escape_presses", sim.escape_presses()},
      {"items", items},
      {"notes", notes},
      {"physics_step_s", sim.config().physics_step},
      {"control_period_s", sim.config().control_period},
  };
  if (r.run.team_machine)
    doc["exchange"] = {{"team", r.chart.team},  {"enabled", x.enabled}, {"delay_ticks", x.delay_ticks},
                       {"loss", x.loss},        {"seed", x.seed},       {"reports_sent", x.sent},
                       {"reports_lost", x.lost}};
  return doc.dump(2) + "\n";
}

}  // namespace carbot::driver
