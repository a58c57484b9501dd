#include "json_backend.h"

#include "json_expr.h"
#include "roots.h"

#include <ostream>
#include <algorithm>
#include <set>
#include <stdexcept>

namespace gfec {

namespace {

using json_backend::expression;
using json_backend::Json;
using json_backend::location;
using json_backend::Scope;
using json_backend::statements;

/// Bumped when a field changes meaning or disappears; new fields do not bump it.
constexpr int kFormatVersion = 1;

std::size_t at(int index) { return static_cast<std::size_t>(index); }

/// The fields every document starts with: what it is, and where it came from.
Json header(const model::Model &m, const EmitOptions &o, const char *kind, const std::string &name,
            const SourceRange &range) {
  Json files = Json::array();
  for (FileId i = 0; i < m.sources().size(); ++i) files.push_back(m.sources().file(i).path());
  return {{"format", "gfec-model"},
          {"version", kFormatVersion},
          {"kind", kind},
          {"name", name},
          {"source", o.source_name},
          {"files", std::move(files)},
          {"location", location(m, range)}};
}

Json function(const model::Function &f) {
  Json params = Json::array();
  for (const auto &p : f.params) params.push_back({{"type", model::type_name(p.type)}, {"name", p.name}});
  return {{"name", f.name},
          {"result", model::type_name(f.result)},
          {"params", std::move(params)},
          {"interface", f.interface_name}};
}

const char *terminal_name(model::Terminal t) {
  switch (t) {
  case model::Terminal::Success: return "success";
  case model::Terminal::Failure: return "failure";
  case model::Terminal::None: break;
  }
  return nullptr;
}

/// Everything about one chart but the document header: the root's fields, and each sub-chart's.
void chart_fields(const model::Model &m, const model::Chart &c, Json &doc) {
  bool fsm = c.kind == model::Chart::Kind::Fsm;
  Scope scope{&c, nullptr};
  doc["period_ms"] = c.period_ms > 0 ? Json(c.period_ms) : Json(nullptr);
  doc["team"] = c.team > 0 ? Json(c.team) : Json(nullptr);

  Json places = Json::array();
  for (std::size_t i = 0; i < c.places.size(); ++i) {
    const model::Place &p = c.places[i];
    const char *terminal = terminal_name(p.terminal);
    auto block = [&](const HeapOptional<std::vector<model::Stmt>> &b) {
      return b ? statements(m, scope, *b) : Json(nullptr);
    };
    places.push_back({{"index", i},
                      {"name", p.name},
                      {"initial", p.initial},
                      {"terminal", terminal ? Json(terminal) : Json(nullptr)},
                      {"action", statements(m, scope, p.action)},
                      {"entry", block(p.entry)},
                      {"exit", block(p.exit)},
                      {"post", p.post ? expression(m, scope, *p.post) : Json(nullptr)},
                      {"timed", p.timed},
                      {"runs", p.runs ? Json(m.charts.at(p.runs).name) : Json(nullptr)},
                      {"location", location(m, p.range)}});
  }
  doc[fsm ? "states" : "places"] = std::move(places);

  Json transitions = Json::array();
  for (std::size_t i = 0; i < c.transitions.size(); ++i) {
    const model::Transition &t = c.transitions[i];
    auto names = [&](const model::PlaceList &list) {
      Json a = Json::array();
      for (model::PlaceId p : list) a.push_back(c.places.at(p).name);
      return a;
    };
    Json j = {
        {"index", i}, {"name", t.name}, {"named", t.named}, {"inputs", names(t.inputs)}, {"outputs", names(t.outputs)}};
    if (fsm && t.inputs.size() == 1 && t.outputs.size() == 1) {
      j["from"] = c.places.at(t.inputs[0]).name;
      j["to"] = c.places.at(t.outputs[0]).name;
    }
    j["when"] = t.condition ? json_backend::expression_text(m, scope, *t.condition) : "true";
    j["condition"] = t.condition ? expression(m, scope, *t.condition) : Json(nullptr);
    j["location"] = location(m, t.range);
    transitions.push_back(std::move(j));
  }
  doc["transitions"] = std::move(transitions);

  Json vars = Json::array();
  for (const auto &v : c.vars) {
    Json j = {{"name", v.name},
              {"type", model::type_name(v.type)},
              {"init", v.init ? expression(m, scope, *v.init) : Json(nullptr)},
              {"location", location(m, v.range)}};
    // Only inputs and outputs carry a role (docs/model-json.md): a chart's own var has none.
    if (v.role != model::VarRole::Local) j["role"] = model::role_keyword(v.role);
    if (!v.address.empty()) j["address"] = v.address;
    vars.push_back(std::move(j));
  }
  doc["vars"] = std::move(vars);

  // Only a chart with block instances has the fields (docs/model-json.md "Blocks").
  if (!c.instances.empty()) {
    Json instances = Json::array();
    std::set<model::BlockId> used;
    for (const model::Instance &i : c.instances) {
      used.insert(i.block);
      if (i.name.find('.') != std::string::npos) continue;  // inside another instance
      instances.push_back({{"name", i.name},
                           {"block", m.blocks[i.block].name},
                           {"first_var", i.first.index()},
                           {"var_count", i.count},
                           {"location", location(m, i.range)}});
    }
    doc["instances"] = std::move(instances);
    Json blocks = Json::array();
    for (model::BlockId id : used) {
      const model::Block &b = m.blocks[id];
      Json members = Json::array();
      for (const model::Var &v : b.vars) {
        if (v.name.find('.') != std::string::npos) continue;  // a member of an inner instance
        Json j = {{"name", v.name}, {"type", model::type_name(v.type)}};
        if (v.role != model::VarRole::Local) j["role"] = model::role_keyword(v.role);
        members.push_back(std::move(j));
      }
      blocks.push_back({{"name", b.name},
                        {"standard", b.standard},
                        {"members", std::move(members)},
                        {"location", location(m, b.range)}});
    }
    doc["blocks"] = std::move(blocks);
  }

  Json consts = Json::array();
  for (model::ConstId k : c.consts) {
    const model::Const &cst = m.consts.at(k);
    consts.push_back({{"name", cst.name},
                      {"type", model::type_name(cst.type)},
                      {"value", json_backend::expression_tree(m, scope, cst.value).value("value", Json(nullptr))},
                      {"location", location(m, cst.range)}});
  }
  doc["consts"] = std::move(consts);

  // Only a chart with named actions has the field (docs/model-json.md), so that the documents of
  // the others stay as they were.
  if (!c.actions.empty()) {
    Json actions = Json::array();
    for (const model::Action &a : c.actions) {
      Json held = Json::array();
      for (const model::Association &as : a.associations) {
        const bool timed = model::is_timed(as.qualifier);
        held.push_back({{"place", c.places.at(as.place).name},
                        {"qualifier", model::qualifier_name(as.qualifier)},
                        {"duration_ms", timed ? Json(as.duration_ms) : Json(nullptr)},
                        {"ticks", timed ? Json(as.ticks) : Json(nullptr)},
                        {"location", location(m, as.range)}});
      }
      actions.push_back({{"name", a.name},
                         {"body", statements(m, scope, a.body)},
                         {"associations", std::move(held)},
                         {"location", location(m, a.range)}});
    }
    doc["actions"] = std::move(actions);
  }

  Json functions = Json::array();
  for (model::FunctionId f : c.functions) functions.push_back(function(m.functions.at(f)));
  doc["functions"] = std::move(functions);
}

Json chart_document(const model::Model &m, const EmitOptions &o, const model::Chart &c) {
  Json doc = header(m, o, c.kind == model::Chart::Kind::Fsm ? "fsm" : "sfc", c.name, c.range);
  chart_fields(m, c, doc);
  // Every chart the compiled one runs, directly or through others, once, in declaration order
  // (docs/language.md "Sub-charts"); places name them in `runs`.
  Json subcharts = Json::array();
  const auto in = charts_in_tree(m, m.charts.id_of(c));
  for (model::ChartId i : m.charts.ids()) {
    const model::Chart &sub = m.charts[i];
    if (!in[i] || &sub == &c) continue;
    Json j = {{"kind", sub.kind == model::Chart::Kind::Fsm ? "fsm" : "sfc"}, {"name", sub.name}};
    chart_fields(m, sub, j);
    j["location"] = location(m, sub.range);
    subcharts.push_back(std::move(j));
  }
  doc["subcharts"] = std::move(subcharts);
  return doc;
}

// ---------------------------------------------------------------- plans

const char *template_kind(model::Template::Kind k) {
  switch (k) {
  case model::Template::Kind::Actor: return "actor";
  case model::Template::Kind::Computation: return "computation";
  case model::Template::Kind::Supervisor: return "supervisor";
  }
  return "?";
}

struct PlanWriter {
  const model::Model &m;
  const model::Plan &plan;
  Scope scope{nullptr, &plan};
  Json flat_rules = Json::array();

