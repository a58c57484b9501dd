#include "text_index.h"

#include "utf8.h"

#include <algorithm>

namespace gfec::lsp {

TextIndex::TextIndex(std::string_view text) : text_(text) {
  starts_.push_back(0);
  bool ascii = true;
  // \n, \r\n and \r all end a line (docs/language.md §1), as they do for LSP.
  for (std::uint32_t i = 0; i < text.size(); ++i) {
    if (static_cast<unsigned char>(text[i]) >= 0x80) ascii = false;
    if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    if (text[i] == '\n' || text[i] == '\r') {
      starts_.push_back(i + 1);
      ascii_.push_back(ascii);
      ascii = true;
    }
  }
  ascii_.push_back(ascii);
}

std::uint32_t TextIndex::line_end(std::uint32_t line) const {
  std::uint32_t end = line + 1 < starts_.size() ? starts_[line + 1] : static_cast<std::uint32_t>(text_.size());
  while (end > starts_[line] && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
  return end;
}

std::uint32_t utf16_length(std::string_view s) {
  std::uint32_t units = 0;
  for (std::size_t i = 0; i < s.size();) {
    text::Utf8 u = text::decode_utf8(s, i);
    if (u.length == 0) {
      ++units, ++i;
      continue;
    }
    units += u.code_point >= 0x10000 ? 2 : 1;
    i += u.length;
  }
  return units;
}

Position TextIndex::position(std::uint32_t offset) const {
  offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text_.size()));
  auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
  std::uint32_t line = static_cast<std::uint32_t>(it - starts_.begin()) - 1;
  if (ascii_[line]) return {line, std::min(offset, line_end(line)) - starts_[line]};
  // An offset inside a character (or inside a "\r\n") stands for that character's start.
  std::uint32_t at = starts_[line], units = 0;
  const std::uint32_t end = std::min(offset, line_end(line));
  while (at < end) {
    text::Utf8 u = text::decode_utf8(text_, at);
    const std::uint32_t bytes = u.length == 0 ? 1 : static_cast<std::uint32_t>(u.length);
    if (at + bytes > end) break;
    at += bytes;
    units += u.length != 0 && u.code_point >= 0x10000 ? 2 : 1;
  }
  return {line, units};
}

std::uint32_t TextIndex::offset(Position p) const {
  if (p.line >= starts_.size()) return static_cast<std::uint32_t>(text_.size());
  std::uint32_t i = starts_[p.line], end = line_end(p.line), units = 0;
  // 64-bit: a column near 2^32 must clamp to the line's end, not wrap before its start.
  if (ascii_[p.line]) return static_cast<std::uint32_t>(std::min<std::uint64_t>(end, std::uint64_t{i} + p.character));
  while (i < end && units < p.character) {
    text::Utf8 u = text::decode_utf8(text_, i);
    const std::uint32_t bytes = u.length == 0 ? 1 : static_cast<std::uint32_t>(u.length);
    const std::uint32_t width = u.length != 0 && u.code_point >= 0x10000 ? 2 : 1;
    // A position inside a surrogate pair is the pair's start (the spec leaves it to the server).
    if (units + width > p.character) break;
    units += width;
    i += bytes;
  }
  return std::min(i, end);
}

}  // namespace gfec::lsp
