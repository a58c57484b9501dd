#include "c_layout.h"

#include <algorithm>
#include <functional>

namespace gfec::c_backend {

namespace {

int bits_for(std::uint64_t max) { return max <= UINT8_MAX ? 8 : max <= UINT16_MAX ? 16 : 32; }

/// Owners such that visiting the active places in increasing order, and at each its transitions
/// in declaration order, tries the transitions in declaration order: the owner of each
/// transition is one of its inputs, never before the previous transition's owner. A transition
/// whose owner is not active is not open, so nothing is missed. Greedy: the smallest input that
/// is not before the last owner leaves the most room for the transitions after it.
bool choose_owners(const model::Chart &c, IdMap<model::TransitionId, model::PlaceId> &owner) {
  owner.clear();
  model::PlaceId last(0);
  bool in_order = true;
  for (const auto &t : c.transitions) {
    model::PlaceId best;
    for (model::PlaceId p : t.inputs)
      if (p >= last && (!best || p < best)) best = p;
    if (!best) {
      in_order = false;
      best = *std::min_element(t.inputs.begin(), t.inputs.end());
    }
    owner.push_back(best);
    last = std::max(last, best);
  }
  return in_order;
}

bool is_sequential(const model::Chart &c) {
  int initial = 0;
  for (const auto &p : c.places) initial += p.initial ? 1 : 0;
  if (initial != 1) return false;
  for (const auto &t : c.transitions)
    if (t.inputs.size() != 1 || t.outputs.size() != 1) return false;
  return true;
}

void plan_lists(const model::Chart &c, Layout &l) {
  std::vector<std::size_t> outputs;
  std::size_t all = 0;
  for (const auto &t : c.transitions) {
    outputs.push_back(t.outputs.size());
    all += t.outputs.size();
  }
  l.add_capacity = all;
  if (l.activation.bounded && l.activation.total < outputs.size()) {
    // Each transition fires at most once a tick and consumes activation present at its start,
    // so at most `tokens` fire: the most outputs they can have is the `tokens` largest counts.
    std::sort(outputs.begin(), outputs.end(), std::greater<>());
    std::size_t most = 0;
    for (std::size_t i = 0; i < l.activation.total; ++i) most += outputs[i];
    l.add_capacity = most;
  }
  std::size_t watched = static_cast<std::size_t>(std::count(l.watched.begin(), l.watched.end(), true));
  l.watch_capacity = l.activation.bounded ? std::min<std::uint64_t>(watched, l.activation.total) : watched;
  if (l.watch_capacity == 0) return;
  // At most `tokens` places are active at once, so at most that many fall to 0 or rise from 0
  // in a tick; and only a watched place some transition consumes from (produces into) can.
  IdMap<model::PlaceId, bool> consumed(c.places.size()), produced(c.places.size());
  for (const auto &t : c.transitions) {
    for (model::PlaceId p : t.inputs) consumed[p] = true;
    for (model::PlaceId p : t.outputs) produced[p] = true;
  }
  auto capacity = [&](const IdMap<model::PlaceId, bool> &moved) {
    std::size_t n = 0;
    for (model::PlaceId p : c.places.ids()) n += l.watched[p.index()] && moved[p] ? 1 : 0;
    return std::max<std::size_t>(1, l.activation.bounded ? std::min<std::uint64_t>(n, l.activation.total) : n);
  };
  l.lost_capacity = capacity(consumed);
  l.gained_capacity = capacity(produced);
}

}  // namespace

BitLevels bit_levels(std::size_t n) {
  // At least two levels, so that the top (one word) always summarises a level below it.
  BitLevels b;
  b.from.push_back(0);
  std::size_t words = std::max<std::size_t>(1, (n + 31) / 32);
  for (;;) {
    b.from.push_back(b.from.back() + static_cast<std::uint32_t>(words));
    if (words == 1 && b.from.size() >= 3) break;
    words = (words + 31) / 32;
  }
  return b;
}

const char *uint_type(int bits) { return bits == 8 ? "uint8_t" : bits == 16 ? "uint16_t" : "uint32_t"; }

Layout plan_layout(const model::Chart &chart, EngineForm requested, std::vector<bool> watched) {
  Layout l;
  l.watched = std::move(watched);
  // The bound is a fact of the model, proven once by the analyses (analysis/activation_bounds.h).
  l.activation = chart.activation;
  l.counter_bits = l.activation.bounded ? bits_for(l.activation.place) : 32;
  // One state of an fsm is ever active: its scalable form is the sequential one, a switch on the
  // state (c_switch_run.h), which spares a tick the chain's one test per transition.
  const bool sequential = chart.kind == model::Chart::Kind::Fsm || is_sequential(chart);
  // `auto`: the scalable form pays per active place for its bookkeeping, so it wins only where
  // little of a large chart is active at once; a chart that keeps a quarter of its places or more
  // active (as many parallel branches do) runs faster in the readable form.
  const bool concurrent = l.activation.bounded && l.activation.total * 4 > chart.places.size();
  bool scalable =
      requested == EngineForm::Scalable ||
      (requested == EngineForm::Auto && chart.places.size() > kReadableMaxPlaces && (sequential || !concurrent));
  if (!scalable) return l;
  l.form = sequential ? Layout::Form::Sequential : Layout::Form::Sparse;
  l.index_bits = bits_for(chart.places.size());
  if (l.form == Layout::Form::Sequential) {
    if (chart.places.size() > kSplitAbovePlaces) l.part_places = kPartPlaces;
    return l;
  }
  l.saturate = !l.activation.bounded;
  l.place_driven = choose_owners(chart, l.owner);
  l.active = bit_levels(chart.places.size());
  if (!l.place_driven) l.candidates = bit_levels(chart.transitions.size());
  plan_lists(chart, l);
  return l;
}

}  // namespace gfec::c_backend
