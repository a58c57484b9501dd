// The base protocol's framing (LSP 3.17 "Base Protocol"): a header of `Name: value` lines ended
// by an empty line, then Content-Length bytes of JSON. A broken frame is reported, never a reason
// to stop: the server answers it and reads on.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>

namespace gfec::lsp {

/// One message read, or why none was.
struct Frame {
  enum class Status {
    Ok,        ///< body holds the message's bytes
    End,       ///< the input ended (between messages or inside one)
    BadHeader  ///< the header had no usable Content-Length (or one too large); error says which
  };
  Status status = Status::End;
  std::string body;
  std::string error;
};

/// The largest body read; a larger one is skipped unread (its bytes are discarded) and refused.
inline constexpr std::size_t kMaxBody = std::size_t{64} << 20;

/// Reads one frame from `in`. Header lines that are not `Name: value` are skipped as garbage
/// (an editor's log line written to the pipe); other headers (Content-Type) are ignored.
Frame read_frame(std::istream &in);

/// Writes `body` as one frame and flushes: the client must see each message as soon as it is sent.
void write_frame(std::ostream &out, const std::string &body);

}  // namespace gfec::lsp
