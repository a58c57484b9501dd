#include "code_actions.h"

#include <string>

namespace gfec::lsp {

namespace {

std::string in_quotes(std::string_view s) {
  constexpr std::size_t kShown = 40;  // a title is one line of a menu
  std::string out(s.substr(0, kShown));
  if (s.size() > kShown) out += "...";
  return "'" + out + "'";
}

/// "Replace 'x' with 'y'", "Insert ';'", "Remove 'z'": what the edit does, read in a menu.
std::string title(const SourceManager &sources, const FixIt &f) {
  std::string_view was =
      std::string_view(sources.file(f.range.file).text()).substr(f.range.begin, f.range.end - f.range.begin);
  if (was.empty()) return "Insert " + in_quotes(f.replacement);
  if (f.replacement.empty()) return "Remove " + in_quotes(was);
  return "Replace " + in_quotes(was) + " with " + in_quotes(f.replacement);
}

}  // namespace

nlohmann::json code_actions(const Diagnostics &diags, const SourceManager &sources, FileId file, std::uint32_t begin,
                            std::uint32_t end, const std::string &uri) {
  SourceRanges ranges(sources);
  nlohmann::json out = nlohmann::json::array();
  for (const Diagnostic &d : diags.all()) {
    if (d.dropped || d.fixits.empty() || d.range.file != file) continue;
    if (d.range.end < begin || d.range.begin > end) continue;
    nlohmann::json edits = nlohmann::json::array();
    bool one_file = true;
    for (const FixIt &f : d.fixits) {
      if (f.range.file != file) one_file = false;
      edits.push_back({{"range", ranges.range(f.range)}, {"newText", f.replacement}});
    }
    if (!one_file) continue;  // no fix-it edits another file today; never apply half of one
    std::string name = d.fixits.size() == 1 ? title(sources, d.fixits[0]) : "Apply the fix-its";
    nlohmann::json diagnostic = {{"range", ranges.range(d.range)},
                                 {"message", d.message},
                                 {"severity", d.severity == Severity::Error     ? 1
                                              : d.severity == Severity::Warning ? 2
                                                                                : 3},
                                 {"source", "gfec"}};
    if (!d.check().empty()) diagnostic["code"] = d.check();
    out.push_back({{"title", name},
                   {"kind", "quickfix"},
                   {"isPreferred", true},
                   {"diagnostics", nlohmann::json::array({diagnostic})},
                   {"edit", {{"changes", {{uri, edits}}}}}});
  }
  return out;
}

}  // namespace gfec::lsp
