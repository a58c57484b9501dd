// The decoder of a plan's live trace (docs/live.md "Plans"): bytes in, in any chunking; exactly
// decoded events out, to a PlanSink. The framing is the C engines' (trace_decoder.h): sync bytes,
// a length no larger than this plan's longest frame, the CRC; then the version and fingerprint.
// Every plan frame is whole (an event and the state after it), so after a loss the next intact
// frame is exact again.
#pragma once

#include "frame_stream.h"
#include "plan_sink.h"
#include "plan_trace_format.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gfec::monitor {

class PlanTraceDecoder : public FrameStream {
public:
  PlanTraceDecoder(const model::Model &model, const trace::PlanLayout &layout, PlanSink &sink);

  void finish() override;

  /// Frames handed on, and of them the events (the others are LinkTrace::heartbeat's state).
  std::uint64_t frames_shown() const { return shown_; }
  std::uint64_t events_shown() const { return events_; }
  std::uint64_t events_lost() const { return lost_; }

private:
  std::optional<std::size_t> max_payload(std::uint8_t kind) const override;
  int frame_at_front() override;
  /// Decodes an intact frame's payload; false if it is malformed.
  bool decode(const std::uint8_t *payload, std::size_t length, DecodedPlanEvent &e) const;
  void show(DecodedPlanEvent &e);

  const model::Model &model_;
  const trace::PlanLayout layout_;
  PlanSink &sink_;
  bool started_ = false;
  std::uint32_t last_shown_ = 0;  ///< the last frame handed on (0: none yet)
  std::uint64_t bad_ = 0;         ///< intact frames that did not decode, since the last one handed on
  std::uint64_t shown_ = 0, events_ = 0, lost_ = 0;
};

}  // namespace gfec::monitor
