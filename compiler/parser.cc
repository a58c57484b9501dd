#include "parser.h"

#include "lexer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <optional>

namespace gfec {

namespace {

using namespace ast;

/// Thrown to abandon the current declaration or statement after a syntax error; caught where
/// the parser can resynchronise, so an error never cascades into a list of follow-on errors.
struct SyntaxError {};

class Parser {
public:
  Parser(const SourceManager &sources, FileId file, Diagnostics &diag)
      : file_(file), diag_(diag), lexer_(sources, file, diag), text_(sources.file(file).text()) {
    advance();
  }

  std::unique_ptr<File> parse();

private:
  // ------------------------------------------------------------ token handling
  void advance() {
    prev_end_ = tok_.range.end;
    if (lookahead_) {
      tok_ = std::move(*lookahead_);
      lookahead_.reset();
      return;
    }
    tok_ = lex();
  }
  Token lex() {
    Token t = lexer_.next();
    bool after_error = false;
    while (t.kind == Tok::Error) {  // already reported by the lexer
      after_error = true;
      t = lexer_.next();
    }
    t.follows_error = after_error;
    return t;
  }
  /// The token after the current one (one token of lookahead is all the grammar needs).
  const Token &peek() {
    if (!lookahead_) lookahead_ = lex();
    return *lookahead_;
  }
  bool at(Tok k) const { return tok_.kind == k; }
  /// Whether the text from `pos` on, after white space, is `=` and not `==`: a second token of
  /// lookahead for `inst(a = e)`, which only a block call has.
  bool assign_follows(std::uint32_t pos) const {
    while (pos < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos]))) ++pos;
    return pos < text_.size() && text_[pos] == '=' && (pos + 1 >= text_.size() || text_[pos + 1] != '=');
  }
  bool accept(Tok k) {
    if (!at(k)) return false;
    advance();
    return true;
  }
  Token take() {
    Token t = tok_;
    advance();
    return t;
  }
  /// Consumes `k` or reports "expected X before Y" and abandons the construct.
  Token expect(Tok k, std::string_view context = {}) {
    if (at(k)) return take();
    if (k == Tok::Semi) missing_semicolon(context);
    fail(fmt::format("expected {}{}", describe(k), context.empty() ? "" : fmt::format(" {}", context)));
  }
  /// A `;` forgotten at the end of a line: gcc's place for it, just after the previous token (the
  /// next line's first token is not where the mistake is), with the fix-it inserting it.
  void missing_semicolon(std::string_view context) {
    if (tok_.follows_error || prev_end_ == 0 || prev_end_ > tok_.range.begin) return;
    const std::string_view between = std::string_view(text_).substr(prev_end_, tok_.range.begin - prev_end_);
    if (between.find('\n') == std::string_view::npos) return;
    const SourceRange at{file_, prev_end_, prev_end_};
    diag_
        .error(at, ErrorKind::Syntax,
               fmt::format("expected ';'{} at the end of the line", context.empty() ? "" : fmt::format(" {}", context)))
        .fix(at, ";")
        .note(tok_.range, at_end() ? "the file ends here" : fmt::format("before '{}' on the next line", tok_.text));
    throw SyntaxError{};
  }
  bool at_end() const { return at(Tok::End); }
  [[noreturn]] void fail(const std::string &what) {
    // Right after a lexical error the parser's complaint is only its echo: stay quiet.
    if (!tok_.follows_error) {
      std::string found = at(Tok::End) ? "end of file" : fmt::format("'{}'", tok_.text);
      diag_.error(tok_.range, ErrorKind::Syntax, fmt::format("{}, found {}", what, found));
    }
    throw SyntaxError{};
  }
  /// fail() for a beginner's mistake the parser recognises: the error, a note saying what to
  /// write instead, and a fix-it when the fix is certain (`fix_text` non-empty).
  [[noreturn]] void fail_hint(const std::string &what, const std::string &hint, SourceRange fix_range = {},
                              const std::string &fix_text = {}) {
    if (!tok_.follows_error) {
      std::string found = at(Tok::End) ? "end of file" : fmt::format("'{}'", tok_.text);
      auto &d = diag_.error(tok_.range, ErrorKind::Syntax, fmt::format("{}, found {}", what, found));
      if (!fix_text.empty()) d.fix(fix_range, fix_text);
      d.note(hint);
    }
    throw SyntaxError{};
  }
  SourceRange from(std::uint32_t begin) const { return {file_, begin, prev_end_}; }
  std::uint32_t here() const { return tok_.range.begin; }

  /// After an error: skip to just past the next ';' or to the next '}' at this nesting level.
  void recover() {
    int depth = 0;
    while (!at(Tok::End)) {
      if (at(Tok::LBrace)) ++depth;
      if (at(Tok::RBrace)) {
        if (depth == 0) return;
        --depth;
        advance();
        if (depth == 0) return;
        continue;
      }
      if (at(Tok::Semi) && depth == 0) {
        advance();
        return;
      }
      advance();
    }
  }

  /// Parses `{ item* }`, calling `item` until the closing brace; errors inside one item skip
  /// only that item.
  template <typename Item> void braced(const char *what, Item item) {
    Token open = expect(Tok::LBrace, what);
    while (!at(Tok::RBrace)) {
      if (at(Tok::End)) {
        // Only the innermost unclosed brace: the outer ones are the same mistake.
        if (!eof_reported_)
          diag_.error(tok_.range, ErrorKind::Syntax, "expected '}' at end of input")
              .note(open.range, "to match this '{'");
        eof_reported_ = true;
        throw SyntaxError{};
      }
      std::uint32_t before = here();
      try {
        item();
      } catch (const SyntaxError &) {
        recover();
        if (here() == before && !at(Tok::RBrace) && !at(Tok::End)) advance();
      }
    }
    advance();
  }

  Name name(std::string_view context = {}) {
    Token t = expect(Tok::Ident, context);
    return {t.text, t.range};
  }
  TypeName type_name(std::string_view context = {}) {
    Token t = expect(Tok::Ident, context.empty() ? std::string_view("(a type name)") : context);
    return {std::string(t.text), t.range};
  }

  // ------------------------------------------------------------ declarations
  void top_level(File &file);
  void import_decl(File &file);
  Interface interface_decl();
  FunctionDecl function_decl();
  ValueDecl value_decl();
  Chart chart(Chart::Kind kind);
  void chart_item(Chart &chart);
  Period period();
  void team_decl(Chart &chart);
  Place place(Chart::Kind kind);
  Block block();
  void place_body(Place &p);
  Association association();
  ActionDecl action_decl();
  BlockDecl block_decl();
  Name member_name(Name first);
  void invoke_arguments(Stmt &s);
  Transition transition();
  std::vector<Name> place_list(bool &parenthesised);
  Toolbox toolbox();
  Template template_decl();
  Plan plan();
  void plan_item(Plan &plan);
  Supervise supervise();
  ActorUse actor_use();
  Rule rule();
  ExprList arguments();
  ExprList active_arguments();
  ExprPtr path(Name first);
  Test test_decl();
  void test_step(Test &test, long long agent, SourceRange agent_range);
  ExprPtr test_operand();
  /// The contextual keywords of a test block (`tick set expect called calls status`): plain
  /// identifiers everywhere else.
  bool at_word(std::string_view word) const { return at(Tok::Ident) && tok_.text == word; }

  // ------------------------------------------------------------ statements and expressions
  Stmt statement();
  Stmt if_statement(int chain = 0);  ///< chain: the `else if`s before this `if`
  Stmt loop_statement();
  Stmt assignment(Name target, std::uint32_t begin);
  /// `(` expr `)`: a loop's condition.
  ExprPtr loop_condition(const char *keyword);
  ExprPtr expr() { return binary(1); }
  ExprPtr binary(int min_precedence);
  ExprPtr unary();
  ExprPtr primary();
  ExprPtr make(Expr::Kind kind, SourceRange range) {
    auto e = std::make_unique<Expr>();
    e->kind = kind;
    e->range = range;
    return e;
  }

  struct DepthGuard {
    Parser &p;
    explicit DepthGuard(Parser &parser) : p(parser) {
      if (++p.depth_ > kMaxNesting) {
        p.diag_.error(p.tok_.range, ErrorKind::Nesting,
                      fmt::format("expression nested too deeply (more than {} levels)", kMaxNesting));
        --p.depth_;
        throw SyntaxError{};
      }
    }
    ~DepthGuard() { --p.depth_; }
  };

  /// One level more than `height`, refused past kMaxNesting: a flat chain `x + x + ...` is a
  /// left spine as deep as it is long, and every later walk of the tree recurses along it.
  int grow(int height, SourceRange at) {
    if (height + 1 > kMaxNesting) {
      diag_.error(at, ErrorKind::Nesting,
                  fmt::format("expression nested too deeply (more than {} levels; each operator of a "
                              "chain counts as one)",
                              kMaxNesting));
      throw SyntaxError{};
    }
    return height + 1;
  }

  FileId file_;
  File *out_ = nullptr;  ///< the file being parsed: it keeps the decoded string literals
  Diagnostics &diag_;
  Lexer lexer_;
  Token tok_;
  std::optional<Token> lookahead_;
  std::uint32_t prev_end_ = 0;
  const std::string &text_;  ///< the file's text (where a line ends)
  int depth_ = 0;
  int height_ = 0;  ///< height of the expression the last binary/unary/primary returned
  bool eof_reported_ = false;
  bool in_test_ = false;  ///< inside a test block: the test-only operands parse
};

