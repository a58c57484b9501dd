// Chart expressions and statements as C (docs/language.md §4): the chart's own text, made readable
// and warning-free, with `#line` back to the chart around every statement.
//
// Where C would read the chart differently, the C says what the chart means:
//  - int literals are written by their value in decimal (`010` is 10 in a chart, 8 in C), and a
//    float constant as a float (`0.1f`), not as the double C would read;
//  - a floating value that becomes an int (an argument, `=`, `+=`, `-=`, an initialiser) is
//    converted by an explicit `(int)` cast, as is an int constant a float cannot hold exactly;
//  - calls are made left to right. C leaves the order of an operator's operands and of a call's
//    arguments open, so where two or more of them call functions, all but the last of those are
//    evaluated first into temporaries: `gfec_t0 = S2(); A(gfec_t0, S0() < 2);`, or in an
//    expression `(gfec_t0 = S2(), A(gfec_t0, S0() < 2))`. `&&` and `||` are sequenced by C.
#pragma once

#include "c_context.h"
#include "code_writer.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gfec::c_backend {

/// The C type of a chart type: "bool", "int", "float", "double".
const char *c_type(model::Type type);

/// The temporaries of one function of the engine that keep calls in the chart's order: named
/// `gfec_t0`, `gfec_t1`, ... (EngineContext::temp_prefix) through the whole function, so that no two
/// of them meet in nested blocks; each is declared at the top of the block that uses it.
class Temporaries {
public:
  explicit Temporaries(std::string prefix) : prefix_(std::move(prefix)) {}

  /// A new temporary of `type`; it is pending until declare() writes its declaration.
  std::string add(model::Type type);
  /// Some temporary has been added since the last declare().
  bool pending() const { return !pending_.empty(); }
  /// How many have been added so far.
  int count() const { return count_; }
  /// Declares the pending temporaries at the current line, one line per type
  /// (`int gfec_t0, gfec_t2;`), and forgets them.
  void declare(CodeWriter &w);
  /// The same declarations as lines of text, forgetting them.
  std::vector<std::string> declarations();
  /// Sets the pending temporaries aside (`take`) and back (`restore`): an `if` branch declares
  /// its own at its top, in the smallest scope that uses them.
  std::vector<std::pair<model::Type, std::string>> take() { return std::move(pending_); }
  void restore(std::vector<std::pair<model::Type, std::string>> pending) { pending_ = std::move(pending); }

private:
  std::string prefix_;
  int count_ = 0;
  std::vector<std::pair<model::Type, std::string>> pending_;
};

/// `e` as one C expression. Temporaries it needs are added to `temps`.
std::string c_expr(const EngineContext &c, const model::Expr &e, Temporaries &temps);

/// `e` as the operand of `&&`: parenthesised unless it already is a bracket or a primary.
/// `at_start`: `e` is a transition's condition (active() and the like read the start of the tick).
/// `from`: the state an fsm's (or a sequential sfc's) transition leaves, none otherwise.
std::string c_condition(const EngineContext &c, const model::Expr &e, Temporaries &temps, bool at_start = false,
                        model::PlaceId from = {});

/// `e` as the whole test of an `if`: as c_condition(), except that an equality comparison is
/// not bracketed (clang -Wparentheses-equality takes `if ((a == b))` for a mistyped `=`).
std::string c_test(const EngineContext &c, const model::Expr &e, Temporaries &temps, bool at_start = false,
                   model::PlaceId from = {});

/// `e` as the condition of an `if` statement, written inside its brackets: `X()`, `n > 2`, or
/// where calls need temporaries, the bracketed comma expression `(gfec_t0 = N(), gfec_t0 + M() > 2)`.
std::string c_if_test(const EngineContext &c, const model::Expr &e, Temporaries &temps);

/// A postcondition as the statement that asserts it: `assert(e);`, or where keeping the calls
/// in order needs temporaries, `gfec_t0 = S0(); gfec_t1 = gfec_t0 < S1(); assert(gfec_t1);`
/// (code checkers flag an assertion that assigns).
std::string c_assertion(const EngineContext &c, const model::Expr &e, Temporaries &temps);

/// A constant expression (a var's initialiser: it calls nothing) as a value of type `to`,
/// converted as the model converts it.
std::string c_value(const EngineContext &c, const model::Expr &e, model::Type to);

/// Whether the engine writes `e`, a condition of `&&`, `||` and `!` over tests that read without
/// side effects, as a constant because those tests cannot change its value (what gcc and clang
/// would decide and warn about). Such a condition reads nothing at run time.
bool written_as_constant(const EngineContext &c, const model::Expr &e);

/// `bool f(void)`, `void Motor(int side, float speed)`: an interface function's prototype;
/// `first`, if not empty, is a parameter before the function's own (`void *ctx`, --context);
/// `names`, if given, the parameters' names to write instead of the declared ones.
std::string c_prototype(const model::Function &f, const std::string &first = "",
                        const std::vector<std::string> &names = {});

/// The statements as C, one line each (empty for verbatim code), rendered before they are
/// written so that the temporaries they need can be declared first, at the top of the block.
/// An `if` is its test (what goes between the brackets of `if ( )`) followed by each branch,
/// then and else: one entry with the declarations of the branch's own temporaries (empty if
/// none), then the branch's statements the same way, in textual order.
std::vector<std::string> c_statements(const EngineContext &c, const std::vector<model::Stmt> &stmts,
                                      Temporaries &temps);

/// The statements, one per line at the current indentation, each preceded by `#line` to the
/// chart where needed; `text` is what c_statements() made of them. The caller writes
/// `line_back()` after the code that follows.
void emit_statements(CodeWriter &w, const EngineContext &c, const std::vector<model::Stmt> &stmts,
                     const std::vector<std::string> &text);

}  // namespace gfec::c_backend
