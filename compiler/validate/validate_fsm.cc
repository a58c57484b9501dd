// The rules of an fsm (§7): one initial state, terminal states that end the machine, one
// transition per ordered pair of distinct states, and every state connected to the rest.
#include "id_groups.h"
#include "validate/families.h"

#include <fmt/format.h>

#include <cstdint>
#include <vector>

namespace gfec::validation {

namespace {

SourceRange where(const ast::Transition &t) { return t.named ? t.name.range : t.range; }

bool terminal(const ast::Place &p) { return p.terminal != ast::StateKind::Normal; }

/// sfc-only syntax in an fsm, and the rules of terminal states.
void check_state(Context &cx, ChartScope &s, const ast::Place &p, model::Place &out) {
  if (!p.is_state && !terminal(p))
    cx.diag.error(p.range, ErrorKind::WrongKeyword,
                  fmt::format("'place' in an fsm: an fsm has states (write 'state {}')", p.name.text));
  // `entry` and `exit` blocks run when the state is entered and left (docs/language.md "fsm
  // entry and exit"); a terminal state has no body at all, so neither.
  if (terminal(p) && p.has_body)
    cx.diag.error(p.range, ErrorKind::TerminalState,
                  fmt::format("terminal state '{}' cannot have a body", p.name.text));
  if (p.initial && terminal(p))
    cx.diag.error(p.name.range, ErrorKind::InitialState,
                  fmt::format("initial state '{}' cannot be a success or failure state", p.name.text));
  if (!p.post()) return;
  if (!terminal(p)) {
    cx.diag.error(p.post()->range, ErrorKind::TerminalState,
                  "only a success or failure state can have a 'post' condition");
    return;
  }
  ExprScope scope{cx, &s, false};
  out.post = lower_condition(p.post(), scope, "postcondition");
}

/// Notes initial state `index`; a second one is an error (§7: exactly one).
void note_initial(Context &cx, ChartScope &s, model::PlaceId index, model::PlaceId &initial) {
  if (!initial) {
    initial = index;
    return;
  }
  const ast::Place &first = s.ast.places[initial.index()];
  cx.diag
      .error(s.ast.places[index.index()].name.range, ErrorKind::InitialState,
             fmt::format("fsm '{}' has more than one initial state", s.out.name))
      .note(first.name.range, fmt::format("'{}' is already its initial state", first.name.text));
}

/// One side of an fsm transition: exactly one state.
model::PlaceId one_state(Context &cx, ChartScope &s, const ast::Transition &t, ast::NameSpan names, const char *side) {
  if (names.size() != 1) {
    cx.diag.error(t.range, ErrorKind::FsmTransition, fmt::format("an fsm transition has exactly one {} state", side));
    return {};
  }
  return resolve_place(s, cx, names[0]);
}

constexpr std::size_t kNoTransition = SIZE_MAX;

/// For each transition, the first one before it with the same two states, or kNoTransition:
/// the transitions grouped by the state they leave, then within a group each state entered
/// stamped with the group. Linear in the machine, where a map of the pairs was n log n and an
/// allocation a transition (a chain of a million states spent more there than anywhere else).
std::vector<std::size_t> earlier_twins(const model::Chart &c) {
  std::vector<std::pair<model::PlaceId, std::size_t>> by_source;
  by_source.reserve(c.transitions.size());
  for (std::size_t i = 0; i < c.transitions.size(); ++i) {
    const model::Transition &t = c.transitions[model::TransitionId(i)];
    if (!t.inputs.empty() && !t.outputs.empty()) by_source.emplace_back(t.inputs[0], i);
  }
  const IdGroups<model::PlaceId, std::size_t> leaving(c.places.size(), by_source);
  std::vector<std::size_t> twin(c.transitions.size(), kNoTransition);
  IdMap<model::PlaceId, model::PlaceId> stamp(c.places.size());  // the source that entered it last
  IdMap<model::PlaceId, std::size_t> first(c.places.size());     // and by which transition
  for (model::PlaceId from : c.places.ids())
    for (std::size_t i : leaving[from]) {
      const model::PlaceId to = c.transitions[model::TransitionId(i)].outputs[0];
      if (stamp[to] == from) {
        twin[i] = first[to];
      } else {
        stamp[to] = from;
        first[to] = i;
      }
    }
  return twin;
}

/// Checks one resolved transition `from -> to` against the rules of §7; `twin` is the first
/// transition before it between the same two states, if any.
void check_transition(Context &cx, ChartScope &s, std::size_t i, model::PlaceId from, model::PlaceId to,
                      std::size_t twin) {
  const ast::Transition &t = s.ast.transitions[i];
  const ast::Place &source = s.ast.places[from.index()];
  if (terminal(source))
    cx.diag
        .error(where(t), ErrorKind::TerminalState,
               fmt::format("transition leaves terminal state '{}'", source.name.text))
        .note(source.name.range, fmt::format("'{}' ends the machine", source.name.text));
  if (from == to)
    cx.diag.error(where(t), ErrorKind::SelfTransition,
                  fmt::format("transition from state '{}' to itself", source.name.text));
  if (twin != kNoTransition)
    cx.diag
        .error(where(t), ErrorKind::DuplicateTransition,
               fmt::format("second transition from '{}' to '{}'", source.name.text, s.ast.places[to.index()].name.text))
        .note(where(s.ast.transitions[twin]), "the first one is here");
}

/// Every state must be weakly connected to the initial state (§7).
void check_connected(Context &cx, ChartScope &s, model::PlaceId initial) {
  IdMap<model::PlaceId, model::PlaceId> parent(s.out.places.size());  // union-find
  for (model::PlaceId p : s.out.places.ids()) parent[p] = p;
  auto root = [&](model::PlaceId x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto &t : s.out.transitions)
    if (!t.inputs.empty() && !t.outputs.empty()) parent[root(t.inputs[0])] = root(t.outputs[0]);
  for (model::PlaceId p : s.out.places.ids()) {
    if (root(p) == root(initial)) continue;
    cx.diag.error(s.ast.places[p.index()].name.range, ErrorKind::NotConnected,
                  fmt::format("state '{}' is not connected to the initial state '{}'", s.out.places[p].name,
                              s.out.places[initial].name));
  }
}

/// States the machine can never enter (conditions treated as free, except a constant false)
/// and the transitions that leave them.
void warn_unreachable(Context &cx, ChartScope &s, model::PlaceId initial) {
  const model::Chart &c = s.out;
  std::vector<bool> live;
  IdMap<model::PlaceId, bool> reach(c.places.size());
  std::vector<std::pair<model::PlaceId, model::PlaceId>> edges;  // a search, linear in the machine
  for (const auto &t : c.transitions) {
    live.push_back(constant_condition(t.condition, cx.model) != false);
    if (live.back()) edges.emplace_back(t.inputs[0], t.outputs[0]);
  }
  const IdGroups<model::PlaceId, model::PlaceId> next(c.places.size(), edges);
  std::vector<model::PlaceId> work{initial};
  reach[initial] = true;
  while (!work.empty()) {
    model::PlaceId p = work.back();
    work.pop_back();
    for (model::PlaceId q : next[p])
      if (!reach[q]) {
        reach[q] = true;
        work.push_back(q);
      }
  }
  for (model::PlaceId p : c.places.ids())
    if (!reach[p])
      cx.diag.warning(Warning::UnreachablePlace, s.ast.places[p.index()].name.range,
                      fmt::format("state '{}' can never become active", c.places[p].name));
  for (std::size_t t = 0; t < c.transitions.size(); ++t) {
    const auto &tr = c.transitions[t];
    if (!live[t])
      cx.diag.warning(Warning::DeadTransition, where(s.ast.transitions[t]),
                      fmt::format("transition '{}' can never fire: its condition is always false", tr.name));
    else if (!reach[tr.inputs[0]])
      cx.diag.warning(Warning::DeadTransition, where(s.ast.transitions[t]),
                      fmt::format("transition '{}' can never fire: state '{}' never becomes active", tr.name,
                                  c.places[tr.inputs[0]].name));
  }
}

}  // namespace

void resolve_fsm_places(Context &cx, ChartScope &s, std::size_t index) {
  const ast::Transition &t = s.ast.transitions[index];
  model::PlaceId from = one_state(cx, s, t, t.inputs(), "source");
  model::PlaceId to = one_state(cx, s, t, t.outputs(), "target");
  if (!from || !to) return;  // left without places: check_fsm sees it was not resolved
  s.out.transitions[index].inputs = {from};
  s.out.transitions[index].outputs = {to};
}

void check_fsm(Context &cx, ChartScope &s, const ErrorWatch &watch) {
  model::PlaceId initial;
  for (model::PlaceId p : s.out.places.ids()) {
    check_state(cx, s, s.ast.places[p.index()], s.out.places[p]);
    if (s.ast.places[p.index()].initial) note_initial(cx, s, p, initial);
  }
  if (!initial)
    cx.diag.error(s.ast.name.range, ErrorKind::InitialState, fmt::format("fsm '{}' has no initial state", s.out.name))
        .note("mark the state it starts in with 'initial state'");
  const std::vector<std::size_t> twins = earlier_twins(s.out);
  bool resolved = true;  // every transition has its two states (resolve_fsm_places)
  for (std::size_t i = 0; i < s.ast.transitions.size(); ++i) {
    const model::Transition &t = s.out.transitions[i];
    if (!t.inputs.empty() && !t.outputs.empty()) check_transition(cx, s, i, t.inputs[0], t.outputs[0], twins[i]);
    else resolved = false;
    lower_transition_condition(cx, s, i);
  }
  // A transition that could not be resolved would make the connectivity check report its
  // consequences.
  if (initial && resolved) check_connected(cx, s, initial);
  if (initial && watch.clean()) warn_unreachable(cx, s, initial);
}

}  // namespace gfec::validation