//G file: { import | interface | sfc | fsm | toolbox | plan | const_decl | test | VERBATIM }
std::unique_ptr<File> Parser::parse() {
  auto file = std::make_unique<File>();
  file->id = file_;
  out_ = file.get();
  while (!at(Tok::End)) {
    if (diag_.limit_reached()) break;
    std::uint32_t before = here();
    try {
      top_level(*file);
    } catch (const SyntaxError &) {
      recover();
      if (at(Tok::RBrace)) advance();  // a stray '}' at file level
      if (here() == before && !at(Tok::End)) advance();
    }
  }
  return file;
}

void Parser::top_level(File &file) {
  switch (tok_.kind) {
  case Tok::KwImport: import_decl(file); return;
  case Tok::KwInterface: file.interfaces.push_back(interface_decl()); return;
  case Tok::KwSfc: file.charts.push_back(chart(Chart::Kind::Sfc)); return;
  case Tok::KwFsm: file.charts.push_back(chart(Chart::Kind::Fsm)); return;
  case Tok::KwToolbox: file.toolboxes.push_back(toolbox()); return;
  case Tok::KwPlan: file.plans.push_back(plan()); return;
  case Tok::KwConst: file.consts.push_back(value_decl()); return;
  case Tok::KwTest: file.tests.push_back(test_decl()); return;
  case Tok::Verbatim: {
    Token t = take();
    file.verbatims.push_back({t.value, t.range});
    return;
  }
  case Tok::KwVar:
    diag_.error(tok_.range, ErrorKind::Syntax, "'var' declares chart state and belongs inside an sfc or fsm");
    throw SyntaxError{};
  case Tok::Ident:
    // `block` is a keyword only here, before a name (docs/language.md "Blocks").
    if (tok_.text == "block" && peek().kind == Tok::Ident) {
      file.blocks.push_back(block_decl());
      return;
    }
    [[fallthrough]];
  default: {
    const std::string what = "expected a declaration (import, interface, sfc, fsm, toolbox, plan, const or test)";
    // A file that opens with '{' is JSON, most likely an ALICA plan under another extension.
    if (at(Tok::LBrace) && prev_end_ == 0)
      fail_hint(what, "this looks like JSON: to read an ALICA plan, give the file ALICA's extension (.pml, .beh, "
                      ".pty) or pass '-x alica' before it");
    fail(what);
  }
  }
}

//G import: 'import' STRING ';'
void Parser::import_decl(File &file) {
  advance();
  Token path = expect(Tok::String, "after 'import'");
  expect(Tok::Semi, "after the import");
  file.imports.push_back({path.value, path.range});
}

//G interface: 'interface' IDENT '{' { function } '}'
Interface Parser::interface_decl() {
  std::uint32_t begin = here();
  advance();
  Interface i;
  i.name = name("after 'interface'");
  braced("to open the interface", [&] { i.functions.push_back(function_decl()); });
  i.range = from(begin);
  return i;
}

//G function: type IDENT '(' [ 'void' | param { ',' param } ] ')' ';'
//G param: type [IDENT]
FunctionDecl Parser::function_decl() {
  std::uint32_t begin = here();
  FunctionDecl f;
  f.result = type_name("(the function's result type)");
  f.name = name("(the function's name)");
  expect(Tok::LParen, "after the function name");
  // `f(void)` is C's spelling of no parameters.
  bool c_void = at(Tok::Ident) && tok_.text == "void" && peek().kind == Tok::RParen;
  if (c_void) advance();
  if (!c_void && !at(Tok::RParen)) {
    do {
      std::uint32_t pbegin = here();
      Param p;
      p.type = type_name("(a parameter type)");
      if (at(Tok::Ident)) p.name = name();
      p.range = from(pbegin);
      f.params.push_back(std::move(p));
    } while (accept(Tok::Comma));
  }
  expect(Tok::RParen, "to close the parameter list");
  expect(Tok::Semi, "after the function declaration");
  f.range = from(begin);
  return f;
}

