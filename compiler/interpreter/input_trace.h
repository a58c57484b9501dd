// The input trace of a run (docs/verification.md): CSV with a header row naming interface
// functions and one row per tick, giving what each function returns during that tick.
//
//   # comment lines and blank lines are skipped
//   tick, Left_IR_Black, Left_IR_White, Distance
//   1,    1,             0,             0.25
//   2,    0,             1,             0.5
//
// Without a `tick` column row k is tick k. With one, a row holds from its tick until the next
// row's (a sparse trace: `1` then `250` is 249 ticks of the first row), the ticks go up from 1,
// and before the first row's tick every function returns 0. A function without a column
// returns 0 (false). Past the last row, the last row holds (sensors keep their value).
//
// A team run (several agents, docs/cli.md) gives each agent its own columns: `F@2` is what F
// returns to agent 2; a plain `F` column serves every agent that has no `F@k` of its own.
#pragma once

#include "diagnostics.h"
#include "evaluator.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gfec::interp {

class InputTrace : public Environment {
public:
  /// Reads the CSV file `file` of `sources` against the model's interface functions. Malformed
  /// lines, unknown or void functions and values of the wrong type are reported to `diag`,
  /// located in the CSV file.
  InputTrace(const model::Model &model, const SourceManager &sources, FileId file, Diagnostics &diag, int agents = 1);
  /// No inputs: every function returns 0 (false).
  explicit InputTrace(const model::Model &model);

  std::size_t rows() const { return rows_.size(); }
  /// The tick of the last row (its number without a tick column); 0 without rows.
  std::uint64_t last_tick() const;
  /// What `function` returns to agent `agent` during `tick` (counted from 1).
  Value value(model::FunctionId function, std::uint64_t tick, int agent = 0) const;
  Value call(model::FunctionId function, const std::vector<Value> &args, std::uint64_t tick) override;
  /// A column named after an input (`in` variable) of a chart gives its value; before the
  /// first row's tick, or without a column, the input keeps its value.
  std::optional<Value> input(const model::Var &var, std::uint64_t tick) override;

  /// The inputs of one agent of a team run: what its engine calls.
  class Agent : public Environment {
  public:
    Agent(const InputTrace &trace, int agent) : trace_(trace), agent_(agent) {}
    Value call(model::FunctionId function, const std::vector<Value> &, std::uint64_t tick) override {
      return trace_.value(function, tick, agent_);
    }

  private:
    const InputTrace &trace_;
    int agent_;
  };

private:
  const model::Model &model_;
  struct Column {
    enum class Kind { Function, Tick, Bad, Input };
    Kind kind = Kind::Bad;
    model::FunctionId function;         ///< Kind::Function
    int agent = -1;                     ///< the agent of `F@k`, or -1 for every agent
    const model::Var *input = nullptr;  ///< Kind::Input: a chart's `in` variable of that name
  };
  /// The row that holds at `tick`, if any has come.
  std::optional<std::size_t> row_at(std::uint64_t tick) const;
  std::vector<Column> columns_;
  std::vector<std::vector<Value>> rows_;  ///< by row, by column
  std::optional<std::size_t> tick_column_;
  std::vector<std::uint64_t> ticks_;  ///< with a tick column: by row, its tick (going up)
};

}  // namespace gfec::interp
