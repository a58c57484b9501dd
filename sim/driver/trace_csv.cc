#include <fmt/format.h>

#include "driver/reports.h"

namespace carbot::driver {

std::string trace_csv(const RunReport& r) {
  std::string out = "t,x,y,heading\n";
  out.reserve(out.size() + r.run.trace.size() * 32);
  for (const TraceRow& row : r.run.trace) {
    // Fixed decimals: 0.1 mm and 0.01 degree are finer than anything a test asserts, and the
    // text is byte-identical whenever the physics is.
    out += fmt::format("{:.3f},{:.4f},{:.4f},{:.2f}\n", row.t, row.x, row.y, row.heading_deg);
  }
  return out;
}

}  // namespace carbot::driver
