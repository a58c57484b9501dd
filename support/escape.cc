#include "escape.h"

#include "utf8.h"

#include <cstdint>

namespace gfec::text {

namespace {

/// Characters a terminal obeys or that reorder the text around them: C1 controls, and the
/// bidirectional marks, embeddings, overrides and isolates.
bool hidden_control(std::uint32_t cp) {
  return (cp >= 0x80 && cp <= 0x9F) || cp == 0x061C || cp == 0x200E || cp == 0x200F || (cp >= 0x202A && cp <= 0x202E) ||
         (cp >= 0x2066 && cp <= 0x2069);
}

/// `value` in hexadecimal, at least `digits` digits (no fmt: carbot-sim builds the
/// support tier on its own).
std::string hex(std::uint32_t value, int digits, bool upper) {
  const char *numerals = upper ? "0123456789ABCDEF" : "0123456789abcdef";
  std::string out;
  for (; value != 0 || digits > 0; value >>= 4, --digits) out.insert(out.begin(), numerals[value & 0xF]);
  return out;
}

std::string code_point(std::uint32_t cp) { return "<U+" + hex(cp, 4, true) + ">"; }

}  // namespace

Shown shown_at(std::string_view s, std::size_t at, bool keep_newline) {
  const auto c = static_cast<unsigned char>(s[at]);
  if (c < 0x80) {
    const bool plain = (c >= 0x20 && c != 0x7F) || c == '\t' || (keep_newline && c == '\n');
    if (plain) return {1, std::string(1, static_cast<char>(c)), false};
    return {1, code_point(c), true};
  }
  if (const Utf8 u = decode_utf8(s, at); u.length > 0) {
    if (hidden_control(u.code_point)) return {u.length, code_point(u.code_point), true};
    return {u.length, std::string(s.substr(at, u.length)), false};
  }
  return {1, "<" + hex(c, 2, false) + ">", true};
}

std::string printable(std::string_view s, bool keep_newlines) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t at = 0; at < s.size();) {
    Shown ch = shown_at(s, at, keep_newlines);
    out += ch.text;
    at += ch.length;
  }
  return out;
}

}  // namespace gfec::text
