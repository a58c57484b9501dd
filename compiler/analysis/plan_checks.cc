// Plans: config entries that may be read before anything writes them, and supervisors that can
// interrupt the same actor in the same step (the runtime then picks one by a fixed order).
#include "analysis/passes.h"

#include <fmt/format.h>

#include <deque>

namespace gfec::analysis {

namespace {

using model::ActorId;
using model::ConfigId;
using Written = IdMap<ConfigId, bool>;  ///< by config entry: certainly written by now

void config_reads(const model::Expr &e, std::vector<const model::Expr *> &out) {
  if (e.kind == model::Expr::Kind::Config) out.push_back(&e);
  for (const auto &a : e.args) config_reads(a, out);
}

std::vector<const model::Expr *> reads(const std::vector<model::Arg> &args) {
  std::vector<const model::Expr *> out;
  for (const auto &a : args)
    if (a.dir == model::ParamDir::In) config_reads(a.formula, out);
  return out;
}

/// An actor's or supervisor's out arguments, written when it ends (or interrupts).
void add_writes(const std::vector<model::Arg> &args, Written &w) {
  for (const auto &a : args)
    if (a.dir == model::ParamDir::Out && a.formula.kind == model::Expr::Kind::Config && a.formula.config())
      w.at(a.formula.config()) = true;
}

/// A rule whose outcome does interrupt (an `ignore` never does).
bool interrupts(const model::SupervisorUse &s) {
  for (const auto &r : s.rules)
    if (r.target.kind != model::RuleTarget::Kind::Ignore) return true;
  return false;
}

class ConfigFlow {
public:
  ConfigFlow(const model::Plan &p) : p_(p), in_(p.actors.size()), reached_(p.actors.size(), false) {}

  /// What is certainly written when each actor starts (intersection over the ways in).
  void run() {
    Written initial(p_.config.size());
    for (ConfigId e : p_.config.ids()) initial[e] = p_.config[e].init.has_value();
    initial_ = initial;
    if (!p_.actors.contains(p_.start)) return;
    std::deque<ActorId> todo;
    arrive(p_.start, initial, todo);
    while (!todo.empty()) {
      ActorId a = todo.front();
      todo.pop_front();
      const model::ActorUse &actor = p_.actors[a];
      Written done = in_[a];
      add_writes(actor.args, done);
      follow(actor.rules, done, todo);
      for (const auto &s : actor.supervisors) follow(s.rules, with(in_[a], s.args), todo);
      for (const auto &s : p_.globals) follow(s.rules, with(in_[a], s.args), todo);
    }
  }

  bool reached(ActorId a) const { return reached_[a]; }
  const Written &at(ActorId a) const { return in_[a]; }
  const Written &initial() const { return initial_; }

private:
  static Written with(Written w, const std::vector<model::Arg> &args) {
    add_writes(args, w);
    return w;
  }

  void follow(const std::vector<model::Rule> &rules, const Written &w, std::deque<ActorId> &todo) {
    for (const auto &r : rules)
      if (r.target.kind == model::RuleTarget::Kind::Actor) arrive(r.target.actor, w, todo);
  }

  void arrive(ActorId a, const Written &w, std::deque<ActorId> &todo) {
    if (!p_.actors.contains(a)) return;
    Written &in = in_[a];
    bool changed = false;
    if (!reached_[a]) {
      reached_[a] = true;
      in = w;
      changed = true;
    } else {
      for (ConfigId e : in.ids())
        if (in[e] && !w[e]) in[e] = false, changed = true;
    }
    if (changed) todo.push_back(a);
  }

  const model::Plan &p_;
  IdMap<ActorId, Written> in_;
  IdMap<ActorId, bool> reached_;
  Written initial_;
};

}  // namespace

void check_plan(const model::Model & /*m*/, const model::Plan &p, Diagnostics &diag, std::string &summary) {
  ConfigFlow flow(p);
  flow.run();
  std::size_t unwritten = 0, races = 0;
  auto check_reads = [&](const std::vector<const model::Expr *> &list, const Written &w, const std::string &who) {
    for (const model::Expr *e : list) {
      if (!e->config() || w.at(e->config())) continue;
      ++unwritten;
      const model::ConfigEntry &entry = p.config[e->config()];
      diag.warning(Warning::UninitializedConfig, e->range,
                   fmt::format("{} may read config entry '{}' before anything has written it", who, entry.name))
          .note(name_at(entry),
                fmt::format("'{}' has no initial value, and not every way to {} passes an actor or supervisor that "
                            "writes it; give it a value here, or set it from the application before the plan starts",
                            entry.name, who));
    }
  };
  // Global supervisors start with the plan: they read what is there at the start.
  for (const auto &s : p.globals) check_reads(reads(s.args), flow.initial(), fmt::format("supervisor '{}'", s.name));
  for (ActorId a : p.actors.ids()) {
    if (!flow.reached(a)) continue;
    const model::ActorUse &actor = p.actors[a];
    check_reads(reads(actor.args), flow.at(a), fmt::format("actor '{}'", actor.name));
    for (const auto &s : actor.supervisors)
      check_reads(reads(s.args), flow.at(a), fmt::format("supervisor '{}' of actor '{}'", s.name, actor.name));

    // Races: globals first, then the actor's own, each in declaration order (docs/runtime.md).
    std::vector<std::string> order;
    for (const auto &s : p.globals)
      if (interrupts(s)) order.push_back(fmt::format("'{}' (global)", s.name));
    for (const auto &s : actor.supervisors)
      if (interrupts(s)) order.push_back(fmt::format("'{}'", s.name));
    if (order.size() < 2) continue;
    ++races;
    std::string list;
    for (std::size_t i = 0; i < order.size(); ++i) list += (i ? ", then " : "") + order[i];
    diag.warning(Warning::SupervisorRace, name_at(actor),
                 fmt::format("{} supervisors watch actor '{}' and can raise events in the same step; {} wins",
                             order.size(), actor.name, order.front()))
        .note(fmt::format("they are checked in this order, and the first to raise an event interrupts: {}", list));
  }
  std::size_t reachable = 0;
  for (ActorId a : p.actors.ids()) reachable += flow.reached(a);
  summary += fmt::format("plan {}: {}, {}, {}\n", p.name, counted(p.actors.size(), "actor", "actors"),
                         counted(p.config.size(), "config entry", "config entries"),
                         counted(p.globals.size(), "global supervisor", "global supervisors"));
  summary += fmt::format("  reachable actors: {} of {}\n", reachable, p.actors.size());
  summary += fmt::format("  config reads before any write: {}\n", unwritten);
  summary += fmt::format("  actors that several supervisors can interrupt at once: {}\n", races);
}

}  // namespace gfec::analysis
