// sfc and fsm charts as DOT: places/states as boxes, transitions as bars between them.
#pragma once

#include "model.h"

#include <string>

namespace gfec::dot {

std::string chart_picture(const model::Model &m, const model::Chart &chart);

}  // namespace gfec::dot
