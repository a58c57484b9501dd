// The reference interpreter's machine: one chart of a model, run tick by tick exactly as
// docs/language.md says — §5.1 for an sfc, §7 for an fsm. Its API mirrors the generated C engine's
// (§5.2): init, run, activation, state, status. It reads only the model.
#pragma once

#include "evaluator.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace gfec::interp {

struct MachineOptions {
  /// Evaluate a terminal state's postcondition when the machine enters it (an engine built with
  /// -DX_CHECKS asserts it). Its calls are then logged like any other.
  bool check_post = false;
};

/// A sub-chart (docs/language.md "Sub-charts") is a Machine too: each place or state that runs
/// a chart owns one instance, built with its parent and named by its path from the root
/// ("Search", "Search.Grab"). Instances are started, ticked and stopped by their parent.
class Machine {
public:
  Machine(const model::Model &model, model::ChartId chart, MachineOptions options = {});

  /// `_init`: the initial marking (or state), timers 0, vars set to their initialisers, and the
  /// same for every sub-chart instance. Calls no code of the chart. Throws RuntimeError if an
  /// initialiser has no defined value.
  void init();
  /// `_run`: one tick. Every event goes to `log` (if given). Throws RuntimeError where C would
  /// have undefined behaviour; the engine is then unusable until init().
  void run(Environment &env, EventLog *log);

  /// The instance that place `place` runs, or null if it runs no chart.
  const Machine *instance(model::PlaceId place) const;
  /// `active(P.Q.R)`: every place along `path` is active, each in the instance the previous
  /// one runs.
  bool active(const std::vector<model::PlaceId> &path) const;
  /// `succeeded(P)` (1) / `failed(P)` (-1): P is active and its fsm instance has that status.
  bool outcome(model::PlaceId place, int status) const;
  /// `active(A)` / `running(A)` of a named action: its Q, or whether its body runs, as the latest
  /// action control left them (docs/iec.md "Action flags").
  bool action_flag(model::ActionId action, bool running) const { return running ? runs_[action] : was_q_[action]; }
  /// A team machine (docs/language.md "Teams"), as the C engine's X_set_agent and X_report:
  /// this engine's agent number (init() makes it 0), and agent `agent`'s state as it arrives
  /// (ignored for the own number, a number out of range or an invalid state). init() forgets
  /// every report. A number out of range is ignored by set_agent too, and both do nothing for
  /// a machine that is no team.
  void set_agent(int agent);
  void report(int agent, model::PlaceId state);
  int agent() const { return agent_; }
  int team_size() const { return chart_.team; }
  /// By agent: the state it last reported, or none.
  const std::vector<model::PlaceId> &reports() const { return reports_; }

  unsigned activation(model::PlaceId place) const;
  model::PlaceId state() const { return state_; }  ///< fsm: the current state
  int status() const { return status_; }           ///< fsm: 0 running, 1 succeeded, -1 failed
  std::uint64_t ticks() const { return tick_; }
  const IdMap<model::VarId, Value> &vars() const { return vars_; }
  std::uint32_t timer(model::PlaceId place) const { return timers_.at(place); }
  const model::Chart &chart() const { return chart_; }
  bool is_fsm() const { return chart_.kind == model::Chart::Kind::Fsm; }

private:
  Machine(const model::Model &model, model::ChartId chart, MachineOptions options, std::string path, int depth);
  /// One tick of this chart (§5.1 or §7) in `f`, a frame of this engine (frame()): its events
  /// are logged from depth `depth_`.
  void step(Frame &f);
  /// §9: reset place `place`'s instance as `_init` would (no code runs), before its entry block.
  void start(model::PlaceId place, Frame &f);
  /// §9: stop place `place`'s instance: the active places of the instance, in declaration
  /// order, each stopping its own instance and then running its exit block (innermost first).
  void stop(model::PlaceId place, Frame &f);
  void stop_all(Environment *env, EventLog *log, std::uint64_t tick);
  /// §9: one tick of place `place`'s instance, right after the place's action block.
  void tick_instance(model::PlaceId place, Frame &f);
  /// The activation (and state) of every running instance, for people: `av Search: 0 1`.
  void log_instances(EventLog &log) const;
  Frame frame(Environment *env, EventLog *log, std::uint64_t tick);
  void run_sfc(Frame &f);
  void run_fsm(Frame &f);
  /// Evaluates transition `t`'s condition (absent: true) and logs it.
  bool condition(model::TransitionId t, Frame &f);
  /// Runs a place's block, if it has one, logged under `kind` and the place's name.
  void block(EventKind kind, const char *word, model::PlaceId place, const std::vector<model::Stmt> *stmts, Frame &f);
  void end_of_tick(Frame &f);
  void named_actions(Frame &f);
  void run_action(model::ActionId a, Frame &f);
  std::string label(const model::Transition &t) const;

  const model::Model &model_;
  const model::Chart &chart_;
  MachineOptions options_;
  std::string path_;    ///< "" for the root; "Search", "Search.Grab" for instances
  std::string prefix_;  ///< path_ + "." (or ""): names in the log are prefixed with it
  int depth_ = 1;       ///< the indentation of this chart's own events
  IdMap<model::PlaceId, std::unique_ptr<Machine>> instances_;  ///< the instance a place runs, or null
  IdMap<model::PlaceId, std::uint32_t> av_;                    ///< sfc: activation counters (C's unsigned)
  model::PlaceId state_;                                       ///< fsm
  int status_ = 0;                                             ///< fsm
  IdMap<model::PlaceId, std::uint32_t> timers_;                ///< ticks active (saturating, as in C)
  IdMap<model::VarId, Value> vars_;
  /// Action control (docs/iec.md "Action control"): each place's state as the previous tick's
  /// action control saw it (false before tick 1, so an initial place rises in tick 1), each
  /// action's stored flags, one per stored qualifier, and its Q of the previous tick (for the
  /// final run).
  IdMap<model::PlaceId, bool> acted_active_;
  /// The action control has run once: until then an initial place counts as active before for
  /// P0 (left in tick 1, it falls in tick 1) while it counts as inactive before for P and P1.
  bool acted_ = false;
  /// A stored qualifier's flag, and for SD and SL the ticks since it was set (0 in the tick of
  /// the set, saturating as the place timers do).
  struct Stored {
    bool set = false;
    std::uint32_t ticks = 0;
  };
  struct StoredFlags {
    Stored s, sd, ds, sl;
  };
  IdMap<model::ActionId, StoredFlags> stored_;
  IdMap<model::ActionId, bool> was_q_;   ///< the Q of the latest action control
  IdMap<model::ActionId, bool> runs_;    ///< the body runs at the latest action control (`running(A)`)
  bool started_ = false;                 ///< the first tick has run the initial entries
  int agent_ = 0;                        ///< team machine: this engine's agent number
  std::vector<model::PlaceId> reports_;  ///< team machine: by agent, its last state (none: none yet)
  std::uint64_t tick_ = 0;
};

}  // namespace gfec::interp