//G const_decl: 'const' type IDENT '=' expr ';'
//G var_decl: ( 'var' | 'in' | 'out' | 'inout' ) type IDENT [ '=' expr ] ';'
ValueDecl Parser::value_decl() {
  std::uint32_t begin = here();
  ValueDecl v;
  const Tok kw = take().kind;
  v.is_const = kw == Tok::KwConst;
  v.role = kw == Tok::KwIn      ? VarRole::In
           : kw == Tok::KwOut   ? VarRole::Out
           : kw == Tok::KwInOut ? VarRole::InOut
                                : VarRole::Local;
  v.type = type_name();
  v.name = name();
  if (v.is_const) {
    expect(Tok::Assign, "(a constant needs a value)");
    v.init = expr();
  } else if (accept(Tok::Assign)) {
    v.init = expr();
  }
  expect(Tok::Semi, "after the declaration");
  v.range = from(begin);
  return v;
}

/// The qualifiers of IEC 61131-3's action control (docs/iec.md).
bool is_qualifier(std::string_view word) {
  for (const char *q : {"N", "R", "S", "L", "D", "P", "P0", "P1", "SD", "DS", "SL"})
    if (word == q) return true;
  return false;
}

//G sfc: 'sfc' IDENT '{' { chart_item } '}'
//G fsm: 'fsm' IDENT '{' { chart_item } '}'
Chart Parser::chart(Chart::Kind kind) {
  std::uint32_t begin = here();
  advance();
  Chart c;
  c.kind = kind;
  c.name = name(kind == Chart::Kind::Sfc ? "after 'sfc'" : "after 'fsm'");
  braced("to open the chart", [&] { chart_item(c); });
  c.range = from(begin);
  // Growing by doubling leaves up to half of these unused until the tree is dropped: give back
  // what is worth the copy (a quarter or more; copying a nearly full table of a million places
  // touches 80 MB more to save a few).
  auto trim = [](auto &v) {
    if (v.capacity() - v.size() >= v.size() / 4) v.shrink_to_fit();
  };
  trim(c.places);
  trim(c.transitions);
  return c;
}

//G chart_item: period | team | var_decl | const_decl | action_decl | place | state | transition
void Parser::chart_item(Chart &c) {
  switch (tok_.kind) {
  case Tok::KwPeriod: c.periods.push_back(period()); return;
  case Tok::KwTeam: team_decl(c); return;
  case Tok::KwIn:
  case Tok::KwOut:
  case Tok::KwInOut:
  case Tok::KwVar:
  case Tok::KwConst: c.values.push_back(value_decl()); return;
  case Tok::KwInitial:
  case Tok::KwPlace:
  case Tok::KwState:
  case Tok::KwSuccess:
  case Tok::KwFailure: c.places.push_back(place(c.kind)); return;
  case Tok::Ident:
    // `action` is a keyword only here, before a name (docs/language.md §14): no transition
    // begins with two names.
    if (tok_.text == "action" && peek().kind == Tok::Ident) {
      c.actions.push_back(action_decl());
      return;
    }
    c.transitions.push_back(transition());
    return;
  case Tok::KwTransition:
  case Tok::LParen: c.transitions.push_back(transition()); return;
  default:
    fail(c.kind == Chart::Kind::Sfc ? "expected a place, transition, var, const or period"
                                    : "expected a state, transition, var, const or period");
  }
}

//G period: 'period' DURATION ';'
Period Parser::period() {
  std::uint32_t begin = here();
  advance();
  Token d = expect(Tok::Duration, "after 'period' (e.g. 'period 10ms;')");
  expect(Tok::Semi, "after the period");
  return {d.duration_ms, from(begin)};
}

/// The value of an INT token used as a count (`team N`, `tick N`): decimal, as every integer
/// literal of the language (a leading zero is not octal); -1 if it does not fit a long long.
long long count_of(const Token &n) {
  const std::string digits(n.text);  // strtoll's end pointer points into it
  errno = 0;
  char *end = nullptr;
  long long value = std::strtoll(digits.c_str(), &end, 10);
  return errno != 0 || *end != '\0' ? -1 : value;
}

//G team: 'team' INT ';'
void Parser::team_decl(Chart &c) {
  std::uint32_t begin = here();
  advance();
  Token n = expect(Tok::Int, "after 'team' (the number of agents, e.g. 'team 4;')");
  expect(Tok::Semi, "after the team size");
  // The validator checks the size; a number beyond long long is as wrong as 0.
  c.teams.emplace_back(count_of(n), from(begin));
}

//G place: [ 'initial' ] 'place' IDENT [ 'runs' IDENT ] ( ';' | place_body )
//G state: [ 'initial' | 'success' | 'failure' ] 'state' IDENT [ 'runs' IDENT ] [ 'post' expr ] ( ';' | place_body )
Place Parser::place(Chart::Kind) {
  std::uint32_t begin = here();
  Place p;
  if (accept(Tok::KwInitial)) p.initial = true;
  else if (accept(Tok::KwSuccess)) p.terminal = StateKind::Success;
  else if (accept(Tok::KwFailure)) p.terminal = StateKind::Failure;
  if (accept(Tok::KwState)) {
    p.is_state = true;
  } else if (!accept(Tok::KwPlace)) {
    fail(p.terminal != StateKind::Normal ? "expected 'state'" : "expected 'place' or 'state'");
  }
  p.name = name(p.is_state ? "after 'state'" : "after 'place'");
  if (accept(Tok::KwRuns)) p.extra().runs = name("after 'runs' (the sfc or fsm to run)");
  if (accept(Tok::KwPost)) p.extra().post = expr();
  if (!accept(Tok::Semi)) {
    if (!at(Tok::LBrace)) fail("expected ';' or '{'");
    p.has_body = true;
    place_body(p);
  }
  p.range = from(begin);
  return p;
}

