// JSON and SARIF diagnostics in-process: columns, ranges, notes and rules. (The files gfec
// prints are checked against the SARIF schema by sarif.test.js.)
#include "diagnostics_json.h"
#include "diagnostics_sarif.h"
#include "diagnostic_printer.h"
#include "input_languages.h"
#include "../unit/support.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>
#include <utility>

using namespace gfec;
using Json = nlohmann::ordered_json;

namespace {

MemoryFileSystem adding(MemoryFileSystem fs, const std::string &name, const std::string &text) {
  fs.add(name, text);
  return fs;
}

/// `name` holding `text`, beside the files of `fs`, through the front end: the loader's or the
/// validator's diagnostics.
struct FrontEnd : test::Pipeline {
  FrontEnd(const std::string &name, const std::string &text, WarningOptions w = {}, MemoryFileSystem fs = {})
      : Pipeline(name, adding(std::move(fs), name, text), w) {}
};

}  // namespace

TEST_CASE("columns: bytes for gcc's byte-column, code points for SARIF, tabs to 8 for display") {
  SourceFile f("t.sfc", "\tplace A;\n// \xC3\xA9t\xC3\xA9 X\n", chart_text_language());
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
  FrontEnd r("t.sfc", "sfc T {\n  initial place A\n}\n");
  REQUIRE(r.diag.all().size() >= 1);
  const Diagnostic &d = r.diag.all().front();
  Json j = diagnostic_to_json(d, r.sources);
  CHECK(j["kind"] == "error");
  CHECK(j["message"] == d.message);
  CHECK(j["check"] == d.check());
  CHECK_FALSE(j.contains("option"));
  const Json &caret = j["locations"][0]["caret"];
  CHECK(caret["file"] == "t.sfc");
  LineCol at = r.sources.begin_of(d.range);
  CHECK(caret["line"] == at.line);
  CHECK(caret["byte-column"] == at.col);
}

