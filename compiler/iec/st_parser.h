// The parser of structured text, shared by the fragment entry points (st_fragment.h: a PLCopen
// file's <ST> bodies) and the ST reader (st_reader.h: a whole .st file). One class over three
// files, as the ALICA reader's: st_expressions.cc (expressions), st_statements.cc (statement
// lists), st_reader.cc (POUs, SFC elements, configurations). Internal to compiler/iec/.
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "iec/iec_model.h"
#include "iec/st_fragment.h"
#include "iec/st_lexer.h"

#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gfec::iec {

class StParser {
public:
  StParser(std::string_view text, const FragmentPlace &place, std::deque<std::string> &strings, Diagnostics &diag);

  // ---------------------------------------------------------- st_expressions.cc
  /// One expression; null when it could not be read (reported).
  ast::ExprPtr expression();

  // ---------------------------------------------------------- st_statements.cc
  /// Statements up to a keyword that ends a block (END_..., ELSIF, ELSE, a SFC element) or the
  /// end; in a CASE, up to the next label too. Statements that could not be read are reported
  /// and left out.
  ast::Block statements(bool in_case = false);

  // ---------------------------------------------------------- st_reader.cc
  /// The whole text as POUs and configurations.
  void file(Project &project);

  // ---------------------------------------------------------- tokens
  const StToken &tok() const { return toks_[pos_]; }
  const StToken &peek(std::size_t k = 1) const { return pos_ + k < toks_.size() ? toks_[pos_ + k] : toks_.back(); }
  void next() {
    if (pos_ + 1 < toks_.size()) ++pos_;
  }
  bool at_end() const { return tok().kind == StTok::End; }
  bool keyword(std::string_view kw) const { return is_keyword(tok(), kw); }
  /// Whether the current token ends a statement list (END_..., ELSIF, ELSE, UNTIL, an SFC element).
  bool block_end() const;
  SourceRange range(const StToken &t) const { return place_.range(t.begin, t.end); }
  SourceRange range(const StToken &a, const StToken &b) const { return place_.range(a.begin, b.end); }
  ast::Name name(const StToken &t) const { return {t.text, range(t)}; }
  /// How the current token is quoted in a message: 'END_IF', or "the end of the text".
  std::string quoted() const;
  /// Reports an error, unless one was reported since the last resync() (no cascades).
  Diagnostic &error(const SourceRange &at, std::string message, ErrorKind kind = ErrorKind::Syntax);
  Diagnostic &not_supported(const SourceRange &at, std::string message) {
    return error(at, std::move(message), ErrorKind::NotSupported);
  }
  /// After an error: the parse may report again.
  void resync() { quiet_ = false; }
  /// Skips to just past the next `;` at bracket depth 0, stopping before a block end.
  void skip_statement();
  /// Skips past `END_<what>` (nested `<what>` ... `END_<what>` counted) and a `;` after it.
  void skip_block(std::string_view what);
  /// `;` expected here.
  bool expect_semi(const char *after);
  std::deque<std::string> &strings() { return strings_; }

private:
  struct Node {
    ast::ExprPtr e;
    int height = 0;
  };
  Node or_expr();
  Node xor_expr();
  Node and_expr();
  Node equality();
  Node comparison();
  Node additive();
  Node term();
  Node power();
  Node unary();
  Node primary();
  Node binary(Node lhs, Node rhs, BinaryOp op, const StToken &at);
  Node literal();
  Node name_use();
  /// `MAX(a, b)`, `LIMIT(MN := 0, IN := x, MX := 9)`: a standard function the chart language has
  /// (`chart` its name there), once `t` and the `(` after it are read.
  Node standard_call(const StToken &t, const char *chart);

  void statement(ast::Block &out);
  /// `:= value;` once the target is read: an assignment to `target`, `first` its first token.
  void assignment(ast::Block &out, const StToken &first, const ast::Name &target);
  void if_statement(ast::Block &out);
  /// `inst(IN := x, Q => y);`: an Invoke, then `y := inst.Q` for each output bound.
  void block_call(ast::Block &out);
  void case_statement(ast::Block &out);
  void loop_statement(ast::Block &out);
  /// FOR's `i := a TO b BY s` as the header of a chart `for`; false when reported.
  bool for_header(ast::Stmt &loop, const StToken &start);
  bool case_label_ahead() const;

  // st_reader.cc
  void pou(Project &project, PouKind kind, std::string_view end);
  /// A section of variables of `pou`, of the kind its keyword says, or `given` (VAR_GLOBAL's).
  void var_section(Pou &pou, std::optional<Section> given = std::nullopt);
  /// `VAR_GLOBAL [CONSTANT | RETAIN ...] ... END_VAR` of a configuration: into project.globals.
  void global_section(Project &project);
  /// `TYPE ... END_TYPE`: the aliases (`Level : INT;`) into Project::aliases; any other data
  /// type is reported not supported yet, at its name.
  void type_section(Project &project);
  /// A FUNCTION_BLOCK's variables and ST body (an SFC body is not supported yet).
  void function_block(Pou &pou, const StToken &start, std::string_view end);
  /// `VAR_INPUT`, `VAR`, `VAR_OUTPUT` ...: a section of variables starts at `t`.
  bool var_section_start(const StToken &t) const;
  /// The POU's range, and its `END_...` read (or reported missing).
  void close_pou(Pou &p, const StToken &start, std::string_view end);
  void declaration(Pou &pou, Section section, bool constant, std::string_view end);
  void step(Pou &pou, bool initial);
  void transition(Pou &pou);
  void action(Pou &pou);
  void configuration(Project &project);
  void resource(Project &project, std::string_view end);
  void task(Project &project);
  void program_instance(Project &project);
  std::vector<ast::Name> step_list(bool &parenthesised);
  /// One level deeper (`what`: "expression", "statements"): false, reported at `at`, past
  /// kMaxStNesting. The caller that got true goes back up with `--depth_`.
  bool deeper(const SourceRange &at, const char *what);

  std::string_view text_;
  const FragmentPlace &place_;
  std::deque<std::string> &strings_;
  Diagnostics &diag_;
  std::vector<StToken> toks_;
  std::size_t pos_ = 0;
  bool quiet_ = false;
  int depth_ = 0;
  int loops_ = 0;  ///< the loops around the statement being read: EXIT needs one
};

/// Statement-list and expression nesting past which the parser stops (the validator and the back
/// ends recurse on the tree): as the chart parser's.
constexpr int kMaxStNesting = 256;

}  // namespace gfec::iec