//G place_body: '{' { 'entry' block | 'exit' block | association | statement } '}'
void Parser::place_body(Place &p) {
  braced("", [&] {
    if (at(Tok::KwEntry) || at(Tok::KwExit)) {
      Token kw = take();
      std::uint32_t begin = kw.range.begin;
      Block b = block();
      bool entry = kw.kind == Tok::KwEntry;
      PlaceExtras &x = p.extra();
      std::optional<Block> &slot = entry ? x.entry : x.exit;
      if (slot) {
        diag_.error(kw.range, ErrorKind::DuplicateBlock, fmt::format("second '{}' block in '{}'", kw.text, p.name.text))
            .note(entry ? x.entry_range : x.exit_range, "the first one is here");
        return;
      }
      slot = std::move(b);
      (entry ? x.entry_range : x.exit_range) = from(begin);
      return;
    }
    // A qualifier before a name is an association; no statement begins with two names.
    if (at(Tok::Ident) && is_qualifier(tok_.text) && peek().kind == Tok::Ident) {
      p.extra().associations.push_back(association());
      return;
    }
    p.action.push_back(statement());
  });
}

//G association: QUALIFIER IDENT [ DURATION ] ';'
Association Parser::association() {
  std::uint32_t begin = here();
  Association a;
  a.qualifier = name();
  a.action = name();
  if (at(Tok::Duration)) {
    Token d = take();
    a.duration_ms = d.duration_ms;
    a.duration_range = d.range;
  }
  expect(Tok::Semi, "after the action (e.g. 'N Fill;' or 'L Pump 2s;')");
  a.range = from(begin);
  return a;
}

//G action_decl: 'action' IDENT block
ActionDecl Parser::action_decl() {
  std::uint32_t begin = here();
  advance();
  ActionDecl a;
  a.name = name("after 'action'");
  if (!at(Tok::LBrace)) fail("expected '{' and the action's statements");
  a.body = block();
  a.range = from(begin);
  return a;
}

//G block_decl: 'block' IDENT '{' { var_decl | statement } '}'
BlockDecl Parser::block_decl() {
  std::uint32_t begin = here();
  advance();
  BlockDecl b;
  b.name = name("after 'block'");
  braced("to open the block", [&] {
    if (at(Tok::KwIn) || at(Tok::KwOut) || at(Tok::KwVar)) b.values.push_back(value_decl());
    else if (at(Tok::KwConst))
      fail("expected a statement or a declaration (in, out, var); constants belong at file level");
    else b.body.push_back(statement());
  });
  b.range = from(begin);
  return b;
}

/// `inst.member` after its first name, as one name: the text is kept in File::strings.
Name Parser::member_name(Name first) {
  advance();  // the '.'
  Name member = name("after '.' (a member of the block instance)");
  const SourceRange range{file_, first.range.begin, member.range.end};
  return {out_->strings.emplace_back(fmt::format("{}.{}", first.text, member.text)), range};
}

//G invoke_arguments: '(' IDENT '=' expr { ',' IDENT '=' expr } ')'
void Parser::invoke_arguments(Stmt &s) {
  expect(Tok::LParen, "(the arguments)");
  do {
    std::uint32_t begin = here();
    Stmt a;
    a.kind = Stmt::Kind::Assign;
    a.target = name("(an input of the block)");
    expect(Tok::Assign, "after the input's name (a block's arguments are 'name = value')");
    a.value = expr();
    a.range = from(begin);
    s.then_block.push_back(std::move(a));
  } while (accept(Tok::Comma));
  expect(Tok::RParen, "to close the argument list");
}

//G block: '{' { statement } '}'
Block Parser::block() {
  Block b;
  braced("", [&] { b.push_back(statement()); });
  return b;
}

//G transition: [ 'transition' ] [ IDENT ':' ] place_list '->' place_list [ 'else' ] [ 'when' expr ] ';'
Transition Parser::transition() {
  std::uint32_t begin = here();
  Transition t;
  bool keyword = accept(Tok::KwTransition);
  std::vector<Name> inputs;
  if (at(Tok::Ident)) {
    Name first = name();
    if (accept(Tok::Colon)) {
      t.named = true;
      t.name = std::move(first);
      inputs = place_list(t.parenthesised_inputs);
    } else {
      inputs.push_back(std::move(first));
    }
  } else if (at(Tok::LParen)) {
    inputs = place_list(t.parenthesised_inputs);
  } else {
    fail(keyword ? "expected the transition's input place" : "expected a declaration");
  }
  if (at(Tok::Comma) && !t.parenthesised_inputs)
    fail_hint("expected '->' between a transition's inputs and outputs",
              fmt::format("a transition from several places is a join: write them in brackets, '({}, ...) -> ...'",
                          inputs.front().text));
  expect(Tok::Arrow, "between a transition's inputs and outputs");
  std::vector<Name> outputs = place_list(t.parenthesised_outputs);
  if (at(Tok::Comma) && !t.parenthesised_outputs)
    fail_hint("expected ';' after the transition",
              fmt::format("a transition to several places is a fork: write them in brackets, '{} -> ({}, ...)'",
                          inputs.front().text, outputs.front().text));
  t.set_places(inputs, outputs);
  t.otherwise = accept(Tok::KwElse);
  if (accept(Tok::KwWhen)) t.condition = expr();
  expect(Tok::Semi, "after the transition");
  t.range = from(begin);
  return t;
}

//G place_list: IDENT | '(' IDENT { ',' IDENT } ')'
std::vector<Name> Parser::place_list(bool &parenthesised) {
  std::vector<Name> names;
  if (accept(Tok::LParen)) {
    parenthesised = true;
    do names.push_back(name("(a place)"));
    while (accept(Tok::Comma));
    expect(Tok::RParen, "to close the place list");
  } else {
    names.push_back(name("(a place)"));
  }
  return names;
}

//G toolbox: 'toolbox' IDENT '{' { template } '}'
Toolbox Parser::toolbox() {
  std::uint32_t begin = here();
  advance();
  Toolbox tb;
  tb.name = name("after 'toolbox'");
  braced("to open the toolbox", [&] { tb.templates.push_back(template_decl()); });
  tb.range = from(begin);
  return tb;
}

