// The reference engine: one chart of a model, run tick by tick exactly as LANGUAGE.md says —
// §5.1 for an sfc, §7 for an fsm. Its API mirrors the generated C engine's (§5.2): init, run,
// activation, state, status. It reads only the model.
#pragma once

#include "evaluator.h"

#include <cstdint>
#include <vector>

namespace gfec::interp {

struct EngineOptions {
  /// Evaluate a terminal state's postcondition when the machine enters it (an engine built with
  /// -DX_CHECKS asserts it). Its calls are then logged like any other.
  bool check_post = false;
};

class Engine {
public:
  Engine(const model::Model &model, int chart, EngineOptions options = {});

  /// `_init`: the initial marking (or state), timers 0, vars set to their initialisers. Calls
  /// no code of the chart. Throws RuntimeError if an initialiser has no defined value.
  void init();
  /// `_run`: one tick. Every event goes to `log` (if given). Throws RuntimeError where C would
  /// have undefined behaviour; the engine is then unusable until init().
  void run(Environment &env, EventLog *log);

  /// A team machine (docs/language.md "Teams"), as the C engine's X_set_agent and X_report:
  /// this engine's agent number (init() makes it 0), and agent `agent`'s state as it arrives
  /// (ignored for the own number, a number out of range or an invalid state). init() forgets
  /// every report. A number out of range is ignored by set_agent too, and both do nothing for
  /// a machine that is no team.
  void set_agent(int agent);
  void report(int agent, int state);
  int agent() const { return agent_; }
  int team_size() const { return chart_.team; }
  const std::vector<int> &reports() const { return reports_; }

  unsigned activation(int place) const;
  int state() const { return state_; }    ///< fsm: the current state's index
  int status() const { return status_; }  ///< fsm: 0 running, 1 succeeded, -1 failed
  std::uint64_t ticks() const { return tick_; }
  const std::vector<Value> &vars() const { return vars_; }
  std::uint32_t timer(int place) const { return timers_.at(static_cast<std::size_t>(place)); }
  const model::Chart &chart() const { return chart_; }
  bool is_fsm() const { return chart_.kind == model::Chart::Kind::Fsm; }

private:
  void run_sfc(Frame &f);
  void run_fsm(Frame &f);
  /// Evaluates transition `t`'s condition (absent: true) and logs it.
  bool condition(int t, Frame &f);
  /// Runs a place's block, if it has one, logged under `kind` and the place's name.
  void block(EventKind kind, const char *word, int place, const std::vector<model::Stmt> *stmts, Frame &f);
  void end_of_tick(Frame &f);
  std::string label(const model::Transition &t) const;

  const model::Model &model_;
  const model::Chart &chart_;
  EngineOptions options_;
  std::vector<std::uint32_t> av_;      ///< sfc: activation counters (C's unsigned)
  int state_ = -1;                     ///< fsm
  int status_ = 0;                     ///< fsm
  std::vector<std::uint32_t> timers_;  ///< ticks active, by place (saturating, as in C)
  std::vector<Value> vars_;
  bool started_ = false;               ///< the first tick has run the initial entries
  int agent_ = 0;                      ///< team machine: this engine's agent number
  std::vector<int> reports_;           ///< team machine: by agent, its last state (-1: none)
  std::uint64_t tick_ = 0;
};

} // namespace gfec::interp
