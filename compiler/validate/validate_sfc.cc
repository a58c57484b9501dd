// The rules of an sfc (§5): places, at least one initial place, transitions between places of
// the chart; and the warnings that over-approximate what can ever happen.
#include "validate/families.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <set>

namespace gfec::validation {

namespace {

/// Where to point at a transition: its name if it has one.
SourceRange where(const ast::Transition &t) { return t.named ? t.name.range : t.range; }

/// fsm-only syntax in an sfc.
void check_keywords(Context &cx, const ast::Place &p) {
  if (p.terminal != ast::StateKind::Normal)
    cx.diag.error(p.range, ErrorKind::WrongKeyword, "success and failure states belong to an fsm; an sfc has places");
  else if (p.is_state)
    cx.diag.error(p.range, ErrorKind::WrongKeyword,
                  fmt::format("'state' in an sfc: an sfc has places (write 'place {}')", p.name.text));
  if (p.post()) cx.diag.error(p.post()->range, ErrorKind::WrongKeyword, "'post' belongs to a terminal state of an fsm");
}

/// Resolves a transition's inputs or outputs (`side`), reporting a place listed twice.
model::PlaceList resolve_places(Context &cx, ChartScope &s, ast::NameSpan names, const char *side,
                                std::string_view transition) {
  model::PlaceList out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    model::PlaceId p = resolve_place(s, cx, names[i]);
    if (!p) continue;
    bool twice = false;
    for (std::size_t j = 0; j < i && !twice; ++j) {
      if (names[j].text != names[i].text) continue;
      cx.diag
          .error(
              names[i].range, ErrorKind::DuplicatePlace,
              fmt::format("place '{}' is listed twice in the {} of transition '{}'", names[i].text, side, transition))
          .note(names[j].range, "first listed here");
      twice = true;
    }
    if (!twice) out.push_back(p);
  }
  return out;
}

void lower_conditions(Context &cx, ChartScope &s) {
  for (std::size_t i = 0; i < s.ast.transitions.size(); ++i) lower_transition_condition(cx, s, i);
}

/// The places some activation can reach, treating every condition as free except a constant
/// `false`: a place is reachable if a live transition outputs it from reachable inputs.
/// A worklist, so the cost is linear in the chart whatever the order of its declarations.
IdMap<model::PlaceId, bool> reachable_places(const model::Chart &c, const std::vector<bool> &live) {
  IdMap<model::PlaceId, bool> reach(c.places.size());
  // The transitions that consume each place, as one flat array (compressed rows: place p's are
  // consumers[first[p]] up to consumers[first[p + 1]]) rather than a heap vector per place, which
  // a chart of a million places would allocate a million times (docs/performance.md).
  std::vector<std::uint32_t> first(c.places.size() + 1);
  std::vector<std::uint32_t> missing(c.transitions.size());  // inputs not reached yet
  for (std::size_t t = 0; t < c.transitions.size(); ++t) {
    missing[t] = static_cast<std::uint32_t>(c.transitions[t].inputs.size());
    for (model::PlaceId p : c.transitions[t].inputs) ++first[p.index() + 1];
  }
  for (std::size_t p = 0; p < c.places.size(); ++p) first[p + 1] += first[p];
  std::vector<std::uint32_t> consumers(first.back());
  std::vector<std::uint32_t> next(first.begin(), first.end() - 1);  // where each row's next goes
  for (std::size_t t = 0; t < c.transitions.size(); ++t)
    for (model::PlaceId p : c.transitions[t].inputs) consumers[next[p.index()]++] = static_cast<std::uint32_t>(t);
  std::vector<std::uint32_t>().swap(next);
  std::vector<model::PlaceId> work;
  auto reached = [&](model::PlaceId p) {
    if (reach[p]) return;
    reach[p] = true;
    work.push_back(p);
  };
  for (model::PlaceId p : c.places.ids())
    if (c.places[p].initial) reached(p);
  while (!work.empty()) {
    std::size_t p = work.back().index();
    work.pop_back();
    for (std::uint32_t k = first[p]; k < first[p + 1]; ++k)
      if (std::uint32_t t = consumers[k]; --missing[t] == 0 && live[t])
        for (model::PlaceId q : c.transitions[t].outputs) reached(q);
  }
  return reach;
}

void warn_unreachable(Context &cx, ChartScope &s) {
  const model::Chart &c = s.out;
  std::vector<std::optional<bool>> constant;
  std::vector<bool> live;
  for (const auto &t : c.transitions) {
    constant.push_back(constant_condition(t.condition, cx.model));
    live.push_back(constant.back() != false);
  }
  IdMap<model::PlaceId, bool> reach = reachable_places(c, live);
  for (model::PlaceId p : c.places.ids())
    if (!reach[p])
      cx.diag.warning(Warning::UnreachablePlace, s.ast.places[p.index()].name.range,
                      fmt::format("place '{}' can never become active", c.places[p].name));
  std::vector<bool> dead(c.transitions.size());
  for (std::size_t t = 0; t < c.transitions.size(); ++t) {
    const auto &tr = c.transitions[t];
    SourceRange at = where(s.ast.transitions[t]);
    if (!live[t]) {
      cx.diag.warning(Warning::DeadTransition, at,
                      fmt::format("transition '{}' can never fire: its condition is always false", tr.name));
      dead[t] = true;
      continue;
    }
    for (model::PlaceId p : tr.inputs) {
      if (reach[p]) continue;
      cx.diag.warning(Warning::DeadTransition, at,
                      fmt::format("transition '{}' can never fire: its input place '{}' never "
                                  "becomes active",
                                  tr.name, c.places[p].name));
      dead[t] = true;
      break;
    }
  }
  // Conflicts (§5.1): declaration order decides; worth a look when a condition can vary. A
  // transition is reported once, against the first earlier live transition that shares an input
  // (and is not, like it, constant); never a transition written `else`, whose chart says the
  // order is intended (check_else saw that an earlier transition shares its input). Per place, the first such transition of either kind is kept,
  // so the check is linear in the chart rather than quadratic in its transitions.
  const std::size_t none = c.transitions.size();
  IdMap<model::PlaceId, std::size_t> first_any(c.places.size(), none), first_varying(c.places.size(), none);
  for (std::size_t j = 0; j < c.transitions.size(); ++j) {
    if (dead[j]) continue;
    const auto &second = c.transitions[j];
    std::size_t i = none;
    for (model::PlaceId p : second.inputs) i = std::min(i, constant[j] ? first_varying[p] : first_any[p]);
    if (i != none && !second.otherwise) {
      const auto &first = c.transitions[i];
      auto shared =
          std::find_first_of(second.inputs.begin(), second.inputs.end(), first.inputs.begin(), first.inputs.end());
      cx.diag
          .warning(Warning::Conflict, where(s.ast.transitions[j]),
                   fmt::format("transition '{}' competes with '{}' for place '{}'", second.name, first.name,
                               c.places[*shared].name))
          .note(where(s.ast.transitions[i]),
                fmt::format("'{}' is declared first: when both can fire, it takes the activation", first.name));
    }
    for (model::PlaceId p : second.inputs) {
      if (first_any[p] == none) first_any[p] = j;
      if (!constant[j] && first_varying[p] == none) first_varying[p] = j;
    }
  }
}

}  // namespace

void check_sfc(Context &cx, ChartScope &s, const ErrorWatch &watch) {
  bool initial = false;
  for (const ast::Place &p : s.ast.places) {
    check_keywords(cx, p);
    initial = initial || p.initial;
  }
  if (!initial)
    cx.diag.error(s.ast.name.range, ErrorKind::InitialState, fmt::format("sfc '{}' has no initial place", s.out.name))
        .note("mark the places active at start with 'initial place'");
  lower_conditions(cx, s);
  if (watch.clean()) warn_unreachable(cx, s);
}

void resolve_sfc_places(Context &cx, ChartScope &s, std::size_t index) {
  const ast::Transition &t = s.ast.transitions[index];
  model::Transition &out = s.out.transitions[index];
  if (t.inputs().empty())
    cx.diag.error(t.range, ErrorKind::NoInput, fmt::format("transition '{}' has no input place", out.name));
  out.inputs = resolve_places(cx, s, t.inputs(), "inputs", out.name);
  out.outputs = resolve_places(cx, s, t.outputs(), "outputs", out.name);
}

}  // namespace gfec::validation
