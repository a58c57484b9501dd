#include "dot_text.h"

#include "chart_expr.h"
#include "code_writer.h"

#include <fmt/format.h>

namespace gfec::dot {

std::string quote(const std::string &text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string expr_text(const model::Model &m, model::ChartId chart, const model::Expr &e) {
  return in_chart_text(m, e.range) ? source_text(m, e.range) : chart_text::expr(m, chart, e);
}

/// A statement as --emit=chart writes it, its lines joined by line breaks.
std::string statement_text(const model::Model &m, model::ChartId chart, const model::Stmt &s) {
  CodeWriter w("", false);
  chart_text::statements(w, m, chart, {s});
  std::string out = w.take();
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

std::string block_text(const model::Model &m, model::ChartId chart, const std::vector<model::Stmt> &block) {
  std::string out;
  for (const auto &s : block) {
    if (!in_chart_text(m, s.range)) {
      out += (out.empty() ? "" : "\n") + statement_text(m, chart, s);
      continue;
    }
    std::string line = s.kind == model::Stmt::Kind::Verbatim ? "%{ ... %}" : source_text(m, s.range);
    // A statement's range may or may not take in its ';': show it once either way.
    // An `if` ends with its block's brace.
    if (!line.empty() && line.back() != ';' && s.kind != model::Stmt::Kind::Verbatim &&
        s.kind != model::Stmt::Kind::If && s.kind != model::Stmt::Kind::While && s.kind != model::Stmt::Kind::For)
      line += ';';
    out += (out.empty() ? "" : "\n") + line;
  }
  return out;
}

std::string preamble(const std::string &title) {
  return fmt::format("  graph [fontname=\"Helvetica\", fontsize=12, labelloc=t, label={}, nodesep=0.4, ranksep=0.35];\n"
                     "  node [fontname=\"Helvetica\", fontsize=11];\n"
                     "  edge [fontname=\"Helvetica\", fontsize=10, arrowsize=0.6];\n",
                     quote(title));
}

std::string duration(double ms) {
  if (ms >= 1000 && static_cast<long long>(ms) % 1000 == 0) return fmt::format("{}s", ms / 1000);
  return fmt::format("{}ms", ms);
}

}  // namespace gfec::dot
