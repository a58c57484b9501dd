// The one escaping of text in messages (support/escape.h): controls and bytes that are no UTF-8
// as escapes, everything else as itself.
#include "escape.h"

#include <catch2/catch.hpp>

#include <string>

using gfec::text::printable;
using gfec::text::shown_at;

TEST_CASE("escape: control characters are escaped as <U+XXXX>, the tab stays", "[support]") {
  CHECK(printable(std::string("a\nb\x1b]0;x\x07\t\0c\r\x7f", 14)) ==
        "a<U+000A>b<U+001B>]0;x<U+0007>\t<U+0000>c<U+000D><U+007F>");
  CHECK(printable("line one\nline two", true) == "line one\nline two");  // a message's own lines
  CHECK(printable("plain text, 'quoted' \"too\" \\ ~") == "plain text, 'quoted' \"too\" \\ ~");
  CHECK(printable("") == "");
}

TEST_CASE("escape: UTF-8 stays but for C1 controls and bidirectional marks, other bytes as <xx>", "[support]") {
  // é and € stay; CSI (U+009B) and RIGHT-TO-LEFT OVERRIDE (U+202E) are escaped.
  CHECK(printable("\xc3\xa9\xe2\x82\xac\xc2\x9b\xe2\x80\xae") == "\xc3\xa9\xe2\x82\xac<U+009B><U+202E>");
  CHECK(printable("\xd8\x9c\xe2\x80\x8e\xe2\x81\xa6\xe2\x81\xa9") == "<U+061C><U+200E><U+2066><U+2069>");
  // A stray byte, a sequence cut short, an overlong form, a surrogate: each byte on its own.
  CHECK(printable("\xff") == "<ff>");
  CHECK(printable("a\xe2\x82") == "a<e2><82>");
  CHECK(printable("\xc0\xaf") == "<c0><af>");
  CHECK(printable("\xed\xa0\x80") == "<ed><a0><80>");
  CHECK(printable("\xf0\x9f\x98\x80") == "\xf0\x9f\x98\x80");  // a character past U+FFFF stays
}

TEST_CASE("escape: one character at a time, with its length in bytes", "[support]") {
  const std::string s = "a\xc3\xa9\x1b\xff";
  auto a = shown_at(s, 0), e = shown_at(s, 1), esc = shown_at(s, 3), stray = shown_at(s, 4);
  CHECK((a.length == 1 && a.text == "a" && !a.escaped));
  CHECK((e.length == 2 && e.text == "\xc3\xa9" && !e.escaped));
  CHECK((esc.length == 1 && esc.text == "<U+001B>" && esc.escaped));
  CHECK((stray.length == 1 && stray.text == "<ff>" && stray.escaped));
  CHECK(shown_at("\n", 0).text == "<U+000A>");
  CHECK(shown_at("\n", 0, true).text == "\n");
}
