// Text helpers shared by the chart and plan pictures.
#pragma once

#include "model.h"

#include <string>

namespace gfec::dot {

/// `text` as a DOT double-quoted string, quotes included. "\n" inside stays a line break.
std::string quote(const std::string &text);
using model::source_text;  ///< the chart text of a range, whitespace runs folded (model.h)
/// The text of a statement block, one statement per line.
std::string block_text(const model::Model &m, const std::vector<model::Stmt> &block);
/// The common graph, node and edge attributes, after `digraph NAME {`.
std::string preamble(const std::string &title);
/// A duration for a label: "10ms", "1.5s".
std::string duration(double ms);

}  // namespace gfec::dot
