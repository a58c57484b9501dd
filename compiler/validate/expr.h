// Chart expressions and statements (§4): name resolution, typing, lowering to the model.
// Erroneous sub-expressions lower to nothing, which silences every check above them: each
// mistake is reported once, where it is.
#pragma once

#include "validate/context.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gfec::validation {

/// The most agents a team machine may have (`team N;`): each engine keeps a report per agent.
constexpr long long kMaxTeam = 1024;

/// A chart's own names, and what its expressions use, while the chart is validated.
struct ChartScope {
  ChartScope(ast::Chart &a, model::Chart &o, model::ChartId i) : ast(a), out(o), index(i) {}

  ast::Chart &ast;    ///< its bodies and conditions are released as they are lowered
  model::Chart &out;  ///< being filled in; its period is set before any expression is lowered
  model::ChartId index;
  /// Places (or states), named transitions, vars and the chart's constants.
  Namespace names;
  bool period_reported = false;           ///< "needs a period" is said once per chart
  std::set<std::string> unknown;          ///< unknown names already reported, each once per chart
  std::set<model::FunctionId> functions;  ///< interface functions called
  std::set<model::ConstId> consts;        ///< constants read

  bool is_fsm() const { return ast.kind == ast::Chart::Kind::Fsm; }
  const char *place_word() const { return is_fsm() ? "state" : "place"; }
  const char *kind_word() const { return is_fsm() ? "fsm" : "sfc"; }
};

/// Where an expression stands: decides what its names may mean.
struct ExprScope {
  Context &cx;
  ChartScope *chart = nullptr;  ///< null at file level
  bool constant = false;        ///< an initialiser: no calls, no vars, no timers
  int loops = 0;                ///< the loops around the statement being lowered: `break` needs one
};

std::optional<model::Expr> lower_expr(const ast::Expr *e, ExprScope &s);

/// A call of an interface function (or `elapsed`). As a `statement` its result is discarded,
/// so a void function is fine there and only there.
std::optional<model::Expr> lower_call(const ast::Expr &e, ExprScope &s, bool statement);

/// A `when` condition or a `post`condition (`what` says which, for the message): must be bool.
std::optional<model::Expr> lower_condition(const ast::Expr *e, ExprScope &s, const char *what);

/// The initialiser of `name`, a value of type `type`.
std::optional<model::Expr> lower_initializer(const ast::Expr *e, ExprScope &s, model::Type type,
                                             const std::string &name);

/// `value` made what an assignment to a `to` makes it (a constant retyped to a sized integer, a
/// duration to a time) and checked to fit; false after reporting why not. The caller checks that
/// the types are assignable at all.
bool assignable_value(model::Expr &value, model::Type to, ExprScope &s);

/// Moves what it can (verbatim text) out of `b`: a block is released once lowered (validate.h).
std::vector<model::Stmt> lower_block(ast::Block &b, ExprScope &s);

/// Place (or state) `name` of the chart, or none after reporting why not.
model::PlaceId resolve_place(ChartScope &chart, Context &cx, const ast::Name &name);

/// Reports `unknown <what> 'name'` with a did-you-mean, unless `seen` (the names reported in
/// this chart, plan or at file level) says it was already. Returns the error, or null when it was.
Diagnostic *report_unknown(Diagnostics &diag, std::set<std::string> &seen, const ast::Name &name, const char *what,
                           const std::vector<const Symbol *> &candidates);

/// One more than timers can count (they saturate at UINT32_MAX): every duration that long or
/// longer is this many ticks, never reached.
constexpr unsigned long kBeyondTimers = 0x100000000ul;

/// `f / 0` or `f % 0` with `f` not constant: undefined in C (C11 6.5.5), and gcc -Werror refuses
/// the generated code (-Wdiv-by-zero). Reports it at the divisor and returns true.
bool divides_by_zero(BinaryOp op, const model::Expr &a, const model::Expr &b, SourceRange whole, Context &cx);

/// Time needs a period: `what` (a duration, `elapsed(P)`, a timed qualifier) is an error in a
/// chart without one; said once per chart, at the first place that needs it.
void require_period(ExprScope &s, SourceRange at, const std::string &what);

/// `ms` in whole ticks of `period_ms`, rounded up (§5.3), at most kBeyondTimers.
unsigned long to_ticks(double ms, double period_ms);

}  // namespace gfec::validation
