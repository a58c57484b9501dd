// Text helpers shared by the chart and plan pictures.
#pragma once

#include "model.h"

#include <string>

namespace gfec::dot {

/// `text` as a DOT double-quoted string, quotes included. "\n" inside stays a line break.
std::string quote(const std::string &text);
/// The chart text of `range` with whitespace runs folded to one space ("" if unknown).
std::string source_text(const model::Model &m, const SourceRange &range);
/// The text of a statement block, one statement per line.
std::string block_text(const model::Model &m, const std::vector<model::Stmt> &block);
/// The common graph, node and edge attributes, after `digraph NAME {`.
std::string preamble(const std::string &title);
/// A duration for a label: "10ms", "1.5s".
std::string duration(double ms);

} // namespace gfec::dot
