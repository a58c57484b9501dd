#include "sfc_states.h"

#include <fmt/format.h>

#include <deque>
#include <map>
#include <set>

namespace gfec::analysis {

namespace {

std::uint32_t take(std::uint32_t n) { return n == kOmega ? kOmega : n - 1; }
std::uint32_t give(std::uint32_t n, std::uint32_t k) {
  if (n == kOmega || k == kOmega) return kOmega;
  return n + k >= kOmega ? kOmega : n + k;
}

/// `a` has at least as much activation as `b` in every place.
bool covers(const Marking &a, const Marking &b) {
  for (std::size_t p = 0; p < a.size(); ++p)
    if (a[p] < b[p]) return false;
  return true;
}

/// Every outcome of one tick from a marking: each open free transition fires or not. The
/// transitions are walked in a loop; only a free transition that is open branches (the outcome
/// without it is explored first), so the recursion is as deep as the branches taken, which the
/// budget bounds, never as deep as the chart is long.
class Tick {
public:
  Tick(const model::Chart &c, const std::vector<Firing> &firing, std::size_t budget)
      : c_(c), firing_(firing), budget_(budget) {}

  /// The distinct outcomes, each with the transitions that fired; false if the budget ran out.
  bool outcomes(const Marking &m, std::map<Marking, std::vector<model::TransitionId>> &out) {
    visit(0, m, Marking(m.size(), 0), {}, 0, out);
    return used_ <= budget_;
  }
  std::size_t used() const { return used_; }
  /// Every transition that fired in some outcome. `outcomes` keeps one firing set per resulting
  /// marking, so a transition whose firing changes nothing (a self-loop `A -> A`) may be missing
  /// from it; it is never missing here.
  const IdMap<model::TransitionId, bool> &fired_any() const { return fired_any_; }

private:
  static constexpr int kMaxBranches = 64;

  void visit(std::size_t t, Marking avail, Marking add, std::vector<model::TransitionId> fired, int branches,
             std::map<Marking, std::vector<model::TransitionId>> &out) {
    for (; t < c_.transitions.size(); ++t) {
      if (used_ > budget_) return;
      const model::Transition &tr = c_.transitions[t];
      const Firing f = firing_[t];
      if (f == Firing::Never || !is_open(tr, avail)) continue;
      if (f == Firing::Free) {
        if (branches >= kMaxBranches) {
          used_ = budget_ + 1;
          return;
        }
        visit(t + 1, avail, add, fired, branches + 1, out);  // it does not fire
      }
      for (model::PlaceId p : tr.inputs) avail[p.index()] = take(avail[p.index()]);
      for (model::PlaceId p : tr.outputs) add[p.index()] = give(add[p.index()], 1);
      fired.push_back(model::TransitionId(t));
    }
    ++used_;
    for (std::size_t p = 0; p < avail.size(); ++p) avail[p] = give(avail[p], add[p]);
    for (model::TransitionId f : fired) fired_any_[f] = true;
    out.emplace(std::move(avail), std::move(fired));
  }