//G template: ( 'actor' | 'computation' ) IDENT '(' [ tparam { ',' tparam } ] ')' '->' IDENT { '|' IDENT } ';'
//G         | 'supervisor' IDENT '(' [ tparam { ',' tparam } ] ')' 'events' IDENT { ( '|' | ',' ) IDENT } [ 'period' DURATION ] ';'
//G tparam: ( 'in' | 'out' ) type IDENT
Template Parser::template_decl() {
  std::uint32_t begin = here();
  Template t;
  if (accept(Tok::KwActor)) t.kind = Template::Kind::Actor;
  else if (accept(Tok::KwComputation)) t.kind = Template::Kind::Computation;
  else if (accept(Tok::KwSupervisor)) t.kind = Template::Kind::Supervisor;
  else fail("expected 'actor', 'computation' or 'supervisor'");
  t.name = name();
  expect(Tok::LParen, "after the template name");
  if (!at(Tok::RParen)) {
    do {
      std::uint32_t pbegin = here();
      TemplateParam p;
      if (accept(Tok::KwOut)) p.dir = ParamDir::Out;
      else if (!accept(Tok::KwIn)) fail("expected 'in' or 'out'");
      p.type = type_name();
      p.name = name("(the parameter's name)");
      p.range = from(pbegin);
      t.params.push_back(std::move(p));
    } while (accept(Tok::Comma));
  }
  expect(Tok::RParen, "to close the parameter list");
  if (t.kind == Template::Kind::Supervisor) {
    expect(Tok::KwEvents, "(a supervisor lists its events: 'events A | B')");
    do t.outcomes.push_back(name("(an event)"));
    while (accept(Tok::Pipe) || accept(Tok::Comma));
    if (at(Tok::KwPeriod)) {
      std::uint32_t pbegin = here();
      advance();
      Token d = expect(Tok::Duration, "after 'period'");
      t.period = Period{d.duration_ms, from(pbegin)};
    }
  } else {
    expect(Tok::Arrow, "(an actor lists its result states: '-> A | B')");
    do t.outcomes.push_back(name("(a result state)"));
    while (accept(Tok::Pipe));
  }
  expect(Tok::Semi, "after the template");
  t.range = from(begin);
  return t;
}

//G plan: 'plan' IDENT '{' { plan_item } '}'
Plan Parser::plan() {
  std::uint32_t begin = here();
  advance();
  Plan p;
  p.name = name("after 'plan'");
  braced("to open the plan", [&] { plan_item(p); });
  p.range = from(begin);
  return p;
}

//G plan_item: config | supervise | 'start' IDENT ';' | actor_use
//G config: 'config' '{' { type IDENT [ '=' expr ] ';' } '}'
void Parser::plan_item(Plan &p) {
  switch (tok_.kind) {
  case Tok::KwConfig: {
    advance();
    std::vector<ConfigEntry> entries;
    braced("after 'config'", [&] {
      std::uint32_t begin = here();
      ConfigEntry e;
      e.type = type_name();
      e.name = name("(the entry's name)");
      if (accept(Tok::Assign)) e.init = expr();
      expect(Tok::Semi, "after the config entry");
      e.range = from(begin);
      entries.push_back(std::move(e));
    });
    p.config_blocks.push_back(std::move(entries));
    return;
  }
  case Tok::KwSupervise: p.global_supervisors.push_back(supervise()); return;
  case Tok::KwStart: {
    advance();
    p.starts.push_back(name("after 'start'"));
    expect(Tok::Semi, "after the start actor");
    return;
  }
  case Tok::KwActor:
  case Tok::KwComputation: p.actors.push_back(actor_use()); return;
  default: fail("expected 'actor', 'supervise', 'start' or 'config'");
  }
}

//G supervise: 'supervise' IDENT ':' IDENT '(' [ expr { ',' expr } ] ')' '{' { rule } '}'
Supervise Parser::supervise() {
  std::uint32_t begin = here();
  advance();
  Supervise s;
  s.name = name("after 'supervise'");
  expect(Tok::Colon, "after the supervisor's name");
  s.template_name = name("(the supervisor template)");
  s.args = arguments();
  braced("for the supervisor's events", [&] { s.rules.push_back(rule()); });
  s.range = from(begin);
  return s;
}

//G actor_use: ( 'actor' | 'computation' ) IDENT ':' IDENT '(' [ expr { ',' expr } ] ')' ( ';' | '{' { rule | supervise } '}' )
ActorUse Parser::actor_use() {
  std::uint32_t begin = here();
  ActorUse a;
  a.written_as_computation = take().kind == Tok::KwComputation;
  a.name = name();
  expect(Tok::Colon, "after the actor's name");
  a.template_name = name("(the template or sub-plan)");
  a.args = arguments();
  if (!accept(Tok::Semi)) {
    braced("for the actor's rules", [&] {
      if (at(Tok::KwSupervise)) a.supervisors.push_back(supervise());
      else a.rules.push_back(rule());
    });
  }
  a.range = from(begin);
  return a;
}

//G rule: IDENT '->' ( IDENT | 'terminate' | 'ignore' ) ';'
Rule Parser::rule() {
  std::uint32_t begin = here();
  Rule r;
  r.outcome = name("(a result state or event)");
  expect(Tok::Arrow, "after the state or event");
  if (at(Tok::KwTerminate) || at(Tok::KwIgnore)) {
    Token t = take();
    r.target = t.kind == Tok::KwTerminate ? Rule::Target::Terminate : Rule::Target::Ignore;
    r.target_name = {t.text, t.range};
  } else {
    r.target_name = name("(an actor, 'terminate' or 'ignore')");
  }
  expect(Tok::Semi, "after the rule");
  r.range = from(begin);
  return r;
}

//G arguments: '(' [ expr { ',' expr } ] ')'
ExprList Parser::arguments() {
  std::vector<ExprPtr> args;
  expect(Tok::LParen, "(the argument list)");
  int highest = 0;
  if (!at(Tok::RParen)) {
    do {
      args.push_back(expr());
      highest = std::max(highest, height_);
    } while (accept(Tok::Comma));
  }
  expect(Tok::RParen, "to close the argument list");
  height_ = highest;
  return ExprList(std::move(args));
}

//G active_arguments: '(' path ')' | arguments
//G path: IDENT '.' IDENT { '.' IDENT }
ExprList Parser::active_arguments() {
  if (!(at(Tok::LParen) && peek().kind == Tok::Ident)) return arguments();
  advance();
  Name first = name();
  std::vector<ExprPtr> args;
  if (at(Tok::Dot)) {
    args.push_back(path(std::move(first)));
  } else {
    // `active(P)`, or an expression that starts with a name: the validator says what is wrong.
    auto e = make(Expr::Kind::Name, first.range);
    e->name = std::move(first);
    args.push_back(std::move(e));
    if (!at(Tok::RParen) && !at(Tok::Comma)) fail("expected ')' after the place or state");
    while (accept(Tok::Comma)) args.push_back(expr());
  }
  expect(Tok::RParen, "to close the argument list");
  return ExprList(std::move(args));
}

