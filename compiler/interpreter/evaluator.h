// Expressions and statements of a chart (docs/language.md §4) with C's semantics: the usual
// arithmetic conversions, 32-bit ints, float arithmetic in float, `&&` and `||` short-circuit,
// and everything else evaluated left to right (the language fixes the order C leaves open).
#pragma once

#include "event_log.h"
#include "model.h"
#include "value.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace gfec::interp {

class Machine;

/// What the interpreter calls for the interface functions: an input trace in `gfec run`,
/// anything a test likes.
class Environment {
public:
  virtual ~Environment() = default;
  /// The result of interface function `function` called with `args` (already converted to its
  /// parameter types) during tick `tick` (counted from 1).
  /// The interpreter converts the result to the function's type; a void function's is ignored.
  virtual Value call(model::FunctionId function, const std::vector<Value> &args, std::uint64_t tick) = 0;
  /// The value the caller gives the chart's input `var` (an `in` variable, docs/language.md §14)
  /// before tick `tick`; none: the input keeps the value it has.
  virtual std::optional<Value> input(const model::Var &var, std::uint64_t tick) {
    (void)var;
    (void)tick;
    return std::nullopt;
  }
};

/// Everything an expression can read or change while it is evaluated.
struct Frame {
  const model::Model &model;
  const model::Chart &chart;
  IdMap<model::VarId, Value> &vars;
  const IdMap<model::PlaceId, std::uint32_t> &timers;  ///< ticks
  Environment *env = nullptr;                          ///< null: a constant expression, where calls are errors
  EventLog *log = nullptr;                             ///< null: log nothing
  std::uint64_t tick = 0;
  int depth = 1;                    ///< indentation of the events logged
  const Machine *engine = nullptr;  ///< the chart's engine: active(), succeeded(), failed()
  /// A team machine (docs/language.md "Teams"): this engine's agent number, and by agent the
  /// state each one last reported (or none). Null for a machine that is no team.
  int agent = 0;
  const std::vector<model::PlaceId> *reports = nullptr;
};

/// How many times one loop statement may run its body in one execution before the interpreter
/// stops the run with an error (docs/language.md §10): gfec run never hangs.
inline constexpr std::uint64_t kMaxLoopPasses = 1000000;

Value evaluate(const model::Expr &e, Frame &f);
/// Runs the statements in order; an `if` evaluates its condition, then runs one branch; a loop
/// runs as C runs it; `return` ends the block given here.
/// Verbatim code cannot be run: it is skipped with a note.
void execute(const std::vector<model::Stmt> &block, Frame &f);

}  // namespace gfec::interp
