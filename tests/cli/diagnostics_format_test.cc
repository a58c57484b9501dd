// JSON and SARIF diagnostics in-process: columns, ranges, notes and rules. (The files gfec
// prints are checked against the SARIF schema by sarif.test.js.)
#include "diagnostics_json.h"
#include "diagnostics_sarif.h"
#include "loader.h"

#include <catch2/catch.hpp>

using namespace gfec;
using Json = nlohmann::ordered_json;

namespace {

/// The front end's diagnostics for one in-memory file.
struct Run {
  SourceManager sources;
  Diagnostics diag;
  Run(const std::string &name, const std::string &text) {
    MemoryFileSystem fs;
    fs.add(name, text);
    load_program(name, {}, fs, sources, diag);
  }
};

} // namespace

TEST_CASE("columns: bytes for gcc's byte-column, code points for SARIF, tabs to 8 for display") {
  SourceFile f("t.sfc", "\tplace A;\n// \xC3\xA9t\xC3\xA9 X\n");
  Columns tab = columns_at(f, 1);  // 'p' after the tab
  CHECK(tab.line == 1);
  CHECK(tab.byte == 2);
  CHECK(tab.code_point == 2);
  CHECK(tab.display == 9);
  Columns utf8 = columns_at(f, 10 + 3 + 5);  // 'X' after "// été "
  CHECK(utf8.line == 2);
  CHECK(utf8.byte == 9);
  CHECK(utf8.code_point == 7);
  CHECK(utf8.display == 7);
}

TEST_CASE("json diagnostics: a syntax error as gcc writes it") {
  Run r("t.sfc", "sfc T {\n  initial place A\n}\n");
  REQUIRE(r.diag.all().size() >= 1);
  const Diagnostic &d = r.diag.all().front();
  Json j = diagnostic_to_json(d, r.sources);
  CHECK(j["kind"] == "error");
  CHECK(j["message"] == d.message);
  CHECK(j["check"] == d.check);
  CHECK_FALSE(j.contains("option"));
  const Json &caret = j["locations"][0]["caret"];
  CHECK(caret["file"] == "t.sfc");
  LineCol at = r.sources.begin_of(d.range);
  CHECK(caret["line"] == at.line);
  CHECK(caret["byte-column"] == at.col);
}

TEST_CASE("sarif: a result per diagnostic, notes as related locations, rules for every check") {
  Run r("dir/t.sfc", "sfc T {\n  initial place A\n}\n");
  REQUIRE_FALSE(r.diag.all().empty());
  Diagnostic &d = const_cast<Diagnostic &>(r.diag.all().front());
  d.note(d.range, "a note at the same place");
  SarifLog log;
  log.add(r.diag, r.sources);
  Json j = log.to_json(1, "/work/my project");
  CHECK(j["version"] == "2.1.0");
  const Json &run = j["runs"][0];
  CHECK(run["originalUriBaseIds"]["%SRCROOT%"]["uri"] == "file:///work/my%20project/");
  const Json &rules = run["tool"]["driver"]["rules"];
  // Every warning of the table is a rule, and so is each error check that occurred.
  CHECK(rules[0]["id"] == "-Wunreachable-place");
  const Json &result = run["results"][0];
  CHECK(result["ruleId"] == d.check);
  CHECK(rules[result["ruleIndex"].get<std::size_t>()]["id"] == d.check);
  CHECK(result["level"] == "error");
  const Json &loc = result["locations"][0]["physicalLocation"];
  CHECK(loc["artifactLocation"]["uri"] == "dir/t.sfc");
  CHECK(loc["artifactLocation"]["uriBaseId"] == "%SRCROOT%");
  CHECK(loc["region"]["startLine"] == r.sources.begin_of(d.range).line);
  CHECK(loc["region"]["endColumn"] == r.sources.end_of(d.range).col);
  CHECK(result["relatedLocations"][0]["message"]["text"] == "a note at the same place");
  CHECK(run["invocations"][0]["executionSuccessful"] == true);
  CHECK(log.to_json(2, "/")["runs"][0]["invocations"][0]["executionSuccessful"] == false);
}

TEST_CASE("sarif: paths become URIs") {
  CHECK(artifact_location("charts/a b.sfc")["uri"] == "charts/a%20b.sfc");
  CHECK(artifact_location("/abs/x.sfc") == Json{{"uri", "file:///abs/x.sfc"}});
}