  /// Config entries an argument reads (in) or writes (out), in the order they appear.
  void config_names(const model::Expr &e, Json &out) const {
    if (e.kind == model::Expr::Kind::Config) {
      const std::string &name = plan.config.at(e.config()).name;
      if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
    }
    for (const auto &a : e.args) config_names(a, out);
  }

  Json args(const std::vector<model::Arg> &list, model::TemplateId templ) const {
    Json out = Json::array();
    for (std::size_t i = 0; i < list.size(); ++i) {
      const model::Arg &a = list[i];
      Json config = Json::array();
      config_names(a.formula, config);
      Json j = {{"param", nullptr}, {"dir", a.dir == model::ParamDir::Out ? "out" : "in"}};
      if (templ && i < m.templates.at(templ).params.size()) {
        const model::TemplateParam &p = m.templates.at(templ).params[i];
        j["param"] = p.name;
        j["type"] = model::type_name(p.type);
      }
      j["formula"] = expression(m, scope, a.formula);
      j["config"] = std::move(config);
      out.push_back(std::move(j));
    }
    return out;
  }

  std::string outcome(model::TemplateId templ, model::PlanId subplan, int index) const {
    if (subplan) return index >= 0 && index < 3 ? model::kSubPlanStates[index] : "?";
    const auto &outcomes = m.templates.at(templ).outcomes;
    return index >= 0 && at(index) < outcomes.size() ? outcomes[at(index)] : "?";
  }

