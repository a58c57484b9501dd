#include "analyze_command.h"

#include "analysis/analysis.h"
#include "diagnostic_report.h"
#include "driver.h"
#include "loader.h"
#include "validate.h"

#include <fmt/format.h>

#include <algorithm>
#include <ostream>

namespace gfec {

namespace {

/// The warnings the analyses give: all on for --analyze, unless the command line turned one off.
WarningOptions analysis_warnings(const Options &o) {
  WarningOptions w = o.warnings;
  const Warning analyses[] = {Warning::UnreachablePlace, Warning::DeadTransition, Warning::UnsafePlace,
                              Warning::UnboundedPlace,   Warning::Deadlock,       Warning::DeadJoin,
                              Warning::UnjoinedFork,     Warning::AnalysisLimit,  Warning::TrapState,
                              Warning::ShadowedTransition, Warning::UninitializedConfig, Warning::SupervisorRace};
  WarningOptions defaults;
  for (Warning a : analyses)
    if (w.is_on(a) || w.is_on(a) == defaults.is_on(a)) w.set(a, true);
  return w;
}

int analyze_one(const std::string &input, const Options &o, DiagnosticReport &report, std::ostream &out) {
  SourceManager sources;
  Diagnostics diag(analysis_warnings(o), o.error_limit);
  RealFileSystem fs;
  LoadResult loaded = load_program(input, {o.include_dirs}, fs, sources, diag);
  model::Model model;
  std::string summary;
  if (!loaded.main_unreadable && !diag.has_errors()) {
    model = validate(loaded.program, sources, diag);
    if (!diag.has_errors()) summary = analysis::analysis_report(model, diag);
  }
  report.add(input, diag, sources);
  if (loaded.main_unreadable) {
    report.tool_error(input, fmt::format("cannot read '{}'", input), false);
    return kExitUsageOrIo;
  }
  if (diag.has_errors()) return kExitInputError;
  out << fmt::format("{}:\n", input);
  if (summary.empty()) summary = "  no sfc, fsm or plan to analyse\n";
  for (std::size_t at = 0, nl; (nl = summary.find('\n', at)) != std::string::npos; at = nl + 1)
    out << "  " << summary.substr(at, nl - at + 1);
  return kExitOk;
}

} // namespace

int analyze_command(const Options &o, std::ostream &out, std::ostream &err) {
  auto report = make_report(o, err);
  int worst = kExitOk;
  for (const auto &input : o.inputs) worst = std::max(worst, analyze_one(input, o, *report, out));
  std::string failure = report->finish(worst);
  if (!failure.empty()) {
    err << "gfec: error: " << failure << "\n";
    return kExitUsageOrIo;
  }
  return worst;
}

} // namespace gfec
