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

Diagnostic &Diagnostic::fix(SourceRange r, std::string replacement) {
  fixits.push_back({r, std::move(replacement)});
  return *this;
}

WarningOptions::WarningOptions() {
  for (int i = 0; i < static_cast<int>(Warning::Count_); ++i)
    enabled[i] = warning_table()[i].on_by_default;
}

Diagnostics::Diagnostics(WarningOptions warnings, std::size_t error_limit)
    : options_(warnings), error_limit_(error_limit) {}

Diagnostic &Diagnostics::error(SourceRange range, std::string check, std::string message) {
  if (errors_ >= error_limit_) {
    // Past the cap, later errors are most likely consequences of earlier ones.
    limit_reached_ = true;
    discarded_ = {};
    return discarded_;
  }
  ++errors_;
  list_.push_back({Severity::Error, range, std::move(message), std::move(check), {}, {}});
  return list_.back();
}

Diagnostic &Diagnostics::warning(Warning w, SourceRange range, std::string message) {
  std::string name(warning_info(w).name);
  if (!options_.is_on(w)) {
    discarded_ = {};
    return discarded_;
  }
  if (options_.is_error(w)) return error(range, "-W" + name, std::move(message));
  ++warnings_;
  list_.push_back({Severity::Warning, range, std::move(message), "-W" + name, {}, {}});
  return list_.back();
}

} // namespace gfec