/// The rest of `P.Q.R` after its first name.
ExprPtr Parser::path(Name first) {
  std::uint32_t begin = first.range.begin;
  auto e = make(Expr::Kind::Path, first.range);
  auto part = [this](Name n) {
    auto x = make(Expr::Kind::Name, n.range);
    x->name = std::move(n);
    return x;
  };
  e->args.push_back(part(std::move(first)));
  while (accept(Tok::Dot)) e->args.push_back(part(name("after '.' (a place or state of the sub-chart)")));
  e->range = from(begin);
  return e;
}

//G statement: call ';' | IDENT ( '=' | '+=' | '-=' ) expr ';' | VERBATIM | if_statement
//G   | loop_statement | 'break' ';' | 'return' ';'
Stmt Parser::statement() {
  std::uint32_t begin = here();
  Stmt s;
  if (at(Tok::KwIf)) return if_statement();
  if (at(Tok::KwWhile) || at(Tok::KwDo) || at(Tok::KwFor)) return loop_statement();
  if (at(Tok::KwBreak) || at(Tok::KwReturn)) {
    s.kind = at(Tok::KwBreak) ? Stmt::Kind::Break : Stmt::Kind::Return;
    const char *word = at(Tok::KwBreak) ? "after 'break'" : "after 'return' (a statement returns no value)";
    advance();
    expect(Tok::Semi, word);
    s.range = from(begin);
    return s;
  }
  if (at(Tok::KwElse)) fail("expected a statement ('else' must follow the block of an 'if')");
  if (at(Tok::Verbatim)) {
    Token t = take();
    s.kind = Stmt::Kind::Verbatim;
    s.verbatim = t.value;
    s.range = t.range;
    return s;
  }
  if (!at(Tok::Ident)) fail("expected a statement (a call, an assignment, 'if', a loop or %{ ... %})");
  Name target = name();
  if (at(Tok::Dot)) target = member_name(std::move(target));  // `inst.a = e;` sets an input
  if (at(Tok::LParen) && peek().kind == Tok::Ident && target.text.find('.') == std::string_view::npos) {
    // `inst(a = e)`: a block call names its arguments; a function call never starts with `x =`.
    if (assign_follows(peek().range.end)) {
      s.kind = Stmt::Kind::Invoke;
      s.target = std::move(target);
      invoke_arguments(s);
      expect(Tok::Semi, "after the statement");
      s.range = from(begin);
      return s;
    }
  }
  if (at(Tok::Assign) || at(Tok::PlusAssign) || at(Tok::MinusAssign)) {
    s = assignment(std::move(target), begin);
  } else if (at(Tok::LParen)) {
    auto call = make(Expr::Kind::Call, target.range);
    call->name = std::move(target);
    call->args = arguments();
    call->range = from(begin);
    s.kind = Stmt::Kind::Call;
    s.call = std::move(call);
  } else {
    fail("expected '(' or an assignment after the name");
  }
  expect(Tok::Semi, "after the statement");
  s.range = from(begin);
  return s;
}

/// `NAME op expr` after its name, without the `;`: a statement, or a part of a `for`'s header.
Stmt Parser::assignment(Name target, std::uint32_t begin) {
  Stmt s;
  Tok op = take().kind;
  s.kind = Stmt::Kind::Assign;
  s.target = std::move(target);
  s.assign_op = op == Tok::Assign ? AssignOp::Set : op == Tok::PlusAssign ? AssignOp::Add : AssignOp::Sub;
  s.value = expr();
  s.range = from(begin);
  return s;
}

ExprPtr Parser::loop_condition(const char *keyword) {
  expect(Tok::LParen, fmt::format("after '{}'", keyword).c_str());
  ExprPtr condition = expr();
  expect(Tok::RParen, fmt::format("to close the condition of '{}'", keyword).c_str());
  return condition;
}

//G loop_statement: 'while' '(' expr ')' block | 'do' block 'while' '(' expr ')' ';'
//G   | 'for' '(' IDENT ( '=' | '+=' | '-=' ) expr ';' expr ';' IDENT ( '=' | '+=' | '-=' ) expr ')' block
Stmt Parser::loop_statement() {
  DepthGuard guard(*this);
  std::uint32_t begin = here();
  Stmt s;
  const Tok keyword = take().kind;
  if (keyword == Tok::KwWhile) {
    s.kind = Stmt::Kind::While;
    s.value = loop_condition("while");
    if (!at(Tok::LBrace)) fail("expected '{' after the condition of 'while' (a loop's body is a block)");
    s.then_block = block();
  } else if (keyword == Tok::KwDo) {
    s.kind = Stmt::Kind::DoWhile;
    if (!at(Tok::LBrace)) fail("expected '{' after 'do' (a loop's body is a block)");
    s.then_block = block();
    if (!at(Tok::KwWhile)) fail("expected 'while' after the body of 'do'");
    advance();
    s.value = loop_condition("while");
    expect(Tok::Semi, "after 'do { ... } while (...)'");
  } else {
    // C's `for`, restricted to what a counted loop needs: an assignment in the first and third
    // parts, a condition in the second, each one required.
    s.kind = Stmt::Kind::For;
    expect(Tok::LParen, "after 'for'");
    try {
      for (int part = 0; part < 2; ++part) {
        const char *what = part == 0 ? "expected an assignment as the first part of 'for' (i = 0)"
                                     : "expected an assignment as the third part of 'for' (i += 1)";
        std::uint32_t at_part = here();
        if (!at(Tok::Ident)) fail(what);
        Name target = name();
        if (!at(Tok::Assign) && !at(Tok::PlusAssign) && !at(Tok::MinusAssign)) fail(what);
        s.else_block.push_back(assignment(std::move(target), at_part));
        if (part == 0) {
          expect(Tok::Semi, "after the first part of 'for'");
          if (at(Tok::Semi)) fail("expected the condition of 'for' (gfec's 'for' needs all three parts)");
          s.value = expr();
          expect(Tok::Semi, "after the condition of 'for'");
        }
      }
      expect(Tok::RParen, "to close the header of 'for'");
    } catch (const SyntaxError &) {
      // The header's own `;`s would stop the usual recovery inside it: skip to its `)` and read
      // the body, so one mistake in the header is one error. The tree is not validated.
      for (int depth = 0; !at(Tok::End) && !at(Tok::LBrace) && !at(Tok::RBrace);) {
        if (at(Tok::LParen)) ++depth;
        if (at(Tok::RParen) && depth-- == 0) {
          advance();
          break;
        }
        advance();
      }
      s.else_block = std::vector<Stmt>();
    }
    if (!at(Tok::LBrace)) fail("expected '{' after the header of 'for' (a loop's body is a block)");
    s.then_block = block();
  }
  s.range = from(begin);
  return s;
}

