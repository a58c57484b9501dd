#include "engine.h"

#include <fmt/format.h>

#include <limits>
#include <map>

namespace gfec::interp {

namespace {
constexpr std::uint32_t kTimerMax = std::numeric_limits<std::uint32_t>::max();
} // namespace

Engine::Engine(const model::Model &model, int chart, EngineOptions options)
    : model_(model), chart_(model.charts.at(static_cast<std::size_t>(chart))), options_(options) {
  init();
}

void Engine::init() {
  const std::size_t n = chart_.places.size();
  av_.assign(n, 0);
  timers_.assign(n, 0);
  state_ = -1;
  status_ = 0;
  for (std::size_t p = 0; p < n; ++p) {
    if (!chart_.places[p].initial) continue;
    av_[p] = 1;
    if (state_ < 0) state_ = static_cast<int>(p);
  }
  started_ = false;
  tick_ = 0;
  agent_ = 0;
  reports_.assign(static_cast<std::size_t>(chart_.team), -1);
  vars_.clear();
  for (const model::Var &v : chart_.vars) vars_.push_back(Value::zero(v.type));
  // Initialisers are constant: no calls, no vars, no timers (the validator sees to it).
  Frame f{model_, chart_, vars_, timers_, nullptr, nullptr, 0, 1};
  for (std::size_t i = 0; i < chart_.vars.size(); ++i)
    if (chart_.vars[i].init) vars_[i] = convert(evaluate(*chart_.vars[i].init, f), chart_.vars[i].type, chart_.vars[i].range);
}

void Engine::set_agent(int agent) {
  if (agent >= 0 && agent < chart_.team) agent_ = agent;  // agent() stays within 0 ... N-1
}

void Engine::report(int agent, int state) {
  if (agent < 0 || agent >= chart_.team || agent == agent_) return;
  if (state < 0 || static_cast<std::size_t>(state) >= chart_.places.size()) return;
  reports_[static_cast<std::size_t>(agent)] = state;
}

unsigned Engine::activation(int place) const {
  if (place < 0 || static_cast<std::size_t>(place) >= chart_.places.size()) return 0;
  if (is_fsm()) return place == state_ ? 1u : 0u;
  return av_[static_cast<std::size_t>(place)];
}

void Engine::run(Environment &env, EventLog *log) {
  ++tick_;
  if (log) log->add(EventKind::Tick, 0, fmt::format("tick {}", tick_));
  Frame f{model_, chart_, vars_, timers_, &env, log, tick_, 1, agent_, chart_.team > 0 ? &reports_ : nullptr};
  if (!started_) {
    // §5.1: the first tick begins with the entry blocks of the initial places.
    started_ = true;
    for (std::size_t p = 0; p < chart_.places.size(); ++p)
      if (chart_.places[p].initial) block(EventKind::Entry, "entry", static_cast<int>(p), chart_.places[p].entry ? &*chart_.places[p].entry : nullptr, f);
  }
  if (is_fsm())
    run_fsm(f);
  else
    run_sfc(f);
  end_of_tick(f);
}

std::string Engine::label(const model::Transition &t) const {
  auto side = [&](const std::vector<int> &places) {
    std::string s;
    for (int p : places) s += (s.empty() ? "" : ", ") + chart_.places.at(static_cast<std::size_t>(p)).name;
    return places.size() == 1 ? s : "(" + s + ")";
  };
  return side(t.inputs) + " -> " + side(t.outputs);
}

bool Engine::condition(int t, Frame &f) {
  const model::Transition &tr = chart_.transitions[static_cast<std::size_t>(t)];
  if (!tr.condition) return true;
  const std::size_t mark = f.log ? f.log->size() : 0;
  f.depth = 2;
  bool holds = convert(evaluate(*tr.condition, f), model::Type::Bool, tr.condition->range).b;
  f.depth = 1;
  if (f.log) f.log->insert(mark, EventKind::Condition, 1, fmt::format("cond {} = {}", tr.name, holds ? "true" : "false"));
  return holds;
}

void Engine::block(EventKind kind, const char *word, int place, const std::vector<model::Stmt> *stmts, Frame &f) {
  if (f.log) f.log->add(kind, 1, fmt::format("{} {}", word, chart_.places.at(static_cast<std::size_t>(place)).name));
  if (!stmts) return;
  f.depth = 2;
  execute(*stmts, f);
  f.depth = 1;
}

void Engine::run_sfc(Frame &f) {
  const std::size_t n = chart_.places.size();
  const std::vector<std::uint32_t> before = av_;
  // 1. Timers of the places active at the start of the tick.
  for (std::size_t p = 0; p < n; ++p)
    if (av_[p] > 0 && timers_[p] < kTimerMax) ++timers_[p];
  // 2. Transitions in declaration order; produced activation waits in `add`.
  std::vector<std::uint32_t> avail = av_, add(n, 0);
  for (std::size_t t = 0; t < chart_.transitions.size(); ++t) {
    const model::Transition &tr = chart_.transitions[t];
    // Open: every input place has activation left (a place listed twice needs two).
    std::map<int, std::uint32_t> need;
    for (int p : tr.inputs) ++need[p];
    bool open = true;
    for (auto [p, k] : need) open = open && avail[static_cast<std::size_t>(p)] >= k;
    if (!open || !condition(static_cast<int>(t), f)) continue;
    for (int p : tr.inputs) --avail[static_cast<std::size_t>(p)];
    for (int p : tr.outputs) ++add[static_cast<std::size_t>(p)];
    if (f.log) f.log->add(EventKind::Fire, 1, fmt::format("fire {}: {}", tr.name, label(tr)));
  }
  // 3. Commit; compare the start of the tick with its end: all exits, then all entries.
  for (std::size_t p = 0; p < n; ++p) av_[p] = avail[p] + add[p];
  for (std::size_t p = 0; p < n; ++p)
    if (before[p] > 0 && av_[p] == 0) block(EventKind::Exit, "exit", static_cast<int>(p), chart_.places[p].exit ? &*chart_.places[p].exit : nullptr, f);
  for (std::size_t p = 0; p < n; ++p)
    if (before[p] == 0 && av_[p] > 0) {
      timers_[p] = 0;
      block(EventKind::Entry, "entry", static_cast<int>(p), chart_.places[p].entry ? &*chart_.places[p].entry : nullptr, f);
    }
  // The observation hooks: places that lost, then gained activation; transitions whose inputs
  // are all active now but were not all active at the start of the tick.
  if (f.log) {
    for (std::size_t p = 0; p < n; ++p)
      if (before[p] > 0 && av_[p] == 0) f.log->add(EventKind::Lost, 1, "lost " + chart_.places[p].name);
    for (std::size_t p = 0; p < n; ++p)
      if (before[p] == 0 && av_[p] > 0) f.log->add(EventKind::Gained, 1, "gained " + chart_.places[p].name);
    for (const model::Transition &tr : chart_.transitions) {
      if (tr.inputs.empty()) continue;
      bool was = true, is = true;
      for (int p : tr.inputs) {
        was = was && before[static_cast<std::size_t>(p)] > 0;
        is = is && av_[static_cast<std::size_t>(p)] > 0;
      }
      if (!was && is) f.log->add(EventKind::Enabled, 1, "enabled " + tr.name);
    }
  }
  // 4. Actions of the active places, in declaration order.
  for (std::size_t p = 0; p < n; ++p)
    if (av_[p] > 0 && !chart_.places[p].action.empty())
      block(EventKind::Action, "action", static_cast<int>(p), &chart_.places[p].action, f);
}

void Engine::run_fsm(Frame &f) {
  // §7: in a terminal state nothing happens.
  if (status_ != 0) return;
  const std::size_t cur = static_cast<std::size_t>(state_);
  if (timers_[cur] < kTimerMax) ++timers_[cur];
  const int from = state_;
  // The first transition leaving the current state whose precondition holds fires (one a tick).
  for (std::size_t t = 0; t < chart_.transitions.size(); ++t) {
    const model::Transition &tr = chart_.transitions[t];
    if (tr.inputs.empty() || tr.outputs.empty() || tr.inputs[0] != from) continue;
    if (!condition(static_cast<int>(t), f)) continue;
    state_ = tr.outputs[0];
    model::Terminal terminal = chart_.places[static_cast<std::size_t>(state_)].terminal;
    if (terminal != model::Terminal::None) status_ = terminal == model::Terminal::Success ? 1 : -1;
    if (f.log) f.log->add(EventKind::Fire, 1, fmt::format("fire {}: {}", tr.name, label(tr)));
    break;
  }
  const std::size_t now = static_cast<std::size_t>(state_);
  if (state_ != from) {
    const model::Place &old = chart_.places[static_cast<std::size_t>(from)], &neu = chart_.places[now];
    block(EventKind::Exit, "exit", from, old.exit ? &*old.exit : nullptr, f);
    timers_[now] = 0;
    block(EventKind::Entry, "entry", state_, neu.entry ? &*neu.entry : nullptr, f);
    if (f.log) {
      f.log->add(EventKind::Lost, 1, "lost " + old.name);
      f.log->add(EventKind::Gained, 1, "gained " + neu.name);
      for (const model::Transition &tr : chart_.transitions)
        if (!tr.inputs.empty() && tr.inputs[0] == state_) f.log->add(EventKind::Enabled, 1, "enabled " + tr.name);
    }
    if (options_.check_post && neu.terminal != model::Terminal::None && neu.post) {
      const std::size_t mark = f.log ? f.log->size() : 0;
      f.depth = 2;
      bool holds = convert(evaluate(*neu.post, f), model::Type::Bool, neu.post->range).b;
      f.depth = 1;
      if (f.log) f.log->insert(mark, EventKind::Post, 1, fmt::format("post {} = {}", neu.name, holds ? "true" : "false"));
    }
  }
  const model::Place &p = chart_.places[now];
  if (!p.action.empty()) block(EventKind::Action, "action", state_, &p.action, f);
}

void Engine::end_of_tick(Frame &f) {
  if (!f.log) return;
  std::string av = "av";
  for (std::size_t p = 0; p < chart_.places.size(); ++p) av += fmt::format(" {}", activation(static_cast<int>(p)));
  f.log->add(EventKind::Av, 1, std::move(av));
  if (is_fsm()) {
    const char *status = status_ == 0 ? "running" : status_ > 0 ? "succeeded" : "failed";
    f.log->add(EventKind::State, 1,
               fmt::format("state {} {}", chart_.places.at(static_cast<std::size_t>(state_)).name, status));
  }
}

} // namespace gfec::interp