TEST_CASE("sarif: a result per diagnostic, notes as related locations, rules for every check") {
  FrontEnd r("dir/t.sfc", "sfc T {\n  initial place A\n}\n");
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
  // Every row of the table of kinds is a rule, in the table's order, fired or not.
  REQUIRE(rules.size() == diagnostic_kind_count());
  CHECK(rules[static_cast<std::size_t>(ErrorKind::Syntax)]["id"] == "syntax");
  CHECK(rules[static_cast<std::size_t>(ErrorKind::Count_)]["id"] == "-Wunreachable-place");
  const Json &result = run["results"][0];
  CHECK(result["ruleId"] == d.check());
  CHECK(rules[result["ruleIndex"].get<std::size_t>()]["id"] == d.check());
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

namespace {

// A misspelt place: did-you-mean knows the fix, so the error carries a fix-it.
const char *kTypo = "sfc T {\n  initial place Start;\n  place Stopped;\n"
                    "  transition Start -> Stoped when true;\n  transition Stopped -> Start when true;\n}\n";

}  // namespace

TEST_CASE("text diagnostics: gcc 12's gutter, the fix-it under the caret, parseable fix-its") {
  FrontEnd r("t.sfc", kTypo);
  REQUIRE(r.diag.all().size() == 1);
  const Diagnostic &d = r.diag.all().front();
  REQUIRE(d.fixits.size() == 1);
  CHECK(d.fixits[0].replacement == "Stopped");

  TextStyle gcc12;
  gcc12.line_numbers = true;
  gcc12.fixits = true;
  gcc12.parseable_fixits = true;
  CHECK(render_text(d, r.sources, gcc12) == "t.sfc:4:23: error: unknown place 'Stoped' [unknown-name]\n"
                                            "    4 |   transition Start -> Stoped when true;\n"
                                            "      |                       ^~~~~~\n"
                                            "      |                       Stopped\n"
                                            "fix-it:\"t.sfc\":{4:23-4:29}:\"Stopped\"\n"
                                            "t.sfc:3:9: note: did you mean 'Stopped'?\n"
                                            "    3 |   place Stopped;\n"
                                            "      |         ^~~~~~~\n");
  // The default (what the unit tests compare) has no gutter and no fix-it lines.
  CHECK(render_text(d, r.sources)
            .rfind("t.sfc:4:23: error: unknown place 'Stoped' [unknown-name]\n"
                   "   transition Start -> Stoped when true;\n",
                   0) == 0);
}

TEST_CASE("text diagnostics: a long line is quoted around the range, the caret under it") {
  // A chart on one line, as a generator writes it (or an ALICA plan saved as minified JSON): a
  // thousand places before the typo and after it. Each diagnostic quoted the whole line, so a
  // file of one long line with many diagnostics printed their product.
  std::string before, after;
  for (int i = 0; i < 1000; ++i) before += "place P" + std::to_string(i) + "; ";
  for (int i = 0; i < 1000; ++i) after += "place Q" + std::to_string(i) + "; ";
  std::string text = "sfc T { initial place Start; place Stopped; " + before +
                     "transition Start -> Stoped when true; transition Stopped -> Start when true; " + after + "}\n";
  FrontEnd r("t.sfc", text);
  REQUIRE(!r.diag.all().empty());
  const Diagnostic &d = r.diag.all().front();
  REQUIRE(d.fixits.size() == 1);
  TextStyle style;
  style.fixits = true;
  std::string shown = render_text(d, r.sources, style);
  INFO(shown);
  CHECK(shown.size() < 600);
  std::size_t line = shown.find('\n') + 1;
  std::size_t caret_line = shown.find('\n', line) + 1;
  std::string quoted = shown.substr(line, caret_line - line - 1);
  std::string carets = shown.substr(caret_line, shown.find('\n', caret_line) - caret_line);
  CHECK(quoted.rfind(" ...", 0) == 0);
  CHECK(quoted.size() > 3);
  CHECK(quoted.compare(quoted.size() - 3, 3, "...") == 0);
  // The caret is under 'Stoped', and the fix-it's text under the caret.
  std::size_t caret = carets.find('^');
  REQUIRE(caret != std::string::npos);
  CHECK(quoted.compare(caret, 6, "Stoped") == 0);
  CHECK(carets.substr(caret) == "^~~~~~");
  CHECK(shown.find(std::string(caret, ' ') + "Stopped\n") != std::string::npos);
  // A short line is quoted whole, as before.
  FrontEnd s("t.sfc", kTypo);
  CHECK(render_text(s.diag.all().front(), s.sources).find("...") == std::string::npos);
}

TEST_CASE("text diagnostics: colours as gcc's defaults, only when asked") {
  FrontEnd r("t.sfc", kTypo);
  TextStyle colour;
  colour.color = true;
  std::string text = render_text(r.diag.all().front(), r.sources, colour);
  CHECK(text.find("\33[01m\33[Kt.sfc:4:23:\33[m\33[K \33[01;31m\33[Kerror:\33[m\33[K unknown place") == 0);
  CHECK(text.find("\33[32m\33[K^~~~~~\33[m\33[K") != std::string::npos);
  CHECK(text.find("\33[01;36m\33[Knote:\33[m\33[K") != std::string::npos);
  CHECK(render_text(r.diag.all().front(), r.sources).find('\33') == std::string::npos);
}

TEST_CASE("text diagnostics: -Werror's label is gcc's [-Werror=NAME], the check stays the rule") {
  WarningOptions w;
  w.error_override[static_cast<int>(Warning::UnreachablePlace)] = 1;
  FrontEnd r("t.sfc", "sfc T {\n  initial place A;\n  place B;\n}\n", w);
  REQUIRE(r.diag.all().size() == 1);
  CHECK(r.diag.all()[0].severity == Severity::Error);
  CHECK(render_text(r.diag.all()[0], r.sources).find("never become active [-Werror=unreachable-place]\n") !=
        std::string::npos);
  Diagnostic d;
  d.severity = Severity::Error;
  d.kind = &kind_info(Warning::UnreachablePlace);
  CHECK(check_label(d) == "-Werror=unreachable-place");
  d.severity = Severity::Warning;
  CHECK(check_label(d) == "-Wunreachable-place");
  Diagnostics strict(w);
  strict.warning(Warning::UnreachablePlace, {}, "x");
  strict.warning(Warning::DeadTransition, {}, "y");
  REQUIRE(strict.all().size() == 2);
  CHECK(strict.all()[0].severity == Severity::Error);
  CHECK(strict.all()[1].severity == Severity::Warning);
}

TEST_CASE("json and sarif diagnostics: the fix-it as gcc's fixits and SARIF's fixes") {
  FrontEnd r("t.sfc", kTypo);
  const Diagnostic &d = r.diag.all().front();
  Json j = diagnostic_to_json(d, r.sources);
  REQUIRE(j["fixits"].size() == 1);
  CHECK(j["fixits"][0]["string"] == "Stopped");
  CHECK(j["fixits"][0]["start"]["line"] == 4);
  CHECK(j["fixits"][0]["start"]["byte-column"] == 23);
  CHECK(j["fixits"][0]["next"]["byte-column"] == 29);

  SarifLog log;
  log.add(r.diag, r.sources);
  Json result = log.to_json(1, "/w")["runs"][0]["results"][0];
  REQUIRE(result["fixes"].size() == 1);
  const Json &change = result["fixes"][0]["artifactChanges"][0];
  CHECK(change["artifactLocation"]["uri"] == "t.sfc");
  const Json &rep = change["replacements"][0];
  CHECK(rep["insertedContent"]["text"] == "Stopped");
  CHECK(rep["deletedRegion"]["startLine"] == 4);
  CHECK(rep["deletedRegion"]["startColumn"] == 23);
  CHECK(rep["deletedRegion"]["endColumn"] == 29);
}

TEST_CASE("the error limit in gcc's words, singular or plural alike") {
  Diagnostics one(WarningOptions{}, 1);
  one.error({}, ErrorKind::Syntax, "a");
  one.error({}, ErrorKind::Syntax, "b");
  CHECK(one.limit_reached());
  CHECK(limit_message(one) == "compilation terminated due to -fmax-errors=1.");
}

namespace {

/// The first diagnostic of a chart, rendered with its fix-its as gcc's parseable lines.
std::string first_error(const std::string &text, MemoryFileSystem fs = {}) {
  FrontEnd r("t.sfc", text, {}, std::move(fs));
  if (r.diag.all().empty()) return "(no diagnostic)";
  TextStyle style;
  style.fixits = true;
  style.parseable_fixits = true;
  return render_text(r.diag.all().front(), r.sources, style);
}

}  // namespace

TEST_CASE("beginner hints: a fork or join without brackets says to write (B, C)") {
  std::string fork = first_error("sfc T {\n  initial place A;\n  place B;\n  place C;\n  A -> B, C;\n}\n");
  CHECK(fork.rfind("t.sfc:5:9: error: expected ';' after the transition, found ',' [syntax]\n", 0) == 0);
  CHECK(fork.find("note: a transition to several places is a fork: write them in brackets, 'A -> (B, ...)'") !=
        std::string::npos);
  std::string join = first_error("sfc T {\n  initial place A;\n  place B;\n  place C;\n  transition A, B -> C;\n}\n");
  CHECK(join.rfind("t.sfc:5:15: error: expected '->' between a transition's inputs and outputs, found ','", 0) == 0);
  CHECK(join.find("is a join: write them in brackets, '(A, ...) -> ...'") != std::string::npos);
}

TEST_CASE("beginner hints: '2 s' is written '2s', with the fix") {
  std::string e = first_error("interface R { void Go(); }\nsfc T {\n  initial place A { Go(); }\n  place B;\n"
                              "  A -> B when elapsed(A) >= 2 s;\n  B -> A;\n}\n");
  CHECK(e.rfind("t.sfc:5:31: error: expected an operator after the number, found 's' [syntax]\n", 0) == 0);
  CHECK(e.find("fix-it:\"t.sfc\":{5:29-5:32}:\"2s\"\n") != std::string::npos);
  CHECK(e.find("note: durations are written without a space: '2s'") != std::string::npos);
  CHECK(first_error("sfc T {\n  initial place A;\n  A -> A when elapsed(A) >= 1.5 ms;\n}\n").find("'1.5ms'") !=
        std::string::npos);
}

TEST_CASE("beginner hints: '=' in a condition means '=='") {
  std::string e = first_error("interface R { bool Button(); }\nsfc T {\n  initial place A;\n  place B;\n"
                              "  A -> B when Button() = true;\n  B -> A;\n}\n");
  CHECK(e.rfind("t.sfc:5:24: error: expected an operator, found '=' [syntax]\n", 0) == 0);
  CHECK(e.find("fix-it:\"t.sfc\":{5:24-5:25}:\"==\"\n") != std::string::npos);
  CHECK(e.find("note: '=' assigns; to compare, write '=='") != std::string::npos);
}

TEST_CASE("did-you-mean for imports: the nearest file name in the folders searched") {
  MemoryFileSystem fs;
  fs.add("crossing.iface", "interface C { void Go(); }\n");
  fs.add("other.fsm", "");
  std::string e = first_error("import \"crosing.iface\";\nsfc T { initial place A; }\n", fs);
  CHECK(e.find("cannot find imported file 'crosing.iface'") != std::string::npos);
  CHECK(e.find("note: did you mean 'crossing.iface'?") != std::string::npos);
  CHECK(e.find("fix-it:\"t.sfc\":{1:8-1:23}:\"\\\"crossing.iface\\\"\"") != std::string::npos);
  // Nothing near: no suggestion.
  CHECK(first_error("import \"zzz.iface\";\nsfc T { initial place A; }\n", fs).find("did you mean") ==
        std::string::npos);
}

TEST_CASE("the table of diagnostic kinds: every kind named once, described, with help, and documented") {
  REQUIRE(diagnostic_kind_count() ==
          static_cast<std::size_t>(ErrorKind::Count_) + static_cast<std::size_t>(Warning::Count_));
  std::ifstream doc_file(std::string(GFEC_SOURCE_DIR) + "/docs/diagnostics.md");
  REQUIRE(doc_file);
  std::string doc((std::istreambuf_iterator<char>(doc_file)), std::istreambuf_iterator<char>());
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < diagnostic_kind_count(); ++i) {
    const DiagnosticKind &k = diagnostic_kinds()[i];
    INFO(k.name);
    CHECK(names.insert(k.name).second);  // one name, one kind: no spelling twice
    // Stable names are lower-case words joined by '-', as gcc's warnings.
    CHECK(std::regex_match(std::string(k.name), std::regex("[a-z]+(-[a-z]+)*")));
    CHECK(k.summary.size() > 10);
    CHECK(k.help.size() > 10);
    CHECK(k.warning == (i >= static_cast<std::size_t>(ErrorKind::Count_)));
    CHECK(doc.find("| `" + k.check() + "` |") != std::string::npos);
  }
  // The spelling kept where two existed for one concept.
  CHECK(find_kind("not-connected") != nullptr);
  CHECK(find_kind("unconnected") == nullptr);
  CHECK(kind_info(ErrorKind::NotConnected).check() == "not-connected");
  CHECK(kind_info(Warning::DeadJoin).check() == "-Wdead-join");
  CHECK(find_warning("dead-join") == Warning::DeadJoin);
  CHECK_FALSE(find_warning("syntax"));
}