//G if_statement: 'if' '(' expr ')' block [ 'else' ( if_statement | block ) ]
Stmt Parser::if_statement(int chain) {
  // A block inside an `if` is one level deeper; the `if` of an `else if` is not (it is the next
  // branch of a flat chain) but still a level of the tree every later walk recurses along, so
  // chains have a bound of their own.
  std::optional<DepthGuard> guard;
  if (chain == 0) guard.emplace(*this);
  if (chain >= kMaxElseIfChain) {
    diag_.error(tok_.range, ErrorKind::Nesting,
                fmt::format("an 'else if' chain longer than {} branches", kMaxElseIfChain));
    throw SyntaxError{};
  }
  std::uint32_t begin = here();
  advance();
  Stmt s;
  s.kind = Stmt::Kind::If;
  expect(Tok::LParen, "after 'if'");
  s.value = expr();
  expect(Tok::RParen, "to close the condition of 'if'");
  if (!at(Tok::LBrace)) fail("expected '{' after the condition of 'if' (the branches of an 'if' are blocks)");
  s.then_block = block();
  if (accept(Tok::KwElse)) {
    s.has_else = true;
    if (at(Tok::KwIf)) {
      s.else_if = true;
      s.else_block.push_back(if_statement(chain + 1));
    } else {
      if (!at(Tok::LBrace)) fail("expected '{' or 'if' after 'else'");
      s.else_block = block();
    }
  }
  s.range = from(begin);
  return s;
}

//G expr: or ;  or: and { '||' and } ;  and: eq { '&&' eq } ;  eq: rel { ( '==' | '!=' ) rel } ;
//G rel: add { ( '<' | '<=' | '>' | '>=' ) add } ;  add: mul { ( '+' | '-' ) mul } ;
//G mul: unary { ( '*' | '/' | '%' ) unary }
ExprPtr Parser::binary(int min_precedence) {
  DepthGuard guard(*this);
  std::uint32_t begin = here();
  ExprPtr left = unary();
  int left_height = height_;
  for (;;) {
    BinaryOp op;
    switch (tok_.kind) {
    case Tok::OrOr: op = BinaryOp::Or; break;
    case Tok::AndAnd: op = BinaryOp::And; break;
    case Tok::EqEq: op = BinaryOp::Eq; break;
    case Tok::NotEq: op = BinaryOp::Ne; break;
    case Tok::Lt: op = BinaryOp::Lt; break;
    case Tok::Le: op = BinaryOp::Le; break;
    case Tok::Gt: op = BinaryOp::Gt; break;
    case Tok::Ge: op = BinaryOp::Ge; break;
    case Tok::Plus: op = BinaryOp::Add; break;
    case Tok::Minus: op = BinaryOp::Sub; break;
    case Tok::Star: op = BinaryOp::Mul; break;
    case Tok::Slash: op = BinaryOp::Div; break;
    case Tok::Percent: op = BinaryOp::Mod; break;
    case Tok::Assign:
      // No expression is followed by '=': "Button() = true" meant a comparison.
      fail_hint("expected an operator", "'=' assigns; to compare, write '=='", tok_.range, "==");
    default: height_ = left_height; return left;
    }
    int prec = precedence(op);
    if (prec < min_precedence) {
      height_ = left_height;
      return left;
    }
    SourceRange op_range = tok_.range;
    advance();
    ExprPtr right = binary(prec + 1);  // left-associative
    left_height = grow(std::max(left_height, height_), op_range);
    auto e = make(Expr::Kind::Binary, from(begin));
    e->binary_op = op;
    e->set_op_range(op_range);
    e->args.push_back(std::move(left));
    e->args.push_back(std::move(right));
    left = std::move(e);
  }
}

//G unary: ( '!' | '-' ) unary | primary
ExprPtr Parser::unary() {
  if (at(Tok::Not) || at(Tok::Minus)) {
    DepthGuard guard(*this);
    std::uint32_t begin = here();
    SourceRange op_range = tok_.range;
    UnaryOp op = take().kind == Tok::Not ? UnaryOp::Not : UnaryOp::Neg;
    ExprPtr operand = unary();
    height_ = grow(height_, from(begin));
    auto e = make(Expr::Kind::Unary, from(begin));
    e->unary_op = op;
    e->set_op_range(op_range);
    e->args.push_back(std::move(operand));
    return e;
  }
  return primary();
}

//G primary: INT | FLOAT | STRING | DURATION | 'true' | 'false' | IDENT [ arguments ] | 'team' arguments
//G         | '(' expr ')' | 'active' active_arguments
ExprPtr Parser::primary() {
  std::uint32_t begin = here();
  height_ = 1;  // a leaf; calls and brackets add theirs below
  if (in_test_)
    if (ExprPtr e = test_operand()) return e;
  switch (tok_.kind) {
  case Tok::KwTeam: {
    // `team(S)`: a built-in like `elapsed(P)`, though its name is a keyword (`team N;`).
    Token t = take();
    auto e = make(Expr::Kind::Call, t.range);
    e->name = {t.text, t.range};
    if (!at(Tok::LParen)) fail("expected '(' after 'team' (team(S) counts the other agents in state S)");
    e->args = arguments();
    e->range = from(begin);
    return e;
  }
  case Tok::Int:
  case Tok::Float: {
    Token t = take();
    // "2 s": the unit came apart from its number, which the lexer only joins when they touch.
    if (at(Tok::Ident) && (tok_.text == "s" || tok_.text == "ms")) {
      std::string joined = fmt::format("{}{}", t.text, tok_.text);
      fail_hint("expected an operator after the number",
                fmt::format("durations are written without a space: '{}'", joined),
                {file_, t.range.begin, tok_.range.end}, joined);
    }
    auto e = make(t.kind == Tok::Int ? Expr::Kind::Int : Expr::Kind::Float, t.range);
    e->name = {t.text, t.range};
    return e;
  }
  case Tok::String: {
    Token t = take();
    auto e = make(Expr::Kind::String, t.range);
    e->name = {out_->strings.emplace_back(std::move(t.value)), t.range};
    return e;
  }
  case Tok::Duration: {
    Token t = take();
    auto e = make(Expr::Kind::Duration, t.range);
    e->duration_ms = t.duration_ms;
    e->name = {t.text, t.range};
    return e;
  }
  case Tok::KwTrue:
  case Tok::KwFalse: {
    Token t = take();
    auto e = make(Expr::Kind::Bool, t.range);
    e->bool_value = t.kind == Tok::KwTrue;
    return e;
  }
  case Tok::Ident: {
    Name n = name();
    // `inst.q`, an output of a block instance; the validator says what any other path is.
    if (at(Tok::Dot)) return path(std::move(n));
    if (!at(Tok::LParen)) {
      auto e = make(Expr::Kind::Name, n.range);
      e->name = std::move(n);
      return e;
    }
    auto e = make(Expr::Kind::Call, n.range);
    bool active = n.text == "active";
    e->name = std::move(n);
    e->args = active ? active_arguments() : arguments();
    e->range = from(begin);
    height_ = grow(height_, e->range);
    return e;
  }
  case Tok::LParen: {
    DepthGuard guard(*this);
    advance();
    ExprPtr inner = expr();
    expect(Tok::RParen, "to close the bracket");
    height_ = grow(height_, from(begin));
    auto e = make(Expr::Kind::Paren, from(begin));
    e->args.push_back(std::move(inner));
    return e;
  }
  default: fail("expected an expression");
  }
}

