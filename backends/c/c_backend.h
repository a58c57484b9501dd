// The C back end: an sfc or fsm chart as a GFE-style C99 engine, engine.c plus engine.h
// (docs/language.md §5.2 and §7; the engine's shape is described in docs/c-engine.md).
#pragma once

#include "backend.h"

#include <memory>

namespace gfec {

/// The back end registered as `c`.
std::unique_ptr<Backend> make_c_backend();

}  // namespace gfec
