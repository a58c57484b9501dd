// PLCopen files as pugixml reads them, with every element, attribute and text located in the file
// as the user sees it: pugixml gives each node's byte offset (offset_debug), and this finds the
// rest (an attribute's value, where a text ends) in the raw text, so that a diagnostic points at
// the element's tag or the attribute's value.
#pragma once

#include "source.h"

#include <pugixml.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gfec::plcopen {

/// The element name without its namespace prefix: "xhtml:p" -> "p".
std::string_view local_name(const pugi::xml_node &node);

/// The first child element whose local name is `name`, or an empty node.
pugi::xml_node child(const pugi::xml_node &node, std::string_view name);

/// A text of the file with its entities decoded (`&lt;` -> `<`), and where each piece of it
/// lies in the file: text offset o is at file offset `b.second + (o - b.first)` for the last
/// break b with b.first <= o. A new break follows each entity and each piece of markup between
/// two texts (`]]>`, `</xhtml:p>`; such markup reads as one newline, so it separates tokens).
struct LocatedText {
  std::string text;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> breaks;
  /// The file offset of text offset `o`.
  std::uint32_t file_offset(std::uint32_t o) const;
  bool blank() const { return text.find_first_not_of(" \t\r\n") == std::string::npos; }
};

/// The file a document was parsed from, for locating its nodes.
class XmlFile {
public:
  XmlFile(FileId file, std::string_view text) : file_(file), text_(text) {}
  FileId id() const { return file_; }
  std::string_view text() const { return text_; }

  /// The element's start tag up to the end of its name: "<step".
  SourceRange range(const pugi::xml_node &node) const;
  /// The value of attribute `name` of `node`, between its quotes; the element's range when the
  /// attribute is not written.
  SourceRange attribute_range(const pugi::xml_node &node, std::string_view name) const;
  /// The attribute's value, located.
  LocatedText attribute_text(const pugi::xml_node &node, std::string_view name) const;
  /// Every text (plain or CDATA) below `node`, in document order, as one located text.
  LocatedText text_below(const pugi::xml_node &node) const;

private:
  /// Appends file text [begin, end) to `out` with its entities decoded.
  void decode(std::uint32_t begin, std::uint32_t end, LocatedText &out) const;

  FileId file_;
  std::string_view text_;
};

}  // namespace gfec::plcopen