TEST_CASE("sarif rules: every kind is a rule with its summary, help and default level") {
  const Json log = SarifLog().to_json(0, "/w");
  const Json &rules = log["runs"][0]["tool"]["driver"]["rules"];
  REQUIRE(rules.size() == diagnostic_kind_count());
  const Json &syntax = rules[static_cast<std::size_t>(ErrorKind::Syntax)];
  CHECK(syntax["id"] == "syntax");
  CHECK(syntax["shortDescription"]["text"] == std::string(kind_info(ErrorKind::Syntax).summary));
  CHECK(syntax["help"]["text"] == std::string(kind_info(ErrorKind::Syntax).help));
  CHECK(syntax["defaultConfiguration"]["level"] == "error");
  const Json &conflict =
      rules[static_cast<std::size_t>(ErrorKind::Count_) + static_cast<std::size_t>(Warning::Conflict)];
  CHECK(conflict["id"] == "-Wconflict");
  CHECK(conflict["defaultConfiguration"]["level"] == "warning");
  CHECK(conflict["defaultConfiguration"]["enabled"] == false);
}

TEST_CASE("diagnostics are reported in source order: by file as loaded, then by position") {
  Diagnostics diag;
  diag.error({0, 40, 41}, ErrorKind::Syntax, "third");
  diag.error({1, 0, 1}, ErrorKind::Import, "fifth: another file");
  diag.error({0, 5, 6}, ErrorKind::UnknownName, "first");
  diag.warning(Warning::UnreachablePlace, {0, 20, 21}, "second");
  diag.error({0, 40, 42}, ErrorKind::TypeMismatch, "fourth: same place, found later");
  std::vector<std::string> order;
  for (const Diagnostic *d : in_source_order(diag)) order.push_back(d->message);
  CHECK(order ==
        std::vector<std::string>{"first", "second", "third", "fourth: same place, found later", "fifth: another file"});
}

