#include "plcopen/xml_text.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace gfec::plcopen {

std::string_view local_name(const pugi::xml_node &node) {
  std::string_view name = node.name();
  auto colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

pugi::xml_node child(const pugi::xml_node &node, std::string_view name) {
  for (pugi::xml_node c : node.children())
    if (c.type() == pugi::node_element && local_name(c) == name) return c;
  return {};
}

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

/// The entity at `at` ("&lt;"): its length and its UTF-8 text, or length 0 if none is there.
std::size_t entity_at(std::string_view t, std::size_t at, std::string &decoded) {
  auto semi = t.find(';', at);
  if (semi == std::string_view::npos || semi - at > 10) return 0;
  std::string_view name = t.substr(at + 1, semi - at - 1);
  decoded.clear();
  if (name == "lt") decoded = "<";
  else if (name == "gt") decoded = ">";
  else if (name == "amp") decoded = "&";
  else if (name == "quot") decoded = "\"";
  else if (name == "apos") decoded = "'";
  else if (name.size() >= 2 && name[0] == '#') {
    unsigned long code = 0;
    bool hex = name[1] == 'x' || name[1] == 'X';
    std::string_view digits = name.substr(hex ? 2 : 1);
    if (digits.empty()) return 0;
    for (char c : digits) {
      int v = c >= '0' && c <= '9'          ? c - '0'
              : hex && c >= 'a' && c <= 'f' ? c - 'a' + 10
              : hex && c >= 'A' && c <= 'F' ? c - 'A' + 10
                                            : -1;
      if (v < 0 || code > 0x10FFFF) return 0;
      code = code * (hex ? 16 : 10) + static_cast<unsigned>(v);
    }
    if (code == 0 || code > 0x10FFFF) return 0;
    if (code < 0x80) {
      decoded += static_cast<char>(code);
    } else if (code < 0x800) {
      decoded += static_cast<char>(0xC0 | (code >> 6));
      decoded += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      decoded += static_cast<char>(0xE0 | (code >> 12));
      decoded += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      decoded += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      decoded += static_cast<char>(0xF0 | (code >> 18));
      decoded += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
      decoded += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      decoded += static_cast<char>(0x80 | (code & 0x3F));
    }
  } else {
    return 0;
  }
  return semi - at + 1;
}

}  // namespace

std::uint32_t LocatedText::file_offset(std::uint32_t o) const {
  if (breaks.empty()) return o;
  auto it =
      std::upper_bound(breaks.begin(), breaks.end(), o,
                       [](std::uint32_t v, const std::pair<std::uint32_t, std::uint32_t> &b) { return v < b.first; });
  if (it != breaks.begin()) --it;
  return it->second + (o - it->first);
}

namespace {

/// Records that text offset `at` is at file offset `file`, unless that already follows.
void place(LocatedText &out, std::uint32_t file) {
  auto at = static_cast<std::uint32_t>(out.text.size());
  if (!out.breaks.empty() && out.file_offset(at) == file) return;
  if (!out.breaks.empty() && out.breaks.back().first == at) out.breaks.back().second = file;
  else out.breaks.emplace_back(at, file);
}

}  // namespace

void XmlFile::decode(std::uint32_t begin, std::uint32_t end, LocatedText &out) const {
  std::string decoded;
  std::size_t i = begin;
  place(out, begin);
  while (i < end) {
    std::size_t n = text_[i] == '&' ? entity_at(text_.substr(0, end), i, decoded) : 0;
    if (n == 0) {
      out.text += text_[i++];
      continue;
    }
    out.text += decoded;
    i += n;
    place(out, static_cast<std::uint32_t>(i));
  }
}

SourceRange XmlFile::range(const pugi::xml_node &node) const {
  std::ptrdiff_t at = node.offset_debug();
  if (at < 0) return {file_, 0, 0};
  auto name = static_cast<std::uint32_t>(std::strlen(node.name()));
  std::uint32_t begin =
      at > 0 && node.type() == pugi::node_element ? static_cast<std::uint32_t>(at) - 1 : static_cast<std::uint32_t>(at);
  return {file_, begin, static_cast<std::uint32_t>(at) + name};
}

SourceRange XmlFile::attribute_range(const pugi::xml_node &node, std::string_view name) const {
  SourceRange whole = range(node);
  std::ptrdiff_t at = node.offset_debug();
  if (at < 0 || node.type() != pugi::node_element) return whole;
  std::size_t i = static_cast<std::size_t>(at) + std::strlen(node.name());
  const std::size_t n = text_.size();
  while (i < n) {
    while (i < n && is_space(text_[i])) ++i;
    if (i >= n || text_[i] == '>' || text_[i] == '/' || text_[i] == '?') break;
    std::size_t name_begin = i;
    while (i < n && !is_space(text_[i]) && text_[i] != '=' && text_[i] != '>') ++i;
    std::string_view attr = text_.substr(name_begin, i - name_begin);
    while (i < n && is_space(text_[i])) ++i;
    if (i >= n || text_[i] != '=') break;
    ++i;
    while (i < n && is_space(text_[i])) ++i;
    if (i >= n || (text_[i] != '"' && text_[i] != '\'')) break;
    char quote = text_[i++];
    std::size_t value_begin = i;
    while (i < n && text_[i] != quote) ++i;
    if (attr == name) return {file_, static_cast<std::uint32_t>(value_begin), static_cast<std::uint32_t>(i)};
    ++i;
  }
  return whole;
}

LocatedText XmlFile::attribute_text(const pugi::xml_node &node, std::string_view name) const {
  SourceRange r = attribute_range(node, name);
  LocatedText located;
  if (r.begin == range(node).begin) {  // not found as written: its value, at the element
    located.text = node.attribute(std::string(name).c_str()).value();
    located.breaks.emplace_back(0, r.begin);
    return located;
  }
  decode(r.begin, r.end, located);
  return located;
}

LocatedText XmlFile::text_below(const pugi::xml_node &node) const {
  LocatedText located;
  std::vector<pugi::xml_node> stack{node};
  // Depth-first in document order, without recursion: a hostile file nests deep.
  while (!stack.empty()) {
    pugi::xml_node n = stack.back();
    stack.pop_back();
    if (n.type() == pugi::node_pcdata || n.type() == pugi::node_cdata) {
      std::ptrdiff_t at = n.offset_debug();
      if (at < 0) continue;
      auto b = static_cast<std::size_t>(at);
      std::size_t e = n.type() == pugi::node_cdata ? text_.find("]]>", b) : text_.find('<', b);
      if (e == std::string_view::npos) e = text_.size();
      if (!located.text.empty()) {  // markup between two texts separates them
        located.text += '\n';
      }
      if (n.type() == pugi::node_cdata) {
        place(located, static_cast<std::uint32_t>(b));
        located.text += text_.substr(b, e - b);
      } else {
        decode(static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(e), located);
      }
      continue;
    }
    std::vector<pugi::xml_node> children(n.begin(), n.end());
    for (auto it = children.rbegin(); it != children.rend(); ++it) stack.push_back(*it);
  }
  if (located.breaks.empty()) located.breaks.emplace_back(0, range(node).end);
  return located;
}

}  // namespace gfec::plcopen
