// The decoder of a live trace stream (docs/live.md): bytes in, in any chunking; exactly decoded
// ticks out, to a RunSink. It finds frames by their sync bytes, checks length, CRC, version and
// fingerprint, and keeps the activation. A frame of changes is applied only on top of the tick
// before it, decoded exactly: after a loss nothing is shown until the next full frame.
#pragma once

#include "frame_stream.h"
#include "run_sink.h"
#include "trace_format.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gfec::monitor {

class TraceDecoder : public FrameStream {
public:
  /// `model`: the chart's, for the names and types of the calls a frame may carry.
  TraceDecoder(const model::Model &model, const trace::Layout &layout, RunSink &sink, std::size_t robot = 0);

  void finish() override;

  /// A refused stream (FrameStream::refused) was also reported to the sink (RunSink::ended).

  std::uint64_t ticks_shown() const { return shown_; }
  std::uint64_t ticks_lost() const { return lost_; }

private:
  std::optional<std::size_t> max_payload(std::uint8_t kind) const override;
  int frame_at_front() override;
  void frame(std::uint8_t kind, std::uint32_t tick, const std::uint8_t *payload, std::size_t length);
  /// The calls' section at payload[at]: false if it is malformed.
  bool read_calls(const std::uint8_t *payload, std::size_t length, std::size_t &at);
  void show(std::uint32_t tick);

  const model::Model &model_;
  const trace::Layout layout_;
  RunSink &sink_;
  const std::size_t robot_;
  std::vector<std::uint32_t> values_;
  std::vector<std::uint32_t> scratch_;
  std::vector<std::string> calls_;  ///< the calls of the frame being read
  bool has_calls_ = false, calls_cut_ = false;
  bool exact_ = false;            ///< values_ are the engine's after tick last_seen_
  bool started_ = false;          ///< a frame of this chart has arrived
  std::uint32_t last_seen_ = 0;   ///< the last frame's tick
  std::uint32_t last_shown_ = 0;  ///< the last tick handed on (0: none yet)
  std::uint64_t shown_ = 0, lost_ = 0;
};

}  // namespace gfec::monitor
