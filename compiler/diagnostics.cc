#include "diagnostics.h"

namespace gfec {

Diagnostic &Diagnostic::note(std::string message) {
  notes.push_back({std::move(message), {}, false});
  return *this;
}

Diagnostic &Diagnostic::note(SourceRange r, std::string message) {
  notes.push_back({std::move(message), r, true});
  return *this;
}

Diagnostic &Diagnostic::fix(SourceRange r, std::string_view replacement) {
  fixits.push_back({r, std::string(replacement)});
  return *this;
}

WarningOptions::WarningOptions() {
  for (int i = 0; i < static_cast<int>(Warning::Count_); ++i)
    enabled[i] = kind_info(static_cast<Warning>(i)).on_by_default;
}

Diagnostics::Diagnostics(WarningOptions warnings, std::size_t error_limit)
    : options_(warnings), error_limit_(error_limit) {}

Diagnostic &Diagnostics::error(SourceRange range, ErrorKind kind, std::string message) {
  return add_error(range, kind_info(kind), std::move(message));
}

Diagnostic &Diagnostics::add_error(SourceRange range, const DiagnosticKind &kind, std::string message) {
  if (errors_ >= error_limit_) {
    // Past the cap, later errors are most likely consequences of earlier ones.
    limit_reached_ = true;
    discarded_ = {};
    discarded_.dropped = true;
    return discarded_;
  }
  ++errors_;
  list_.push_back({Severity::Error, range, std::move(message), &kind, {}, {}});
  return list_.back();
}

Diagnostic &Diagnostics::warning(Warning w, SourceRange range, std::string message) {
  const DiagnosticKind &kind = kind_info(w);
  if (!options_.is_on(w)) {
    discarded_ = {};
    discarded_.dropped = true;
    return discarded_;
  }
  if (options_.is_error(w)) return add_error(range, kind, std::move(message));
  ++warnings_;
  list_.push_back({Severity::Warning, range, std::move(message), &kind, {}, {}});
  return list_.back();
}

}  // namespace gfec
