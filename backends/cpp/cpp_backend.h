// The C++ back ends of Action Flow Plans (docs/language.md §8): the wiring of a plan (`cpp`: plan.cpp
// and plan.hpp, docs/plans.md) and the skeleton of a toolbox's C++ classes (`toolbox-skeleton`:
// the header the wiring includes and a source file to fill in, docs/toolbox.md).
#pragma once

#include "backend.h"

#include <memory>

namespace gfec {

/// The back end registered as `cpp`.
std::unique_ptr<Backend> make_cpp_backend();

/// The back end registered as `toolbox-skeleton`.
std::unique_ptr<Backend> make_toolbox_skeleton_backend();

}  // namespace gfec
