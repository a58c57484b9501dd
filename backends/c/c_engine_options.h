// The C engine's own options (docs/c-engine.md): what the back end reads through
// EmitOptions::backend, and the option group its registry row declares on the command line.
#pragma once

#include "backend.h"
#include "backend_option_group.h"

#include <cstdint>
#include <memory>
#include <string>

namespace gfec::c_backend {

struct CEngineOptions : BackendOptions {
  /// `--context[-type]`: the C type of the instance context every interface call receives
  /// first (docs/c-engine.md "Instance context"); empty: no context, GFE's calls.
  std::string context_type;
  bool names = false;  ///< `--names`: X_place_name and X_transition_name
  /// `--trace`: each tick ends with a frame through X_trace_write (docs/live.md).
  bool trace = false;
  /// `--trace-full-every N`: a full frame at least every N ticks (the others carry changes).
  unsigned trace_full_every = 32;
};

/// --context, --context-type, --names, --trace and --trace-full-every (c_engine_option_group.cc).
std::unique_ptr<BackendOptionGroup> make_c_engine_option_group();

}  // namespace gfec::c_backend