  /// The rules of one actor or supervisor; each also goes to the plan's flat "rules" list.
  Json rules(const std::vector<model::Rule> &list, model::TemplateId templ, model::PlanId subplan,
             const std::string &actor, const std::string &supervisor) {
    Json out = Json::array();
    for (const auto &r : list) {
      Json target = r.target.kind == model::RuleTarget::Kind::Actor       ? Json(plan.actors.at(r.target.actor).name)
                    : r.target.kind == model::RuleTarget::Kind::Terminate ? Json("terminate")
                                                                          : Json("ignore");
      const char *kind = r.target.kind == model::RuleTarget::Kind::Actor       ? "actor"
                         : r.target.kind == model::RuleTarget::Kind::Terminate ? "terminate"
                                                                               : "ignore";
      Json j = {{"outcome", outcome(templ, subplan, r.outcome)},
                {"target", target},
                {"target_kind", kind},
                {"location", location(m, r.range)}};
      out.push_back(j);
      Json flat = {{"actor", actor.empty() ? Json(nullptr) : Json(actor)},
                   {"supervisor", supervisor.empty() ? Json(nullptr) : Json(supervisor)},
                   {"outcome", j["outcome"]},
                   {"target", target},
                   {"target_kind", kind}};
      flat_rules.push_back(std::move(flat));
    }
    return out;
  }

