// gfec fmt's library (compiler/format/format_source.h): its layout on hand-made text, the golden
// before/after pairs of tests/golden/fmt, and its promises over every chart text of the
// repository and over random charts: the tokens and the comments are kept, the compiled model
// does not change, and formatting twice gives what formatting once gave (docs/formatting.md).
#include "backend.h"
#include "format/format_source.h"
#include "json_backend.h"
#include "lexer.h"
#include "random_chart.h"
#include "support.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <utility>

namespace fs = std::filesystem;
using namespace gfec;

namespace {

const fs::path kSource = GFEC_SOURCE_DIR;

std::optional<std::string> format(const std::string &path, const std::string &text, std::string *errors = nullptr) {
  SourceManager sources;
  Diagnostics diag;
  auto result = format_source(sources, sources.add(path, text), diag);
  if (errors)
    for (const auto &d : diag.all()) *errors += render_text(d, sources);
  return result;
}

/// The tokens (kind and spelling) and the comments of a text, as the lexer reads them.
struct Lexed {
  std::vector<std::pair<Tok, std::string>> tokens;
  std::vector<std::string> comments;
};

Lexed lex(const std::string &text) {
  SourceManager sources;
  Diagnostics diag;
  FileId id = sources.add("t.sfc", text);
  std::vector<SourceRange> ranges;
  Lexer lexer(sources, id, diag);
  lexer.record_comments(&ranges);
  Lexed out;
  for (Token t = lexer.next(); t.kind != Tok::End; t = lexer.next()) out.tokens.emplace_back(t.kind, t.text);
  for (const SourceRange &r : ranges) {
    std::string c = sources.file(id).text().substr(r.begin, r.end - r.begin);
    if (c.rfind("//", 0) == 0) c.erase(c.find_last_not_of(" \t\f\v") + 1);  // gfec fmt drops trailing blanks
    out.comments.push_back(c);
  }
  return out;
}

/// The model as --emit=json writes it for every chart and plan, without what only the layout
/// decides: source positions, and the spaces inside the text of an expression or statement.
nlohmann::json layout_free(nlohmann::json j) {
  if (j.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (auto &[key, value] : j.items()) {
      if (key == "location") continue;
      if ((key == "text" || key == "formula" || key == "when") && value.is_string()) {
        std::string s = value.get<std::string>();
        s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }), s.end());
        out[key] = s;
      } else {
        out[key] = layout_free(value);
      }
    }
    return out;
  }
  if (j.is_array())
    for (auto &e : j) e = layout_free(e);
  return j;
}

/// Every chart's and plan's model as JSON, or nothing when the front end reports errors.
std::optional<nlohmann::json> model_json(const std::string &main, const FileSystem &files) {
  test::Pipeline p(main, files);
  if (p.diag.has_errors()) return std::nullopt;
  nlohmann::json all = nlohmann::json::array();
  auto backend = make_json_backend();
  for (model::ChartId c : p.model.charts.ids()) {
    EmitOptions o;
    o.output_path = "out.json";
    o.source_name = main;
    o.chart = c;
    all.push_back(layout_free(nlohmann::json::parse(emit_to_memory(*backend, p.model, o).at(0).contents)));
  }
  for (model::PlanId plan : p.model.plans.ids()) {
    EmitOptions o;
    o.output_path = "out.json";
    o.source_name = main;
    o.plan = plan;
    all.push_back(layout_free(nlohmann::json::parse(emit_to_memory(*backend, p.model, o).at(0).contents)));
  }
  return all;
}

bool is_chart_text(const fs::path &p) {
  static const std::vector<std::string> kinds = {".sfc", ".fsm", ".plan", ".toolbox", ".iface", ".test"};
  return std::find(kinds.begin(), kinds.end(), p.extension().string()) != kinds.end();
}

/// "" when the texts are equal, else where they first differ.
std::string difference(const std::string &expected, const std::string &actual) {
  return expected == actual ? "" : test::first_difference(expected, actual);
}

/// What every formatted text must keep of its original: checked for one text, reported with it.
void check_kept(const std::string &name, const std::string &original, const std::string &formatted) {
  INFO(name << "\n--- formatted:\n" << formatted);
  Lexed before = lex(original), after = lex(formatted);
  CHECK(before.tokens == after.tokens);
  CHECK(before.comments == after.comments);
  auto again = format(name, formatted);
  REQUIRE(again);
  CHECK(difference(formatted, *again) == "");
}

}  // namespace

