#include <cmath>

#include <nlohmann/json.hpp>

#include "core/geometry.h"
#include "driver/engine_log.h"
#include "driver/reports.h"

namespace carbot::driver {
namespace {

/// Rounded so the file reads well (0.1 mm, 0.001 s); the trace has the same precision.
double r4(double v) { return std::round(v * 1e4) / 1e4; }

nlohmann::json point(Vec2 p) { return nlohmann::json::array({r4(p.x), r4(p.y)}); }

}  // namespace

std::string result_json(const RunReport& r) {
  if (!r.run.robots.empty()) return team_result_json(r);
  using nlohmann::json;
  const Simulation& sim = r.sim;
  const Pose p = sim.pose();
  json items = json::array();
  for (const ItemState& it : sim.items()) {
    items.push_back({{"name", it.name},
                     {"at", point(it.at)},
                     {"destination", point(it.destination)},
                     {"held", it.held},
                     {"distance_to_destination_m", r4(distance(it.at, it.destination))}});
  }
  json bumps = json::array();
  for (const Bump& b : sim.bump_log()) bumps.push_back({{"t", r4(b.t)}, {"at", point(b.at)}});
  json plan = json::array();
  for (const EngineEvent& e : engine_log()) plan.push_back({{"t", r4(e.t)}, {"event", e.text}});
  json notes = json::array();
  for (const SimNote& n : sim.notes()) notes.push_back({{"t", r4(n.t)}, {"text", n.text}});
  json doc = {
      {"chart", {{"file", r.chart_file}, {"name", r.chart.name}, {"kind", r.chart.kind}}},
      {"world", {{"file", sim.world().path}, {"name", sim.world().name}}},
      {"sim_time_s", r4(sim.time())},
      {"status", r.run.status},
      {"bumps", sim.bumps()},
      {"bump_log", bumps},
      {"escape_presses", sim.escape_presses()},
      {"distance_m", r4(sim.odometer())},
      {"final_pose", {{"x", r4(p.x)}, {"y", r4(p.y)}, {"heading_deg", r4(deg(p.heading))}}},
      {"left_floor", sim.left_floor()},
      {"items", items},
      {"notes", notes},
      {r.chart.kind == "fsm" ? "state_log" : "plan_log", plan},
      {"physics_step_s", sim.config().physics_step},
      {"control_period_s", sim.config().control_period},
  };
  return doc.dump(2) + "\n";
}

}  // namespace carbot::driver
