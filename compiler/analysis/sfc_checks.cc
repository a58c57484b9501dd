// What the reachable activation states of an sfc say about it (sfc_states.h), and the forks
// whose branches never meet (from the chart's structure alone).
#include "analysis/passes.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace gfec::analysis {

namespace {

using model::Chart;
using model::PlaceId;
using model::TransitionId;

std::string_view place_name(const Chart &c, PlaceId p) { return c.places.at(p).name; }

std::string names(const Chart &c, const model::PlaceList &places) {
  std::string out;
  for (std::size_t i = 0; i < places.size(); ++i)
    out += fmt::format("{}'{}'", i == 0 ? "" : i + 1 == places.size() ? " and " : ", ", place_name(c, places[i]));
  return out;
}

/// What the validator already reports: places no chain of live transitions reaches (it warns
/// about those; this pass speaks only of the rest). A worklist: linear in the chart.
IdMap<PlaceId, bool> structurally_reachable(const Chart &c) {
  IdMap<PlaceId, std::vector<TransitionId>> consumers(c.places.size());
  IdMap<TransitionId, std::size_t> waiting(c.transitions.size());  // inputs not yet reached
  std::vector<PlaceId> todo;
  for (TransitionId t : c.transitions.ids()) {
    const auto &tr = c.transitions[t];
    waiting[t] = tr.inputs.size();
    for (PlaceId p : tr.inputs) consumers[p].push_back(t);
  }
  IdMap<PlaceId, bool> reach(c.places.size());
  auto reached = [&](PlaceId p) {
    if (reach[p]) return;
    reach[p] = true;
    todo.push_back(p);
  };
  auto fire = [&](const model::Transition &tr) {
    if (firing_of(tr) == Firing::Never) return;
    for (PlaceId q : tr.outputs) reached(q);
  };
  for (const auto &tr : c.transitions)
    if (tr.inputs.empty()) fire(tr);
  for (PlaceId p : c.places.ids())
    if (c.places[p].initial) reached(p);
  while (!todo.empty()) {
    PlaceId p = todo.back();
    todo.pop_back();
    for (TransitionId t : consumers[p])
      if (--waiting[t] == 0) fire(c.transitions[t]);
  }
  return reach;
}

/// Places reachable from `start` along transitions (a place leads to the outputs of every
/// transition it is an input of).
std::set<PlaceId> downstream(const Chart &c, const IdMap<PlaceId, std::vector<TransitionId>> &consumers,
                             PlaceId start) {
  std::set<PlaceId> seen{start};
  std::vector<PlaceId> todo{start};
  while (!todo.empty()) {
    PlaceId p = todo.back();
    todo.pop_back();
    for (TransitionId t : consumers[p])
      for (PlaceId q : c.transitions[t].outputs)
        if (seen.insert(q).second) todo.push_back(q);
  }
  return seen;
}

/// A fork's branches meet when some join takes inputs from two different branches.
void check_forks(const Chart &c, Diagnostics &diag) {
  if (!diag.warning_options().is_on(Warning::UnjoinedFork)) return;  // off by default; not cheap
  IdMap<PlaceId, std::vector<TransitionId>> consumers(c.places.size());
  for (TransitionId t : c.transitions.ids())
    for (PlaceId p : c.transitions[t].inputs) consumers[p].push_back(t);
  for (const auto &fork : c.transitions) {
    if (fork.outputs.size() < 2) continue;
    std::vector<std::set<PlaceId>> branch;
    for (PlaceId o : fork.outputs) branch.push_back(downstream(c, consumers, o));
    bool meet = false;
    for (const auto &join : c.transitions) {
      if (join.inputs.size() < 2) continue;
      for (std::size_t i = 0; i < branch.size() && !meet; ++i)
        for (std::size_t j = 0; j < branch.size() && !meet; ++j) {
          if (i == j) continue;
          for (PlaceId a : join.inputs)
            for (PlaceId b : join.inputs)
              if (a != b && branch[i].count(a) && branch[j].count(b)) meet = true;
        }
      if (meet) break;
    }
    if (!meet)
      diag.warning(Warning::UnjoinedFork, name_at(fork),
                   fmt::format("the branches that fork '{}' starts ({}) never meet again in a join", fork.name,
                               names(c, fork.outputs)))
          .note("each branch runs on its own; a join (A, B) -> C synchronises them");
  }
}

}  // namespace

