// The chart back end: writes an sfc or fsm of the model, with every chart it runs and the
// interface functions they call, back as gfec source text. Compiling that text gives the same
// engine; its use is converting ALICA plans (docs/alica.md) for teams who move to chart text.
#pragma once

#include "backend.h"

#include <memory>

namespace gfec {

/// The back end registered as `chart`.
std::unique_ptr<Backend> make_chart_backend();

}  // namespace gfec
