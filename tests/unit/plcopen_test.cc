// The PLCopen reader's pieces that the CLI test (tests/cli/plcopen.sh) cannot see alone: texts of
// the XML located offset for offset through entities, CDATA and markup; attribute values
// located; TIME literals; which .xml files are PLCopen's; and the IEC program model the reader
// fills before any lowering (SFC bodies of actions and function blocks).
#include "plcopen/iec_duration.h"
#include "plcopen/plcopen_reader.h"
#include "plcopen/reader_context.h"
#include "plcopen/xml_text.h"
#include "support.h"

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

/// The IEC program model the reader fills from tests/iec/plcopen/NAME, as the lowering receives it.
struct ReadSample {
  std::string text;
  pugi::xml_document doc;
  ast::File file;
  Diagnostics diag;
  iec::Project project;
  explicit ReadSample(const std::string &name)
      : text(gfec::test::read_file(std::string(GFEC_SOURCE_DIR) + "/tests/iec/plcopen/" + name)) {
    REQUIRE(doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8));
    XmlFile xml(0, text);
    Reader reader(xml, file, diag);
    project = reader.read_project(doc.document_element());
  }
  const iec::Pou &pou(std::string_view name) const {
    for (const iec::Pou &p : project.pous)
      if (p.name.text == name) return p;
    FAIL("no POU " << name);
    throw;
  }
};

std::vector<std::string> names_of(const std::vector<iec::Step> &steps) {
  std::vector<std::string> out;
  for (const iec::Step &s : steps) out.emplace_back(s.name.text);
  return out;
}
std::vector<std::string> names_of(const std::vector<iec::Action> &actions) {
  std::vector<std::string> out;
  for (const iec::Action &a : actions) out.emplace_back(a.name.text);
  return out;
}
std::vector<std::string> names_of(const std::vector<ast::Name> &names) {
  std::vector<std::string> out;
  for (const ast::Name &n : names) out.emplace_back(n.text);
  return out;
}
using Names = std::vector<std::string>;

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

TEST_CASE("plcopen: an action whose body is an SFC holds its steps and transitions", "[plcopen]") {
  ReadSample r("sfc_action.xml");
  CHECK_FALSE(r.diag.has_errors());
  const iec::Pou &feeder = r.pou("Feeder");
  // The program's own SFC, as before.
  CHECK(names_of(feeder.steps) == Names{"Idle", "Run"});
  REQUIRE(feeder.transitions.size() == 2);
  // Named actions first (Seq, and Show whose body is LD), then the inline action of Seq's step
  // Take, numbered over the POU.
  CHECK(names_of(feeder.actions) == Names{"Seq", "Show", "Take_inline1"});
  const iec::Action &seq = feeder.actions[0];
  CHECK(seq.sfc());
  CHECK(seq.body.empty());
  CHECK(names_of(seq.steps) == Names{"Wait", "Take"});
  CHECK(seq.steps[0].initial);
  CHECK_FALSE(seq.steps[1].initial);
  REQUIRE(seq.transitions.size() == 2);
  CHECK(names_of(seq.transitions[0].from) == Names{"Wait"});
  CHECK(names_of(seq.transitions[0].to) == Names{"Take"});
  CHECK(names_of(seq.transitions[1].from) == Names{"Take"});
  CHECK(names_of(seq.transitions[1].to) == Names{"Wait"});
  CHECK(seq.transitions[0].condition);
  REQUIRE(seq.steps[1].associations.size() == 1);
  CHECK(seq.steps[1].associations[0].qualifier.text == "N");
  CHECK(seq.steps[1].associations[0].action.text == "Take_inline1");
  CHECK(feeder.actions[1].body.size() == 1);  // the LD rung, read as `Busy := Go;`
  CHECK_FALSE(feeder.actions[1].sfc());
  CHECK(feeder.actions[2].body.size() == 1);
  CHECK_FALSE(feeder.actions[2].sfc());
  // The program's step Run holds Seq and Show.
  REQUIRE(feeder.steps[1].associations.size() == 2);
  CHECK(feeder.steps[1].associations[0].action.text == "Seq");
  CHECK(feeder.steps[1].associations[1].action.text == "Show");
}

TEST_CASE("plcopen: a function block whose body is an SFC is read as an SFC program is", "[plcopen]") {
  ReadSample r("sfc_fb.xml");
  CHECK_FALSE(r.diag.has_errors());
  const iec::Pou &light = r.pou("TrafficLight");
  CHECK(light.kind == iec::PouKind::FunctionBlock);
  CHECK_FALSE(light.body);
  CHECK(light.variables.size() == 4);
  CHECK(names_of(light.steps) == Names{"Stop", "Pass", "Caution"});
  CHECK(light.steps[0].initial);
  REQUIRE(light.transitions.size() == 3);
  CHECK(names_of(light.transitions[1].from) == Names{"Pass"});
  CHECK(names_of(light.transitions[1].to) == Names{"Caution"});
  CHECK(names_of(light.transitions[2].to) == Names{"Stop"});  // the jump
  // The named transition Asked, an FBD network, gives its output variable's value: Request.
  REQUIRE(light.transitions[0].condition);
  CHECK(light.transitions[0].condition->kind == ast::Expr::Kind::Name);
  CHECK(light.transitions[0].condition->name.text == "Request");
  CHECK(names_of(light.actions) == Names{"Stop_inline1", "Pass_inline2", "Caution_inline3"});
  for (const iec::Step &s : light.steps) CHECK(s.associations.size() == 1);
  // The program calling it has its ST body.
  const iec::Pou &crossing = r.pou("Crossing");
  CHECK(crossing.kind == iec::PouKind::Program);
  REQUIRE(crossing.body);
  CHECK(crossing.body->size() == 4);
}
