#include <cerrno>
#include <cstdio>
#include <cstring>

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

bool write_atomically(const std::string& path, const std::string& text, std::string& error) {
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) {
    error = fmt::format("{}: cannot write: {}", path, std::strerror(errno));
    return false;
  }
  const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed || std::rename(tmp.c_str(), path.c_str()) != 0) {
    error = fmt::format("{}: cannot write: {}", path, std::strerror(errno));
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

}  // namespace carbot::driver
