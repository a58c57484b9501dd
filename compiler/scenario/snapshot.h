// What a tick left behind, as the runner sees it from either engine (the reference interpreter
// or the generated C engine's harness), and an expectation evaluated on it. Both runs are
// reduced to the same Snapshot, so one evaluator decides for both.
#pragma once

#include "interpreter/value.h"
#include "model.h"
#include "scenario/scenario.h"

#include <cstdint>
#include <string>
#include <vector>

namespace gfec::scenario {

/// One call of an interface function, its arguments formatted as the engines print them.
struct Call {
  model::FunctionId function;
  std::vector<std::string> args;
  std::string text;  ///< `Motor(1, 0.5)`
};

struct Snapshot {
  std::uint64_t tick = 0;  ///< ticks run so far (0: just after _init)
  IdMap<model::PlaceId, unsigned> activation;
  IdMap<model::PlaceId, std::uint32_t> timers;  ///< meaningful for timed places only
  IdMap<model::VarId, interp::Value> vars;
  model::PlaceId state;     ///< fsm
  int status = 0;           ///< fsm
  std::vector<Call> calls;  ///< during the last tick, in order
};

/// An operand's value, for the notes of a failed expectation.
struct Operand {
  SourceRange range;
  std::string value;
};

struct Verdict {
  bool holds = false;
  std::vector<Operand> operands;  ///< in source order, each once
  std::string error;              ///< not empty: the expression has no defined value (e.g. / 0)
};

Verdict evaluate(const Expect &e, const Snapshot &s, const model::Model &model, model::ChartId chart);

/// The first difference between two snapshots of the same tick, or "" (calls first, then
/// activation, state, variables and timers). `a` and `b` name the two runs.
std::string compare(const Snapshot &x, const Snapshot &y, const model::Model &model, model::ChartId chart,
                    const char *a, const char *b);

/// A constant as `set` formats it (validate_tests.cc), back to a value of type `t`.
interp::Value parse_value(const std::string &text, model::Type t);

}  // namespace gfec::scenario
