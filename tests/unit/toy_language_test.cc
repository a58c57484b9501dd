// A fourth input language that lives in this file alone: a row registered with the table of input
// languages (compiler/input_languages.h) and a reader that turns a few lines into the syntax tree
// of an fsm. Nothing else in gfec knows it, yet it goes through the loader, the validator, the
// model and the C back end, and its engine runs. This is the worked example of
// docs/architecture.md "Adding an input language": a language is its row and its reader.
#include "../run/c_backend_support.h"
#include "input_languages.h"

#include <catch2/catch.hpp>

#include <sstream>

using namespace cbt;

namespace {

// The toy language, one declaration per line; `#` begins a comment:
//   machine NAME                an fsm
//   state NAME [ACTION]         a state (the first is the initial one) running ACTION() each tick
//   FROM -> TO when CONDITION   a transition taken when CONDITION() is true
class ToyReader {
public:
  ToyReader(SourceManager &sources, Diagnostics &diag, LoadResult &result) : sources_(sources), diag_(diag) {
    result.program.files.push_back(std::make_unique<ast::File>());
    file_ = result.program.files.back().get();
  }

  void read(const std::string &path, std::string text, const InputLanguage &language) {
    file_->id = sources_.add(path, std::move(text), language);
    const std::string &t = sources_.file(file_->id).text();  // names view it: it outlives the tree
    file_->interfaces.emplace_back();
    iface_ = &file_->interfaces.back();
    iface_->name = {"ToyFunctions", {file_->id, 0, 0}};
    for (std::size_t begin = 0; begin < t.size();) {
      std::size_t end = t.find('\n', begin);
      if (end == std::string::npos) end = t.size();
      line(std::string_view(t).substr(begin, end - begin), static_cast<std::uint32_t>(begin));
      begin = end + 1;
    }
    if (!chart_) diag_.error({file_->id, 0, 0}, ErrorKind::Syntax, "a toy file declares a machine");
  }

private:
  /// The words of one line, each with its range.
  std::vector<ast::Name> words(std::string_view line, std::uint32_t at) {
    std::vector<ast::Name> out;
    for (std::size_t i = 0; i < line.size() && line[i] != '#';) {
      if (line[i] == ' ') {
        ++i;
        continue;
      }
      std::size_t end = line.find_first_of(" #", i);
      if (end == std::string_view::npos) end = line.size();
      out.push_back({line.substr(i, end - i), {file_->id, at + std::uint32_t(i), at + std::uint32_t(end)}});
      i = end;
    }
    return out;
  }

  void line(std::string_view text, std::uint32_t at) {
    std::vector<ast::Name> w = words(text, at);
    if (w.empty()) return;
    SourceRange whole = w.front().range.to(w.back().range);
    if (w.size() == 2 && w[0].text == "machine" && !chart_) {
      file_->charts.push_back({});
      chart_ = &file_->charts.back();
      chart_->kind = ast::Chart::Kind::Fsm;
      chart_->name = w[1];
      chart_->range = whole;
      chart_->periods.push_back({10, whole});
    } else if (chart_ && (w.size() == 2 || w.size() == 3) && w[0].text == "state") {
      ast::Place &p = chart_->places.emplace_back();
      p.is_state = true;
      p.initial = chart_->places.size() == 1;
      p.name = w[1];
      p.range = whole;
      if (w.size() == 3) {
        p.has_body = true;
        ast::Stmt &s = p.action.emplace_back();
        s.kind = ast::Stmt::Kind::Call;
        s.range = w[2].range;
        s.call = call(w[2], "void");
      }
    } else if (chart_ && w.size() == 5 && w[1].text == "->" && w[3].text == "when") {
      ast::Transition &t = chart_->transitions.emplace_back();
      t.range = whole;
      t.set_places({w[0]}, {w[2]});
      t.condition = call(w[4], "bool");
    } else {
      diag_.error(whole, ErrorKind::Syntax, "a toy line is 'machine M', 'state S [ACTION]' or 'A -> B when C'");
    }
  }

  /// `name()`, declaring name in the interface the first time it is called.
  ast::ExprPtr call(const ast::Name &name, const char *result) {
    bool declared = false;
    for (const auto &f : iface_->functions) declared = declared || f.name.text == name.text;
    if (!declared) {
      ast::FunctionDecl &f = iface_->functions.emplace_back();
      f.result = {result, name.range};
      f.name = name;
      f.range = name.range;
    }
    auto e = std::make_unique<ast::Expr>();
    e->kind = ast::Expr::Kind::Call;
    e->range = name.range;
    e->name = name;
    return e;
  }

