#include "diagnostics_json.h"

#include "diagnostic_printer.h"

#include <fmt/format.h>

#include <ostream>

namespace gfec {

namespace {

using Json = nlohmann::ordered_json;

Json position(const SourceManager &sources, const SourceRange &range, std::uint32_t offset) {
  const SourceFile &file = sources.file(range.file);
  Columns c = columns_at(file, offset);
  return {{"file", file.path()},
          {"line", c.line},
          {"display-column", c.display},
          {"byte-column", c.byte},
          {"column", c.display}};
}

/// gcc's location: "caret" at the start, "finish" on the last character (inclusive, unlike
/// our half-open ranges); a one-character range has no "finish", as in gcc.
Json location(const SourceManager &sources, const SourceRange &range) {
  Json loc = {{"caret", position(sources, range, range.begin)}};
  if (range.end > range.begin + 1) loc["finish"] = position(sources, range, range.end - 1);
  return loc;
}

class JsonReport : public DiagnosticReport {
public:
  explicit JsonReport(std::ostream &err) : err_(err) {}

  void add(const std::string &, const Diagnostics &diag, const SourceManager &sources) override {
    for (const Diagnostic *d : in_source_order(diag)) all_.push_back(diagnostic_to_json(*d, sources));
    if (diag.limit_reached()) tool_message("note", "", limit_message(diag));
  }
  void tool_error(const std::string &input, const std::string &message, bool) override {
    tool_message("error", input, message);
  }
  std::string finish(int) override {
    err_ << all_.dump(-1, ' ', false, Json::error_handler_t::replace) << '\n';
    return {};
  }

private:
  /// A message of the run itself: no location in a chart, so an empty "locations".
  void tool_message(const char *kind, const std::string &input, const std::string &message) {
    Json j = {{"kind", kind},
              {"message", input.empty() ? message : fmt::format("{}: {}", input, message)},
              {"children", Json::array()},
              {"column-origin", 1},
              {"locations", Json::array()},
              {"escape-source", false}};
    all_.push_back(std::move(j));
  }

  std::ostream &err_;
  Json all_ = Json::array();
};

}  // namespace

Json diagnostic_to_json(const Diagnostic &d, const SourceManager &sources) {
  Json children = Json::array();
  for (const auto &n : d.notes) {
    // A note without a place of its own is about the diagnostic's place, as the text shows it.
    children.push_back({{"kind", "note"},
                        {"message", n.message},
                        {"locations", Json::array({location(sources, n.has_range ? n.range : d.range)})}});
  }
  Json j = {{"kind", severity_name(d.severity)},
            {"message", d.message},
            {"children", std::move(children)},
            {"column-origin", 1},
            {"locations", Json::array({location(sources, d.range)})},
            {"escape-source", false}};
  // gcc: "-Wname" for a warning, "-Werror=name" for one -Werror made an error.
  if (d.from_warning()) j["option"] = check_label(d);
  j["check"] = d.check();
  if (!d.fixits.empty()) {
    // gcc's fix-its: "start" at the first byte replaced, "next" just past the last one.
    Json fixits = Json::array();
    for (const FixIt &f : d.fixits)
      fixits.push_back({{"start", position(sources, f.range, f.range.begin)},
                        {"next", position(sources, f.range, f.range.end)},
                        {"string", f.replacement}});
    j["fixits"] = std::move(fixits);
  }
  return j;
}

std::unique_ptr<DiagnosticReport> make_json_report(std::ostream &err) { return std::make_unique<JsonReport>(err); }

}  // namespace gfec
