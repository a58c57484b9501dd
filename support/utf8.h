// Decoding one UTF-8 sequence: shared by everything that prints or embeds a chart's text, which
// need not be UTF-8 (the diagnostics printer, the XML escaping of labels and reports).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace gfec::text {

/// The code point of the well-formed UTF-8 sequence at `s[at]` (shortest form, no surrogate, at
/// most U+10FFFF) and its length in bytes; length 0 if the bytes there are no such sequence (a
/// stray byte, a sequence cut short).
struct Utf8 {
  std::uint32_t code_point = 0;
  std::size_t length = 0;
};
Utf8 decode_utf8(std::string_view s, std::size_t at);

}  // namespace gfec::text