  SourceManager &sources_;
  Diagnostics &diag_;
  ast::File *file_ = nullptr;
  ast::Interface *iface_ = nullptr;
  ast::Chart *chart_ = nullptr;
};

const InputLanguage &toy_language();

void read_toy_program(const std::string &main_path, std::string text, const LoadOptions &, const FileSystem &,
                      SourceManager &sources, Diagnostics &diag, LoadResult &result) {
  result.paths.push_back(main_path);
  ToyReader(sources, diag, result).read(main_path, std::move(text), toy_language());
}

/// The row: everything gfec is told about the language.
const InputLanguage &toy_language() {
  static const InputLanguage row{
      "toy",
      "a toy fsm language",
      {{".toy", "a toy machine"}},
      nullptr,
      read_toy_program,
      false,  // its ranges are lines of its own syntax: back ends print from the model
      "#",
      nullptr,
  };
  return row;
}

const char *const kBlink = "# a lamp that a button toggles\n"
                           "machine Blink\n"
                           "state Off lamp_off\n"
                           "state On lamp_on   # lit\n"
                           "Off -> On when pressed\n"
                           "On -> Off when pressed\n";

}  // namespace

TEST_CASE("toy language: a registered row is read, validated, compiled to C and run", "[languages][c-run]") {
  InputLanguageRegistration toy(toy_language());
  REQUIRE(find_input_language("toy") == &toy_language());
  CHECK(&input_language_of("blink.toy", kBlink) == &toy_language());

  auto compiled = compile_chart({{"blink.toy", kBlink}}, "blink.toy", "engine.c");
  INFO(compiled->errors);
  REQUIRE(!compiled->diag.has_errors());
  REQUIRE(compiled->loaded.language == &toy_language());
  REQUIRE(compiled->the_chart().name == "Blink");
  CHECK(compiled->the_chart().places.size() == 2);
  CHECK(!model::in_chart_text(compiled->model, compiled->the_chart().range));
  // A press toggles the lamp; the new state's action runs in the tick that enters it.
  std::string log =
      compile_and_run("toy_blink", compiled->files, compiled->model, compiled->the_chart(), "\npressed\n\npressed\n");
  CHECK(log == "tick 1\n"
               "cond pressed -> 0\n"
               "act lamp_off\n"
               "state Off status 0\n"
               "tick 2\n"
               "cond pressed -> 1\n"
               "act lamp_on\n"
               "state On status 0\n"
               "tick 3\n"
               "cond pressed -> 0\n"
               "act lamp_on\n"
               "state On status 0\n"
               "tick 4\n"
               "cond pressed -> 1\n"
               "act lamp_off\n"
               "state Off status 0\n");
}

TEST_CASE("toy language: the reader's and the validator's messages point into the toy file", "[languages]") {
  InputLanguageRegistration toy(toy_language());
  test::Pipeline unknown("bad.toy", test::files({{"bad.toy", "machine M\nstate A\nA -> B when go\n"}}));
  INFO(unknown.text());
  CHECK(unknown.text().rfind("bad.toy:3:6: error: unknown state 'B'", 0) == 0);
  test::Pipeline syntax("bad.toy", test::files({{"bad.toy", "machine M\n  fly away # no toy\n"}}));
  CHECK(syntax.text() == "bad.toy:2:3: error: a toy line is 'machine M', 'state S [ACTION]' or 'A -> B when C' "
                         "[syntax]\n"
                         "   fly away # no toy\n"
                         "   ^~~~~~~~\n");
}

TEST_CASE("toy language: without its row a .toy file is chart text, and -x toy is unknown", "[languages]") {
  { InputLanguageRegistration toy(toy_language()); }
  CHECK(find_input_language("toy") == nullptr);
  CHECK(&input_language_of("blink.toy", kBlink) == &chart_text_language());
  test::Pipeline p("blink.toy", test::files({{"blink.toy", kBlink}}));
  CHECK(p.loaded.language == &chart_text_language());
  CHECK(p.text().find("blink.toy:1:1: error:") != std::string::npos);  // `#` is no chart syntax
}
