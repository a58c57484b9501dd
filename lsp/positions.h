// LSP positions (a line and a UTF-16 code unit offset within it, both from 0) and the byte
// offsets of the compiler's SourceRange. Lines end at "\n", "\r\n" or a lone "\r" (as for LSP and
// gfec's lexer). A byte that is no UTF-8 counts as one code unit (editors show it as U+FFFD); a character outside the BMP counts two.
#pragma once

#include <cstdint>
#include <string_view>

#include <nlohmann/json.hpp>

namespace gfec::lsp {

struct Position {
  std::uint32_t line = 0;
  std::uint32_t character = 0;  ///< UTF-16 code units from the line's start
};

/// The byte offset of `p` in `text`: a line past the end is the end of the text, a character
/// past the line's end its end (the spec says to clamp so).
std::size_t offset_of(std::string_view text, Position p);
/// The position of byte `offset` (clamped to the text; inside a character: that character's start).
Position position_of(std::string_view text, std::size_t offset);

/// Reads {"line": L, "character": C}; throws nlohmann::json::exception when it is not that.
Position read_position(const nlohmann::json &j);
nlohmann::json to_json(Position p);
/// {"start": ..., "end": ...} of the bytes [begin, end) of `text`.
nlohmann::json range_json(std::string_view text, std::size_t begin, std::size_t end);

}  // namespace gfec::lsp
