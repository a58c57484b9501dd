#include "xml_text.h"

#include <cstddef>
#include <cstdint>

namespace gfec::text {

namespace {

/// The UTF-8 sequence at `s[i]`: how many bytes it takes (at least 1) and whether it is
/// well-formed UTF-8 of a code point XML 1.0 may hold (not an overlong form, a surrogate,
/// U+FFFE or U+FFFF). A sequence cut short or a stray byte is one byte that is not.
struct Sequence {
  std::size_t length = 1;
  bool ok = false;
};

Sequence utf8_sequence(const std::string &s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(s[k]); };
  const std::uint8_t b = byte(i);
  std::size_t n = 0;
  std::uint32_t cp = 0;
  if (b >= 0xC2 && b <= 0xDF) n = 2, cp = b & 0x1Fu;
  else if (b >= 0xE0 && b <= 0xEF) n = 3, cp = b & 0x0Fu;
  else if (b >= 0xF0 && b <= 0xF4) n = 4, cp = b & 0x07u;
  else return {};
  if (i + n > s.size()) return {};
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0u) != 0x80u) return {};
    cp = (cp << 6) | (byte(i + k) & 0x3Fu);
  }
  const bool overlong = (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000);
  const bool allowed = !overlong && cp <= 0x10FFFF && !(cp >= 0xD800 && cp <= 0xDFFF) && cp != 0xFFFE && cp != 0xFFFF;
  return {n, allowed};
}

}  // namespace

std::string xml_escape(const std::string &text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    case '\t':
    case '\n':
    case '\r': out += c; break;
    default:
      if (static_cast<unsigned char>(c) < 0x20) {
        out += ' ';
      } else if (static_cast<unsigned char>(c) < 0x80) {
        out += c;
      } else {
        const Sequence q = utf8_sequence(text, i);
        if (q.ok) out.append(text, i, q.length);
        else out += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER for what XML cannot hold
        i += q.length - 1;
      }
    }
  }
  return out;
}

}  // namespace gfec::text
