// Plans as charts: a plan with one entry point becomes an fsm, a plan with several an sfc whose
// initial places run one fsm per entry point; a plan type runs its first activated plan. Each plan
// is converted once, whichever states run it, and the states it holds are states.cc's.
#include "alica/reader_context.h"

#include <fmt/format.h>

#include <numeric>

namespace gfec::alica {

/// The chart a plan becomes (its fsm, or its sfc with several entry points); converted once.
/// `at` is the reference that runs it: a plan nested too deep is an error there, and "".
std::string Reader::plan_chart(Doc &doc, const JsonValue &plan, const SourceRange &at) {
  std::string id = id_of(plan.find("id")).value_or("");
  std::string key = doc.path + "#" + id;
  auto it = plan_charts_.find(key);
  if (it != plan_charts_.end()) return it->second;
  if (plan_depth_ > kMaxPlanDepth) {
    diag_.error(at, ErrorKind::AlicaReference,
                fmt::format("plans nested more than {} deep: plan '{}' (id {}) would run {} levels below the "
                            "compiled plan",
                            kMaxPlanDepth, label_of(plan), id, plan_depth_));
    plan_charts_[key] = "";  // reported once, however many states run it
    return "";
  }
  std::string name = global_name(label_of(plan), id, "Plan");
  plan_charts_[key] = name;  // before the states: a plan that runs itself stops here
  const JsonValue *entries = plan.find("entryPoints");
  fsm_charts_[name] = !entries || !entries->is_array() || entries->items.size() <= 1;
  ++plan_depth_;
  convert_plan(doc, plan, name);
  --plan_depth_;
  return name;
}

/// The chart a plan type runs: its first activated plan.
std::string Reader::plan_type_chart(const Resolved &t, const SourceRange &at) {
  std::string label = label_of(*t.object);
  std::string id = id_of(t.object->find("id")).value_or("");
  const JsonValue *list = t.object->find("annotatedPlans");
  if (!list) list = t.object->find("plans");
  std::vector<std::pair<std::string, const JsonValue *>> activated;
  if (list && list->is_array())
    for (const auto &item : list->items) {
      if (!item.is_object()) continue;
      const JsonValue *on = item.find("activated");
      if (on && on->kind == JsonValue::Kind::Bool && !on->boolean) continue;
      const JsonValue *plan = item.find("plan");
      if (plan && plan->is_string()) activated.emplace_back(plan->text, plan);
    }
  bool first_use = plan_type_warned_.insert(t.object).second;
  for (const char *key : {"variables", "variableBindings"})
    if (const JsonValue *v = t.object->find(key); non_empty(v) && first_use)
      ignored(*t.doc, *v,
              fmt::format("the {} of plan type '{}' (id {}) are ignored: gfec sub-charts share no "
                          "variables",
                          key, label, id));
  if (activated.empty()) {
    diag_
        .error(at, ErrorKind::AlicaReference,
               fmt::format("plan type '{}' (id {}) has no activated plan to run", label, id))
        .note(range(*t.doc, *t.object), "the plan type is here");
    return "";
  }
  Resolved first = files_.resolve(activated.front().first, *t.doc, range(*t.doc, *activated.front().second));
  if (!first.object) return "";
  std::string chart = plan_chart(*first.doc, *first.object, at);
  if (activated.size() > 1 && first_use) {
    std::string others;
    for (std::size_t i = 1; i < activated.size(); ++i)
      others += fmt::format("{}'{}'", i > 1 ? ", " : "", activated[i].first);
    ignored(*t.doc, *t.object,
            fmt::format("plan type '{}' (id {}) runs its first activated plan, '{}'; ignored: {} "
                        "(ALICA chooses by utility at run time)",
                        label, id, chart, others));
  }
  return chart;
}

void Reader::plan_warnings(Doc &doc, const JsonValue &plan, const std::string &what) {
  for (const char *c : {"preCondition", "runtimeCondition"})
    if (const JsonValue *v = plan.find(c); non_empty(v))
      ignored(doc, *v,
              fmt::format("the {} of {} is ignored: gfec starts a sub-chart whenever its state is "
                          "entered and never aborts it",
                          c, what));
  if (const JsonValue *v = plan.find("variables"); non_empty(v))
    ignored(doc, *v, fmt::format("the variables of {} are ignored: gfec has no plan variables", what));
  if (const JsonValue *v = plan.find("blackboard"); non_empty(v))
    ignored(doc, *v, fmt::format("the blackboard of {} is ignored: gfec has no blackboard", what));
  if (const JsonValue *syncs = plan.find("synchronisations"); syncs && syncs->is_array())
    for (const auto &s : syncs->items)
      if (s.is_object())
        ignored(doc, s,
                fmt::format("synchronisation '{}' (id {}) of {} is ignored: gfec fires each transition "
                            "on its own condition",
                            label_of(s), id_of(s.find("id")).value_or("?"), what));
}

/// The entry point's label: its name, else its task's name, else "EntryPoint<id>".
std::string Reader::entry_label(Doc &doc, const JsonValue &ep) {
  std::string name = label_of(ep);
  const JsonValue *task = ep.find("task");
  if (task && task->is_string() && !task->text.empty()) {
    Resolved t = files_.resolve(task->text, doc, range(doc, *task), Need::LabelOnly);
    if (t.object && !meaningful(name)) name = label_of(*t.object);
  }
  return name;
}

void Reader::convert_plan(Doc &doc, const JsonValue &plan, const std::string &name) {
  std::string plan_id = id_of(plan.find("id")).value_or("");
  std::string what = fmt::format("plan '{}' (id {})", label_of(plan), plan_id);
  element(doc, plan, "ALICA " + what);
  plan_warnings(doc, plan, what);

  // The plan's states and transitions, by id.
  std::vector<const JsonValue *> states, transitions, entries;
  auto objects = [](const JsonValue *list, std::vector<const JsonValue *> &out) {
    if (list && list->is_array())
      for (const auto &i : list->items)
        if (i.is_object()) out.push_back(&i);
  };
  objects(plan.find("states"), states);
  objects(plan.find("transitions"), transitions);
  objects(plan.find("entryPoints"), entries);
  // Ids only messages quote: one that is no id is still reported where it is written.
  not_an_id(doc, plan.find("id"), fmt::format("the id of plan '{}'", label_of(plan)));
  for (const JsonValue *e : entries)
    not_an_id(doc, e->find("id"), fmt::format("the id of entry point '{}' of {}", label_of(*e), what));
  for (const JsonValue *t : transitions)
    not_an_id(doc, t->find("id"), fmt::format("the id of transition '{}' of {}", label_of(*t), what));
  StateIndex state_index;
  for (std::size_t i = 0; i < states.size(); ++i) {
    auto id = id_of(states[i]->find("id"));
    if (!id) {
      if (!not_an_id(doc, states[i]->find("id"), fmt::format("the id of state '{}' of {}", label_of(*states[i]), what)))
        diag_.error(range(doc, *states[i]), ErrorKind::AlicaFormat, fmt::format("a state of {} has no id", what));
      continue;
    }
    if (!state_index.emplace(*id, i).second)
      diag_
          .error(range(doc, *states[i]), ErrorKind::AlicaFormat,
                 fmt::format("second state with id {} in {}", *id, what))
          .note(range(doc, *states[state_index[*id]]), "the first one is here");
  }
  if (entries.empty()) {
    diag_.error(range(doc, plan), ErrorKind::AlicaFormat,
                fmt::format("{} has no entry point: gfec needs one to know where its machine starts", what));
    return;
  }

  // States weakly connected by transitions belong to the same entry point's machine.
  std::vector<std::size_t> parent(states.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  auto state_of = [&](const JsonValue *v) { return state_named(state_index, v); };
  for (const JsonValue *t : transitions) {
    auto a = state_of(t->find("inState")), b = state_of(t->find("outState"));
    if (a && b) parent[root(*a)] = root(*b);
  }

  std::vector<Machine> machines(entries.size());
  std::vector<int> owner(states.size(), -1);
  std::vector<std::string> entry_names(entries.size());  ///< "'label' (id N)", for messages
  bool several = entries.size() > 1;
  for (std::size_t e = 0; e < entries.size(); ++e) {
    const JsonValue &ep = *entries[e];
    std::string ep_id = id_of(ep.find("id")).value_or("");
    std::string label = entry_label(doc, ep);
    entry_names[e] = fmt::format("'{}' (id {})", label, ep_id);
    element(doc, ep, fmt::format("ALICA entry point '{}' (id {}) of {}", label, ep_id, what));
    entry_warnings(doc, ep, label, ep_id, several);
    Machine &m = machines[e];
    m.chart.kind = ast::Chart::Kind::Fsm;
    m.chart.range = several ? range(doc, ep) : range(doc, plan);
    std::string chart_name = several ? global_name(name + identifier(label, "EntryPoint" + ep_id), ep_id, "") : name;
    m.chart.name = {keep(chart_name), m.chart.range};
    auto start = state_of(ep.find("state"));
    if (!start) {
      if (not_an_id(doc, ep.find("state"),
                    fmt::format("the state of entry point '{}' (id {}) of {}", label, ep_id, what)))
        continue;
      diag_.error(range(doc, ep), ErrorKind::AlicaReference,
                  fmt::format("entry point '{}' (id {}) starts in state {}, which {} does not have", label, ep_id,
                              id_of(ep.find("state")).value_or("(none)"), what));
      continue;
    }
    if (owner[*start] >= 0) {
      diag_
          .error(range(doc, ep), ErrorKind::AlicaFormat,
                 fmt::format("entry point {} starts in state '{}', which entry point {} already reaches: gfec "
                             "gives each entry point a machine of its own states",
                             entry_names[e], label_of(*states[*start]), entry_names[owner[*start]]))
          .note(range(doc, *states[*start]), "the state is here");
      continue;
    }
    m.entry_state = *id_of(ep.find("state"));
    for (std::size_t s = 0; s < states.size(); ++s)
      if (owner[s] < 0 && root(s) == root(*start)) owner[s] = static_cast<int>(e);
  }
  // States no entry point reaches go to the first machine, whose checks call them disconnected.
  int first = -1;
  for (std::size_t e = 0; e < machines.size() && first < 0; ++e)
    if (!machines[e].entry_state.empty()) first = static_cast<int>(e);
  if (first < 0) return;  // reported above
  for (auto &o : owner)
    if (o < 0) o = first;

  std::vector<std::string> state_names(states.size());
  for (std::size_t s = 0; s < states.size(); ++s) {
    Machine &m = machines[owner[s]];
    m.chart.places.push_back(convert_state(doc, *states[s], m, what, state_names[s]));
  }
  for (const JsonValue *t : transitions) convert_transition(doc, *t, machines, owner, state_names, state_index, what);

  ast::File &file = *result_.program.files[file_index(doc)];
  if (several) {
    ast::Chart sfc;
    sfc.kind = ast::Chart::Kind::Sfc;
    sfc.range = range(doc, plan);
    sfc.name = {keep(name), sfc.range};
    NameScope places;
    for (std::size_t e = 0; e < entries.size(); ++e) {
      if (machines[e].entry_state.empty()) continue;
      ast::Place p;
      p.initial = true;
      p.range = range(doc, *entries[e]);
      std::string label = entry_label(doc, *entries[e]);
      p.name = {keep(places.take(identifier(label, "EntryPoint" + id_of(entries[e]->find("id")).value_or("")),
                                 id_of(entries[e]->find("id")).value_or(""))),
                p.range};
      p.extra().runs = ast::Name{machines[e].chart.name.text, p.range};
      sfc.places.push_back(std::move(p));
    }
    file.charts.push_back(std::move(sfc));
  }
  for (auto &m : machines)
    if (!m.entry_state.empty()) file.charts.push_back(std::move(m.chart));
}

void Reader::entry_warnings(Doc &doc, const JsonValue &ep, const std::string &label, const std::string &id,
                            bool several) {
  const JsonValue *min = ep.find("minCardinality"), *max = ep.find("maxCardinality");
  bool free = (!min || min->text == "0") && (!max || max->text == "2147483647");
  if (!free)
    ignored(doc, ep,
            fmt::format("the cardinalities [{}..{}] of entry point '{}' (id {}) are ignored: one agent "
                        "runs a gfec engine",
                        min ? min->text : "0", max ? max->text : "*", label, id));
  const JsonValue *required = ep.find("successRequired");
  if (several && required && required->kind == JsonValue::Kind::Bool && required->boolean)
    ignored(doc, ep,
            fmt::format("'successRequired' of entry point '{}' (id {}) is ignored: the sfc of a plan with "
                        "several entry points never ends by itself",
                        label, id));
}

std::size_t Reader::file_index(const Doc &doc) const {
  for (std::size_t i = 0; i < result_.program.files.size(); ++i)
    if (result_.program.files[i]->id == doc.file) return i;
  return 0;
}

}  // namespace gfec::alica