  const model::Chart &c_;
  const std::vector<Firing> &firing_;
  std::size_t budget_;
  std::size_t used_ = 0;
  IdMap<model::TransitionId, bool> fired_any_ = IdMap<model::TransitionId, bool>(c_.transitions.size(), false);
};

/// A quick necessary condition for `a` to cover `b` strictly: more unbounded places, or as many
/// and more activation in the rest. It spares most comparisons of whole markings.
struct Size {
  std::size_t omegas = 0;
  std::uint64_t finite = 0;
};
Size size_of(const Marking &m) {
  Size s;
  for (auto k : m) k == kOmega ? ++s.omegas : s.finite += k;
  return s;
}
bool may_cover_strictly(const Size &a, const Size &b) {
  return a.omegas > b.omegas || (a.omegas == b.omegas && a.finite > b.finite);
}

}  // namespace

Firing firing_of(const model::Transition &t) {
  if (!t.condition) return Firing::Always;
  const model::Expr *e = &*t.condition;
  while (e->kind == model::Expr::Kind::Paren && !e->args.empty()) e = &e->args[0];
  if (e->kind == model::Expr::Kind::Bool) return e->bool_value ? Firing::Always : Firing::Never;
  return Firing::Free;
}

bool is_open(const model::Transition &t, const Marking &m) {
  for (model::PlaceId p : t.inputs)
    if (m[p.index()] == 0) return false;
  return true;
}

StateSpace explore(const model::Chart &chart, const Limits &limits) {
  StateSpace s;
  s.ever_fired.assign(chart.transitions.size(), false);
  std::vector<Firing> firing;
  for (const auto &t : chart.transitions) firing.push_back(firing_of(t));
  Marking initial;
  for (const auto &p : chart.places) initial.push_back(p.initial ? 1 : 0);
  std::map<Marking, int> index;
  std::vector<Size> sizes;
  auto add_state = [&](Marking m, int parent, std::vector<model::TransitionId> fired) {
    auto found = index.find(m);
    if (found != index.end()) return found->second;
    int i = static_cast<int>(s.states.size());
    index.emplace(m, i);
    sizes.push_back(size_of(m));
    s.states.push_back(std::move(m));
    s.parent.push_back(parent);
    s.fired.push_back(std::move(fired));
    s.successors.emplace_back();
    return i;
  };
  add_state(initial, -1, {});
  const std::size_t size = chart.places.size() + chart.transitions.size() + 1;
  for (std::size_t i = 0; i < s.states.size(); ++i) {
    std::map<Marking, std::vector<model::TransitionId>> outcomes;
    Tick tick(chart, firing, limits.max_outcomes - std::min(limits.max_outcomes, s.outcomes));
    bool all = tick.outcomes(s.states[i], outcomes);
    s.outcomes += tick.used();
    s.work += size * (1 + tick.used());
    if (!all || s.work > limits.max_work) {
      s.limit_hit = true;
      break;
    }
    for (model::TransitionId t : tick.fired_any().ids())
      if (tick.fired_any()[t]) s.ever_fired[t] = true;
    std::set<int> seen;
    for (auto &[next, fired] : outcomes) {
      Marking m = next;
      Size m_size = size_of(m);
      // Karp-Miller: growth over an ancestor can repeat, so it is unbounded.
      for (int a = static_cast<int>(i); a >= 0; a = s.parent[static_cast<std::size_t>(a)]) {
        ++s.work;
        if (!may_cover_strictly(m_size, sizes[static_cast<std::size_t>(a)])) continue;
        const Marking &old = s.states[static_cast<std::size_t>(a)];
        s.work += size;
        if (m == old || !covers(m, old)) continue;
        for (std::size_t p = 0; p < m.size(); ++p)
          if (m[p] > old[p] && m[p] != kOmega) {
            m[p] = kOmega;
            s.accelerated = true;
          }
        m_size = size_of(m);
      }
      if (index.count(m) == 0 && s.states.size() >= limits.max_states) {
        s.limit_hit = true;
        continue;
      }
      int j = add_state(std::move(m), static_cast<int>(i), fired);
      if (seen.insert(j).second) s.successors[i].push_back(j);
    }
    if (s.limit_hit) break;
  }
  return s;
}

std::string marking_text(const model::Chart &chart, const Marking &m) {
  std::string out;
  for (std::size_t p = 0; p < m.size(); ++p) {
    if (m[p] == 0) continue;
    out += out.empty() ? "" : ", ";
    out += chart.places[p].name;
    if (m[p] == kOmega) out += "=ω";
    else if (m[p] > 1) out += fmt::format("={}", m[p]);
  }
  return out.empty() ? "nothing active" : out;
}

std::string witness(const model::Chart &chart, const StateSpace &space, int state) {
  std::vector<int> path;
  for (int s = state; s > 0; s = space.parent[static_cast<std::size_t>(s)]) path.push_back(s);
  std::string out;
  int tick = 1;
  for (auto it = path.rbegin(); it != path.rend(); ++it, ++tick) {
    std::string fired;
    for (model::TransitionId t : space.fired[static_cast<std::size_t>(*it)])
      fired += (fired.empty() ? "" : ", ") + chart.transitions[t].name;
    out += fmt::format("{}tick {}: {}", out.empty() ? "" : "; ", tick, fired.empty() ? "nothing fires" : fired);
  }
  return out.empty() ? "at the start" : out;
}

}  // namespace gfec::analysis
