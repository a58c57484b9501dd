// The decoder of a live trace stream (docs/live.md): bytes in, in any chunking; exactly decoded
// ticks out, to a RunSink. It finds frames by their sync bytes, checks length, CRC, version and
// fingerprint, and keeps the activation. A frame of changes is applied only on top of the tick
// before it, decoded exactly: after a loss nothing is shown until the next full frame.
#pragma once

#include "run_sink.h"
#include "trace_format.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gfec::monitor {

class TraceDecoder {
public:
  TraceDecoder(const trace::Layout &layout, RunSink &sink, std::size_t robot = 0);

  /// The next bytes of the stream.
  void feed(const std::uint8_t *data, std::size_t n);
  /// The stream ended: bytes of an unfinished frame are reported lost.
  void finish();

  /// A frame of another chart or format arrived: the stream was refused (RunSink::ended) and
  /// every later byte is ignored.
  bool refused() const { return !refusal_.empty(); }
  const std::string &refusal() const { return refusal_; }

  std::uint64_t ticks_shown() const { return shown_; }
  std::uint64_t ticks_lost() const { return lost_; }
  std::uint64_t bytes_garbled() const { return garbled_total_; }

private:
  /// Tries to read a frame at the front of the buffer: 1 read one, 0 needs more bytes, -1 the
  /// front byte begins no frame.
  int frame_at_front();
  void frame(bool full, std::uint32_t tick, const std::uint8_t *payload, std::size_t length);
  void show(std::uint32_t tick);
  void skip_byte();

  const trace::Layout layout_;
  RunSink &sink_;
  const std::size_t robot_;
  std::vector<std::uint8_t> buffer_;
  std::size_t at_ = 0;  ///< where the unread bytes of buffer_ begin
  std::vector<std::uint32_t> values_;
  std::vector<std::uint32_t> scratch_;
  bool exact_ = false;            ///< values_ are the engine's after tick last_seen_
  bool started_ = false;          ///< a frame of this chart has arrived
  std::uint32_t last_seen_ = 0;   ///< the last frame's tick
  std::uint32_t last_shown_ = 0;  ///< the last tick handed on (0: none yet)
  std::uint64_t garbled_ = 0;     ///< bytes skipped since the last tick handed on
  std::uint64_t garbled_total_ = 0;
  std::uint64_t shown_ = 0, lost_ = 0;
  std::string refusal_;
};

}  // namespace gfec::monitor
