#include "frame_stream.h"

#include "trace_format.h"

namespace gfec::monitor {

std::uint32_t le32(const std::uint8_t *p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

bool read_number(const std::uint8_t *data, std::size_t end, std::size_t &at, std::uint32_t &value) {
  value = 0;
  for (int shift = 0; shift < 35; shift += 7) {
    if (at >= end) return false;
    const std::uint8_t byte = data[at++];
    if (shift == 28 && (byte & 0x70) != 0) return false;
    value |= static_cast<std::uint32_t>(byte & 0x7F) << shift;
    if ((byte & 0x80) == 0) return true;
  }
  return false;
}

void FrameStream::feed(const std::uint8_t *data, std::size_t n) {
  if (refused()) return;
  buffer_.insert(buffer_.end(), data, data + n);
  for (;;) {
    const int r = frame_at_front();
    if (refused()) return;
    if (r == 0) break;
    if (r < 0) {
      ++at_;
      ++garbled_;
      ++garbled_total_;
    }
  }
  // Keep the buffer as long as the unread bytes, not the stream.
  if (at_ > 0) {
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(at_));
    at_ = 0;
  }
}

int FrameStream::intact_frame_at_front(Frame &f) const {
  const std::size_t have = buffer_.size() - at_;
  const std::uint8_t *p = buffer_.data() + at_;
  if (have < 1) return 0;
  if (p[0] != trace::kSync0) return -1;
  if (have < 2) return 0;
  if (p[1] != trace::kSync1) return -1;
  if (have < trace::kHeaderBytes) return 0;
  const std::size_t length = static_cast<std::size_t>(p[4]) | static_cast<std::size_t>(p[5]) << 8;
  const std::optional<std::size_t> longest = max_payload(p[3]);
  if (!longest || length > *longest) return -1;
  const std::size_t size = trace::kHeaderBytes + length + trace::kCrcBytes;
  if (have < size) return 0;
  if (trace::crc32(p, trace::kHeaderBytes + length) != le32(p + trace::kHeaderBytes + length)) return -1;
  f = Frame{p, length, size};
  return 1;
}

std::size_t FrameStream::drop_rest() {
  const std::size_t rest = buffer_.size() - at_;
  garbled_total_ += rest;
  buffer_.clear();
  at_ = 0;
  return rest;
}

}  // namespace gfec::monitor
