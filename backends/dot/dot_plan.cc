#include "dot_plan.h"

#include "chart_nodes.h"
#include "dot_text.h"

#include <fmt/format.h>

#include <set>

namespace gfec::dot {

namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

class PlanPicture {
public:
  PlanPicture(const model::Model &m, const model::Plan &plan) : m_(m), plan_(plan) {}

  std::string draw() {
    out_ = fmt::format("digraph {} {{\n", quote(plan_.name));
    out_ += preamble("plan " + plan_.name);
    config();
    // The word inside the circle: an xlabel would be placed after the layout, over the edges.
    out_ += "  terminate [shape=doublecircle, label=\"terminate\", fontsize=9, margin=0];\n";
    out_ += "  // actors: the start actor double-bordered; result states lead to the next actor\n";
    for (model::ActorId i : plan_.actors.ids()) actor(i);
    out_ += "  // global supervisors: may interrupt any actor\n";
    for (std::size_t i = 0; i < plan_.globals.size(); ++i)
      supervisor(plan_.globals[i], chart_nodes::global_supervisor(i), "");
    out_ += "}\n";
    return std::move(out_);
  }

private:
  /// The configuration as one cluster of notes; arguments connect to it with thin edges.
  void config() {
    if (plan_.config.empty()) return;
    out_ += "  subgraph cluster_config {\n    label=\"config\"; style=dashed; color=gray50;\n";
    for (std::size_t i = 0; i < plan_.config.size(); ++i) {
      const model::ConfigEntry &c = plan_.config[i];
      std::string label = fmt::format("{} {}", model::type_name(c.type), c.name);
      if (c.init) label += " = " + source_text(m_, c.init->range);
      out_ += fmt::format("    {} [shape=note, style=filled, fillcolor=\"#fff8dc\", label={}];\n",
                          chart_nodes::constraint(i), quote(label));
    }
    out_ += "  }\n";
  }

  std::string call_text(const std::string &templ, const std::vector<model::Arg> &args) const {
    std::string s = templ + "(";
    for (std::size_t i = 0; i < args.size(); ++i) s += (i ? ", " : "") + source_text(m_, args[i].formula.range);
    return s + ")";
  }

  std::string target(const model::RuleTarget &t) const {
    return t.kind == model::RuleTarget::Kind::Actor ? chart_nodes::actor(t.actor.index()) : "terminate";
  }

  /// Thin gray edges: config -> node for what an `in` argument reads, node -> config for an
  /// `out` argument. constraint=false keeps the control flow in charge of the layout.
  void data_flow(const std::string &node, const std::vector<model::Arg> &args) {
    std::set<std::pair<model::ConfigId, bool>> drawn;
    for (const auto &a : args) {
      std::vector<model::ConfigId> entries;
      collect(a.formula, entries);
      bool out = a.dir == model::ParamDir::Out;
      for (model::ConfigId c : entries) {
        if (!drawn.insert({c, out}).second) continue;
        const std::string entry = chart_nodes::constraint(c.index());
        out_ += out ? fmt::format("  {} -> {}", node, entry) : fmt::format("  {} -> {}", entry, node);
        out_ += " [penwidth=0.5, color=gray45, arrowsize=0.4, constraint=false];\n";
      }
    }
  }

  static void collect(const model::Expr &e, std::vector<model::ConfigId> &entries) {
    if (e.kind == model::Expr::Kind::Config) entries.push_back(e.config());
    for (const auto &a : e.args) collect(a, entries);
  }

  void actor(model::ActorId i) {
    const model::ActorUse &a = plan_.actors[i];
    const std::string node = chart_nodes::actor(i.index());
    bool sub = a.subplan.valid();
    std::string templ = sub ? m_.plans.at(a.subplan).name : m_.templates.at(a.templ).name;
    std::string kind = sub                                                                   ? "plan"
                       : m_.templates.at(a.templ).kind == model::Template::Kind::Computation ? "computation"
                                                                                             : "";
    std::string label = a.name + "\n" + call_text(templ, a.args) + (kind.empty() ? "" : "\n<<" + kind + ">>");
    std::string attrs = sub ? "shape=box, style=\"rounded,bold\"" : "shape=box, style=rounded";
    if (plan_.start == i) attrs += ", peripheries=2";
    out_ += fmt::format("  {} [{}, label={}];\n", node, attrs, quote(label));
    for (const auto &r : a.rules) {
      std::string state = !sub                              ? m_.templates.at(a.templ).outcomes.at(at(r.outcome))
                          : r.outcome >= 0 && r.outcome < 3 ? model::kSubPlanStates[r.outcome]
                                                            : "?";
      out_ += fmt::format("  {} -> {} [label={}];\n", node, target(r.target), quote(state));
    }
    data_flow(node, a.args);
    for (std::size_t s = 0; s < a.supervisors.size(); ++s)
      supervisor(a.supervisors[s], chart_nodes::supervisor(i.index(), s), node);
  }

  /// A supervisor: a hexagon watching its actor (dotted, no arrow), its events as dashed red
  /// edges to where they lead. Ignored events are listed in the node.
  void supervisor(const model::SupervisorUse &s, const std::string &id, const std::string &watched) {
    const model::Template &t = m_.templates.at(s.templ);
    std::string label = s.name + "\n" + call_text(t.name, s.args);
    if (watched.empty()) label += "\n(global)";
    if (t.period_ms > 0) label += "\nevery " + duration(t.period_ms);
    std::string ignored;
    for (const auto &r : s.rules)
      if (r.target.kind == model::RuleTarget::Kind::Ignore)
        ignored += (ignored.empty() ? "" : ", ") + t.outcomes.at(at(r.outcome));
    if (!ignored.empty()) label += "\nignores " + ignored;
    out_ += fmt::format("  {} [shape=hexagon, style=filled, fillcolor=\"#e8eefc\", label={}];\n", id, quote(label));
    if (!watched.empty()) out_ += fmt::format("  {} -> {} [style=dotted, arrowhead=none];\n", watched, id);
    for (const auto &r : s.rules) {
      if (r.target.kind == model::RuleTarget::Kind::Ignore) continue;
      out_ += fmt::format("  {} -> {} [style=dashed, color=firebrick, fontcolor=firebrick, label={}];\n", id,
                          target(r.target), quote(t.outcomes.at(at(r.outcome))));
    }
    data_flow(id, s.args);
  }

  const model::Model &m_;
  const model::Plan &plan_;
  std::string out_;
};

}  // namespace

std::string plan_picture(const model::Model &m, const model::Plan &plan) { return PlanPicture(m, plan).draw(); }

}  // namespace gfec::dot
