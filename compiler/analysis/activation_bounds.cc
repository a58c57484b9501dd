#include "analysis/activation_bounds.h"

#include "analysis/sfc_states.h"
#include "id_groups.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace gfec::analysis {

namespace {

/// Looks for weights w(p) >= 1 with sum(w of inputs) >= sum(w of outputs) for every transition
/// (a transition never creates weight, so sum(w * AV) never grows). Starting from w = 1, a
/// transition short of weight raises its first input by the shortfall, and the transitions
/// producing into that place are looked at again. A chart that pumps activation (P -> (P, Q))
/// keeps raising a weight: past a cap, or after a number of raises proportional to the chart,
/// the search gives up and the chart counts as unbounded. Sound whatever it answers: when it
/// returns weights, they prove the bound.
bool find_weights(const model::Chart &c, IdMap<model::PlaceId, std::uint64_t> &w) {
  const std::size_t np = c.places.size(), nt = c.transitions.size();
  constexpr std::uint64_t kCap = std::uint64_t(1) << 32;
  w.assign(np, 1);
  std::vector<std::pair<model::PlaceId, model::TransitionId>> produced;  // (a place, a transition producing into it)
  std::size_t arcs = 0;
  for (model::TransitionId t : c.transitions.ids()) {
    arcs += c.transitions[t].inputs.size() + c.transitions[t].outputs.size();
    for (model::PlaceId q : c.transitions[t].outputs) produced.emplace_back(q, t);
  }
  const IdGroups<model::PlaceId, model::TransitionId> producers(np, produced);
  std::vector<model::TransitionId> work(nt);
  IdMap<model::TransitionId, bool> queued(nt, true);
  for (std::size_t t = 0; t < nt; ++t) work[t] = model::TransitionId(nt - 1 - t);  // popped from the back: in order
  std::size_t budget = 16 * (arcs + nt) + 1000;
  auto sum = [&](const model::PlaceList &places) {
    std::uint64_t s = 0;
    for (model::PlaceId p : places) s += w[p];
    return s;
  };
  while (!work.empty()) {
    model::TransitionId t = work.back();
    work.pop_back();
    queued[t] = false;
    const auto &tr = c.transitions[t];
    std::uint64_t in = sum(tr.inputs), out = sum(tr.outputs);
    if (in >= out) continue;
    if (tr.inputs.empty() || budget-- == 0) return false;
    model::PlaceId p = tr.inputs.front();
    w[p] += out - in;
    if (w[p] > kCap) return false;
    for (model::TransitionId u : producers[p])
      if (!queued[u]) {
        queued[u] = true;
        work.push_back(u);
      }
    if (!queued[t]) {  // raising its own input may not be enough (a place both in and out)
      queued[t] = true;
      work.push_back(t);
    }
  }
  return true;
}

}  // namespace

model::ActivationBound prove_activation_bound(const model::Chart &c) {
  model::ActivationBound b;
  IdMap<model::PlaceId, std::uint64_t> w;
  if (!find_weights(c, w)) return b;
  std::uint64_t initial = 0;
  for (model::PlaceId p : c.places.ids())
    if (c.places[p].initial) initial += w[p];
  std::uint64_t place = 0;
  for (model::PlaceId p : c.places.ids()) place = std::max(place, initial / w[p]);
  if (place > UINT32_MAX) return b;
  b.bounded = true;
  b.total = initial;  // every weight is at least 1
  b.place = static_cast<std::uint32_t>(place);
  return b;
}

model::ActivationBound exact_activation_bound(const model::Chart &c) {
  model::ActivationBound b;
  if (c.kind != model::Chart::Kind::Sfc) return b;
  const StateSpace space = explore(c);
  if (!space.exact()) return b;
  for (const Marking &m : space.states) {
    std::uint64_t total = 0;
    for (std::uint32_t k : m) {
      b.place = std::max(b.place, k);
      total += k;
    }
    b.total = std::max(b.total, total);
  }
  b.bounded = true;
  return b;
}

void record_activation_bounds(model::Model &model) {
  for (auto &c : model.charts) {
    c.activation = prove_activation_bound(c);
    // The initial marking is a reachable state: a bound it reaches already is exact, and the
    // exploration (a fixed budget, but a chart-sized cost per state) is skipped.
    std::uint64_t initial = 0;
    for (const auto &p : c.places) initial += p.initial ? 1 : 0;
    if (c.activation.bounded && c.activation.place <= 1 && c.activation.total <= initial) continue;
    // The weights' bound can exceed what any reachable state holds (a fork's two branches weigh
    // two, though no place holds more than one); --analyze reports what the states hold, so the
    // engine uses that number too when the exploration saw every state: one bound, in the
    // header and in --analyze alike (issue 41).
    if (model::ActivationBound exact = exact_activation_bound(c); exact.bounded)
      if (!c.activation.bounded || exact.place < c.activation.place || exact.total < c.activation.total) {
        if (c.activation.bounded) {
          exact.place = std::min(exact.place, c.activation.place);
          exact.total = std::min(exact.total, c.activation.total);
        }
        c.activation = exact;
      }
  }
}

}  // namespace gfec::analysis
