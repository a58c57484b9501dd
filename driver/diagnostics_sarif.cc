#include "diagnostics_sarif.h"

#include "backend.h"
#include "diagnostic_printer.h"
#include "output_files.h"

#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <ostream>

namespace gfec {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char *kSchema =
    "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json";
constexpr const char *kRoot = "%SRCROOT%";

/// RFC 3986: keep unreserved characters and '/', percent-encode every other byte.
std::string uri_encode(const std::string &path) {
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') out += static_cast<char>(c);
    else out += fmt::format("%{:02X}", c);
  }
  return out;
}

const char *level(Severity s) {
  switch (s) {
  case Severity::Error: return "error";
  case Severity::Warning: return "warning";
  case Severity::Note: return "note";
  }
  return "none";
}

}  // namespace

Json artifact_location(const std::string &path) {
  if (!path.empty() && path.front() == '/') return {{"uri", "file://" + uri_encode(path)}};
  return {{"uri", uri_encode(path)}, {"uriBaseId", kRoot}};
}

namespace {

/// A row of the table as a SARIF reportingDescriptor.
Json rule(const DiagnosticKind &k) {
  std::string full = k.warning ? fmt::format("Warning: {}. {} by default; -W{} turns it on, -Wno-{} off.", k.summary,
                                             k.on_by_default ? "On" : "Off", k.name, k.name)
                               : fmt::format("Error: {}.", k.summary);
  return {{"id", k.check()},
          {"name", k.name},
          {"shortDescription", {{"text", k.summary}}},
          {"fullDescription", {{"text", std::move(full)}}},
          {"help", {{"text", k.help}}},
          {"defaultConfiguration", {{"enabled", k.on_by_default}, {"level", k.warning ? "warning" : "error"}}}};
}

}  // namespace

SarifLog::SarifLog() {
  // Every kind is a rule even when it did not fire, so a dashboard can list and explain them;
  // rule i is row i of the table.
  for (std::size_t i = 0; i < diagnostic_kind_count(); ++i) rules_.push_back(rule(diagnostic_kinds()[i]));
}

int SarifLog::rule_index(const Diagnostic &d) {
  if (d.kind) return static_cast<int>(d.kind - diagnostic_kinds());
  if (unnamed_rule_ < 0) {
    unnamed_rule_ = static_cast<int>(rules_.size());
    rules_.push_back({{"id", "gfec"}, {"shortDescription", {{"text", "a diagnostic of gfec"}}}});
  }
  return unnamed_rule_;
}

int SarifLog::artifact_index(const std::string &path) {
  auto found = artifact_ids_.find(path);
  if (found != artifact_ids_.end()) return found->second;
  int index = static_cast<int>(artifacts_.size());
  artifact_ids_[path] = index;
  artifacts_.push_back(path);
  analysis_targets_.push_back(false);
  return index;
}

Json SarifLog::physical_location(const SourceManager &sources, const SourceRange &range) {
  const SourceFile &file = sources.file(range.file);
  Columns begin = columns_at(file, range.begin);
  Columns end = columns_at(file, std::max(range.begin, range.end));
  Json artifact = artifact_location(file.path());
  artifact["index"] = artifact_index(file.path());
  // endColumn is exclusive in SARIF, as our ranges are half-open.
  return {{"artifactLocation", std::move(artifact)},
          {"region",
           {{"startLine", begin.line},
            {"startColumn", begin.code_point},
            {"endLine", end.line},
            {"endColumn", end.code_point}}}};
}

Json SarifLog::fixes(const SourceManager &sources, const Diagnostic &d) {
  // One fix holding every replacement: a diagnostic's fix-its are meant to be applied together.
  Json changes = Json::array();
  for (const FixIt &f : d.fixits) {
    Json where = physical_location(sources, f.range);
    changes.push_back({{"artifactLocation", where["artifactLocation"]},
                       {"replacements", Json::array({{{"deletedRegion", where["region"]},
                                                      {"insertedContent", {{"text", f.replacement}}}}})}});
  }
  return Json::array({{{"description", {{"text", d.notes.empty() ? d.message : d.notes.front().message}}},
                       {"artifactChanges", std::move(changes)}}});
}

