// What a run leaves behind: the trace (CSV), the result (JSON) and a picture (SVG).
// main.cc writes them as one set with safe_output::write_all (support/safe_output.h):
// never over the chart or the world, a special file or one file twice, never half a file.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/simulation.h"
#include "driver/chart_build.h"
#include "driver/run.h"

namespace carbot::driver {

/// Everything a report may show about one run.
struct RunReport {
  const ChartInfo& chart;
  const std::string& chart_file;
  const Simulation& sim;
  const RunResult& run;
};

/// `t,x,y,heading` (s, m, m, degrees), one row per control tick.
std::string trace_csv(const RunReport& r);
/// sim_time_s, status, bumps, items [{name, at, ...}], and more (docs/sim.md).
std::string result_json(const RunReport& r);
/// The world and the robot's path, with a title and a legend.
std::string svg_picture(const RunReport& r);

/// Several robots (RunResult::robots): the trace with a robot column, the result with a
/// "robots" array (docs/sim.md, "Several robots"). trace_csv and result_json call these.
std::string team_trace_csv(const RunReport& r);
std::string team_result_json(const RunReport& r);
/// Robot i's colour in the SVG picture and the run viewer's page.
const char* robot_colour(std::size_t i);

/// The run viewer's recording (docs/viewer.md), which its page embeds: `chart_svg` is gfec's SVG
/// of the chart ("" with `svg_note` saying why there is none).
nlohmann::json viewer_data(const RunReport& r, const std::string& chart_svg, const std::string& svg_note);

}  // namespace carbot::driver
