// States and transitions as the places and transitions of an fsm: a state's behaviours become
// calls of action functions, the plans it runs its sub-chart (plans.cc converts them), a
// terminal state's postcondition its `post`; a transition's condition or precondition becomes
// its `when`, ALICA's standard conditions the built-ins they mean. Behaviours and conditions
// become the functions of the robot library, one function each however often they are named.
#include "alica/reader_context.h"

#include <fmt/format.h>

namespace gfec::alica {

/// The references a state holds, in every spelling ALICA's designers have used.
std::vector<std::pair<std::string, SourceRange>> Reader::references(const Doc &doc, const JsonValue &state,
                                                                    const std::string &what) {
  std::vector<std::pair<std::string, SourceRange>> refs;
  auto add_string = [&](const JsonValue &v) {
    // Old files join several references with commas in one string.
    std::string text = v.text;
    std::size_t start = 0;
    while (start < text.size()) {
      std::size_t comma = text.find(',', start);
      std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      if (part.find_first_not_of(' ') != std::string::npos) refs.emplace_back(part, range(doc, v));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  };
  if (const JsonValue *wrappers = state.find("confAbstractPlanWrappers"); wrappers && wrappers->is_array())
    for (const auto &w : wrappers->items) {
      if (!w.is_object()) continue;
      if (const JsonValue *ap = w.find("abstractPlan"); ap && ap->is_string()) {
        // A wrapper exists to run one plan or behaviour: empty, it names nothing ALICA could load.
        if (ap->text.find_first_not_of(' ') == std::string::npos)
          diag_.error(range(doc, *ap), ErrorKind::AlicaReference,
                      fmt::format("{} wraps an empty \"abstractPlan\": ALICA writes a reference as "
                                  "\"File.ext#id\"",
                                  what));
        add_string(*ap);
      }
      if (const JsonValue *km = w.find("keyMapping");
          km && km->is_object() && (non_empty(km->find("input")) || non_empty(km->find("output"))))
        ignored(doc, *km,
                fmt::format("the blackboard key mapping of '{}' in {} is ignored: gfec has no blackboard",
                            w.string_of("abstractPlan"), what));
      if (const JsonValue *c = w.find("configuration"); non_empty(c))
        ignored(doc, *c,
                fmt::format("the configuration {}of '{}' in {} is ignored: gfec sub-charts and action "
                            "functions take no parameters",
                            c->is_string() ? "'" + c->text + "' " : "", w.string_of("abstractPlan"), what));
    }
  for (const char *key : {"abstractPlans", "plans"}) {
    const JsonValue *list = state.find(key);
    if (!list) continue;
    if (list->is_string()) add_string(*list);
    if (list->is_array())
      for (const auto &i : list->items)
        if (i.is_string()) add_string(i);
  }
  return refs;
}

ast::Place Reader::convert_state(Doc &doc, const JsonValue &state, Machine &m, const std::string &plan_what,
                                 std::string &gfec_name) {
  ast::Place p;
  p.is_state = true;
  p.range = range(doc, state);
  std::string id = id_of(state.find("id")).value_or("");
  std::string label = label_of(state);
  gfec_name = m.states.take(identifier(label, "State" + id), id);
  p.name = {keep(gfec_name), p.range};
  p.initial = id == m.entry_state;
  std::string what = fmt::format("state '{}' (id {}) of {}", label, id, plan_what);
  element(doc, state, "ALICA " + what);
  std::string type = state.string_of("type");
  const JsonValue *success = state.find("success");
  if (type == "SuccessState" || (type == "TerminalState" && success && success->boolean))
    p.terminal = ast::StateKind::Success;
  else if (type == "FailureState" || type == "TerminalState") p.terminal = ast::StateKind::Failure;
  else if (!type.empty() && type != "State")
    diag_.error(range(doc, *state.find("type")), ErrorKind::AlicaFormat,
                fmt::format("unknown state type '{}' of {}: ALICA writes \"State\" or \"TerminalState\"", type, what));

  for (const char *key : {"variableBindings", "parametrisations"})
    if (const JsonValue *v = state.find(key); non_empty(v))
      ignored(doc, *v, fmt::format("the {} of {} are ignored: gfec sub-charts share no variables", key, what));

  std::vector<std::string> extra_plans;
  for (const auto &[text, at] : references(doc, state, what)) {
    auto ref = split_ref(text);
    if (!ref) {
      diag_.error(
          at, ErrorKind::AlicaReference,
          fmt::format("{} holds '{}', which is no reference: ALICA writes them as \"File.ext#id\"", what, text));
      continue;
    }
    std::string ext = extension_of(ref->file.empty() ? doc.path : ref->file);
    if (ext == ".plc") {
      ignored(at, fmt::format("{} holds the placeholder '{}', which is ignored: ALICA picks the "
                              "plan or behaviour behind a placeholder at run time, gfec has nothing to run "
                              "for it",
                              what, text));
      continue;
    }
    if (ext != ".beh" && ext != ".pml" && ext != ".pty") {
      diag_.error(
          at, ErrorKind::AlicaReference,
          fmt::format("{} holds '{}': gfec knows behaviours (.beh), plans (.pml) and plan types (.pty)", what, text));
      continue;
    }
    Resolved t = files_.resolve(text, doc, at);
    if (!t.object) continue;
    p.has_body = true;
    if (ext == ".beh") {
      ast::Stmt s;
      s.kind = ast::Stmt::Kind::Call;
      s.range = at;
      s.call = call(behaviour(t), at);
      p.action.push_back(std::move(s));
      continue;
    }
    std::string chart = ext == ".pml" ? plan_chart(*t.doc, *t.object, at) : plan_type_chart(t, at);
    if (chart.empty()) continue;
    if (!p.runs()) p.extra().runs = ast::Name{keep(chart), at};
    else extra_plans.push_back(chart);
  }
  if (!extra_plans.empty()) {
    std::string others;
    for (const auto &c : extra_plans) others += (others.empty() ? "'" : ", '") + c + "'";
    ignored(doc, state,
            fmt::format("{} holds several plans; gfec runs only the first, '{}'; ignored: {}", what, p.runs()->text,
                        others));
  }
  if (const JsonValue *post = state.find("postCondition");
      post && post->is_object() && p.terminal != ast::StateKind::Normal)
    p.extra().post = call(condition(doc, *post, label + "_post"), range(doc, *post));
  return p;
}

/// ALICA's standard conditions: `true` / `false` for AlwaysTrueCondition / AlwaysFalseCondition;
/// on the plan a state runs, `succeeded(S)` / `failed(S)` when state S runs an fsm (a state runs
/// one plan in gfec, so "any" and "all" children agree).
ast::ExprPtr Reader::child_outcome(const JsonValue &cond, const ast::Place *source, const SourceRange &at) {
  std::string name = label_of(cond);
  std::string library = cond.string_of("libraryName");
  if ((name == "AlwaysTrueCondition" || name == "AlwaysFalseCondition") &&
      (library.empty() || library == "alica_standard_library")) {
    // The standard library's constants need no function of the robot library.
    auto e = std::make_unique<ast::Expr>();
    e->kind = ast::Expr::Kind::Bool;
    e->range = at;
    e->bool_value = name == "AlwaysTrueCondition";
    return e;
  }
  bool success = name == "AnyChildSuccess" || name == "AllChildSuccess";
  bool failure = name == "AnyChildFailure" || name == "AllChildFailure";
  if ((!success && !failure) || !source || !source->runs() || !fsm_charts_[std::string(source->runs()->text)])
    return nullptr;
  auto e = call(success ? "succeeded" : "failed", at);
  auto arg = std::make_unique<ast::Expr>();
  arg->kind = ast::Expr::Kind::Name;
  arg->range = at;
  arg->name = {source->name.text, at};
  e->args.push_back(std::move(arg));
  return e;
}

/// A standard child condition gfec cannot read from a sub-chart (the state runs behaviours,
/// whose outcome gfec does not model, or a plan with several entry points, whose sfc never
/// ends): it stays a sensing function, and the user is told so where it is used.
void Reader::child_outcome_unobserved(const JsonValue &cond, const ast::Place *source, const SourceRange &at,
                                      const std::string &what) {
  std::string name = label_of(cond);
  if (name != "AnyChildSuccess" && name != "AllChildSuccess" && name != "AnyChildFailure" && name != "AllChildFailure")
    return;
  std::string state(source ? source->name.text : "?");
  std::string why =
      source && source->runs()
          ? fmt::format("the plan it runs, '{}', has several entry points and its sfc never ends", source->runs()->text)
      : source && !source->action.empty()
          ? "it runs no plan, and gfec does not model the success or failure of behaviours"
          : "it runs neither a plan nor a behaviour";
  ignored(at, fmt::format("{} tests {} of state '{}', but {}: the condition becomes the sensing function '{}()' "
                          "of the robot library",
                          what, name, state, why, name));
}

void Reader::convert_transition(Doc &doc, const JsonValue &t, std::vector<Machine> &machines,
                                const std::vector<int> &owner, const std::vector<std::string> &state_names,
                                const StateIndex &state_index, const std::string &plan_what) {
  std::string id = id_of(t.find("id")).value_or("");
  std::string label = label_of(t);
  std::string what = fmt::format("transition '{}' (id {}) of {}", label, id, plan_what);
  element(doc, t, "ALICA " + what);
  auto from = state_named(state_index, t.find("inState")), to = state_named(state_index, t.find("outState"));
  for (auto [end, key] : {std::pair{from, "inState"}, std::pair{to, "outState"}})
    if (!end && !not_an_id(doc, t.find(key), fmt::format("the {} of {}", key, what))) {
      diag_.error(range(doc, t), ErrorKind::AlicaReference,
                  fmt::format("{} names {} {}, which the plan has no state for", what, key,
                              id_of(t.find(key)).value_or("(none)")));
    }
  if (!from || !to) return;
  Machine &m = machines[owner[*from]];
  if (owner[*from] != owner[*to]) {
    diag_.error(range(doc, t), ErrorKind::AlicaFormat,
                fmt::format("{} leads from entry point machine '{}' to machine '{}': gfec machines do not share "
                            "states",
                            what, m.chart.name.text, machines[owner[*to]].chart.name.text));
    return;
  }
  ast::Transition out;
  out.range = range(doc, t);
  if (meaningful(label)) {
    out.named = true;
    out.name = ast::Name{keep(m.transitions.take(identifier(label, "T" + id), id)), out.range};
  }
  out.set_places({ast::Name{keep(state_names[*from]), out.range}}, {ast::Name{keep(state_names[*to]), out.range}});
  const JsonValue *cond = t.find("condition");
  const JsonValue *pre = t.find("preCondition");
  const ast::Place *source = nullptr;
  for (const auto &p : m.chart.places)
    if (p.name.text == state_names[*from]) source = &p;
  if (cond && cond->is_string() && !cond->text.empty()) {
    Resolved c = files_.resolve(cond->text, doc, range(doc, *cond));
    if (c.object) out.condition = child_outcome(*c.object, source, range(doc, *cond));
    if (c.object && !out.condition) {
      out.condition = call(condition(*c.doc, *c.object, label), range(doc, *cond));
      child_outcome_unobserved(*c.object, source, range(doc, *cond), what);
    }
    // The designer keeps writing a preCondition object beside the reference; it decides nothing,
    // so it gets no function (which would also take a name from the conditions that are used).
    if (pre && pre->is_object())
      condition_warnings(doc, *pre,
                         fmt::format("the transition's \"condition\", '{}', decides when it fires", cond->text));
  } else if (pre && pre->is_object()) {
    out.condition = child_outcome(*pre, source, range(doc, *pre));
    if (!out.condition) {
      out.condition = call(condition(doc, *pre, label), range(doc, *pre));
      child_outcome_unobserved(*pre, source, range(doc, *pre), what);
    }
  }
  if (const JsonValue *sync = t.find("synchronisation"); non_empty(sync))
    ignored(doc, *sync, fmt::format("{} is synchronised with others; the synchronisation is ignored", what));
  if (const JsonValue *km = t.find("keyMapping");
      km && km->is_object() && (non_empty(km->find("input")) || non_empty(km->find("output"))))
    ignored(doc, *km, fmt::format("the blackboard key mapping of {} is ignored: gfec has no blackboard", what));
  m.chart.transitions.push_back(std::move(out));
}

// ------------------------------------------------------------ functions

void Reader::declare(const std::string &name, const char *result, const SourceRange &at) {
  ast::FunctionDecl f;
  f.result = {result, at};
  f.name = {keep(name), at};
  f.range = at;
  main_->interfaces.back().functions.push_back(std::move(f));
}

/// The action function of the behaviour `t`: declared on first use.
std::string Reader::behaviour(const Resolved &t) {
  std::string id = id_of(t.object->find("id")).value_or("");
  std::string key = t.doc->path + "#" + id;
  auto it = functions_.find(key);
  if (it != functions_.end()) return it->second;
  std::string label = label_of(*t.object);
  std::string name = global_name(label, id, "Behaviour");
  functions_[key] = name;
  declare(name, "void", range(*t.doc, *t.object));
  element(*t.doc, *t.object, fmt::format("ALICA behaviour '{}' (id {})", label, id));
  for (const char *c : {"preCondition", "runtimeCondition", "postCondition"})
    if (const JsonValue *v = t.object->find(c); non_empty(v))
      ignored(*t.doc, *v,
              fmt::format("the {} of behaviour '{}' (id {}) is ignored: gfec calls '{}' on every tick "
                          "of the states that hold it",
                          c, label, id, name));
  if (const JsonValue *v = t.object->find("variables"); non_empty(v))
    ignored(*t.doc, *v,
            fmt::format("the variables of behaviour '{}' (id {}) are ignored: a gfec action function "
                        "takes no arguments",
                        label, id));
  if (const JsonValue *v = t.object->find("blackboard"); non_empty(v))
    ignored(*t.doc, *v,
            fmt::format("the blackboard of behaviour '{}' (id {}) is ignored: gfec has no blackboard, "
                        "'{}()' takes no arguments",
                        label, id, name));
  return name;
}

/// The sensing function of a condition object: its name, else `fallback`, else "Condition<id>".
std::string Reader::condition(Doc &doc, const JsonValue &cond, const std::string &fallback) {
  std::string id = id_of(cond.find("id")).value_or("");
  std::string key = doc.path + "#" + id;
  auto it = functions_.find(key);
  if (it != functions_.end()) return it->second;
  std::string label = label_of(cond);
  std::string name = globals_.take(identifier(meaningful(label) ? label : fallback, "Condition" + id), id);
  functions_[key] = name;
  declare(name, "bool", range(doc, cond));
  element(doc, cond, fmt::format("ALICA condition '{}' (id {})", label, id));
  condition_warnings(doc, cond, fmt::format("gfec's '{}()' takes no arguments", name));
  return name;
}

/// What a condition holds that gfec's sensing functions cannot take; `why` ends each warning.
void Reader::condition_warnings(const Doc &doc, const JsonValue &cond, const std::string &why) {
  std::string id = id_of(cond.find("id")).value_or("");
  std::string label = label_of(cond);
  if (const JsonValue *q = cond.find("quantifiers"); non_empty(q))
    ignored(doc, *q, fmt::format("the quantifiers of condition '{}' (id {}) are ignored: {}", label, id, why));
  if (const JsonValue *v = cond.find("variables"); non_empty(v))
    ignored(doc, *v, fmt::format("the variables of condition '{}' (id {}) are ignored: {}", label, id, why));
  if (const JsonValue *v = cond.find("blackboard"); non_empty(v))
    ignored(doc, *v,
            fmt::format("the blackboard inputs of condition '{}' (id {}) are ignored: gfec has no blackboard, {}",
                        label, id, why));
}

ast::ExprPtr Reader::call(const std::string &name, const SourceRange &at) {
  auto e = std::make_unique<ast::Expr>();
  e->kind = ast::Expr::Kind::Call;
  e->range = at;
  e->name = {keep(name), at};
  return e;
}

}  // namespace gfec::alica
