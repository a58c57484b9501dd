// The concrete back ends by name: the one place that knows them all.
#pragma once

#include "backend.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace gfec {

/// The back end called `name`, or null.
std::unique_ptr<Backend> make_backend(std::string_view name);
std::vector<std::string> backend_names();

} // namespace gfec
