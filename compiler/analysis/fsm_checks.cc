// An fsm's states that can never finish, and transitions that can never be the first to hold.
#include "analysis/condition_logic.h"
#include "analysis/passes.h"
#include "id_groups.h"

#include <fmt/format.h>

namespace gfec::analysis {

namespace {

using model::Chart;

using model::PlaceId;

bool terminal(const Chart &c, PlaceId s) { return c.places.at(s).terminal != model::Terminal::None; }

/// States reachable from `from` (forward) or reaching it (backward), over transitions that can
/// fire. A worklist over the edges of those transitions: linear in the chart.
IdMap<PlaceId, bool> closure(const Chart &c, std::vector<PlaceId> from, bool forward) {
  std::vector<std::pair<PlaceId, PlaceId>> edges;
  for (const auto &t : c.transitions) {
    if (t.inputs.empty() || t.outputs.empty() || firing_of(t) == Firing::Never) continue;
    if (forward) edges.emplace_back(t.inputs[0], t.outputs[0]);
    else edges.emplace_back(t.outputs[0], t.inputs[0]);
  }
  const IdGroups<PlaceId, PlaceId> next(c.places.size(), edges);
  IdMap<PlaceId, bool> seen(c.places.size(), false);
  for (PlaceId s : from) seen[s] = true;
  while (!from.empty()) {
    PlaceId s = from.back();
    from.pop_back();
    for (PlaceId b : next[s]) {
      if (seen[b]) continue;
      seen[b] = true;
      from.push_back(b);
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
  // Only transitions that leave the same state compare, so each is compared with the earlier
  // ones of its own state (found through `leaving`), in declaration order as before.
  std::size_t shadowed = 0;
  const IdGroups<PlaceId, model::TransitionId> from = model::transitions_leaving(c);
  for (model::TransitionId j : c.transitions.ids()) {
    const auto &later = c.transitions[j];
    if (later.inputs.empty() || firing_of(later) == Firing::Never) continue;
    for (model::TransitionId i : from[later.inputs[0]]) {
      if (i.index() >= j.index()) break;
      const auto &first = c.transitions[i];
      if (firing_of(first) == Firing::Never) continue;
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
