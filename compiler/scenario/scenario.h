// Scenario tests (docs/testing-charts.md): the checked form of the `test` blocks of a file.
// The validator lowers each `test "NAME" of CHART { ... }` to a Test here; `gfec test` runs it
// on the reference interpreter and on the generated C engine and evaluates its expectations on
// what each run left behind (a Snapshot, snapshot.h). Kept apart from the model: back ends never
// see tests.
#pragma once

#include "model.h"

#include <optional>
#include <string>
#include <vector>

namespace gfec::scenario {

/// An expectation's expression. Chart expressions (vars, constants, `elapsed`, and what the
/// chart's own expressions may read) are lowered by the validator's expression lowering and kept
/// as model expressions; the operands only tests have wrap them.
struct Expect {
  enum class Kind {
    Chart,   ///< chart: a chart expression that calls no function
    Active,  ///< `active(P)`: place = P
    Called,  ///< `called F` / `called F(ARGS)`: function; args (formatted as the engine prints them) if given
    Calls,   ///< `calls F`: function; type Int
    State,   ///< `state(S)`: place = S (fsm root)
    Status,  ///< `status`: type Int (fsm root)
    Unary,   ///< unary_op, args[0]
    Binary,  ///< binary_op, args[0], args[1]
    Paren,   ///< args[0]
  };
  Kind kind = Kind::Chart;
  model::Type type = model::Type::Bool;
  SourceRange range;
  model::Expr chart;
  model::PlaceId place;
  model::FunctionId function;
  std::optional<std::vector<std::string>> call_args;
  UnaryOp unary_op = UnaryOp::Not;
  BinaryOp binary_op = BinaryOp::Add;
  std::vector<Expect> args;
};

struct Step {
  enum class Kind { Tick, Set, Expect };
  Kind kind = Kind::Tick;
  SourceRange range;
  unsigned long count = 1;     ///< Tick
  model::FunctionId function;  ///< Set: the sensing function set, or none when `input` is set
  /// Set: the chart's `in` variable set (docs/language.md §14), or none when `function` is set;
  /// from the next tick on the caller gives it `value` before every tick.
  model::VarId input;
  std::string value;  ///< Set: the constant converted to the function's (input's) type, formatted
  Expect expect;      ///< Expect
  /// A team machine's agent the step is for (`agent K { ... }`), or -1: a `set` for every
  /// agent, an `expect` of agent 0.
  int agent = -1;
  /// The agent an expectation reads.
  int expect_agent() const { return agent < 0 ? 0 : agent; }
};

struct Test {
  std::string name;
  model::ChartId chart;
  /// How many agents run the chart side by side with the reference exchange (docs/language.md
  /// "Teams"): a team machine's size unless `agents N` says fewer; 1 for any other chart.
  int agents = 1;
  std::vector<Step> steps;
  SourceRange range;
};

/// The tests of one file (its own, not those of the files it imports).
struct Suite {
  std::vector<Test> tests;
  /// The names of the `test` blocks written in the main file, checked or not (a file that does
  /// not compile counts them all as failed).
  std::vector<std::string> written;
};

}  // namespace gfec::scenario
