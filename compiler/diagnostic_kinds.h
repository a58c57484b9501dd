// The table of diagnostic kinds (compiler/diagnostic_kinds.def), as C++: one enum of the errors,
// one of the warnings, and the rows with their names and texts. Every error and warning names
// its kind by enumerator, so a misspelt kind does not compile and no name is spelled two ways.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace gfec {

/// Every error gfec can report.
enum class ErrorKind : unsigned char {
#define GFEC_ERROR(id, name, summary, help) id,
#define GFEC_WARNING(id, name, on, summary, help)
#include "diagnostic_kinds.def"
#undef GFEC_ERROR
#undef GFEC_WARNING
  Count_
};

/// Every warning gfec can give (-Wname, -Wno-name); unlike errors, they can be turned off.
enum class Warning : unsigned char {
#define GFEC_ERROR(id, name, summary, help)
#define GFEC_WARNING(id, name, on, summary, help) id,
#include "diagnostic_kinds.def"
#undef GFEC_ERROR
#undef GFEC_WARNING
  Count_
};

/// One row of the table.
struct DiagnosticKind {
  std::string_view name;     ///< stable: "[name]" after an error, "-Wname" for a warning
  bool warning;              ///< a warning (its default severity), else an error
  bool on_by_default;        ///< for a warning: given without -Wname; errors are always on
  std::string_view summary;  ///< one line: what it is about (SARIF shortDescription, --help)
  std::string_view help;     ///< what to do about it (SARIF help)

  /// The name tools see: "name" for an error, "-Wname" for a warning (JSON "check", SARIF ruleId).
  std::string check() const;
};

/// The whole table: the errors, then the warnings, each in the .def's order.
const DiagnosticKind *diagnostic_kinds();
std::size_t diagnostic_kind_count();

const DiagnosticKind &kind_info(ErrorKind e);
const DiagnosticKind &kind_info(Warning w);
std::optional<Warning> find_warning(std::string_view name);
/// Any row by name (a warning's without "-W"); nullptr if none.
const DiagnosticKind *find_kind(std::string_view name);

}  // namespace gfec