// ------------------------------------------------------------ scenario tests

//G test: 'test' STRING 'of' IDENT [ 'agents' INT ] '{' { test_step } '}'
Test Parser::test_decl() {
  std::uint32_t begin = here();
  advance();
  Test t;
  Token name = expect(Tok::String, "(the test's name) after 'test'");
  t.name = name.value;
  t.name_range = name.range;
  if (!at_word("of")) fail("expected 'of' and the chart after the test's name");
  advance();
  t.chart = this->name("(the chart to test) after 'of'");
  if (at_word("agents")) {
    std::uint32_t agents_begin = here();
    advance();
    Token n = expect(Tok::Int, "after 'agents' (how many agents of the team machine run, e.g. 'agents 3')");
    // The validator checks it against the team size; a number beyond long long is too large.
    const long long k = count_of(n);
    t.agents = k < 0 ? LLONG_MAX : k;
    t.agents_range = from(agents_begin);
  }
  in_test_ = true;
  try {
    braced("to begin the test's steps", [&] { test_step(t, -1, {}); });
  } catch (const SyntaxError &) {
    in_test_ = false;
    throw;
  }
  in_test_ = false;
  t.range = from(begin);
  return t;
}

//G test_step: 'tick' [ INT ] ';' | 'set' IDENT '=' expr ';' | 'expect' expr ';'
//G           | 'agent' INT '{' { test_step } '}'
void Parser::test_step(Test &test, long long agent, SourceRange agent_range) {
  std::uint32_t begin = here();
  TestStep step;
  step.agent = agent;
  step.agent_range = agent_range;
  if (at_word("agent") && peek().kind == Tok::Int) {
    // The steps of one agent of a team machine.
    if (agent != -1) fail("'agent' blocks do not nest: end one agent's block before the next");
    advance();
    Token n = take();
    const long long k = count_of(n);
    const SourceRange scope = from(begin);
    braced("to begin the agent's steps", [&] { test_step(test, k < 0 ? LLONG_MAX : k, scope); });
    return;
  }
  if (at_word("tick")) {
    advance();
    step.kind = TestStep::Kind::Tick;
    if (at(Tok::Int)) {
      Token n = take();
      // Too large for a count is as wrong as 0; the validator says so at the number.
      step.count = count_of(n);
      step.value = make(Expr::Kind::Int, n.range);
      step.value->name = {n.text, n.range};
    } else if (at(Tok::Duration)) {
      // `tick 5s;`: as many ticks as the chart's period makes it (the validator counts them).
      Token d = take();
      step.count = 0;
      step.value = make(Expr::Kind::Duration, d.range);
      step.value->duration_ms = d.duration_ms;
      step.value->name = {d.text, d.range};
    } else if (!at(Tok::Semi)) {
      fail("expected a number of ticks, a duration or ';' after 'tick'");
    }
  } else if (at_word("set")) {
    advance();
    step.kind = TestStep::Kind::Set;
    step.function = name("(a sensing function) after 'set'");
    expect(Tok::Assign, "after the function's name");
    step.value = expr();
  } else if (at_word("expect")) {
    advance();
    step.kind = TestStep::Kind::Expect;
    step.value = expr();
  } else {
    fail("expected a test step ('tick', 'set' or 'expect')");
  }
  expect(Tok::Semi, "after the step");
  step.range = from(begin);
  test.steps.push_back(std::move(step));
}

//G test_operand: 'called' IDENT [ arguments ] | 'calls' IDENT | 'state' '(' IDENT ')' | 'status'
// (inside a test block only). They parse as calls of the keyword, which no chart can declare:
// `called F(1)` is Call "called" with args [Call F(1)], `status` is Name "status".
ExprPtr Parser::test_operand() {
  std::uint32_t begin = here();
  if (at_word("called") || at_word("calls")) {
    Token word = take();
    auto e = make(Expr::Kind::Call, word.range);
    e->name = {word.text, word.range};
    Name f = name(word.text == "called" ? "(the function) after 'called'" : "(the function) after 'calls'");
    auto target = make(Expr::Kind::Name, f.range);
    if (word.text == "calls" && at(Tok::LParen))
      fail("'calls F' counts every call of F, whatever its arguments; 'called F(ARGS)' asks for one with "
           "these arguments");
    if (word.text == "called" && at(Tok::LParen)) {
      target->kind = Expr::Kind::Call;
      target->args = arguments();
      target->range = from(f.range.begin);
    }
    target->name = std::move(f);
    e->args.push_back(std::move(target));
    e->range = from(begin);
    return e;
  }
  if (at(Tok::KwState) && peek().kind == Tok::LParen) {
    Token word = take();
    auto e = make(Expr::Kind::Call, word.range);
    e->name = {"state", word.range};
    e->args = arguments();
    e->range = from(begin);
    return e;
  }
  if (at_word("status")) {
    Token word = take();
    auto e = make(Expr::Kind::Name, word.range);
    e->name = {"status", word.range};
    return e;
  }
  return nullptr;
}

}  // namespace

std::unique_ptr<ast::File> parse_file(const SourceManager &sources, FileId file, Diagnostics &diag) {
  return Parser(sources, file, diag).parse();
}

}  // namespace gfec
