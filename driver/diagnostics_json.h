// -fdiagnostics-format=json: gcc's JSON diagnostics (gcc 10-13), one array for the whole run.
#pragma once

#include "diagnostic_report.h"

#include <nlohmann/json.hpp>

namespace gfec {

/// One diagnostic as gcc writes it: kind, message, locations (caret and finish), children
/// (the notes), option ("-W<name>" for warnings); plus gfec's stable "check" name.
nlohmann::ordered_json diagnostic_to_json(const Diagnostic &d, const SourceManager &sources);

std::unique_ptr<DiagnosticReport> make_json_report(std::ostream &err);

}  // namespace gfec
