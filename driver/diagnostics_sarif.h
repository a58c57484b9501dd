// SARIF 2.1.0 diagnostics (-fdiagnostics-format=sarif-stderr|sarif-file), the format GitHub
// code scanning and other CI dashboards read. One log has one run of gfec; every row of the
// table of diagnostic kinds (compiler/diagnostic_kinds.def) is a rule, every diagnostic a
// result with its rule, level, message and region; notes become related locations.
#pragma once

#include "diagnostic_report.h"

#include <map>
#include <nlohmann/json.hpp>
#include <vector>

namespace gfec {

class SarifLog {
public:
  SarifLog();
  /// The diagnostics of one input; every file it read is listed as an artifact, the input
  /// itself (the first file) as an analysis target.
  void add(const Diagnostics &diag, const SourceManager &sources);
  /// A message about the run (e.g. "cannot read 'x.sfc'"), not a result about a chart.
  void notification(const std::string &level, const std::string &input, const std::string &message);
  /// The whole log. `cwd` is the folder relative paths are relative to (%SRCROOT%).
  nlohmann::ordered_json to_json(int exit_code, const std::string &cwd) const;

private:
  int rule_index(const Diagnostic &d);
  int artifact_index(const std::string &path);
  nlohmann::ordered_json physical_location(const SourceManager &sources, const SourceRange &range);
  /// SARIF "fixes": the diagnostic's fix-its as replacements of regions.
  nlohmann::ordered_json fixes(const SourceManager &sources, const Diagnostic &d);

  nlohmann::ordered_json rules_ = nlohmann::ordered_json::array();
  int unnamed_rule_ = -1;  ///< the rule of a diagnostic without a kind (made by hand), once needed
  std::vector<std::string> artifacts_;
  std::vector<bool> analysis_targets_;  ///< per artifact: an input gfec was asked to check
  std::map<std::string, int> artifact_ids_;
  nlohmann::ordered_json results_ = nlohmann::ordered_json::array();
  nlohmann::ordered_json notifications_ = nlohmann::ordered_json::array();
};

/// A file path as a SARIF artifact location: a relative URI reference (percent-encoded) based
/// on %SRCROOT%, or a file:// URI for an absolute path.
nlohmann::ordered_json artifact_location(const std::string &path);

/// `err` null: sarif-file, one "<input basename>.sarif" per input in the current folder, as gcc.
std::unique_ptr<DiagnosticReport> make_sarif_report(std::ostream *err);

}  // namespace gfec
