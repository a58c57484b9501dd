// The language server's features as pure functions (lsp/features/): positions, semantic
// tokens, folding, completion's context and names, fix-its as code actions, code lenses and the
// chart picture's elements. The protocol around them is tested by tests/lsp/ with real clients.
#include "chart_picture.h"
#include "child_process.h"
#include "code_actions.h"
#include "code_lenses.h"
#include "completion.h"
#include "folding_ranges.h"
#include "semantic_tokens.h"
#include "server.h"
#include "transport.h"
#include "positions.h"
#include "text_index.h"

#include "pipeline/compilation.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace gfec;
using namespace gfec::lsp;
using nlohmann::json;

namespace {

const char *const kChart = R"(// A chart
// over two lines
import "bot.iface";
import "more.iface";

sfc Line {
  period 10ms;
  var int laps = 0;
  initial place Go { Forward(); }
  place Stop { laps += 1; }
  transition Go -> Stop when Black() && laps < 3;
  Stop -> Go when elapsed(Stop) > 1s;
}
)";

const char *const kIface = "interface Bot {\n  bool Black();\n  void Forward();\n  int Count();\n}\n";

/// The offset just after the first `marker` in `text`.
std::uint32_t after(std::string_view text, std::string_view marker) {
  return static_cast<std::uint32_t>(text.find(marker) + marker.size());
}

std::vector<std::string> labels(const json &completion) {
  std::vector<std::string> out;
  for (const json &item : completion["items"]) out.push_back(item["label"]);
  return out;
}

bool contains(const std::vector<std::string> &v, const std::string &s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

/// Graphviz's dot run as the driver runs it: input and output through files.
std::string run_tool(const ExternalTool &tool, const std::string &input) {
  char in_name[] = "/tmp/gfec-lsp-test-in-XXXXXX", out_name[] = "/tmp/gfec-lsp-test-out-XXXXXX";
  ::close(::mkstemp(in_name));
  ::close(::mkstemp(out_name));
  std::ofstream(in_name) << input;
  child_process::Spawn s;
  s.argv = tool.command;
  s.stdin_path = in_name;
  s.stdout_path = out_name;
  s.time_limit = 60;
  child_process::Result r = child_process::run(s);
  std::ifstream in(out_name);
  std::ostringstream text;
  text << in.rdbuf();
  std::remove(in_name);
  std::remove(out_name);
  if (!r.ok()) throw std::runtime_error("dot " + child_process::describe(r));
  return text.str();
}

}  // namespace

TEST_CASE("LSP positions count UTF-16 code units per line", "[lsp]") {
  // "é" is two bytes and one unit; "𝄞" four bytes and two units (a surrogate pair).
  const std::string text = "a\r\né𝄞x\n\xff"
                           "b";
  TextIndex index(text);
  CHECK(index.line_count() == 3);
  Position x = index.position(static_cast<std::uint32_t>(text.find('x')));
  CHECK(x.line == 1);
  CHECK(x.character == 3);
  CHECK(index.offset({1, 3}) == text.find('x'));
  CHECK(index.offset({2, 1}) == text.find('b'));       // a byte that is not UTF-8 is one unit
  CHECK(index.offset({1, 99}) == text.find('x') + 1);  // past the line: its end
  CHECK(index.offset({9, 0}) == text.size());
}

TEST_CASE("The server's positions end lines at \\r, \\r\\n and \\n alike", "[lsp]") {
  // offset_of/position_of (the text sync and requests) and TextIndex are one code: a lone "\r"
  // ends a line for LSP and for gfec's lexer.
  for (const std::string eol : {"\n", "\r\n", "\r"}) {
    const std::string text = "ab" + eol + "c\xf0\x9d\x84\x9e" + "d" + eol + "e";
    const std::size_t d = text.find('d'), e = text.find('e');
    CHECK(offset_of(text, {1, 3}) == d);
    CHECK(offset_of(text, {2, 0}) == e);
    CHECK(offset_of(text, {0, 99}) == 2);                  // past the line: its end, before the break
    CHECK(offset_of(text, {0, 0xFFFFFFFFu}) == 2);         // no wrap-around before the line's start
    CHECK(offset_of(text, {1, 2}) == text.find('c') + 1);  // inside the surrogate pair: its start
    Position pd = position_of(text, d);
    CHECK(pd.line == 1);
    CHECK(pd.character == 3);
    Position pe = position_of(text, e);
    CHECK(pe.line == 2);
    CHECK(pe.character == 0);
    Position inside = position_of(text, text.find('c') + 2);  // inside the 4-byte character
    CHECK(inside.character == 1);
    Position at_break = position_of(text, 2 + eol.size() - 1);  // on the break's last byte
    CHECK(at_break.line == 0);
    CHECK(at_break.character == 2);  // the line's end, never past it
  }
}

