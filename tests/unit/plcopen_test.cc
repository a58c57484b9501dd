// The PLCopen reader's pieces that the CLI test (tests/cli/plcopen.sh) cannot see alone: texts of
// the XML located offset for offset through entities, CDATA and markup; attribute values
// located; TIME literals; and which .xml files are PLCopen's.
#include "plcopen/iec_duration.h"
#include "plcopen/plcopen_reader.h"
#include "plcopen/xml_text.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;
using namespace gfec::plcopen;

namespace {

struct Parsed {
  std::string text;
  pugi::xml_document doc;
  explicit Parsed(std::string t) : text(std::move(t)) {
    REQUIRE(doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8));
  }
};

/// The file offset of the `n`th occurrence (0-based) of `what` in `text`.
std::uint32_t offset_of(const std::string &text, const std::string &what, int n = 0) {
  std::size_t at = text.find(what);
  while (n-- > 0) at = text.find(what, at + 1);
  REQUIRE(at != std::string::npos);
  return static_cast<std::uint32_t>(at);
}

}  // namespace

TEST_CASE("plcopen: an ST text with entities maps every character back to the file", "[plcopen]") {
  Parsed p("<ST>\n  <xhtml:p>Level &lt;= 80 AND Mode &lt;&gt; 2 &amp; Go</xhtml:p>\n</ST>");
  XmlFile xml(0, p.text);
  LocatedText t = xml.text_below(p.doc.child("ST"));
  REQUIRE(t.text == "Level <= 80 AND Mode <> 2 & Go");
  for (const char *word : {"Level", "80", "Mode", "2 ", "Go"})
    CHECK(t.file_offset(static_cast<std::uint32_t>(t.text.find(word))) == offset_of(p.text, word));
  // The decoded operators stand where their entities begin.
  CHECK(t.file_offset(static_cast<std::uint32_t>(t.text.find("<="))) == offset_of(p.text, "&lt;="));
  CHECK(t.file_offset(static_cast<std::uint32_t>(t.text.find("<>"))) == offset_of(p.text, "&lt;&gt;"));
}

TEST_CASE("plcopen: CDATA and markup between texts keep their places, and separate tokens", "[plcopen]") {
  Parsed p("<ST><xhtml:p><![CDATA[x := a < 1;]]></xhtml:p><xhtml:p>y := b &gt; 2;</xhtml:p></ST>");
  XmlFile xml(0, p.text);
  LocatedText t = xml.text_below(p.doc.child("ST"));
  REQUIRE(t.text == "x := a < 1;\ny := b > 2;");
  CHECK(t.file_offset(static_cast<std::uint32_t>(t.text.find('x'))) == offset_of(p.text, "x :="));
  CHECK(t.file_offset(static_cast<std::uint32_t>(t.text.find('<'))) == offset_of(p.text, "< 1"));
  CHECK(t.file_offset(static_cast<std::uint32_t>(t.text.find('y'))) == offset_of(p.text, "y :="));
  CHECK(t.file_offset(static_cast<std::uint32_t>(t.text.find('2'))) == offset_of(p.text, "2;"));
}

TEST_CASE("plcopen: an attribute's value is located between its quotes", "[plcopen]") {
  Parsed p("<connection  formalParameter = 'x'\n   refLocalId=\"12\"/>");
  XmlFile xml(3, p.text);
  pugi::xml_node c = p.doc.child("connection");
  SourceRange r = xml.attribute_range(c, "refLocalId");
  CHECK(r.file == 3);
  CHECK(p.text.substr(r.begin, r.end - r.begin) == "12");
  r = xml.attribute_range(c, "formalParameter");
  CHECK(p.text.substr(r.begin, r.end - r.begin) == "x");
  // Not written: the element's tag.
  r = xml.attribute_range(c, "negated");
  CHECK(p.text.substr(r.begin, r.end - r.begin) == "<connection");
  LocatedText v = xml.attribute_text(c, "refLocalId");
  CHECK(v.text == "12");
  CHECK(v.file_offset(0) == offset_of(p.text, "12"));
}

TEST_CASE("plcopen: TIME literals and XML durations", "[plcopen]") {
  CHECK(duration_ms("T#2s") == 2000);
  CHECK(duration_ms("TIME#1m30s") == 90000);
  CHECK(duration_ms("t#1.5s") == 1500);
  CHECK(duration_ms("T#2s_500ms") == 2500);
  CHECK(duration_ms("T#1h") == 3600000);
  CHECK(duration_ms("PT0.01S") == 10);
  CHECK(duration_ms("PT1M") == 60000);
  CHECK_FALSE(duration_ms("2 seconds"));
  CHECK_FALSE(duration_ms("T#"));
  CHECK_FALSE(duration_ms("T#5x"));
  CHECK_FALSE(duration_ms("P1Y"));
}

TEST_CASE("plcopen: every XML document of a .xml file goes to the PLCopen reader", "[plcopen]") {
  CHECK(is_xml_document(
      "<?xml version=\"1.0\"?>\n<!-- export -->\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">"));
  CHECK(is_xml_document("\xEF\xBB\xBF<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\"/>"));
  CHECK(is_xml_document(" \r\n<ppx:project xmlns:ppx=\"http://www.plcopen.org/xml/tc6.xsd\">"));
  CHECK(is_xml_document("\xFF\xFE<\0p\0"));
  // Not PLCopen, but XML: the reader names the root or the namespace (tests/cli/plcopen.sh).
  CHECK(is_xml_document("<?xml version=\"1.0\"?><project xmlns=\"http://maven.apache.org/POM/4.0.0\">"));
  CHECK(is_xml_document("<BeremizRoot URI_location=\"LOCAL://\"/>"));
  CHECK_FALSE(is_xml_document("sfc Blink { initial place A; when a < b }"));
  CHECK_FALSE(is_xml_document("// <project>\nsfc A { initial place a; }"));
  CHECK_FALSE(is_xml_document(""));
}
