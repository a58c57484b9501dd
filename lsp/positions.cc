#include "positions.h"

#include "text_index.h"

#include <algorithm>

namespace gfec::lsp {

// One position code for the whole server: TextIndex (features/text_index.h). These take a
// text and index it per call; a handler asking many positions of one text keeps a TextIndex.
std::size_t offset_of(std::string_view text, Position p) { return TextIndex(text).offset(p); }

Position position_of(std::string_view text, std::size_t offset) {
  return TextIndex(text).position(static_cast<std::uint32_t>(std::min(offset, text.size())));
}

Position read_position(const nlohmann::json &j) {
  Position p;
  p.line = j.at("line").get<std::uint32_t>();
  p.character = j.at("character").get<std::uint32_t>();
  return p;
}

nlohmann::json to_json(Position p) { return {{"line", p.line}, {"character", p.character}}; }

nlohmann::json range_json(std::string_view text, std::size_t begin, std::size_t end) {
  TextIndex index(text);
  auto clamp = [&](std::size_t o) { return static_cast<std::uint32_t>(std::min(o, text.size())); };
  return {{"start", to_json(index.position(clamp(begin)))}, {"end", to_json(index.position(clamp(end)))}};
}

}  // namespace gfec::lsp
