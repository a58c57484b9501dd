#include "machine.h"

#include <fmt/format.h>

#include <limits>
#include <map>

namespace gfec::interp {

using model::PlaceId;
using model::TransitionId;

namespace {
constexpr std::uint32_t kTimerMax = std::numeric_limits<std::uint32_t>::max();
}  // namespace

Machine::Machine(const model::Model &model, model::ChartId chart, MachineOptions options)
    : Machine(model, chart, options, "", 1) {}

Machine::Machine(const model::Model &model, model::ChartId chart, MachineOptions options, std::string path, int depth)
    : model_(model), chart_(model.charts.at(chart)), options_(options), path_(std::move(path)),
      prefix_(path_.empty() ? "" : path_ + "."), depth_(depth) {
  // The validator rejects charts that run themselves, so this recursion ends.
  for (const model::Place &place : chart_.places)
    instances_.push_back(
        place.runs ? std::unique_ptr<Machine>(new Machine(model, place.runs, options, prefix_ + place.name, depth + 1))
                   : nullptr);
  init();
}

const Machine *Machine::instance(PlaceId place) const {
  if (!chart_.places.contains(place)) return nullptr;
  return instances_[place].get();
}

bool Machine::active(const std::vector<PlaceId> &path) const {
  const Machine *e = this;
  for (std::size_t k = 0; k < path.size(); ++k) {
    if (!e || e->activation(path[k]) == 0) return false;
    if (k + 1 < path.size()) e = e->instance(path[k]);
  }
  return !path.empty();
}

bool Machine::outcome(PlaceId place, int status) const {
  const Machine *sub = instance(place);
  return activation(place) > 0 && sub && sub->is_fsm() && sub->status() == status;
}

Frame Machine::frame(Environment *env, EventLog *log, std::uint64_t tick) {
  Frame f{model_, chart_, vars_, timers_, env, log, tick, depth_ + 1};
  f.engine = this;
  f.agent = agent_;
  f.reports = chart_.team > 0 ? &reports_ : nullptr;
  return f;
}

void Machine::init() {
  // Every instance is reset too: an initial place's instance is started by _init (§9); the
  // others are reset again when their place becomes active.
  for (auto &sub : instances_)
    if (sub) sub->init();
  const std::size_t n = chart_.places.size();
  av_.assign(n, 0);
  timers_.assign(n, 0);
  acted_active_.assign(n, false);
  acted_ = false;
  stored_.assign(chart_.actions.size(), StoredFlags{});
  was_q_.assign(chart_.actions.size(), false);
  runs_.assign(chart_.actions.size(), false);
  state_ = PlaceId::none();
  status_ = 0;
  for (PlaceId p : chart_.places.ids()) {
    if (!chart_.places[p].initial) continue;
    av_[p] = 1;
    if (!state_) state_ = p;
  }
  started_ = false;
  tick_ = 0;
  agent_ = 0;
  reports_.assign(static_cast<std::size_t>(chart_.team), PlaceId::none());
  vars_.clear();
  for (const model::Var &v : chart_.vars) vars_.push_back(Value::zero(v.type));
  // Initialisers are constant: no calls, no vars, no timers (the validator sees to it).
  Frame f = frame(nullptr, nullptr, 0);
  for (model::VarId i : chart_.vars.ids())
    if (chart_.vars[i].init)
      vars_[i] = convert(evaluate(*chart_.vars[i].init, f), chart_.vars[i].type, chart_.vars[i].range);
}

void Machine::set_agent(int agent) {
  if (agent >= 0 && agent < chart_.team) agent_ = agent;  // agent() stays within 0 ... N-1
}

void Machine::report(int agent, PlaceId state) {
  if (agent < 0 || agent >= chart_.team || agent == agent_) return;
  if (!chart_.places.contains(state)) return;
  reports_[static_cast<std::size_t>(agent)] = state;
}

unsigned Machine::activation(PlaceId place) const {
  if (!chart_.places.contains(place)) return 0;
  if (is_fsm()) return place == state_ ? 1u : 0u;
  return av_[place];
}

void Machine::run(Environment &env, EventLog *log) {
  ++tick_;
  if (log) log->add(EventKind::Tick, 0, fmt::format("tick {}", tick_));
  // docs/iec.md "The scan": the caller sets the inputs before the tick.
  for (model::VarId v : chart_.vars.ids())
    if (model::set_by_caller(chart_.vars[v].role))
      if (std::optional<Value> value = env.input(chart_.vars[v], tick_)) vars_[v] = *value;
  Frame f = frame(&env, log, tick_);
  step(f);
  end_of_tick(f);
  if (log) log_instances(*log);
}

void Machine::step(Frame &f) {
  if (!started_) {
    // §5.1: the first tick begins with the entry blocks of the initial places.
    started_ = true;
    for (PlaceId p : chart_.places.ids())
      if (chart_.places[p].initial)
        block(EventKind::Entry, "entry", p, chart_.places[p].entry ? &*chart_.places[p].entry : nullptr, f);
  }
  if (is_fsm()) run_fsm(f);
  else run_sfc(f);
}

void Machine::start(PlaceId place, Frame &f) {
  Machine *sub = instances_[place].get();
  if (!sub) return;
  if (f.log) f.log->add(EventKind::Start, depth_, fmt::format("start {}: {}", sub->path_, sub->chart_.name));
  sub->init();
}

void Machine::stop(PlaceId place, Frame &f) {
  Machine *sub = instances_[place].get();
  if (!sub) return;
  if (f.log) f.log->add(EventKind::Stop, depth_, fmt::format("stop {}: {}", sub->path_, sub->chart_.name));
  sub->stop_all(f.env, f.log, f.tick);
}

void Machine::stop_all(Environment *env, EventLog *log, std::uint64_t tick) {
  Frame f = frame(env, log, tick);
  auto leave = [&](PlaceId p) {
    const model::Place &place = chart_.places[p];
    stop(p, f);
    block(EventKind::Exit, "exit", p, place.exit ? &*place.exit : nullptr, f);
  };
  if (is_fsm()) {
    if (status_ == 0) leave(state_);  // a terminal state runs nothing and has no exit
    return;
  }
  for (PlaceId p : chart_.places.ids())
    if (av_[p] > 0) leave(p);
}

void Machine::tick_instance(PlaceId place, Frame &f) {
  Machine *sub = instances_[place].get();
  if (!sub) return;
  if (f.log) f.log->add(EventKind::RunInstance, depth_, fmt::format("run {}: {}", sub->path_, sub->chart_.name));
  Frame own = sub->frame(f.env, f.log, f.tick);
  sub->step(own);
}

void Machine::log_instances(EventLog &log) const {
  for (PlaceId p : instances_.ids()) {
    const Machine *sub = instances_[p].get();
    if (!sub || activation(p) == 0) continue;
    std::string av = "av " + sub->path_ + ":";
    for (PlaceId q : sub->chart_.places.ids()) av += fmt::format(" {}", sub->activation(q));
    log.add(EventKind::InstanceAv, 1, std::move(av));
    if (sub->is_fsm()) {
      const char *status = sub->status_ == 0 ? "running" : sub->status_ > 0 ? "succeeded" : "failed";
      log.add(EventKind::InstanceState, 1,
              fmt::format("state {}: {} {}", sub->path_, sub->chart_.places.at(sub->state_).name, status));
    }
    sub->log_instances(log);
  }
}

std::string Machine::label(const model::Transition &t) const {
  auto side = [&](const model::PlaceList &places) {
    std::string s;
    for (PlaceId p : places) s += (s.empty() ? "" : ", ") + chart_.places.at(p).name;
    return places.size() == 1 ? s : "(" + s + ")";
  };
  return side(t.inputs) + " -> " + side(t.outputs);
}

bool Machine::condition(TransitionId t, Frame &f) {
  const model::Transition &tr = chart_.transitions[t];
  if (!tr.condition) return true;
  const std::size_t mark = f.log ? f.log->size() : 0;
  f.depth = depth_ + 1;
  bool holds = convert(evaluate(*tr.condition, f), model::Type::Bool, tr.condition->range).b;
  if (f.log)
    f.log->insert(mark, EventKind::Condition, depth_,
                  fmt::format("cond {}{} = {}", prefix_, tr.name, holds ? "true" : "false"));
  return holds;
}

void Machine::block(EventKind kind, const char *word, PlaceId place, const std::vector<model::Stmt> *stmts, Frame &f) {
  if (f.log) f.log->add(kind, depth_, fmt::format("{} {}{}", word, prefix_, chart_.places.at(place).name));
  if (!stmts) return;
  f.depth = depth_ + 1;
  execute(*stmts, f);
}

void Machine::run_sfc(Frame &f) {
  const std::size_t n = chart_.places.size();
  const IdMap<PlaceId, std::uint32_t> before = av_;
  // 1. Timers of the places active at the start of the tick.
  for (PlaceId p : chart_.places.ids())
    if (av_[p] > 0 && timers_[p] < kTimerMax) ++timers_[p];
  // 2. Transitions in declaration order; produced activation waits in `add`.
  IdMap<PlaceId, std::uint32_t> avail = av_, add(n, 0);
  for (TransitionId t : chart_.transitions.ids()) {
    const model::Transition &tr = chart_.transitions[t];
    // Open: every input place has activation left (a place listed twice needs two).
    std::map<PlaceId, std::uint32_t> need;
    for (PlaceId p : tr.inputs) ++need[p];
    bool open = true;
    for (auto [p, k] : need) open = open && avail[p] >= k;
    if (!open || !condition(t, f)) continue;
    for (PlaceId p : tr.inputs) --avail[p];
    for (PlaceId p : tr.outputs) ++add[p];
    if (f.log) f.log->add(EventKind::Fire, depth_, fmt::format("fire {}{}: {}", prefix_, tr.name, label(tr)));
  }
  // 3. Commit; compare the start of the tick with its end: all exits, then all entries. A
  // place's instance stops before its exit block and starts before its entry block (§9).
  for (PlaceId p : chart_.places.ids()) av_[p] = avail[p] + add[p];
  for (PlaceId p : chart_.places.ids())
    if (before[p] > 0 && av_[p] == 0) {
      stop(p, f);
      block(EventKind::Exit, "exit", p, chart_.places[p].exit ? &*chart_.places[p].exit : nullptr, f);
    }
  for (PlaceId p : chart_.places.ids())
    if (before[p] == 0 && av_[p] > 0) {
      timers_[p] = 0;
      start(p, f);
      block(EventKind::Entry, "entry", p, chart_.places[p].entry ? &*chart_.places[p].entry : nullptr, f);
    }
  // The observation hooks: places that lost, then gained activation; transitions whose inputs
  // are all active now but were not all active at the start of the tick. Only the root's: the
  // engine's hooks report the compiled chart.
  if (f.log && path_.empty()) {
    for (PlaceId p : chart_.places.ids())
      if (before[p] > 0 && av_[p] == 0) f.log->add(EventKind::Lost, 1, "lost " + chart_.places[p].name);
    for (PlaceId p : chart_.places.ids())
      if (before[p] == 0 && av_[p] > 0) f.log->add(EventKind::Gained, 1, "gained " + chart_.places[p].name);
    for (const model::Transition &tr : chart_.transitions) {
      if (tr.inputs.empty()) continue;
      bool was = true, is = true;
      for (PlaceId p : tr.inputs) {
        was = was && before[p] > 0;
        is = is && av_[p] > 0;
      }
      if (!was && is) f.log->add(EventKind::Enabled, 1, "enabled " + tr.name);
    }
  }
  // 4. Actions of the active places, in declaration order; each then ticks its instance (§9).
  for (PlaceId p : chart_.places.ids()) {
    if (av_[p] == 0) continue;
    if (!chart_.places[p].action.empty()) block(EventKind::Action, "action", p, &chart_.places[p].action, f);
    tick_instance(p, f);
  }
  // 5. Named actions under their action control (docs/language.md §14).
  if (!chart_.actions.empty()) named_actions(f);
}

void Machine::named_actions(Frame &f) {
  using model::Qualifier;
  for (model::ActionId a : chart_.actions.ids()) {
    const model::Action &action = chart_.actions[a];
    StoredFlags &flags = stored_[a];
    // The timers of SD and SL count one more tick once their flag is set (0 in the tick of the
    // set, as a place's timer is in the tick it is entered).
    for (Stored *timed : {&flags.sd, &flags.sl})
      if (timed->set && timed->ticks < kTimerMax) ++timed->ticks;
    bool q = false, edge = false, reset = false;
    bool set_s = false, set_sd = false, set_ds = false, set_sl = false;
    // One duration per action for SD and for SL (the validator sees to it): their timer's.
    unsigned long sd_ticks = 0, sl_ticks = 0;
    for (const model::Association &as : action.associations) {
      const bool x = av_[as.place] > 0, was = acted_active_[as.place];
      const std::uint32_t t = timers_[as.place];
      switch (as.qualifier) {
      case Qualifier::N: q = q || x; break;
      case Qualifier::P: q = q || (x && !was); break;
      case Qualifier::L: q = q || (x && t < as.ticks); break;
      case Qualifier::D: q = q || (x && t >= as.ticks); break;
      case Qualifier::S: set_s = set_s || x; break;
      case Qualifier::R: reset = reset || x; break;
      case Qualifier::P1: edge = edge || (x && !was); break;
      // Initialisation activated an initial place: left in tick 1, it falls in tick 1.
      case Qualifier::P0: edge = edge || (!x && (was || (!acted_ && chart_.places[as.place].initial))); break;
      case Qualifier::SD:
        set_sd = set_sd || x;
        sd_ticks = as.ticks;
        break;
      // Set only while the place is still active when its timer reaches the duration.
      case Qualifier::DS: set_ds = set_ds || (x && t >= as.ticks); break;
      case Qualifier::SL:
        set_sl = set_sl || x;
        sl_ticks = as.ticks;
        break;
      }
    }
    // A set starts the timer only when the flag rises: a place that sets it again while it is
    // set (or another place) does not restart it.
    auto raise = [](Stored &flag, bool set) {
      if (!set || flag.set) return;
      flag.set = true;
      flag.ticks = 0;
    };
    raise(flags.s, set_s);
    raise(flags.sd, set_sd);
    raise(flags.ds, set_ds);
    raise(flags.sl, set_sl);
    // Reset dominates: the sets of this tick first, then the reset of every stored form.
    if (reset) flags = StoredFlags{};
    q = q || flags.s.set || (flags.sd.set && flags.sd.ticks >= sd_ticks) || flags.ds.set ||
        (flags.sl.set && flags.sl.ticks < sl_ticks);
    // Q true, its final run as Q falls, or an edge of P1 / P0: at most one run per tick.
    runs_[a] = q || was_q_[a] || edge;
    was_q_[a] = q;
    // A body reads every action's flags of this tick, so all the controls come first then; the
    // bodies do not change what a control reads (places, timers, flags), so that order is the
    // other's otherwise.
    if (!chart_.reads_action_flags) run_action(a, f);
  }
  if (chart_.reads_action_flags)
    for (model::ActionId a : chart_.actions.ids()) run_action(a, f);
  for (PlaceId p : chart_.places.ids()) acted_active_[p] = av_[p] > 0;
  acted_ = true;
}

void Machine::run_action(model::ActionId a, Frame &f) {
  if (!runs_[a]) return;
  if (f.log) f.log->add(EventKind::Action, depth_, fmt::format("action {}{}", prefix_, chart_.actions[a].name));
  f.depth = depth_ + 1;
  execute(chart_.actions[a].body, f);
}

void Machine::run_fsm(Frame &f) {
  // §7: in a terminal state nothing happens.
  if (status_ != 0) return;
  if (timers_[state_] < kTimerMax) ++timers_[state_];
  const PlaceId from = state_;
  PlaceId to = from;
  // The first transition leaving the current state whose precondition holds fires (one a tick).
  for (TransitionId t : chart_.transitions.ids()) {
    const model::Transition &tr = chart_.transitions[t];
    if (tr.inputs.empty() || tr.outputs.empty() || tr.inputs[0] != from) continue;
    if (!condition(t, f)) continue;
    to = tr.outputs[0];
    if (f.log) f.log->add(EventKind::Fire, depth_, fmt::format("fire {}{}: {}", prefix_, tr.name, label(tr)));
    break;
  }
  if (to != from) {
    const model::Place &old = chart_.places[from], &neu = chart_.places[to];
    // The old state's instance stops, then its exit block runs while it is still current; then
    // the new state becomes current, its instance starts and its entry block runs (§9, §10).
    stop(from, f);
    block(EventKind::Exit, "exit", from, old.exit ? &*old.exit : nullptr, f);
    state_ = to;
    if (neu.terminal != model::Terminal::None) status_ = neu.terminal == model::Terminal::Success ? 1 : -1;
    timers_[to] = 0;
    start(state_, f);
    block(EventKind::Entry, "entry", state_, neu.entry ? &*neu.entry : nullptr, f);
    if (f.log && path_.empty()) {
      f.log->add(EventKind::Lost, 1, "lost " + old.name);
      f.log->add(EventKind::Gained, 1, "gained " + neu.name);
      for (const model::Transition &tr : chart_.transitions)
        if (!tr.inputs.empty() && tr.inputs[0] == state_) f.log->add(EventKind::Enabled, 1, "enabled " + tr.name);
    }
    if (options_.check_post && neu.terminal != model::Terminal::None && neu.post) {
      const std::size_t mark = f.log ? f.log->size() : 0;
      f.depth = depth_ + 1;
      bool holds = convert(evaluate(*neu.post, f), model::Type::Bool, neu.post->range).b;
      if (f.log)
        f.log->insert(mark, EventKind::Post, depth_,
                      fmt::format("post {}{} = {}", prefix_, neu.name, holds ? "true" : "false"));
    }
  }
  // The action of the (new) current state, then one tick of its instance; a terminal state has
  // neither.
  const model::Place &p = chart_.places[to];
  if (p.terminal != model::Terminal::None) return;
  if (!p.action.empty()) block(EventKind::Action, "action", state_, &p.action, f);
  tick_instance(state_, f);
}

void Machine::end_of_tick(Frame &f) {
  if (!f.log) return;
  std::string av = "av";
  for (PlaceId p : chart_.places.ids()) av += fmt::format(" {}", activation(p));
  f.log->add(EventKind::Av, 1, std::move(av));
  if (is_fsm()) {
    const char *status = status_ == 0 ? "running" : status_ > 0 ? "succeeded" : "failed";
    f.log->add(EventKind::State, 1, fmt::format("state {} {}", chart_.places.at(state_).name, status));
  }
  // docs/iec.md "`gfec run` on a program": what the caller reads after the tick.
  for (model::VarId v : chart_.vars.ids())
    if (model::read_by_caller(chart_.vars[v].role))
      f.log->add(EventKind::Output, 1, fmt::format("out {} = {}", chart_.vars[v].name, format_value(vars_[v])));
}

}  // namespace gfec::interp
