#include "dot_chart.h"

#include "dot_text.h"

#include <fmt/format.h>

namespace gfec::dot {

namespace {

/// A place or state: a box (Grafcet's step, ALICA's state) with its actions under the name.
/// Initial ones are double-bordered as in Grafcet; terminal fsm states are filled, green for
/// success and red for failure, and say which they are.
std::string place_node(const model::Model &m, const model::Chart &c, std::size_t i) {
  const model::Place &p = c.places[i];
  std::string label = p.name;
  std::string attrs = "shape=box";
  if (p.initial) attrs += ", peripheries=2";
  if (p.terminal != model::Terminal::None) {
    bool ok = p.terminal == model::Terminal::Success;
    label += ok ? "\n(success)" : "\n(failure)";
    if (p.post) label += "\npost " + source_text(m, p.post->range);
    attrs += fmt::format(", style=\"filled,bold,rounded\", fillcolor=\"{}\"", ok ? "#d5f5d5" : "#f8d4d4");
  }
  std::string actions = block_text(m, p.action);
  if (p.entry) actions = "entry: " + block_text(m, *p.entry) + (actions.empty() ? "" : "\n" + actions);
  if (p.exit) actions += (actions.empty() ? "" : "\n") + std::string("exit: ") + block_text(m, *p.exit);
  if (!actions.empty()) label += "\n" + std::string(12, '-') + "\n" + actions;
  return fmt::format("  p{} [{}, label={}];\n", i, attrs, quote(label));
}

/// Grafcet's double line where a transition forks into several places or several places join
/// into one transition: a thin double-bordered bar.
std::string sync_bar(const std::string &id, std::size_t width) {
  return fmt::format("  {} [shape=box, label=\"\", peripheries=2, height=0.02, width={:.1f}, fixedsize=true];\n", id,
                     0.6 + 0.6 * static_cast<double>(width));
}

} // namespace

std::string chart_picture(const model::Model &m, const model::Chart &c) {
  bool fsm = c.kind == model::Chart::Kind::Fsm;
  std::string title = fmt::format("{} {}", fsm ? "fsm" : "sfc", c.name);
  std::string details;
  if (c.period_ms > 0) details = fmt::format("period {}", duration(c.period_ms));
  if (c.team > 0) details += fmt::format("{}team of {} agents", details.empty() ? "" : ", ", c.team);
  if (!details.empty()) title += " (" + details + ")";
  std::string out = fmt::format("digraph {} {{\n", quote(c.name));
  out += preamble(title);
  out += "  // places and states, in declaration order\n";
  for (std::size_t i = 0; i < c.places.size(); ++i) out += place_node(m, c, i);

  out += "  // transitions: a bar each, labelled with its name and condition\n";
  for (std::size_t i = 0; i < c.transitions.size(); ++i) {
    const model::Transition &t = c.transitions[i];
    std::string cond = t.condition ? source_text(m, t.condition->range) : "true";
    std::string label = t.named || !fsm ? fmt::format("{}: {}", t.name, cond) : cond;
    out += fmt::format("  t{} [shape=box, style=filled, fillcolor=black, label=\"\", height=0.05, width=0.5, "
                       "fixedsize=true, xlabel={}];\n",
                       i, quote(label));
    std::string into = fmt::format("t{}", i), from = into;
    if (t.inputs.size() > 1) {
      into = fmt::format("join{}", i);
      out += sync_bar(into, t.inputs.size());
      out += fmt::format("  {} -> t{} [arrowhead=none];\n", into, i);
    }
    if (t.outputs.size() > 1) {
      from = fmt::format("fork{}", i);
      out += sync_bar(from, t.outputs.size());
      out += fmt::format("  t{} -> {} [arrowhead=none];\n", i, from);
    }
    for (int p : t.inputs) out += fmt::format("  p{} -> {} [arrowhead=none];\n", p, into);
    for (int p : t.outputs) out += fmt::format("  {} -> p{};\n", from, p);
  }
  out += "}\n";
  return out;
}

} // namespace gfec::dot