TEST_CASE("fmt: indentation, spaces around operators and blank lines are set; line breaks and comments kept", "[fmt]") {
  auto out = format("t.sfc", "// head\n\n\n\nsfc   S{\nperiod 10ms;var int n=0;\n\n\n"
                             "   initial place A{entry{n+=1;}Go(-n*2,!true); }  // trailing\n"
                             "place B {}\n"
                             "transition A->B when n>=3&&\n"
                             "(n<9||n%2==0);\n"
                             "/* block\n   comment */ transition B -> A;\n}\n\n\n");
  REQUIRE(out);
  CHECK(*out == "// head\n\nsfc S {\n  period 10ms; var int n = 0;\n\n"
                "  initial place A { entry { n += 1; } Go(-n * 2, !true); }  // trailing\n"
                "  place B {}\n"
                "  transition A -> B when n >= 3 &&\n"
                "      (n < 9 || n % 2 == 0);\n"
                "  /* block\n   comment */ transition B -> A;\n}\n");
}

TEST_CASE("fmt: text that does not parse is reported and not formatted", "[fmt]") {
  std::string errors;
  CHECK_FALSE(format("bad.sfc", "sfc S { place A { Go( } }\n", &errors));
  CHECK(errors.find("bad.sfc:1:") != std::string::npos);
  errors.clear();
  CHECK_FALSE(format("bad.sfc", "sfc S { /* never closed\n", &errors));
  CHECK(errors.find("unterminated comment") != std::string::npos);
}

TEST_CASE("fmt: CR and CRLF line ends become LF; no line ends in blanks; a byte-order mark stays", "[fmt]") {
  auto out = format("t.fsm", "\xEF\xBB\xBF// x \t\rfsm F {\r\n  initial state A;\r}");
  REQUIRE(out);
  CHECK(*out == "\xEF\xBB\xBF// x\nfsm F {\n  initial state A;\n}\n");
}

TEST_CASE("fmt: the golden before/after pairs of tests/golden/fmt", "[fmt][golden]") {
  int pairs = 0;
  for (const auto &entry : fs::directory_iterator(kSource / "tests" / "golden" / "fmt")) {
    std::string name = entry.path().filename().string();
    auto at = name.find(".before.");
    if (at == std::string::npos) continue;
    fs::path after = entry.path().parent_path() / (name.substr(0, at) + ".after." + name.substr(at + 8));
    INFO(entry.path().string());
    auto out = format(entry.path().string(), test::read_file(entry.path().string()));
    REQUIRE(out);
    CHECK(difference(test::read_file(after.string()), *out) == "");
    check_kept(name, test::read_file(entry.path().string()), *out);
    ++pairs;
  }
  CHECK(pairs >= 3);
}

TEST_CASE("fmt: every chart text of the repository keeps its tokens, comments and model, and is a fixed point",
          "[fmt]") {
  MemoryFileSystem originals, formatted;
  std::vector<std::string> paths;
  for (const char *top : {"samples", "docs", "examples", "tests"}) {
    if (!fs::exists(kSource / top)) continue;
    for (auto it = fs::recursive_directory_iterator(kSource / top); it != fs::recursive_directory_iterator(); ++it) {
      if (it->is_directory() && it->path().filename() == "node_modules") it.disable_recursion_pending();
      if (it->is_regular_file() && is_chart_text(it->path())) paths.push_back(it->path().string());
    }
  }
  int parsed = 0, compared = 0;
  for (const std::string &path : paths) {
    std::string text = test::read_file(path);
    originals.add(path, text);
    auto out = format(path, text);
    formatted.add(path, out ? *out : text);
    if (!out) continue;  // the diagnostics tests' broken files, the fuzz corpus
    ++parsed;
    check_kept(path, text, *out);
  }
  for (const std::string &path : paths) {
    auto before = model_json(path, originals);
    if (!before) continue;
    INFO(path);
    auto after = model_json(path, formatted);
    REQUIRE(after);
    CHECK(nlohmann::json::diff(*before, *after).dump() == "[]");
    ++compared;
  }
  // A walk that found nothing must not pass: these are the repository's counts, give or take.
  CHECK(parsed >= 120);
  CHECK(compared >= 60);
}

TEST_CASE("fmt: random charts keep their tokens and model, and are fixed points", "[fmt]") {
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    std::mt19937_64 rng(seed);
    diff::GenOptions o;
    o.fsm = seed % 2 == 0;
    o.subcharts = static_cast<int>(seed % 3);
    o.agents = o.fsm && seed % 5 == 0 ? 3 : 0;
    std::string name = o.fsm ? "r.fsm" : "r.sfc";
    std::string text = diff::chart_text(diff::random_chart(rng, static_cast<int>(seed), o));
    INFO("seed " << seed << "\n" << text);
    auto out = format(name, text);
    REQUIRE(out);
    check_kept(name, text, *out);
    auto before = model_json(name, test::files({{name, text}}));
    REQUIRE(before);
    CHECK(nlohmann::json::diff(*before, *model_json(name, test::files({{name, *out}}))).dump() == "[]");
  }
}
