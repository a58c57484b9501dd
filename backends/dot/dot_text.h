// Text helpers shared by the chart and plan pictures.
#pragma once

#include "model.h"

#include <string>

namespace gfec::dot {

/// `text` as a DOT double-quoted string, quotes included. "\n" inside stays a line break.
std::string quote(const std::string &text);
using model::in_chart_text;  ///< labels show chart text as written, an ALICA plan's as --emit=chart does
using model::source_text;    ///< the chart text of a range, whitespace runs folded (model.h)
/// An expression of chart `chart` for a label: as written in chart text, else (ALICA) as
/// --emit=chart spells it (`FromPickUpToMove()`).
std::string expr_text(const model::Model &m, model::ChartId chart, const model::Expr &e);
/// The text of a statement block of chart `chart`, one statement per line.
std::string block_text(const model::Model &m, model::ChartId chart, const std::vector<model::Stmt> &block);
/// The common graph, node and edge attributes, after `digraph NAME {`.
std::string preamble(const std::string &title);
/// A duration for a label: "10ms", "1.5s".
std::string duration(double ms);

}  // namespace gfec::dot