TEST_CASE("Semantic tokens classify declarations and uses", "[lsp]") {
  json legend = semantic_tokens_legend();
  json data = semantic_tokens(kChart)["data"];
  REQUIRE(data.size() % 5 == 0);
  // Decode to (line, char, length) -> type name.
  std::map<std::tuple<int, int, int>, std::string> seen;
  int line = 0, ch = 0;
  for (std::size_t i = 0; i < data.size(); i += 5) {
    line += data[i].get<int>();
    ch = data[i].get<int>() == 0 && i > 0 ? ch + data[i + 1].get<int>() : data[i + 1].get<int>();
    seen[{line, ch, data[i + 2].get<int>()}] = legend["tokenTypes"][data[i + 3].get<int>()];
  }
  CHECK(seen[{0, 0, 10}] == "comment");
  CHECK(seen[{5, 0, 3}] == "keyword");       // sfc
  CHECK(seen[{5, 4, 4}] == "class");         // Line
  CHECK(seen[{6, 9, 4}] == "number");        // 10ms
  CHECK(seen[{7, 6, 3}] == "type");          // int
  CHECK(seen[{7, 10, 4}] == "variable");     // laps
  CHECK(seen[{8, 16, 2}] == "enumMember");   // Go, declared
  CHECK(seen[{8, 21, 7}] == "function");     // Forward
  CHECK(seen[{10, 13, 2}] == "enumMember");  // Go, used
  CHECK(seen[{11, 18, 7}] == "function");    // elapsed
  CHECK(seen[{2, 7, 11}] == "string");
}

TEST_CASE("Semantic tokens of a range are the whole text's that overlap it", "[lsp]") {
  const std::string text = kChart;
  json all = semantic_tokens(text)["data"];
  // Line 8 alone: `  initial place Go { Forward(); }`.
  TextIndex index(text);
  json part = semantic_tokens(text, index.line_start(8), index.line_end(8))["data"];
  REQUIRE(part.size() == 9 * 5);  // initial place Go { Forward ( ) ; }
  CHECK(part[0] == 8);            // the first token's line, relative to the start
  CHECK(part[1] == 2);
  // The same tokens as in the whole text's data, apart from the first one's relative line.
  std::vector<int> decoded_lines;
  int line = 0;
  for (std::size_t i = 0; i < all.size(); i += 5) {
    line += all[i].get<int>();
    decoded_lines.push_back(line);
  }
  CHECK(std::count(decoded_lines.begin(), decoded_lines.end(), 8) == 9);
}

TEST_CASE("Semantic tokens: a test block's own keywords", "[lsp]") {
  json legend = semantic_tokens_legend();
  const std::string text = "test \"t\" of Line {\n  tick 2;\n  set Black = true;\n  expect called Go;\n}\nvar tick;\n";
  json data = semantic_tokens(text)["data"];
  std::vector<std::string> types;
  for (std::size_t i = 0; i < data.size(); i += 5) types.push_back(legend["tokenTypes"][data[i + 3].get<int>()]);
  // test "t" of Line { tick 2 ; set Black = true ; expect called Go ; } var tick ;
  REQUIRE(types.size() == 21);
  CHECK(types[2] == "keyword");    // of
  CHECK(types[5] == "keyword");    // tick
  CHECK(types[8] == "keyword");    // set
  CHECK(types[9] == "variable");   // Black
  CHECK(types[13] == "keyword");   // expect
  CHECK(types[14] == "keyword");   // called
  CHECK(types[15] == "variable");  // Go
  CHECK(types[19] == "variable");  // `tick` outside a test is a name
}

TEST_CASE("Folding ranges: blocks, comment runs and import groups", "[lsp]") {
  json folds = folding_ranges(kChart);
  CHECK(folds.size() == 3);
  CHECK(folds[0] == json{{"startLine", 0}, {"endLine", 1}, {"kind", "comment"}});
  CHECK(folds[1] == json{{"startLine", 2}, {"endLine", 3}, {"kind", "imports"}});
  CHECK(folds[2] == json{{"startLine", 5}, {"endLine", 11}});
}

