#include "dot_chart.h"

#include "chart_nodes.h"
#include "dot_text.h"
#include "xml_text.h"

#include <fmt/format.h>

#include <ostream>
#include <vector>

namespace gfec::dot {

namespace {

/// A place or state: a box (Grafcet's step, ALICA's state) with its actions under the name.
/// Initial ones are double-bordered as in Grafcet; terminal fsm states are filled, green for
/// success and red for failure, and say which they are.
std::string place_node(const model::Model &m, const model::Chart &c, std::size_t i, const std::string &id) {
  const model::Place &p = c.places[i];
  std::string label = p.name.str();
  // Grafcet's enclosing step: the chart it runs is drawn beside it, in a frame (below).
  if (p.runs) label += "\nruns " + m.charts.at(p.runs).name;
  std::string attrs = "shape=box";
  if (p.initial) attrs += ", peripheries=2";
  if (p.terminal != model::Terminal::None) {
    bool ok = p.terminal == model::Terminal::Success;
    label += ok ? "\n(success)" : "\n(failure)";
    if (p.post) label += "\npost " + expr_text(m, m.charts.id_of(c), *p.post);
    attrs += fmt::format(", style=\"filled,bold,rounded\", fillcolor=\"{}\"", ok ? "#d5f5d5" : "#f8d4d4");
  }
  model::ChartId chart = m.charts.id_of(c);
  // Each block under its own heading, in the order they run for a place entered and left: a
  // block's further statements follow on their own lines, up to the next heading.
  std::string actions;
  auto section = [&](const char *heading, const std::vector<model::Stmt> &block) {
    std::string text = block_text(m, chart, block);
    if (!text.empty()) actions += (actions.empty() ? "" : "\n") + std::string(heading) + text;
  };
  if (p.entry) section("entry: ", *p.entry);
  section("every tick: ", p.action);
  if (p.exit) section("exit: ", *p.exit);
  if (!actions.empty()) label += "\n" + std::string(12, '-') + "\n" + actions;
  return fmt::format("  {} [{}, label={}];\n", chart_nodes::place(id, i), attrs, quote(label));
}

/// A transition: Grafcet's bar with its label to its right. The label is a cell of the node's
/// own table rather than an `xlabel`: Graphviz places xlabels after the layout, where they may
/// overlap each other and the edges (two transitions on one rank: "T1: ... >= 2sT2: ..."), while a
/// node's size is part of the layout, which keeps nodes apart. Edges meet the bar at its `bar`
/// port, top and bottom.
std::string transition_node(const std::string &id, const std::string &label) {
  return fmt::format("  {} [shape=plain, label=<<TABLE BORDER=\"0\" CELLBORDER=\"0\" CELLSPACING=\"0\" "
                     "CELLPADDING=\"0\"><TR><TD PORT=\"bar\" BGCOLOR=\"black\" WIDTH=\"36\" HEIGHT=\"4\" "
                     "FIXEDSIZE=\"TRUE\"></TD><TD ALIGN=\"LEFT\" CELLPADDING=\"3\">{}</TD></TR></TABLE>>];\n",
                     id, text::xml_escape(label));
}

/// Grafcet's double line where a transition forks into several places or several places join
/// into one transition: a thin double-bordered bar.
std::string sync_bar(const std::string &id, std::size_t width) {
  return fmt::format("  {} [shape=box, label=\"\", peripheries=2, height=0.02, width={:.1f}, fixedsize=true];\n", id,
                     0.6 + 0.6 * static_cast<double>(width));
}

/// The places and transitions of `c`, every node id prefixed with `id` (empty for the compiled
/// chart); then, for each place that runs a chart, that instance in a dashed frame named after
/// the place, linked to it by a dashed line, as Grafcet draws an enclosing step's chart. Written
/// to `out`: an instance's text returned and copied into its parent's would be copied once per
/// level it is nested.
void chart_body(const model::Model &m, const model::Chart &c, const std::string &id, std::ostream &out) {
  bool fsm = c.kind == model::Chart::Kind::Fsm;
  out << "  // places and states, in declaration order\n";
  for (std::size_t i = 0; i < c.places.size(); ++i) out << place_node(m, c, i, id);

  out << "  // transitions: a bar each, its label beside it inside the same node (see transition_node)\n";
  // An fsm's transitions counted so far by the state they leave: the rank of the next one.
  std::vector<int> leaving(fsm ? c.places.size() : 0, 0);
  for (std::size_t i = 0; i < c.transitions.size(); ++i) {
    const model::Transition &t = c.transitions[i];
    std::string label =
        fmt::format("{}: {}", t.name, t.condition ? expr_text(m, m.charts.id_of(c), *t.condition) : "true");
    // An fsm tries the transitions leaving its state in declaration order and takes the first
    // whose condition holds: the picture numbers them so, 1 first, per state.
    if (fsm && !t.inputs.empty()) label = fmt::format("{}. {}", ++leaving.at(t.inputs[0].index()), label);
    std::string bar = chart_nodes::transition(id, i);
    out << transition_node(bar, label);
    std::string into = bar + ":bar", from = bar + ":bar";
    if (t.inputs.size() > 1) {
      into = chart_nodes::join(id, i);
      out << sync_bar(into, t.inputs.size());
      out << fmt::format("  {} -> {}:bar [arrowhead=none];\n", into, bar);
    }
    if (t.outputs.size() > 1) {
      from = chart_nodes::fork(id, i);
      out << sync_bar(from, t.outputs.size());
      out << fmt::format("  {}:bar -> {} [arrowhead=none];\n", bar, from);
    }
    for (model::PlaceId p : t.inputs)
      out << fmt::format("  {} -> {} [arrowhead=none];\n", chart_nodes::place(id, p.index()), into);
    for (model::PlaceId p : t.outputs) out << fmt::format("  {} -> {};\n", from, chart_nodes::place(id, p.index()));
  }
  for (std::size_t i = 0; i < c.places.size(); ++i) {
    const model::Place &p = c.places[i];
    if (!p.runs) continue;
    const model::Chart &sub = m.charts.at(p.runs);
    std::string inner = chart_nodes::instance_prefix(id, i), frame = chart_nodes::instance_frame(id, i);
    out << fmt::format("  subgraph {} {{\n", frame);
    out << fmt::format(
        "  graph [label={}, style=\"dashed,rounded\", labeljust=l];\n",
        quote(fmt::format("{}: {} {}", p.name, sub.kind == model::Chart::Kind::Fsm ? "fsm" : "sfc", sub.name)));
    chart_body(m, sub, inner, out);
    out << "  }\n";
    // To the sub-chart's first place, clipped at the frame: the line reads "this step encloses that".
    if (!sub.places.empty())
      out << fmt::format("  {} -> {} [style=dashed, arrowhead=none, lhead={}];\n", chart_nodes::place(id, i),
                         chart_nodes::place(inner, 0), frame);
  }
}

/// A var's value without an initialiser (docs/language.md: zero).
std::string type_zero(model::Type t) {
  switch (t) {
  case model::Type::Bool: return "false";
  case model::Type::Float:
  case model::Type::Double: return "0.0";
  default: return "0";
  }
}

/// The chart's vars, a note beside the places (as the plan picture's config entries are): name,
/// type and initial value, one a line, in declaration order. A sub-chart's vars are its own
/// and are not listed: the note is the compiled chart's state besides its activation.
void vars_note(const model::Model &m, const model::Chart &c, std::ostream &out) {
  if (c.vars.empty()) return;
  std::string text = "vars";
  for (const model::Var &v : c.vars) {
    std::string init = v.init ? expr_text(m, m.charts.id_of(c), *v.init) : type_zero(v.type);
    text += fmt::format("\n{} {} = {}", type_name(v.type), v.name, init);
  }
  out << "  // the chart's vars with their initial values\n";
  out << fmt::format("  {} [shape=note, style=filled, fillcolor=\"#f4f4f4\", fontsize=10, label={}];\n",
                     chart_nodes::vars(), quote(text));
}

}  // namespace

void chart_picture(const model::Model &m, const model::Chart &c, std::ostream &out) {
  bool fsm = c.kind == model::Chart::Kind::Fsm;
  std::string title = fmt::format("{} {}", fsm ? "fsm" : "sfc", c.name);
  std::string details;
  if (c.period_ms > 0) details = fmt::format("period {}", duration(c.period_ms));
  if (c.team > 0) details += fmt::format("{}team of {} agents", details.empty() ? "" : ", ", c.team);
  if (!details.empty()) title += " (" + details + ")";
  out << fmt::format("digraph {} {{\n", quote(c.name));
  out << preamble(title);
  bool nested = false;
  for (const auto &p : c.places) nested = nested || p.runs;
  if (nested) out << "  compound=true;\n";  // edges may end at a sub-chart's frame
  chart_body(m, c, "", out);
  vars_note(m, c, out);
  out << "}\n";
}

}  // namespace gfec::dot
