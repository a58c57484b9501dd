// What Harness::prepare keeps of a case for the builds: the compiled chart, the interpreter's
// logs, the engine's files, and what a target's program needs to write its harness.
#pragma once

#include "backend.h"
#include "interpreter/input_trace.h"
#include "pipeline/compilation.h"

#include <memory>
#include <string>
#include <vector>

namespace gfec::diff {

struct Prepared {
  pipeline::Compilation c{options()};
  SourceManager &sources = c.sources;
  Diagnostics &diag = c.diag;
  model::Model &model = c.model;
  std::string expected_plain, expected_hooks;
  std::vector<OutputFile> engine;
  std::vector<std::string> places, transitions;
  std::unique_ptr<interp::InputTrace> inputs;  ///< the trace, as the interpreter read it
  model::ChartId root;                         ///< the chart compiled
  EmitOptions emit;                            ///< how its engine was written

  static pipeline::FrontEndOptions options() {
    pipeline::FrontEndOptions f;
    f.analyze = false;  // the case is judged by its runs, not by the analyses
    return f;
  }
};

}  // namespace gfec::diff
