// sfc and fsm charts as DOT: places/states as boxes, transitions as bars between them.
#pragma once

#include "model.h"

#include <ostream>

namespace gfec::dot {

/// Writes `chart` as a DOT digraph to `out`, streamed: a chart of a million places is never
/// held as text in memory whole.
void chart_picture(const model::Model &m, const model::Chart &chart, std::ostream &out);

}  // namespace gfec::dot
