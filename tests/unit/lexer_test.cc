#include "lexer.h"

#include "support.h"

#include <catch2/catch.hpp>

using namespace gfec;

namespace {

std::vector<Token> lex_all(const std::string &text, Diagnostics &diag, SourceManager &sm) {
  FileId id = sm.add("t.sfc", text);
  Lexer lexer(sm, id, diag);
  std::vector<Token> tokens;
  for (Token t = lexer.next(); t.kind != Tok::End; t = lexer.next()) tokens.push_back(t);
  return tokens;
}

}  // namespace

TEST_CASE("lexer: keywords, identifiers, punctuation and comments") {
  SourceManager sm;
  Diagnostics diag;
  auto toks = lex_all("initial place A_1 { } // c\n/* x */ -> += -= && || != == <= >= ! | %", diag, sm);
  std::vector<Tok> kinds;
  for (auto &t : toks) kinds.push_back(t.kind);
  CHECK(kinds == std::vector<Tok>{Tok::KwInitial, Tok::KwPlace, Tok::Ident, Tok::LBrace, Tok::RBrace, Tok::Arrow,
                                  Tok::PlusAssign, Tok::MinusAssign, Tok::AndAnd, Tok::OrOr, Tok::NotEq, Tok::EqEq,
                                  Tok::Le, Tok::Ge, Tok::Not, Tok::Pipe, Tok::Percent});
  CHECK(toks[2].text == "A_1");
  CHECK_FALSE(diag.has_errors());
}

TEST_CASE("lexer: on request, the comments it skips are recorded in order, as written") {
  SourceManager sm;
  Diagnostics diag;
  const std::string text = "a // one  \r\n/* two\n lines */ b /**/ c // end";
  FileId id = sm.add("t.sfc", text);
  std::vector<SourceRange> comments;
  Lexer lexer(sm, id, diag);
  lexer.record_comments(&comments);
  std::vector<std::string_view> tokens;
  for (Token t = lexer.next(); t.kind != Tok::End; t = lexer.next()) tokens.push_back(t.text);
  CHECK(tokens == std::vector<std::string_view>{"a", "b", "c"});
  std::vector<std::string> written;
  for (const SourceRange &r : comments) written.push_back(text.substr(r.begin, r.end - r.begin));
  CHECK(written == std::vector<std::string>{"// one  ", "/* two\n lines */", "/**/", "// end"});
  CHECK_FALSE(diag.has_errors());
}

TEST_CASE("lexer: numbers, durations and strings") {
  SourceManager sm;
  Diagnostics diag;
  auto toks = lex_all(R"(42 0.5 1e-3 10ms 1.5s 2s "a\n\"b")", diag, sm);
  REQUIRE(toks.size() == 7);
  CHECK(toks[0].kind == Tok::Int);
  CHECK(toks[1].kind == Tok::Float);
  CHECK(toks[2].kind == Tok::Float);
  CHECK(toks[3].kind == Tok::Duration);
  CHECK(toks[3].duration_ms == 10);
  CHECK(toks[4].duration_ms == 1500);
  CHECK(toks[5].duration_ms == 2000);
  CHECK(toks[6].kind == Tok::String);
  CHECK(toks[6].value == "a\n\"b");
  CHECK_FALSE(diag.has_errors());
}

TEST_CASE("lexer: verbatim blocks keep their text unparsed") {
  SourceManager sm;
  Diagnostics diag;
  auto toks = lex_all("%{ #include <math.h>\n int x = 1 % 2; %}", diag, sm);
  REQUIRE(toks.size() == 1);
  CHECK(toks[0].kind == Tok::Verbatim);
  CHECK(toks[0].value == " #include <math.h>\n int x = 1 % 2; ");
}

TEST_CASE("lexer: malformed tokens are located errors") {
  CHECK(test::parse_errors("sfc X { period 10min; }") ==
        "t.sfc:1:16: error: invalid suffix 'min' on number; durations are written like 10ms or 1.5s [syntax]\n"
        " sfc X { period 10min; }\n"
        "                ^~~~~\n");
  CHECK(test::parse_errors("sfc X { place A { f(\"abc); } }\n") ==
        "t.sfc:1:21: error: missing terminating '\"' character [syntax]\n"
        " sfc X { place A { f(\"abc); } }\n"
        "                     ^~~~~~~~~~\n"
        "t.sfc:2:1: error: expected '}' at end of input [syntax]\n"
        " \n"
        " ^\n"
        "t.sfc:1:17: note: to match this '{'\n"
        " sfc X { place A { f(\"abc); } }\n"
        "                 ^\n");
  CHECK(test::parse_errors("/* never closed") == "t.sfc:1:1: error: unterminated comment [syntax]\n"
                                                 " /* never closed\n"
                                                 " ^~\n");
  CHECK(test::parse_errors("%{ int x;") == "t.sfc:1:1: error: unterminated verbatim block: missing '%}' [syntax]\n"
                                           " %{ int x;\n"
                                           " ^~\n");
  CHECK(test::parse_errors("sfc X { place A { f(a & b); } }") ==
        "t.sfc:1:23: error: '&' is not an operator here; did you mean '&&'? [syntax]\n"
        " sfc X { place A { f(a & b); } }\n"
        "                       ^\n");
  // The caret counts characters as the terminal shows them: é is two bytes and one column.
  CHECK(test::parse_errors("sfc X { place A \xc3\xa9; }") ==
        "t.sfc:1:17: error: unexpected character '\xc3\xa9' [syntax]\n"
        " sfc X { place A \xc3\xa9; }\n"
        "                 ^\n");
}

TEST_CASE("lexer: 'runs' is a keyword and '.' a token between names, still part of a number") {
  SourceManager sm;
  Diagnostics diag;
  auto toks = lex_all("place P runs Sub; active(P.Q.R) .5 1.", diag, sm);
  std::vector<Tok> kinds;
  for (auto &t : toks) kinds.push_back(t.kind);
  CHECK(diag.all().empty());
  CHECK(kinds == std::vector<Tok>{Tok::KwPlace, Tok::Ident, Tok::KwRuns, Tok::Ident, Tok::Semi, Tok::Ident, Tok::LParen,
                                  Tok::Ident, Tok::Dot, Tok::Ident, Tok::Dot, Tok::Ident, Tok::RParen, Tok::Float,
                                  Tok::Float});
}
