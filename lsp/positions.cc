#include "positions.h"

#include "utf8.h"

#include <algorithm>

namespace gfec::lsp {

namespace {

/// The byte where line `line` begins (the text's end if it has fewer lines).
std::size_t line_start(std::string_view text, std::uint32_t line) {
  std::size_t at = 0;
  for (std::uint32_t l = 0; l < line; ++l) {
    std::size_t nl = text.find('\n', at);
    if (nl == std::string_view::npos) return text.size();
    at = nl + 1;
  }
  return at;
}

/// Where the line beginning at `start` ends, before its "\n" or "\r\n".
std::size_t line_end(std::string_view text, std::size_t start) {
  std::size_t nl = text.find('\n', start);
  if (nl == std::string_view::npos) return text.size();
  if (nl > start && text[nl - 1] == '\r') --nl;
  return nl;
}

/// The length in bytes and UTF-16 code units of the character at `at`.
void step(std::string_view text, std::size_t at, std::size_t &bytes, std::uint32_t &units) {
  text::Utf8 u = text::decode_utf8(text, at);
  if (u.length == 0) {
    bytes = 1;
    units = 1;
  } else {
    bytes = u.length;
    units = u.code_point >= 0x10000 ? 2 : 1;
  }
}

}  // namespace

std::size_t offset_of(std::string_view text, Position p) {
  std::size_t at = line_start(text, p.line);
  std::size_t end = line_end(text, at);
  std::uint32_t units = 0;
  while (at < end && units < p.character) {
    std::size_t b;
    std::uint32_t u;
    step(text, at, b, u);
    // A position inside a surrogate pair is the pair's start (the spec leaves it to the server).
    if (units + u > p.character) break;
    at += b;
    units += u;
  }
  return std::min(at, end);
}

Position position_of(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  Position p;
  std::size_t start = 0;
  for (std::size_t nl = text.find('\n'); nl != std::string_view::npos && nl < offset; nl = text.find('\n', nl + 1)) {
    ++p.line;
    start = nl + 1;
  }
  for (std::size_t at = start; at < offset;) {
    std::size_t b;
    std::uint32_t u;
    step(text, at, b, u);
    if (at + b > offset) break;
    at += b;
    p.character += u;
  }
  return p;
}

Position read_position(const nlohmann::json &j) {
  Position p;
  p.line = j.at("line").get<std::uint32_t>();
  p.character = j.at("character").get<std::uint32_t>();
  return p;
}

nlohmann::json to_json(Position p) { return {{"line", p.line}, {"character", p.character}}; }

nlohmann::json range_json(std::string_view text, std::size_t begin, std::size_t end) {
  return {{"start", to_json(position_of(text, begin))}, {"end", to_json(position_of(text, end))}};
}

}  // namespace gfec::lsp