TEST_CASE(
    "text diagnostics: control characters and bytes that are no UTF-8 are printed escaped, the caret on its column") {
  // Before the error, in a comment: ESC (a terminal's escape sequence), DEL, a byte that is no
  // UTF-8, a C1 control (CSI) and a right-to-left override; then an é, printed as it is.
  const std::string line = "  transition Start -> /*\x1b[2J\x7f\xff\xc2\x9b\xe2\x80\xae\xc3\xa9*/ Stoped when true;";
  FrontEnd r("t\x1b.sfc", std::string("sfc T {\n  initial place Start;\n  place Stopped;\n") + line +
                              "\n  transition Stopped -> Start when true;\n}\n");
  REQUIRE(r.diag.all().size() == 1);
  TextStyle gcc12;
  gcc12.line_numbers = true;
  gcc12.fixits = true;
  const std::string out = render_text(r.diag.all().front(), r.sources, gcc12);
  INFO(out);
  // Nothing a terminal obeys: no control character but the newlines, no byte that is no UTF-8,
  // no C1 control or override.
  for (unsigned char ch : out) CHECK((ch == '\n' || (ch >= 0x20 && ch != 0x7f && ch != 0xff)));
  CHECK(out.find("\xc2\x9b") == std::string::npos);
  CHECK(out.find("\xe2\x80\xae") == std::string::npos);
  // As gcc escapes them, the file name too.
  CHECK(out.rfind("t<U+001B>.sfc:4:", 0) == 0);
  CHECK(out.find("/*<U+001B>[2J<U+007F><ff><U+009B><U+202E>\xc3\xa9*/ Stoped") != std::string::npos);
  // The caret and the fix-it stand under the S of Stoped as printed, a column a character.
  std::vector<std::string> lines;
  std::istringstream in(out);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  REQUIRE(lines.size() >= 4);
  const std::string &quoted = lines[1];
  std::size_t column = 0;  // in characters: é is two bytes and one column
  for (std::size_t i = 0; i < quoted.find(" Stoped") + 1; ++i)
    if ((static_cast<unsigned char>(quoted[i]) & 0xC0) != 0x80) ++column;
  CHECK(lines[2].find('^') == column);
  CHECK(lines[2].substr(column) == "^~~~~~");
  CHECK(lines[3].find("Stopped") == column);
  // The parseable fix-it writes the file name's bytes in octal, as gcc does.
  gcc12.parseable_fixits = true;
  CHECK(render_text(r.diag.all().front(), r.sources, gcc12).find("fix-it:\"t\\033.sfc\":{4:") != std::string::npos);
}

TEST_CASE("text diagnostics: a control character the lexer quotes is escaped in the message too") {
  FrontEnd r("t.sfc", "sfc T {\n  initial place A;\n  place B \xc2\x9b;\n}\n");
  REQUIRE(!r.diag.all().empty());
  const std::string out = render_text(r.diag.all().front(), r.sources);
  INFO(out);
  CHECK(out.find("unexpected character '<U+009B>'") != std::string::npos);
  CHECK(out.find("\xc2\x9b") == std::string::npos);
}
