// An fsm's states that can never finish, and transitions that can never be the first to hold.
#include "analysis/condition_logic.h"
#include "analysis/passes.h"

#include <fmt/format.h>

namespace gfec::analysis {

namespace {

using model::Chart;

using model::PlaceId;

bool terminal(const Chart &c, PlaceId s) { return c.places.at(s).terminal != model::Terminal::None; }

/// States reachable from `from` (forward) or reaching it (backward), over transitions that can fire.
IdMap<PlaceId, bool> closure(const Chart &c, std::vector<PlaceId> from, bool forward) {
  IdMap<PlaceId, bool> seen(c.places.size(), false);
  for (PlaceId s : from) seen[s] = true;
  while (!from.empty()) {
    PlaceId s = from.back();
    from.pop_back();
    for (const auto &t : c.transitions) {
      if (t.inputs.empty() || t.outputs.empty() || firing_of(t) == Firing::Never) continue;
      PlaceId a = forward ? t.inputs[0] : t.outputs[0], b = forward ? t.outputs[0] : t.inputs[0];
      if (a == s && !seen[b]) {
        seen[b] = true;
        from.push_back(b);
      }
    }
  }
  return seen;
}

std::string label(const Chart &c, const model::Transition &t) {
  return fmt::format("{} -> {}", c.places.at(t.inputs.at(0)).name, c.places.at(t.outputs.at(0)).name);
}

}  // namespace

void check_fsm(const model::Model & /*m*/, const Chart &c, Diagnostics &diag, std::string &summary) {
  std::vector<PlaceId> initial, terminals;
  for (PlaceId s : c.places.ids()) {
    if (c.places[s].initial) initial.push_back(s);
    if (terminal(c, s)) terminals.push_back(s);
  }
  IdMap<PlaceId, bool> reach = closure(c, initial, true);
  std::size_t traps = 0;
  // A machine without terminal states is meant to run for ever: nothing to say.
  if (!terminals.empty()) {
    IdMap<PlaceId, bool> finish = closure(c, terminals, false);
    for (PlaceId s : c.places.ids()) {
      if (!reach[s] || finish[s]) continue;
      ++traps;
      diag.warning(Warning::TrapState, name_at(c.places[s]),
                   fmt::format("state '{}' can never reach a success or failure state: once there, fsm '{}' runs for "
                               "ever",
                               c.places[s].name, c.name));
    }
  }
  // Shadowing: from the same state, an earlier transition holds whenever a later one does.
  std::size_t shadowed = 0;
  for (std::size_t j = 0; j < c.transitions.size(); ++j) {
    const auto &later = c.transitions[j];
    if (later.inputs.empty() || firing_of(later) == Firing::Never) continue;
    for (std::size_t i = 0; i < j; ++i) {
      const auto &first = c.transitions[i];
      if (first.inputs.empty() || first.inputs[0] != later.inputs[0] || firing_of(first) == Firing::Never) continue;
      const model::Expr *a = later.condition ? &*later.condition : nullptr;
      const model::Expr *b = first.condition ? &*first.condition : nullptr;
      if (implies(a, b) != true) continue;
      ++shadowed;
      diag.warning(Warning::ShadowedTransition, name_at(later),
                   fmt::format("transition '{}' ({}) can never fire: '{}' ({}) is tried first and holds whenever it "
                               "does",
                               later.name, label(c, later), first.name, label(c, first)))
          .note(name_at(first), fmt::format("'{}' has {} precondition", first.name, b ? "the same or a weaker" : "no"));
      break;
    }
  }
  std::size_t reachable = 0;
  for (bool r : reach) reachable += r;
  summary += fmt::format("fsm {}: {} ({} terminal), {}\n", c.name, counted(c.places.size(), "state", "states"),
                         terminals.size(), counted(c.transitions.size(), "transition", "transitions"));
  summary += fmt::format("  reachable states: {} of {}\n", reachable, c.places.size());
  summary += terminals.empty() ? "  no terminal state: the machine runs for ever\n"
                               : fmt::format("  states that can never finish: {}\n", traps);
  summary += fmt::format("  shadowed transitions: {}\n", shadowed);
}

}  // namespace gfec::analysis
