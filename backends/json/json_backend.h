// The JSON back end: the validated model of one chart or plan as a JSON document, for tools
// (the simulator, visualisers, test generators). docs/model-json.md describes every field.
#pragma once

#include "backend.h"

#include <memory>

namespace gfec {

/// The back end registered as `json`.
std::unique_ptr<Backend> make_json_backend();

}  // namespace gfec
