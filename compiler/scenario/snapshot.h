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

/// A sub-chart instance of a test's chart (docs/language.md "Sub-charts"), numbered depth first
/// in declaration order as the C engine's `X_instance` numbers them.
struct Instance {
  model::ChartId chart;  ///< the chart it runs
  int parent = -1;       ///< the instance that holds the place running it, -1 for the root
  model::PlaceId place;  ///< that place
};

/// The instances of `chart`, depth first in declaration order.
std::vector<Instance> instances_of(const model::Model &model, model::ChartId chart);

/// One agent's state after a tick (a chart that is no team machine has only agent 0).
struct Snapshot {
  std::uint64_t tick = 0;  ///< ticks run so far (0: just after _init)
  IdMap<model::PlaceId, unsigned> activation;
  IdMap<model::PlaceId, std::uint32_t> timers;  ///< meaningful for timed places only
  IdMap<model::VarId, interp::Value> vars;
  model::PlaceId state;     ///< fsm
  int status = 0;           ///< fsm
  std::vector<Call> calls;  ///< during the last tick, in order
  /// By instance (instances_of): the activation of each of its places; all 0 while the place
  /// that runs it, or one above, is inactive (then the instance is not running).
  std::vector<std::vector<unsigned>> instances;
  /// A team machine: this agent's number, and by agent the state it last reported (none
  /// before the first exchange; docs/language.md "Teams").
  int agent = 0;
  std::vector<model::PlaceId> reports;
};

/// Zeroes the activation of the instances that are not running (normalises what the two runs
/// report about stopped instances, which keep where their last tick left them).
void settle_instances(Snapshot &s, const std::vector<Instance> &instances);

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

/// A digest of what compare() reads of a record: two records that compare equal have the same
/// digest, so runs are told apart tick by tick without keeping every record.
std::uint64_t digest(const Snapshot &s, const model::Model &model, model::ChartId chart);

/// "P.Q": the places that lead from the root of `chart` to instance `i`, for messages.
std::string instance_path(const model::Model &model, model::ChartId chart, const std::vector<Instance> &instances,
                          std::size_t i);

/// Whether a call's arguments (as the engines print them) equal the expected ones (as `called
/// F(ARGS)` converted them to the parameter types), compared as values: `-0` is `0`, as in C.
bool same_arguments(const model::Function &f, const std::vector<std::string> &seen,
                    const std::vector<std::string> &want);

/// A constant as `set` formats it (validate_tests.cc), back to a value of type `t`.
interp::Value parse_value(const std::string &text, model::Type t);

}  // namespace gfec::scenario
