// What the analyses' tests share: run the analyses on a compiled chart and print what they say.
#pragma once

#include "analysis/analysis.h"
#include "interpreter_support.h"
#include "support.h"

namespace gfec::test {

/// Every warning on (or the defaults), the analyses run, the diagnostics as gfec prints them.
inline std::string analyze_text(const Compiled &c, bool all_on = true, analysis::Limits limits = {},
                                std::string *report = nullptr) {
  Diagnostics diag(all_on ? all_warnings() : WarningOptions{});
  if (report) *report = analysis::analysis_report(c.model, diag, limits);
  else analysis::analyze(c.model, diag, limits);
  std::string out;
  for (const auto &d : diag.all()) out += render_text(d, c.sources);
  return out;
}

/// Only the first line of each diagnostic and note ("file:line:col: warning: ... [-Wname]").
inline std::string headlines(const std::string &printed) {
  std::string out;
  for (std::size_t at = 0, nl; (nl = printed.find('\n', at)) != std::string::npos; at = nl + 1)
    if (printed.compare(at, 2, "t.") == 0 || printed.compare(at, 4, "bot.") == 0)
      out += printed.substr(at, nl - at + 1);
  return out;
}

}  // namespace gfec::test