  Json supervisors(const std::vector<model::SupervisorUse> &list, const std::string &actor) {
    Json out = Json::array();
    for (const auto &s : list) {
      const model::Template &t = m.templates.at(s.templ);
      out.push_back({{"name", s.name},
                     {"template", t.name},
                     {"period_ms", t.period_ms > 0 ? Json(t.period_ms) : Json(nullptr)},
                     {"args", args(s.args, s.templ)},
                     {"rules", rules(s.rules, s.templ, {}, actor, s.name)},
                     {"location", location(m, s.range)}});
    }
    return out;
  }

  Json document(const EmitOptions &o) {
    Json doc = header(m, o, "plan", plan.name, plan.range);
    Json config = Json::array();
    for (const auto &c : plan.config) {
      Json init =
          c.init ? json_backend::expression_tree(m, scope, *c.init).value("value", Json(nullptr)) : Json(nullptr);
      config.push_back(
          {{"name", c.name}, {"type", model::type_name(c.type)}, {"init", init}, {"location", location(m, c.range)}});
    }
    doc["config"] = std::move(config);
    doc["start"] = plan.start ? Json(plan.actors.at(plan.start).name) : Json(nullptr);
    doc["supervisors"] = supervisors(plan.globals, "");
    Json actors = Json::array();
    for (const auto &a : plan.actors) {
      bool sub = a.subplan.valid();
      const char *kind = sub ? "plan" : template_kind(m.templates.at(a.templ).kind);
      actors.push_back({{"name", a.name},
                        {"kind", kind},
                        {"template", sub ? m.plans.at(a.subplan).name : m.templates.at(a.templ).name},
                        {"args", args(a.args, a.templ)},
                        {"rules", rules(a.rules, a.templ, a.subplan, a.name, "")},
                        {"supervisors", supervisors(a.supervisors, a.name)},
                        {"location", location(m, a.range)}});
    }
    doc["actors"] = std::move(actors);
    doc["rules"] = std::move(flat_rules);
    doc["templates"] = templates();
    return doc;
  }

  /// The toolbox templates the plan uses, in toolbox order, so a tool needs no toolbox parser.
  Json templates() const {
    IdMap<model::TemplateId, bool> used(m.templates.size(), false);
    for (const auto &s : plan.globals) used.at(s.templ) = true;
    for (const auto &a : plan.actors) {
      if (a.templ) used.at(a.templ) = true;
      for (const auto &s : a.supervisors) used.at(s.templ) = true;
    }
    Json out = Json::array();
    for (model::TemplateId i : m.templates.ids()) {
      if (!used[i]) continue;
      const model::Template &t = m.templates[i];
      Json params = Json::array();
      for (const auto &p : t.params)
        params.push_back({{"dir", p.dir == model::ParamDir::Out ? "out" : "in"},
                          {"type", model::type_name(p.type)},
                          {"name", p.name}});
      out.push_back({{"name", t.name},
                     {"kind", template_kind(t.kind)},
                     {"toolbox", t.toolbox ? Json(m.toolboxes.at(t.toolbox).name) : Json(nullptr)},
                     {"params", std::move(params)},
                     {t.kind == model::Template::Kind::Supervisor ? "events" : "results", t.outcomes},
                     {"period_ms", t.period_ms > 0 ? Json(t.period_ms) : Json(nullptr)}});
    }
    return out;
  }
};

class JsonBackend : public Backend {
public:
  void emit(const model::Model &m, const EmitOptions &o, OutputSink &sink) const override {
    Json doc;
    if (o.chart) doc = chart_document(m, o, m.charts.at(o.chart));
    else if (o.plan) doc = PlanWriter{m, m.plans.at(o.plan)}.document(o);
    else throw std::invalid_argument("json back end: no chart or plan chosen");
    sink.open(o.output_path) << doc.dump(2, ' ', false, Json::error_handler_t::replace) << "\n";
  }
};

}  // namespace

std::unique_ptr<Backend> make_json_backend() { return std::make_unique<JsonBackend>(); }

}  // namespace gfec
