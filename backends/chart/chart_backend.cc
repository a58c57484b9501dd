#include "chart_backend.h"

#include "chart_expr.h"
#include "code_writer.h"

#include <ostream>
#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace gfec {

namespace {

/// The compiled chart and every chart it runs, directly or not, in model order.
std::set<model::ChartId> charts_to_write(const model::Model &m, model::ChartId root) {
  std::set<model::ChartId> out;
  std::vector<model::ChartId> work{root};
  while (!work.empty()) {
    model::ChartId c = work.back();
    work.pop_back();
    if (!c || !out.insert(c).second) continue;
    for (const auto &p : m.charts[c].places) work.push_back(p.runs);
  }
  return out;
}

std::string prototype(const model::Function &f) {
  std::string params;
  for (const auto &p : f.params)
    params += fmt::format("{}{}{}{}", params.empty() ? "" : ", ", model::type_name(p.type), p.name.empty() ? "" : " ",
                          p.name);
  return fmt::format("{} {}({});", model::type_name(f.result), f.name, params);
}

/// The interfaces, each with the functions the written charts call, in declaration order.
void interfaces(CodeWriter &w, const model::Model &m, const std::set<model::ChartId> &charts) {
  std::set<model::FunctionId> used;
  for (model::ChartId c : charts)
    for (model::FunctionId f : m.charts[c].functions) used.insert(f);
  std::vector<std::string> order;
  for (model::FunctionId f : used) {
    const std::string &iface = m.functions[f].interface_name;
    if (std::find(order.begin(), order.end(), iface) == order.end()) order.push_back(iface);
  }
  for (const auto &iface : order) {
    {
      auto body = w.block(fmt::format("interface {} {{", iface));
      for (model::FunctionId f : used)
        if (m.functions[f].interface_name == iface) w.line("{}", prototype(m.functions[f]));
    }
    w.blank();
  }
}

void value(CodeWriter &w, const model::Model &m, model::ChartId chart, const char *keyword, model::Type type,
           const std::string &name, const model::Expr *init, const std::string &address = {}) {
  // An IEC located variable keeps its address as a comment: chart text has no addresses, and the
  // engine's field is the variable's name either way (docs/iec.md "Located variables").
  const std::string at = address.empty() ? "" : "  // AT " + address;
  if (init)
    w.line("{} {} {} = {};{}", keyword, model::type_name(type), chart_text::name(name),
           chart_text::expr(m, chart, *init), at);
  else w.line("{} {} {};{}", keyword, model::type_name(type), chart_text::name(name), at);
}

void block(CodeWriter &w, const model::Model &m, model::ChartId chart, const char *keyword,
           const std::vector<model::Stmt> &stmts) {
  auto body = w.block(fmt::format("{} {{", keyword));
  chart_text::statements(w, m, chart, stmts);
}

/// The associations place `p` holds: `N Fill;`, `L Pump 2000ms;`. Grouped by action in
/// declaration order, each action's in the order written: what its action control reads.
std::vector<std::string> associations(const model::Chart &c, model::PlaceId p) {
  std::vector<std::string> out;
  for (const model::Action &a : c.actions)
    for (const model::Association &as : a.associations) {
      if (as.place != p) continue;
      std::string line = fmt::format("{} {}", model::qualifier_name(as.qualifier), chart_text::name(a.name.view()));
      if (model::is_timed(as.qualifier)) line += fmt::format(" {}ms", as.duration_ms);
      out.push_back(line + ";");
    }
  return out;
}

void place(CodeWriter &w, const model::Model &m, model::ChartId chart, model::PlaceId id, bool fsm) {
  const model::Place &p = m.charts[chart].places[id];
  const std::vector<std::string> held = associations(m.charts[chart], id);
  std::string head = p.initial ? "initial " : "";
  if (p.terminal == model::Terminal::Success) head += "success ";
  if (p.terminal == model::Terminal::Failure) head += "failure ";
  head += fmt::format("{} {}", fsm ? "state" : "place", chart_text::name(p.name.view()));
  if (p.runs) head += " runs " + m.charts[p.runs].name;
  if (p.post) head += " post " + chart_text::expr(m, chart, *p.post);
  if (p.action.empty() && !p.entry && !p.exit && held.empty()) {
    w.line("{};", head);
    return;
  }
  auto body = w.block(fmt::format("{} {{", head));
  for (const std::string &line : held) w.line("{}", line);
  chart_text::statements(w, m, chart, p.action);
  if (p.entry) block(w, m, chart, "entry", *p.entry);
  if (p.exit) block(w, m, chart, "exit", *p.exit);
}

std::string places(const model::Chart &c, const model::PlaceList &list) {
  if (list.size() == 1) return chart_text::name(c.places[list[0]].name.view());
  std::string out;
  for (model::PlaceId p : list) out += (out.empty() ? "" : ", ") + chart_text::name(c.places[p].name.view());
  return "(" + out + ")";
}

/// The vars of chart `index`: each block instance as `var B inst;` where its members begin.
void vars(CodeWriter &w, const model::Model &m, model::ChartId index) {
  const model::Chart &c = m.charts[index];
  for (model::VarId v : c.vars.ids()) {
    const model::Instance *holder = nullptr;
    for (const model::Instance &i : c.instances)
      if (i.name.find('.') == std::string::npos && v.index() >= i.first.index() &&
          v.index() < i.first.index() + i.count)
        holder = &i;
    if (holder) {
      if (holder->first == v) w.line("var {} {};", m.blocks[holder->block].name, holder->name);
      continue;
    }
    const model::Var &x = c.vars[v];
    value(w, m, index, model::role_keyword(x.role), x.type, x.name, x.init ? &*x.init : nullptr, x.address);
  }
}

/// The user's blocks (the standard ones are predefined), each written over a scratch chart
/// that holds its vars, so that its statements are spelled as a chart's.
void blocks(CodeWriter &w, const model::Model &m) {
  bool any = false;
  for (const model::Block &b : m.blocks) any = any || !b.standard;
  if (!any) return;
  model::Model scratch = m;
  for (const model::Block &b : m.blocks) {
    if (b.standard) continue;
    model::Chart shell;
    shell.name = b.name;
    for (const model::Var &v : b.vars) shell.vars.push_back(v);
    shell.instances = b.instances;
    const model::ChartId id = scratch.charts.next_id();
    scratch.charts.push_back(std::move(shell));
    {
      auto body = w.block(fmt::format("block {} {{", b.name));
      vars(w, scratch, id);
      chart_text::statements(w, scratch, id, b.body);
    }
    w.blank();
  }
}

void chart(CodeWriter &w, const model::Model &m, model::ChartId index) {
  const model::Chart &c = m.charts[index];
  bool fsm = c.kind == model::Chart::Kind::Fsm;
  auto body = w.block(fmt::format("{} {} {{", fsm ? "fsm" : "sfc", c.name));
  if (c.period_ms > 0) w.line("period {}ms;", c.period_ms);
  if (c.team > 0) w.line("team {};", c.team);
  for (const auto &k : m.consts)
    if (k.chart == index) value(w, m, index, "const", k.type, k.name, &k.value);
  vars(w, m, index);
  for (const auto &a : c.actions) {
    auto action = w.block(fmt::format("action {} {{", chart_text::name(a.name.view())));
    chart_text::statements(w, m, index, a.body);
  }
  for (model::PlaceId p : c.places.ids()) place(w, m, index, p, fsm);
  for (const auto &t : c.transitions) {
    std::string line = fsm ? "" : "transition ";
    if (t.named) line += chart_text::name(t.name) + ": ";
    line += places(c, t.inputs) + " -> " + places(c, t.outputs);
    if (t.otherwise) line += " else";
    if (t.condition) line += " when " + chart_text::expr(m, index, *t.condition);
    w.line("{};", line);
  }
}

class ChartBackend : public Backend {
public:
  void emit(const model::Model &m, const EmitOptions &o, OutputSink &sink) const override {
    // Plans and toolboxes are chart text already; this back end exists to convert other inputs.
    if (!o.chart) throw std::runtime_error("--emit=chart writes sfc and fsm charts; choose one with --chart");
    CodeWriter w(sink.open(o.output_path), o.output_path, false);
    const model::ChartId root = o.chart;
    std::set<model::ChartId> charts = charts_to_write(m, root);
    w.line("// Converted by gfec {} from {}: compiling this file gives the same engine.", GFEC_VERSION, o.source_name);
    w.blank();
    for (const auto &v : m.verbatims) w.line("%{{{}%}}", v.text);
    if (!m.verbatims.empty()) w.blank();
    interfaces(w, m, charts);
    std::set<model::ConstId> consts;
    for (model::ChartId c : charts)
      for (model::ConstId k : m.charts[c].consts)
        if (!m.consts[k].chart) consts.insert(k);
    for (model::ConstId k : consts) {
      const model::Const &cst = m.consts[k];
      value(w, m, root, "const", cst.type, cst.name, &cst.value);
    }
    if (!consts.empty()) w.blank();
    blocks(w, m);
    // Model order, which is the order the converted file declares them in again.
    bool first = true;
    for (model::ChartId c : charts) {
      if (!first) w.blank();
      first = false;
      chart(w, m, c);
    }
  }
};

}  // namespace

std::unique_ptr<Backend> make_chart_backend() { return std::make_unique<ChartBackend>(); }

}  // namespace gfec