void check_sfc(const model::Model & /*m*/, const Chart &c, Diagnostics &diag, const Limits &limits,
               std::string &summary) {
  const std::size_t np = c.places.size(), nt = c.transitions.size();
  StateSpace space = explore(c, limits);
  const SourceRange chart_at = name_at(c);
  if (space.limit_hit)
    diag.warning(
        Warning::AnalysisLimit, chart_at,
        fmt::format("the analysis of sfc '{}' stopped after {} activation states and {} tick outcomes; what it "
                    "says about unreachable places, dead transitions and joins is left out",
                    c.name, space.states.size(), space.outcomes));

  // Per place: the largest count seen, and the first state that shows it above one.
  IdMap<PlaceId, std::uint32_t> most(np, 0);
  IdMap<PlaceId, int> unsafe_at(np, -1), unbounded_at(np, -1);
  IdMap<TransitionId, bool> join_ready(nt, false);
  const IdMap<TransitionId, bool> &fired = space.ever_fired;
  std::vector<int> deadlocks;
  for (std::size_t s = 0; s < space.states.size(); ++s) {
    const Marking &mk = space.states[s];
    for (PlaceId p : c.places.ids()) {
      most[p] = std::max(most[p], mk[p.index()]);
      if (mk[p.index()] >= 2 && unsafe_at[p] < 0) unsafe_at[p] = static_cast<int>(s);
      if (mk[p.index()] == kOmega && unbounded_at[p] < 0) unbounded_at[p] = static_cast<int>(s);
    }
    bool can_fire = false, waiting = false;
    for (TransitionId t : c.transitions.ids()) {
      const auto &tr = c.transitions[t];
      bool open = is_open(tr, mk);
      join_ready[t] = join_ready[t] || open;
      if (firing_of(tr) == Firing::Never) continue;
      can_fire = can_fire || open;
      for (PlaceId p : tr.inputs) waiting = waiting || mk[p.index()] > 0;
    }
    if (!can_fire && waiting) deadlocks.push_back(static_cast<int>(s));
  }

  for (PlaceId p : c.places.ids()) {
    const auto &place = c.places[p];
    SourceRange at = name_at(place);
    if (unbounded_at[p] >= 0)
      diag.warning(Warning::UnboundedPlace, at, fmt::format("place '{}' can gain activation without bound", place.name))
          .note(fmt::format("a cycle adds to it every time round: {}", witness(c, space, unbounded_at[p])));
    else if (unsafe_at[p] >= 0)
      diag.warning(Warning::UnsafePlace, at,
                   fmt::format("place '{}' can hold {} activations at once", place.name, most[p]))
          .note(fmt::format("for example after {}", witness(c, space, unsafe_at[p])));
  }
  if (!deadlocks.empty()) {
    int s = deadlocks.front();
    const Marking &mk = space.states[static_cast<std::size_t>(s)];
    auto &d = diag.warning(
        Warning::Deadlock, chart_at,
        fmt::format("sfc '{}' can reach a state in which nothing can fire any more: {}", c.name, marking_text(c, mk)));
    d.note(fmt::format("it gets there after {}", witness(c, space, s)));
    for (const auto &tr : c.transitions) {
      if (firing_of(tr) == Firing::Never) continue;
      model::PlaceList active, missing;
      for (PlaceId p : tr.inputs) (mk[p.index()] > 0 ? active : missing).push_back(p);
      if (!active.empty() && !missing.empty())
        d.note(name_at(tr), fmt::format("'{}' waits for {}", tr.name, names(c, missing)));
    }
  }

  // What never happens, claimed only when every reachable state is known exactly. The summary
  // counts every place never active and every transition never firing, the validator's
  // structural findings included, so that it never says "0" under their warnings.
  std::size_t unreachable = 0, dead = 0;
  if (space.exact()) {
    IdMap<PlaceId, bool> structural = structurally_reachable(c);
    for (PlaceId p : c.places.ids()) {
      if (most[p] > 0) continue;
      ++unreachable;
      if (!structural[p]) continue;  // the validator speaks of it
      diag.warning(
          Warning::UnreachablePlace, name_at(c.places[p]),
          fmt::format("place '{}' can never become active: no reachable activation state holds it", c.places[p].name));
    }
    for (TransitionId t : c.transitions.ids()) {
      const auto &tr = c.transitions[t];
      if (fired[t]) continue;
      ++dead;
      if (firing_of(tr) == Firing::Never) continue;  // the validator: its condition is always false
      SourceRange at = name_at(tr);
      PlaceId never;
      bool structurally_dead = false;
      for (PlaceId p : tr.inputs) {
        if (most[p] > 0) continue;
        if (!never) never = p;
        structurally_dead = structurally_dead || !structural[p];
      }
      if (structurally_dead) continue;  // the validator: an input place never becomes active
      if (never)
        diag.warning(Warning::DeadTransition, at,
                     fmt::format("transition '{}' can never fire: its input place '{}' never becomes active (no "
                                 "reachable activation state holds it)",
                                 tr.name, c.places[never].name));
      else if (!join_ready[t])
        diag.warning(Warning::DeadJoin, at,
                     fmt::format("join '{}' can never fire: its input places {} are never active at the same time",
                                 tr.name, names(c, tr.inputs)));
      else
        diag.warning(Warning::DeadTransition, at,
                     fmt::format("transition '{}' can never fire: whenever it is open, a transition declared before it "
                                 "without a condition takes the activation first",
                                 tr.name));
    }
  }
  check_forks(c, diag);

  // The summary for --analyze. Its bound is the C engine's (model::Chart::activation, the one
  // the header's comment names) whenever that is proven; the states explored here reach it
  // exactly when they are all of them (activation_bounds.h).
  std::uint32_t bound = 0;
  for (auto k : most) bound = std::max(bound, k);
  if (c.activation.bounded) bound = c.activation.place;
  bool safe = bound <= 1;
  summary +=
      fmt::format("sfc {}: {}, {}\n", c.name, counted(np, "place", "places"), counted(nt, "transition", "transitions"));
  summary +=
      fmt::format("  activation states: {}{}\n", space.states.size(),
                  space.limit_hit ? fmt::format(" (stopped at the limit of {} states; incomplete)", limits.max_states)
                  : space.accelerated ? " (some counts unbounded: an over-approximation)"
                                      : " (all of them)");
  summary +=
      fmt::format("  {}\n", safe              ? "safe: no place ever holds more than one activation"
                            : bound == kOmega ? "unbounded: some place can gain activation without end"
                                              : fmt::format("bounded: no place holds more than {} activations", bound));
  summary +=
      fmt::format("  deadlocks: {}\n", deadlocks.empty() ? "none" : counted(deadlocks.size(), "state", "states"));
  if (space.exact())
    summary += fmt::format("  never active: {}; never firing: {}\n", counted(unreachable, "place", "places"),
                           counted(dead, "transition", "transitions"));
}

}  // namespace gfec::analysis
