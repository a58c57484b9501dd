// The per-tick log of a run: the one format that `gfec run` prints and that differential
// testing compares. Its lines come in three layers:
//
//   observable   what code linked with an engine can see through its API and the interface
//                functions:  `tick 3`, `call Left_IR_Black() = true`, `call Motor(1, 0.5)`,
//                `av 1 0 1 0` (sfc and fsm), `state Z1 running` (fsm); in a team run,
//                `agent 1` before each agent's part of the tick; `out Valve = true` per
//                output variable of the chart, in declaration order (docs/iec.md)
//   hooks        what the observation hooks (-DX_HOOKS) report: `lost P`, `gained P`,
//                `enabled T`
//   explanation  why it happened, for people: `cond T0 = true`, `fire T0`, `exit P`,
//                `entry P`, `action P`, `set laps = 3`, `post Done = true`, `note ...`;
//                sub-charts: `start P: C`, `run P: C`, `stop P: C`, and after the root's
//                activation each running instance's: `av P: 0 1`, `state P: Grab running`
//                in a team run the exchange after the tick, `team Go Grab Go` (each agent's state)
//
// A generated engine's test driver prints the observable (and, with hooks, the hooks) lines
// exactly as written here, unindented; docs/verification.md is the reference for people.
#pragma once

#include <string>
#include <vector>

namespace gfec::interp {

enum class EventKind {
  Tick,
  Call,
  Av,
  State,
  Agent,
  Output,  // observable
  Lost,
  Gained,
  Enabled,  // hooks
  Condition,
  Fire,
  Exit,
  Entry,
  Action,
  Assign,
  Post,
  Note,
  Exchange,  // explanation
  Start,
  RunInstance,
  Stop,
  InstanceAv,
  InstanceState,  // explanation: sub-charts
};

enum class Layer { Observable, Hooks, Explanation };
Layer layer_of(EventKind kind);

struct Event {
  EventKind kind;
  int depth = 0;     ///< nesting, for indentation: 0 tick, 1 what the tick does, 2 calls inside
  std::string text;  ///< the whole line, without indentation
};

struct RenderOptions {
  bool hooks = false;    ///< include the hooks layer
  bool explain = false;  ///< include the explanation layer
  bool indent = false;   ///< indent by depth (two spaces a level)
};

class EventLog {
public:
  void add(EventKind kind, int depth, std::string text) { events_.push_back({kind, depth, std::move(text)}); }
  /// Inserts an event before the one at `position`: a condition's verdict goes before the
  /// calls that decided it, so that the indented log reads top-down.
  void insert(std::size_t position, EventKind kind, int depth, std::string text) {
    events_.insert(events_.begin() + static_cast<std::ptrdiff_t>(position), Event{kind, depth, std::move(text)});
  }
  std::size_t size() const { return events_.size(); }
  const std::vector<Event> &events() const { return events_; }
  void clear() { events_.clear(); }
  /// The selected layers, one event a line.
  std::string render(const RenderOptions &options) const;

private:
  std::vector<Event> events_;
};

}  // namespace gfec::interp
