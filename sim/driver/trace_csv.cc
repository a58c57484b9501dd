#include <fmt/format.h>

#include "driver/reports.h"

namespace carbot::driver {

std::string trace_csv(const RunReport& r) {
  if (!r.run.robots.empty()) return team_trace_csv(r);
  std::string out = "t,x,y,heading,active\n";
  out.reserve(out.size() + r.run.trace.size() * 48);
  const std::vector<std::vector<int>>& active = r.run.recording.active;
  for (std::size_t k = 0; k < r.run.trace.size(); ++k) {
    const TraceRow& row = r.run.trace[k];
    // Fixed decimals: 0.1 mm and 0.01 degree are finer than anything a test asserts, and the
    // text is byte-identical whenever the physics is.
    out += fmt::format("{:.3f},{:.4f},{:.4f},{:.2f},", row.t, row.x, row.y, row.heading_deg);
    // The places, states or actor active after this row's engine call, by name, space-separated.
    if (k < active.size())
      for (std::size_t i = 0; i < active[k].size(); ++i) {
        const int a = active[k][i];
        out += (i ? " " : "");
        out += a >= 0 && a < static_cast<int>(r.chart.rows.size()) ? r.chart.rows[static_cast<std::size_t>(a)].name
                                                                   : std::to_string(a);
      }
    out += '\n';
  }
  return out;
}

}  // namespace carbot::driver
