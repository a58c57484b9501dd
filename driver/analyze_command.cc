#include "analyze_command.h"

#include "escape.h"
#include "analysis/analysis.h"
#include "diagnostic_report.h"
#include "driver.h"
#include "pipeline/compilation.h"

#include <fmt/format.h>

#include <algorithm>
#include <ostream>

namespace gfec {

namespace {

/// The warnings the analyses give: all on for --analyze, unless the command line turned one off.
WarningOptions analysis_warnings(const Options &o) {
  WarningOptions w = o.warnings;
  const Warning analyses[] = {
      Warning::UnreachablePlace, Warning::DeadTransition,     Warning::UnsafePlace,         Warning::UnboundedPlace,
      Warning::Deadlock,         Warning::DeadJoin,           Warning::UnjoinedFork,        Warning::AnalysisLimit,
      Warning::TrapState,        Warning::ShadowedTransition, Warning::UninitializedConfig, Warning::SupervisorRace};
  WarningOptions defaults;
  for (Warning a : analyses)
    if (w.is_on(a) || w.is_on(a) == defaults.is_on(a)) w.set(a, true);
  return w;
}

int analyze_one(const std::string &input, const Options &o, DiagnosticReport &report, std::ostream &out) {
  pipeline::FrontEndOptions f = front_end_options(o);
  f.warnings = analysis_warnings(o);
  f.analyze = false;  // analysis_report runs them all, once, and says what they found
  pipeline::Compilation c(f);
  std::string summary;
  if (c.front_end(input)) summary = analysis::analysis_report(c.model, c.diag);
  report.add(input, c.diag, c.sources);
  if (c.unreadable()) {
    report.tool_error(input, c.cannot_read_main(input), false);
    return kExitUsageOrIo;
  }
  if (c.diag.has_errors()) return kExitInputError;
  out << fmt::format("{}:\n", text::printable(input));
  if (summary.empty()) summary = "  no sfc, fsm or plan to analyse\n";
  for (std::size_t at = 0, nl; (nl = summary.find('\n', at)) != std::string::npos; at = nl + 1)
    out << "  " << summary.substr(at, nl - at + 1);
  return kExitOk;
}

}  // namespace

int analyze_command(const Options &o, std::ostream &out, std::ostream &err) {
  auto report = make_report(o, err);
  int worst = kExitOk;
  for (const auto &input : o.inputs) worst = std::max(worst, analyze_one(input, o, *report, out));
  return finish_report(*report, worst, err);
}

}  // namespace gfec
