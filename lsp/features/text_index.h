// Byte offsets of one text against LSP positions (line, UTF-16 code unit), for the feature
// handlers that work on a text alone (semantic tokens, folding, completion). LSP counts columns
// in UTF-16 code units while gfec's ranges count bytes: a character outside the BMP is two units,
// a byte that is not UTF-8 one (as editors show it: one replacement character).
#pragma once

#include "positions.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace gfec::lsp {

class TextIndex {
public:
  explicit TextIndex(std::string_view text);

  Position position(std::uint32_t offset) const;
  /// The byte offset of `p`; a line past the end is the end of the text, a column past the end
  /// of its line is that line's end (LSP: "defaults back to the line length").
  std::uint32_t offset(Position p) const;
  std::uint32_t line_count() const { return static_cast<std::uint32_t>(starts_.size()); }
  std::uint32_t line_start(std::uint32_t line) const { return starts_.at(line); }
  /// Where line `line`'s text ends, before its line break.
  std::uint32_t line_end(std::uint32_t line) const;
  std::string_view text() const { return text_; }

private:
  std::string_view text_;
  std::vector<std::uint32_t> starts_;
  /// Per line: only ASCII, so a column in code units is its byte offset from the line's start
  /// (the common case: a position costs a binary search, not a walk along the line).
  std::vector<bool> ascii_;
};

/// UTF-16 code units in `s`.
std::uint32_t utf16_length(std::string_view s);

}  // namespace gfec::lsp
