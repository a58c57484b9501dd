// What both decoders of the live link (trace_decoder.h: a chart engine's ticks; plan_decoder.h: a
// plan's events) do before a frame is theirs: keep the bytes in any chunking, find a frame by its
// sync bytes, a length the stream can have and its CRC (docs/live.md "The frame"), and skip and
// count every byte that begins no intact frame. What a frame means is the decoder's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gfec::monitor {

/// The little-endian 32-bit number at p.
std::uint32_t le32(const std::uint8_t *p);

/// A number of 7 bits a byte at data[at]; false if it runs past `end` or past 32 bits.
bool read_number(const std::uint8_t *data, std::size_t end, std::size_t &at, std::uint32_t &value);

class FrameStream {
public:
  virtual ~FrameStream() = default;

  /// The next bytes of the stream: every frame they complete is taken, in order.
  void feed(const std::uint8_t *data, std::size_t n);
  /// The stream ended: bytes of an unfinished frame are reported lost.
  virtual void finish() = 0;

  /// A frame of another chart, plan or format arrived: the stream was refused and every later
  /// byte is ignored.
  bool refused() const { return !refusal_.empty(); }
  const std::string &refusal() const { return refusal_; }
  std::uint64_t bytes_garbled() const { return garbled_total_; }

protected:
  /// An intact frame at the front of the buffer: its header at `p`, its payload's length, and
  /// its size with header and CRC.
  struct Frame {
    const std::uint8_t *p = nullptr;
    std::size_t length = 0;
    std::size_t size = 0;
  };
  /// 1: `f` is an intact frame at the front; 0: more bytes are needed; -1: the front byte begins
  /// no frame (a sync byte out of place, a kind or length this stream never has, a bad CRC).
  int intact_frame_at_front(Frame &f) const;
  /// The longest payload a frame of `kind` can have in this stream; none: no frame has that kind.
  /// A length beyond it is a garbled header: waiting for that many bytes would stall the stream.
  virtual std::optional<std::size_t> max_payload(std::uint8_t kind) const = 0;
  /// Takes the frame at the front of the buffer, if one is there: 1 took it (or refused the
  /// stream), 0 needs more bytes, -1 the front byte begins no frame.
  virtual int frame_at_front() = 0;
  /// The bytes of an unfinished frame when the stream ends, counted garbled; the buffer emptied.
  std::size_t drop_rest();

  std::vector<std::uint8_t> buffer_;
  std::size_t at_ = 0;         ///< where the unread bytes of buffer_ begin
  std::uint64_t garbled_ = 0;  ///< bytes skipped since the decoder last handed something on
  std::uint64_t garbled_total_ = 0;
  std::string refusal_;
};

}  // namespace gfec::monitor
