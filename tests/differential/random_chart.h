// Random charts for differential testing: a small structured form of an sfc or fsm (so the
// shrinker can take it apart), printed as chart text that goes through the whole pipeline.
// Every chart is valid by construction; what it does at run time is the point.
#pragma once

#include "model.h"

#include <optional>
#include <random>
#include <string>
#include <vector>

namespace gfec::diff {

using model::Type;

struct GExpr {
  /// Active: text `P` or `P.Q.R`; Succeeded, Failed: text `P` (a place that runs an fsm);
  /// Team: text `S`, `team(S)`; Agent: `agent()` (team machines, docs/language.md "Teams").
  enum class Kind { Lit, Var, Const, Call, Elapsed, Unary, Binary, Paren, Active, Succeeded, Failed, Team, Agent };
  Kind kind = Kind::Lit;
  Type type = Type::Int;  ///< for an Elapsed comparison's operands: Duration
  std::string text;       ///< literal spelling, name, or operator
  std::vector<GExpr> args;
};

struct GStmt {
  bool assign = false;
  std::string target;     ///< assignments: the var
  std::string op;         ///< "=", "+=", "-="
  GExpr expr;             ///< the value, or the call; an `if`: its condition
  bool is_if = false;     ///< `if (expr) { then_block } else { else_block }`
  bool is_break = false;  ///< `break;` (only as an `if`'s branch, inside a loop)
  /// `for (counter = 0; counter < bound; counter += 1) { then_block }` when counter is not empty;
  /// the counter is a var of its own that no statement assigns, so the loop ends.
  std::string counter;
  int bound = 0;
  bool has_else = false;
  std::vector<GStmt> then_block, else_block;  ///< an `else if` is one `if` in else_block
};

struct GFunction {
  std::string name;
  Type result = Type::Void;
  std::vector<Type> params;
};

struct GValue {  ///< a var, or a constant (chart or file level)
  Type type = Type::Int;
  std::string name;
  std::string init;  ///< literal; empty: none (vars only)
  bool file_level = false;
};

struct GPlace {
  std::string name;
  bool initial = false;
  model::Terminal terminal = model::Terminal::None;
  bool body = true;  ///< false: `place X;`
  std::vector<GStmt> action;
  std::optional<std::vector<GStmt>> entry, exit;
  std::optional<GExpr> post;
  int runs = -1;  ///< the sub-chart it runs: an index into the root's GChart::pool
};

struct GTransition {
  std::string name;  ///< empty: unnamed
  std::vector<int> inputs, outputs;
  std::optional<GExpr> condition;
};

struct GChart {
  bool fsm = false;
  std::string name;    ///< R<id>
  std::string prefix;  ///< c<id>: the interface functions' prefix
  int period_ms = 0;
  std::vector<GFunction> functions;
  std::vector<GValue> consts;
  std::vector<GValue> vars;
  std::vector<GPlace> places;
  std::vector<GTransition> transitions;
  int loop_counters = 0;  ///< `var int <prefix>_n<k>;` for k below this: the counters of nested loops
  /// The root only: the sub-charts, each with the root's interface and period. pool[j] runs
  /// only pool[k] with k > j, and the root any of them, so there is no cycle; the same chart
  /// may be run by several places.
  std::vector<GChart> pool;
  /// A team machine (the root fsm only): `team <team>;`, run by `agents` engines (2..team) in
  /// lockstep under the reference exchange; 0 for an ordinary chart.
  int team = 0;
  int agents = 0;
};

/// What each function with a result returns, tick by tick, as literal text.
struct GTrace {
  int ticks = 0;
  std::vector<std::vector<std::string>> values;  ///< [function][tick]; empty for void functions
  /// A team run: what agent k (from 1) is told apart from the others, [k - 1][function][tick]
  /// (its `F@k` columns); an empty list: agent k shares `values` for that function.
  std::vector<std::vector<std::vector<std::string>>> agents;
};

struct GenOptions {
  bool fsm = false;
  // Constructs that a known, reported bug makes fail, so that a run can look past it
  // (gfec_differential --avoid); by default every construct is generated.
  /// Chart elements gfec already warns are dead (fsm states the initial state cannot reach,
  /// fsm transitions shadowed by an unconditional one, `when false`): their engine code is
  /// dead too, which cppcheck reports.
  bool dead_code = true;
  /// Hierarchical programs: up to this many sub-charts (0: a flat chart).
  int subcharts = 0;
  /// A team machine (an fsm only) run by this many agents (2 to 4; 0: not a team).
  int agents = 0;
  /// Values near the limits (docs/targets.md): int literals and inputs past 16 bits and at
  /// INT32's ends, float constants that need exact rounding (`1.00000005960464478`), and
  /// `a * b + c` of floats, which a target with a fused multiply-add must not fuse.
  bool limits = false;
  /// false: no double anywhere (a target whose double is binary32 refuses it).
  bool doubles = true;
  /// Counted `for` loops (docs/language.md §10), some with a `break` under an `if`.
  bool loops = false;
};

GChart random_chart(std::mt19937_64 &rng, int id, const GenOptions &options);
/// `limits`: now and then an int input past 16 bits or at INT32's ends, a float input that
/// needs all of binary32's digits.
GTrace random_trace(std::mt19937_64 &rng, const GChart &chart, bool limits = false);

/// The chart as one file: its interface, its file-level constants, the chart.
std::string chart_text(const GChart &chart);
/// The trace as gfec run's CSV (docs/verification.md).
std::string trace_csv(const GChart &chart, const GTrace &trace);
std::string expr_text(const GExpr &e);

}  // namespace gfec::diff
