// The reachable activation states of an sfc with its conditions treated as free: at each tick
// every open transition may fire or not, in declaration order, exactly as §5.1 consumes
// activation — except a transition without condition (or `when true`), which fires whenever it
// is open, and one `when false`, which never does. Timers are not modelled (elapsed() is free
// like any other condition), so this over-approximates what the chart can do.
//
// The exploration is bounded. A state that covers one of its ancestors (at least as much
// activation everywhere, more somewhere) is accelerated as in Karp and Miller's coverability
// tree: the places that grew become unbounded (ω), which keeps pumping charts finite.
#pragma once

#include "model.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gfec::analysis {

constexpr std::uint32_t kOmega = UINT32_MAX;  ///< an activation count that can grow without bound
using Marking = std::vector<std::uint32_t>;   ///< by place (PlaceId::index(): a map key, so a plain vector)

struct Limits {
  std::size_t max_states = 20000;     ///< activation states explored
  std::size_t max_outcomes = 400000;  ///< tick outcomes enumerated (2^open free transitions each)
  /// Work, counted in places and transitions visited (a state costs the chart's size, each of
  /// its outcomes as much again): it keeps the analysis of a chart of any size to a fixed cost,
  /// so the compiler stays linear; a large chart gets fewer states.
  std::size_t max_work = 10000000;
};

enum class Firing { Free, Always, Never };
/// How a transition's condition behaves when its condition is not known.
Firing firing_of(const model::Transition &t);
bool is_open(const model::Transition &t, const Marking &m);

struct StateSpace {
  std::vector<Marking> states;                          ///< states[0] is the initial marking
  std::vector<int> parent;                              ///< the state first reached from; -1 for the initial
  std::vector<std::vector<model::TransitionId>> fired;  ///< the transitions that fired in that tick
  std::vector<std::vector<int>> successors;
  IdMap<model::TransitionId, bool> ever_fired;  ///< fires in some explored tick
  bool limit_hit = false;                       ///< stopped at a limit: some reachable states are missing
  std::size_t work = 0;                         ///< work done, as Limits::max_work counts it
  bool accelerated = false;                     ///< some count became ω: the states are an approximation
  std::size_t outcomes = 0;                     ///< tick outcomes enumerated

  /// Every reachable state is here, exactly: what is absent cannot happen.
  bool exact() const { return !limit_hit && !accelerated; }
};

StateSpace explore(const model::Chart &chart, const Limits &limits = {});

/// How the chart gets from its initial marking to `state`: "tick 1: T0; tick 2: T1, T3".
std::string witness(const model::Chart &chart, const StateSpace &space, int state);
/// "A, B=2, C=ω": the active places of a marking.
std::string marking_text(const model::Chart &chart, const Marking &m);

}  // namespace gfec::analysis
