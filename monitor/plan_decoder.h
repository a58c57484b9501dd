// The decoder of a plan's live trace (docs/live.md "Plans"): bytes in, in any chunking; exactly
// decoded events out, to a PlanSink. The framing is the C engines' (trace_decoder.h): sync bytes,
// a length no larger than this plan's longest frame, the CRC; then the version and fingerprint.
// Every plan frame is whole (an event and the state after it), so after a loss the next intact
// frame is exact again.
#pragma once

#include "plan_sink.h"
#include "plan_trace_format.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gfec::monitor {

class PlanTraceDecoder {
public:
  PlanTraceDecoder(const model::Model &model, const trace::PlanLayout &layout, PlanSink &sink);

  void feed(const std::uint8_t *data, std::size_t n);
  /// The stream ended: bytes of an unfinished frame are reported lost.
  void finish();

  bool refused() const { return !refusal_.empty(); }
  const std::string &refusal() const { return refusal_; }
  /// Frames handed on, and of them the events (the others are LinkTrace::heartbeat's state).
  std::uint64_t frames_shown() const { return shown_; }
  std::uint64_t events_shown() const { return events_; }
  std::uint64_t events_lost() const { return lost_; }
  std::uint64_t bytes_garbled() const { return garbled_total_; }

private:
  /// 1 read a frame, 0 needs more bytes, -1 the front byte begins no frame.
  int frame_at_front();
  /// Decodes an intact frame's payload; false if it is malformed.
  bool decode(const std::uint8_t *payload, std::size_t length, DecodedPlanEvent &e) const;
  void show(DecodedPlanEvent &e);
  void skip_byte();

  const model::Model &model_;
  const trace::PlanLayout layout_;
  PlanSink &sink_;
  std::vector<std::uint8_t> buffer_;
  std::size_t at_ = 0;
  bool started_ = false;
  std::uint32_t last_shown_ = 0;  ///< the last frame handed on (0: none yet)
  std::uint64_t garbled_ = 0;     ///< bytes skipped since the last frame handed on
  std::uint64_t bad_ = 0;         ///< intact frames that did not decode, since the last one handed on
  std::uint64_t garbled_total_ = 0;
  std::uint64_t shown_ = 0, events_ = 0, lost_ = 0;
  std::string refusal_;
};

}  // namespace gfec::monitor