TEST_CASE("Completion knows where the cursor is", "[lsp]") {
  const std::string text = kChart;
  CHECK(completion_context(text, 0) == CompletionContext::TopLevel);
  CHECK(completion_context(text, after(text, "period 10ms;")) == CompletionContext::ChartItem);
  CHECK(completion_context(text, after(text, "transition Go -> ")) == CompletionContext::PlaceList);
  CHECK(completion_context(text, after(text, "when Black() && ")) == CompletionContext::Condition);
  CHECK(completion_context(text, after(text, "elapsed(")) == CompletionContext::PlaceList);
  CHECK(completion_context(text, after(text, "place Stop { ")) == CompletionContext::Statement);
  CHECK(completion_context(text, after(text, "laps += ")) == CompletionContext::Condition);
  CHECK(completion_context(text, after(text, "var ")) == CompletionContext::Types);
  CHECK(completion_context(text, after(text, "import \"b")) == CompletionContext::Import);

  // Names from the syntax tree of the imports, and from the text itself.
  pipeline::Compilation c({});
  c.options.keep_syntax_tree = true;
  MemoryFileSystem fs;
  fs.add("line.sfc", text);
  fs.add("bot.iface", kIface);
  fs.add("more.iface", "const int LIMIT = 3;\n");
  REQUIRE(c.front_end("line.sfc", fs));
  auto in_condition = labels(completion(text, after(text, "when Black() && "), &c.loaded.program, "."));
  CHECK(contains(in_condition, "Black"));
  CHECK(contains(in_condition, "Count"));
  CHECK(!contains(in_condition, "Forward"));  // void: no value
  CHECK(contains(in_condition, "laps"));
  CHECK(contains(in_condition, "LIMIT"));
  CHECK(!contains(in_condition, "Go"));
  auto in_list = labels(completion(text, after(text, "transition Go -> "), &c.loaded.program, "."));
  CHECK(in_list == std::vector<std::string>{"Go", "Stop"});
  auto item = labels(completion(text, after(text, "period 10ms;"), nullptr, "."));
  CHECK(contains(item, "place"));
  CHECK(contains(item, "transition"));
  // A word being typed is the prefix, not the context: `when Bl|` is still a condition.
  std::string typing = text;
  typing.insert(after(typing, "when Black() && "), "la");
  CHECK(completion_context(typing, after(typing, "when Black() && la")) == CompletionContext::Condition);
}

TEST_CASE("Completion in an import lists chart files beside the document", "[lsp]") {
  const std::string text = "import \"line";
  auto files = labels(completion(text, static_cast<std::uint32_t>(text.size()), nullptr, GFEC_SOURCE_DIR "/samples"));
  CHECK(contains(files, "line_follower.sfc"));
  CHECK(contains(files, "linebot.iface"));
  CHECK(!contains(files, "line_follower.test"));  // not importable
}

TEST_CASE("Code actions are the compiler's fix-its", "[lsp]") {
  pipeline::Compilation c({});
  MemoryFileSystem fs;
  const std::string text =
      "interface I { bool Go(); }\nsfc S {\n  initial place A;\n  place B;\n  transition A -> B when Go()\n}\n";
  fs.add("s.sfc", text);
  CHECK(!c.front_end("s.sfc", fs));
  json actions = code_actions(c.diag, c.sources, 0, 0, static_cast<std::uint32_t>(text.size()), "file:///s.sfc");
  REQUIRE(actions.size() == 1);
  CHECK(actions[0]["kind"] == "quickfix");
  CHECK(actions[0]["title"] == "Insert ';'");
  json edit = actions[0]["edit"]["changes"]["file:///s.sfc"][0];
  CHECK(edit["newText"] == ";");
  CHECK(edit["range"]["start"] == json{{"line", 4}, {"character", 29}});
  // Outside the diagnostic's range: nothing offered.
  CHECK(code_actions(c.diag, c.sources, 0, 0, 5, "file:///s.sfc").empty());
}

TEST_CASE("Code lenses run each scenario test", "[lsp]") {
  const std::string text = "import \"x.sfc\";\ntest \"first\" of X { tick; }\n\ntest \"sec\\\"ond\" of X { tick; }\n";
  json lenses = code_lenses(text, "file:///x.test");
  REQUIRE(lenses.size() == 2);
  CHECK(lenses[0]["command"]["command"] == kRunTestCommand);
  CHECK(lenses[0]["command"]["arguments"] == json{"file:///x.test", "first"});
  CHECK(lenses[1]["command"]["arguments"][1] == "sec\"ond");
  CHECK(lenses[1]["range"]["start"] == json{{"line", 3}, {"character", 0}});
}

