// The diagnostics sink: every stage reports here; only the driver prints and picks the exit code.
#pragma once

#include "diagnostic_kinds.h"
#include "source.h"

#include <array>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

namespace gfec {

enum class Severity { Note, Warning, Error };

struct DiagnosticNote {
  std::string message;
  SourceRange range;
  bool has_range = false;
};

/// A fix-it hint: replace `range` (empty: insert at its start) with `replacement`. Printed under
/// the caret as gcc does, as gcc's "fix-it:" lines (-fdiagnostics-parseable-fixits), in JSON
/// ("fixits") and in SARIF ("fixes").
struct FixIt {
  SourceRange range;
  std::string replacement;
};

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceRange range;
  std::string message;
  /// Its row of compiler/diagnostic_kinds.def (a warning's row even when -Werror made it an
  /// error); null only in a Diagnostic made by hand.
  const DiagnosticKind *kind = nullptr;
  std::vector<DiagnosticNote> notes;
  std::vector<FixIt> fixits;
  /// Past the error limit, or a warning that is off: it is never printed, so work spent on its
  /// notes (a did-you-mean search) is wasted.
  bool dropped = false;

  Diagnostic &note(std::string message);
  Diagnostic &note(SourceRange range, std::string message);
  Diagnostic &fix(SourceRange range, std::string_view replacement);

  /// The stable check name: "unknown-name", "syntax", ...; for a warning "-Wname".
  std::string check() const { return kind ? kind->check() : std::string(); }
  /// A warning, whatever its severity now (-Werror may have made it an error).
  bool from_warning() const { return kind && kind->warning; }
};

/// Which warnings are on, and whether they count as errors (-W, -Wno-, -Werror, -Wall,
/// -Werror=NAME, -Wno-error=NAME).
struct WarningOptions {
  std::array<bool, static_cast<int>(Warning::Count_)> enabled{};
  bool as_errors = false;
  /// Per warning, as gcc: +1 after -Werror=NAME (an error even without -Werror), -1 after
  /// -Wno-error=NAME (a warning even with -Werror), 0: as -Werror says.
  std::array<signed char, static_cast<int>(Warning::Count_)> error_override{};

  WarningOptions();
  bool is_on(Warning w) const { return enabled[static_cast<int>(w)]; }
  void set(Warning w, bool on) { enabled[static_cast<int>(w)] = on; }
  bool is_error(Warning w) const {
    signed char o = error_override[static_cast<int>(w)];
    return o != 0 ? o > 0 : as_errors;
  }
};

class Diagnostics {
public:
  explicit Diagnostics(WarningOptions warnings = {}, std::size_t error_limit = 50);

  /// Reports an error of the kind given; the returned reference takes notes.
  Diagnostic &error(SourceRange range, ErrorKind kind, std::string message);
  /// Reports a warning if it is on (as an error under -Werror); returns a sink for notes either way.
  Diagnostic &warning(Warning w, SourceRange range, std::string message);

  bool has_errors() const { return errors_ > 0; }
  std::size_t error_count() const { return errors_; }
  std::size_t warning_count() const { return warnings_; }
  /// True once the error limit was hit: later errors were dropped.
  bool limit_reached() const { return limit_reached_; }
  const std::deque<Diagnostic> &all() const { return list_; }
  /// For a front end that adds notes once the validator has reported (compiler/alica/).
  std::deque<Diagnostic> &all() { return list_; }
  const WarningOptions &warning_options() const { return options_; }

private:
  Diagnostic &add_error(SourceRange range, const DiagnosticKind &kind, std::string message);

  WarningOptions options_;
  std::size_t error_limit_;
  std::deque<Diagnostic> list_;  // a deque: references handed out stay valid
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
  bool limit_reached_ = false;
  Diagnostic discarded_;
};

}  // namespace gfec
