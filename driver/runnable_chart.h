// The chart a command runs or watches (gfec run, gfec monitor): the main file compiled without
// the analyses (a run reports what happens, not what they would find), its diagnostics reported,
// and its sfc or fsm chosen — the one --chart names, or the one no chart runs (docs/language.md
// "Sub-charts").
#pragma once

#include "pipeline/compilation.h"

#include <memory>
#include <string>

namespace gfec {

struct Options;
class DiagnosticReport;

struct RunnableChart {
  std::unique_ptr<pipeline::Compilation> compilation;  ///< the main file's, whatever the outcome
  model::ChartId chart;                                ///< set when exit_code is kExitOk (an sfc or fsm)
  model::PlanId plan;                                  ///< or this, when `among` allowed plans
  int exit_code = 0;                                   ///< kExitOk, or the command's exit code
};

/// `verb` completes the messages of a choice that fails ("run", "monitor"); `among`: the kinds
/// it may choose (pipeline/kind.h), sfc and fsm by default.
RunnableChart load_runnable_chart(const Options &options, const std::string &input, const std::string &chart_name,
                                  const char *verb, DiagnosticReport &report,
                                  unsigned among = pipeline::kSfc | pipeline::kFsm);

}  // namespace gfec