void SarifLog::add(const Diagnostics &diag, const SourceManager &sources) {
  for (FileId id = 0; id < sources.size(); ++id) {
    int index = artifact_index(sources.file(id).path());
    if (id == 0) analysis_targets_[static_cast<std::size_t>(index)] = true;
  }
  for (const Diagnostic *in_order : in_source_order(diag)) {
    const Diagnostic &d = *in_order;
    int rule = rule_index(d);
    Json related = Json::array();
    for (const auto &n : d.notes) {
      related.push_back({{"id", related.size()},
                         {"physicalLocation", physical_location(sources, n.has_range ? n.range : d.range)},
                         {"message", {{"text", n.message}}}});
    }
    Json result = {{"ruleId", rules_[rule]["id"]},
                   {"ruleIndex", rule},
                   {"level", level(d.severity)},
                   {"message", {{"text", d.message}}},
                   {"locations", Json::array({{{"physicalLocation", physical_location(sources, d.range)}}})}};
    if (!related.empty()) result["relatedLocations"] = std::move(related);
    if (!d.fixits.empty()) result["fixes"] = fixes(sources, d);
    results_.push_back(std::move(result));
  }
  if (diag.limit_reached()) notification("note", "", limit_message(diag));
}

void SarifLog::notification(const std::string &lvl, const std::string &input, const std::string &message) {
  Json n = {{"level", lvl}, {"message", {{"text", message}}}};
  if (!input.empty())
    n["locations"] = Json::array({{{"physicalLocation", {{"artifactLocation", artifact_location(input)}}}}});
  notifications_.push_back(std::move(n));
}

Json SarifLog::to_json(int exit_code, const std::string &cwd) const {
  Json artifacts = Json::array();
  for (std::size_t i = 0; i < artifacts_.size(); ++i) {
    Json a = {{"location", artifact_location(artifacts_[i])}};
    if (analysis_targets_[i]) a["roles"] = Json::array({"analysisTarget"});
    artifacts.push_back(std::move(a));
  }
  Json invocation = {{"executionSuccessful", exit_code != 2}, {"exitCode", exit_code}};
  if (!notifications_.empty()) invocation["toolExecutionNotifications"] = notifications_;
  std::string root = "file://" + uri_encode(cwd);
  if (root.back() != '/') root += '/';
  Json run = {{"tool",
               {{"driver",
                 {{"name", "gfec"}, {"version", GFEC_VERSION}, {"semanticVersion", GFEC_VERSION}, {"rules", rules_}}}}},
              {"invocations", Json::array({std::move(invocation)})},
              {"originalUriBaseIds", {{kRoot, {{"uri", root}}}}},
              {"artifacts", std::move(artifacts)},
              {"results", results_},
              {"columnKind", "unicodeCodePoints"}};
  return {{"$schema", kSchema}, {"version", "2.1.0"}, {"runs", Json::array({std::move(run)})}};
}

namespace {

class SarifReport : public DiagnosticReport {
public:
  explicit SarifReport(std::ostream *err) : err_(err) {}

  void add(const std::string &input, const Diagnostics &diag, const SourceManager &sources) override {
    log_for(input).add(diag, sources);
    // Every file the input read (its imports too) is one no log may be written over.
    for (FileId f = 0; f < sources.size(); ++f) read_.push_back(sources.file(f).path());
  }
  void tool_error(const std::string &input, const std::string &message, bool) override {
    log_for(input).notification("error", input, message);
  }
  std::string finish(int exit_code) override {
    std::string cwd = std::filesystem::current_path().string();
    // Messages quote the user's text, which need not be UTF-8: replace what JSON cannot hold.
    auto text = [&](const SarifLog &log) {
      return log.to_json(exit_code, cwd).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
    };
    if (err_) {
      *err_ << text(log_for(""));
      return {};
    }
    std::vector<OutputFile> files;
    std::vector<std::string> inputs;
    for (const auto &[input, log] : logs_) {
      files.push_back({base_name(input.empty() ? "gfec" : input) + ".sarif", text(log)});
      if (!input.empty()) inputs.push_back(input);
    }
    inputs.insert(inputs.end(), read_.begin(), read_.end());
    return write_atomically(files, inputs);
  }

private:
  /// sarif-stderr: one log for the whole run; sarif-file: one per input, as gcc writes them.
  SarifLog &log_for(const std::string &input) {
    std::string key = err_ ? std::string() : input;
    for (auto &entry : logs_)
      if (entry.first == key) return entry.second;
    logs_.emplace_back(key, SarifLog());
    return logs_.back().second;
  }

  std::ostream *err_;
  std::vector<std::string> read_;
  std::vector<std::pair<std::string, SarifLog>> logs_;  ///< in input order
};

}  // namespace

std::unique_ptr<DiagnosticReport> make_sarif_report(std::ostream *err) { return std::make_unique<SarifReport>(err); }

}  // namespace gfec
