// Text placed inside XML, SVG, HTML or Graphviz HTML-like labels: one escaping for every output
// that embeds chart text in markup (the DOT back end's labels, carbot-sim's SVG picture, gfec
// test's JUnit report).
#pragma once

#include <string>

namespace gfec::text {

/// `&`, `<`, `>` and `"` as entities, so the text is safe in element content and in
/// double-quoted attributes; control characters other than tab, newline and carriage return
/// (which XML 1.0 cannot hold at all) become spaces, and bytes that are not well-formed UTF-8
/// of a character XML may hold (U+FFFE and U+FFFF are not) become U+FFFD.
std::string xml_escape(const std::string &text);

}  // namespace gfec::text
