// Action Flow Plans as DOT: actors, their result states as labelled edges, supervisors and the
// data flow between arguments and config entries.
#pragma once

#include "model.h"

#include <string>

namespace gfec::dot {

std::string plan_picture(const model::Model &m, const model::Plan &plan);

}  // namespace gfec::dot
