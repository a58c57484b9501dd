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

/// The compiled chart and every chart it runs, directly or not, as a set of model indices.
std::set<int> charts_to_write(const model::Model &m, int root) {
  std::set<int> out;
  std::vector<int> work{root};
  while (!work.empty()) {
    int c = work.back();
    work.pop_back();
    if (c < 0 || !out.insert(c).second) continue;
    for (const auto &p : m.charts[static_cast<std::size_t>(c)].places) work.push_back(p.runs);
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
void interfaces(CodeWriter &w, const model::Model &m, const std::set<int> &charts) {
  std::set<int> used;
  for (int c : charts)
    for (int f : m.charts[static_cast<std::size_t>(c)].functions) used.insert(f);
  std::vector<std::string> order;
  for (int f : used) {
    const std::string &iface = m.functions[static_cast<std::size_t>(f)].interface_name;
    if (std::find(order.begin(), order.end(), iface) == order.end()) order.push_back(iface);
  }
  for (const auto &iface : order) {
    w.line("interface {} {{", iface);
    w.indent();
    for (int f : used)
      if (m.functions[static_cast<std::size_t>(f)].interface_name == iface)
        w.line("{}", prototype(m.functions[static_cast<std::size_t>(f)]));
    w.dedent();
    w.line("}");
    w.blank();
  }
}

void value(CodeWriter &w, const model::Model &m, int chart, const char *keyword, model::Type type,
           const std::string &name, const model::Expr *init) {
  if (init) w.line("{} {} {} = {};", keyword, model::type_name(type), name, chart_text::expr(m, chart, *init));
  else w.line("{} {} {};", keyword, model::type_name(type), name);
}

void block(CodeWriter &w, const model::Model &m, int chart, const char *keyword,
           const std::vector<model::Stmt> &stmts) {
  w.line("{} {{", keyword);
  w.indent();
  chart_text::statements(w, m, chart, stmts);
  w.dedent();
  w.line("}");
}

void place(CodeWriter &w, const model::Model &m, int chart, const model::Place &p, bool fsm) {
  std::string head = p.initial ? "initial " : "";
  if (p.terminal == model::Terminal::Success) head += "success ";
  if (p.terminal == model::Terminal::Failure) head += "failure ";
  head += fmt::format("{} {}", fsm ? "state" : "place", p.name);
  if (p.runs >= 0) head += " runs " + m.charts[static_cast<std::size_t>(p.runs)].name;
  if (p.post) head += " post " + chart_text::expr(m, chart, *p.post);
  if (p.action.empty() && !p.entry && !p.exit) {
    w.line("{};", head);
    return;
  }
  w.line("{} {{", head);
  w.indent();
  chart_text::statements(w, m, chart, p.action);
  if (p.entry) block(w, m, chart, "entry", *p.entry);
  if (p.exit) block(w, m, chart, "exit", *p.exit);
  w.dedent();
  w.line("}");
}

std::string places(const model::Chart &c, const IndexList &list) {
  if (list.size() == 1) return c.places[static_cast<std::size_t>(list[0])].name.str();
  std::string out;
  for (int p : list) out += (out.empty() ? "" : ", ") + c.places[static_cast<std::size_t>(p)].name;
  return "(" + out + ")";
}

void chart(CodeWriter &w, const model::Model &m, int index) {
  const model::Chart &c = m.charts[static_cast<std::size_t>(index)];
  bool fsm = c.kind == model::Chart::Kind::Fsm;
  w.line("{} {} {{", fsm ? "fsm" : "sfc", c.name);
  w.indent();
  if (c.period_ms > 0) w.line("period {}ms;", c.period_ms);
  if (c.team > 0) w.line("team {};", c.team);
  for (const auto &k : m.consts)
    if (k.chart == index) value(w, m, index, "const", k.type, k.name, &k.value);
  for (const auto &v : c.vars) value(w, m, index, "var", v.type, v.name, v.init ? &*v.init : nullptr);
  for (const auto &p : c.places) place(w, m, index, p, fsm);
  for (const auto &t : c.transitions) {
    std::string line = fsm ? "" : "transition ";
    if (t.named) line += t.name + ": ";
    line += places(c, t.inputs) + " -> " + places(c, t.outputs);
    if (t.condition) line += " when " + chart_text::expr(m, index, *t.condition);
    w.line("{};", line);
  }
  w.dedent();
  w.line("}");
}

class ChartBackend : public Backend {
public:
  void emit(const model::Model &m, const EmitOptions &o, OutputSink &sink) const override {
    // Plans and toolboxes are chart text already; this back end exists to convert other inputs.
    if (o.chart < 0) throw std::runtime_error("--emit=chart writes sfc and fsm charts; choose one with --chart");
    CodeWriter w(sink.open(o.output_path), o.output_path, false);
    std::set<int> charts = charts_to_write(m, o.chart);
    w.line("// Converted by gfec {} from {}: compiling this file gives the same engine.", GFEC_VERSION, o.source_name);
    w.blank();
    for (const auto &v : m.verbatims) w.line("%{{{}%}}", v.text);
    if (!m.verbatims.empty()) w.blank();
    interfaces(w, m, charts);
    std::set<int> consts;
    for (int c : charts)
      for (int k : m.charts[static_cast<std::size_t>(c)].consts)
        if (m.consts[static_cast<std::size_t>(k)].chart < 0) consts.insert(k);
    for (int k : consts) {
      const model::Const &cst = m.consts[static_cast<std::size_t>(k)];
      value(w, m, o.chart, "const", cst.type, cst.name, &cst.value);
    }
    if (!consts.empty()) w.blank();
    // Model order, which is the order the converted file declares them in again.
    bool first = true;
    for (int c : charts) {
      if (!first) w.blank();
      first = false;
      chart(w, m, c);
    }
  }
};

}  // namespace

std::unique_ptr<Backend> make_chart_backend() { return std::make_unique<ChartBackend>(); }

}  // namespace gfec
