// The C test driver that differential testing links with a batch of generated engines: it
// implements every interface function from the case's trace (logging the call as the
// interpreter does), runs each engine tick by tick and prints the observable log lines
// (compiler/interpreter/event_log.h), plus the hooks' lines when built with -DX_HOOKS.
#pragma once

#include "random_chart.h"

#include <string>
#include <vector>

namespace gfec::diff {

struct DriverCase {
  int id = 0;
  const GChart *chart = nullptr;
  const GTrace *trace = nullptr;
  std::string header;                    ///< the engine's header file name
  std::vector<std::string> places;       ///< names by model index
  std::vector<std::string> transitions;  ///< names by model index
};

/// driver.c for the batch; each case prints `case <id>` before its log.
std::string driver_source(const std::vector<DriverCase> &cases);

}  // namespace gfec::diff
