// What a live monitor hands on, tick by tick, from a decoded trace stream (docs/live.md): the
// seam between the stream's decoder and what shows the run (the observable log, the live page).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gfec::monitor {

/// One tick of a running engine, decoded exactly (a tick that could not be decoded exactly is
/// never handed on; see RunSink::lost).
struct DecodedTick {
  std::size_t robot = 0;   ///< which stream of a team run (0 for a single engine)
  std::uint32_t tick = 0;  ///< the engine's tick count, from 1
  /// X_activation of every place of the compiled chart in declaration order, then of every
  /// sub-chart instance's places, depth first in declaration order: gfec run's `av` lines in
  /// order, concatenated (viewer::outline_rows gives the rows in this same order).
  std::vector<std::uint32_t> activation;
  /// An fsm's status after the tick: "running", "succeeded" or "failed" ("" for an sfc).
  std::string status;
  /// The calls the tick made, as gfec run's observable log writes them ("Move(2) = true"),
  /// when the stream carries calls; empty otherwise.
  std::vector<std::string> calls;
  bool has_calls = false;
  /// A team machine's engine: its agent number, and by agent the state it last reported (-1:
  /// none yet). -1 and empty for any other chart.
  int agent = -1;
  std::vector<std::int32_t> reports;
};

/// Receives a decoded run. Called from the monitor's reading thread, in stream order.
class RunSink {
public:
  virtual ~RunSink() = default;
  /// The stream names the chart it comes from and it matched the chart given to the monitor.
  virtual void started(std::size_t robot) = 0;
  virtual void tick(const DecodedTick &t) = 0;
  /// Bytes were dropped or garbled: `ticks_missing` ticks (0 if unknown) are not shown; the
  /// monitor is exact again from the next tick it hands on.
  virtual void lost(std::size_t robot, std::uint64_t ticks_missing, const std::string &why) = 0;
  /// Nothing has arrived for `seconds` (called again as the silence lasts; 0 when data resumes).
  virtual void silent(double seconds) = 0;
  /// The stream ended (end of file, connection closed) or was refused (another chart's stream).
  virtual void ended(const std::string &why) = 0;
};

}  // namespace gfec::monitor