TEST_CASE("The chart picture maps every node to its source", "[lsp]") {
  pipeline::Compilation c({});
  MemoryFileSystem fs;
  fs.add("sub.sfc", "sfc Inner { initial place X; place Y; X -> Y; }\n"
                    "sfc Outer { initial place A runs Inner; place B; t: A -> B; }\n");
  REQUIRE(c.front_end("sub.sfc", fs));
  UriOf uri = [](const std::string &p) { return "file:///" + p; };
  json picture = chart_picture(c, "Outer", 7, uri, run_tool);
  CHECK(picture["version"] == 7);
  CHECK(picture["note"] == "sfc Outer");
  std::map<std::string, json> by_node;
  for (const json &e : picture["elements"]) by_node[e["node"]] = e;
  CHECK(by_node["p0"]["name"] == "A");
  CHECK(by_node["p0"]["kind"] == "place");
  CHECK(by_node["p0"]["uri"] == "file:///sub.sfc");
  CHECK(by_node["p0"]["range"]["start"] == json{{"line", 1}, {"character", 12}});
  CHECK(by_node["t0"]["name"] == "t");
  CHECK(by_node["cluster_s0"]["kind"] == "chart");
  CHECK(by_node["s0_p1"]["name"] == "A.Y");
  CHECK(by_node["s0_t0"]["kind"] == "transition");
  REQUIRE(picture["svg"].is_string());
  const std::string svg = picture["svg"];
  for (const auto &[node, element] : by_node) CHECK(svg.find("<title>" + node + "</title>") != std::string::npos);

  // Broken text: no picture, and the note says why.
  pipeline::Compilation broken({});
  MemoryFileSystem bad;
  bad.add("b.sfc", "sfc B { initial place A; A -> Nowhere; }\n");
  CHECK(!broken.front_end("b.sfc", bad));
  json none = chart_picture(broken, "", nullptr, uri, run_tool);
  CHECK(none["svg"].is_null());
  CHECK(none["note"].get<std::string>().find("not redrawn: 1 error in the text; the first: b.sfc:1:") == 0);
  CHECK(none["elements"].empty());
}

TEST_CASE("The analyses wait while messages do, and then run once, on the newest text", "[lsp]") {
  // Two changes in one read: by default a message waits while `in` holds bytes, so the first
  // change's analyses are skipped (the second came first) and the second's run when the input
  // is idle, at its end: two front-end publishes, then one full publish of version 3.
  const std::string uri = "file:///w/choice.sfc";
  std::string choice = "interface Bot { bool Left(); }\nsfc Choice {\n  initial place S;\n  place L;\n  place R;\n"
                       "  place J;\n  transition GoLeft: S -> L when Left();\n  transition GoRight: S -> R when "
                       "!Left();\n  transition Both: (L, R) -> J;\n}\n";
  std::ostringstream session;
  auto send = [&session](const json &m) { write_frame(session, m.dump()); };
  send({{"jsonrpc", "2.0"}, {"id", 1}, {"method", "initialize"}, {"params", {{"capabilities", json::object()}}}});
  for (long long version = 1; version <= 3; ++version) {
    json doc = {{"uri", uri}, {"version", version}};
    if (version == 1) {
      doc["text"] = choice;
      send({{"jsonrpc", "2.0"}, {"method", "textDocument/didOpen"}, {"params", {{"textDocument", doc}}}});
    } else {
      send({{"jsonrpc", "2.0"},
            {"method", "textDocument/didChange"},
            {"params",
             {{"textDocument", doc}, {"contentChanges", {{{"text", choice + "// " + std::to_string(version)}}}}}}});
    }
  }
  std::istringstream in(session.str());
  std::ostringstream out, log;
  MemoryFileSystem disk;
  CHECK(serve(in, out, log, disk) == 1);  // the input ended without shutdown
  std::istringstream written(out.str());
  std::vector<std::pair<long long, std::size_t>> publishes;  // version, diagnostics
  for (Frame f = read_frame(written); f.status == Frame::Status::Ok; f = read_frame(written)) {
    json m = json::parse(f.body);
    if (m.value("method", "") != "textDocument/publishDiagnostics") continue;
    publishes.emplace_back(m["params"]["version"].get<long long>(), m["params"]["diagnostics"].size());
  }
  // The front end finds nothing; the analyses a deadlock, a place never active, a dead join.
  CHECK(publishes == std::vector<std::pair<long long, std::size_t>>{{1, 0}, {2, 0}, {3, 0}, {3, 3}});
}
