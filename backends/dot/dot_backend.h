// Pictures: a chart or plan as Graphviz DOT in the pictures Grafcet, ALICA and Action Flow Plans use (Grafcet steps and
// transition bars, ALICA states, Action Flow Plan actors and supervisors), and as SVG rendered
// by Graphviz. docs/cli.md shows what each shape means.
#pragma once

#include "backend.h"

#include <memory>

namespace gfec {

/// The back end registered as `dot`.
std::unique_ptr<Backend> make_dot_backend();
/// The back end registered as `svg`: needs Graphviz's `dot` on PATH, else emit() throws
/// std::runtime_error with a message saying so.
std::unique_ptr<Backend> make_svg_backend();

/// Writes the DOT text for the chart or plan `options` selects to `out`.
void dot_picture(const model::Model &model, const EmitOptions &options, std::ostream &out);

}  // namespace gfec
