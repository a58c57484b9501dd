// initialize, initialized, shutdown (LSP 3.17 "Lifecycle Messages"); `exit` ends the loop in
// server.cc. initializationOptions: {"includeDirs": [...] (as -I), "warnings": ["all",
// "no-unused-var", ...] (as -W), "period": "10ms" (as --period)}.
#include "diagnostics.h"
#include "methods.h"
#include "period_text.h"
#include "uri.h"

namespace gfec::lsp::handlers {

using nlohmann::json;

namespace {

void read_options(Session &s, const json &options) {
  if (!options.is_object()) return;
  if (options.contains("includeDirs"))
    for (const json &d : options["includeDirs"]) s.front_end.include_dirs.push_back(d.get<std::string>());
  if (options.contains("warnings"))
    for (const json &w : options["warnings"]) {
      std::string name = w.get<std::string>();
      bool on = name.rfind("no-", 0) != 0;
      if (!on) name = name.substr(3);
      if (name == "all") {
        for (int i = 0; i < static_cast<int>(Warning::Count_); ++i)
          s.front_end.warnings.set(static_cast<Warning>(i), on);
      } else if (auto found = find_warning(name)) {
        s.front_end.warnings.set(*found, on);
      } else {
        throw RequestError{error_code::kInvalidParams, "initializationOptions.warnings: no warning '" + name + "'"};
      }
    }
  if (options.contains("period")) {
    const json &p = options["period"];
    s.front_end.period_ms = p.is_string() ? parse_period(p.get<std::string>()) : std::nullopt;
    if (!s.front_end.period_ms)
      throw RequestError{error_code::kInvalidParams,
                         "initializationOptions.period: not a duration above 0 (write it as 10ms, 1.5s or T#10ms)"};
  }
}

}  // namespace

json initialize(Session &s, const json &params) {
  if (params.contains("capabilities")) s.client_capabilities = params["capabilities"];
  if (params.contains("workspaceFolders") && params["workspaceFolders"].is_array())
    for (const json &f : params["workspaceFolders"])
      s.workspace_folders.push_back(path_of_uri(f.at("uri").get<std::string>()));
  else if (params.contains("rootUri") && params["rootUri"].is_string())
    s.workspace_folders.push_back(path_of_uri(params["rootUri"].get<std::string>()));
  else if (params.contains("rootPath") && params["rootPath"].is_string())
    s.workspace_folders.push_back(params["rootPath"].get<std::string>());
  if (params.contains("initializationOptions")) read_options(s, params["initializationOptions"]);
  s.initialized = true;
  return {{"capabilities", server_capabilities()}, {"serverInfo", {{"name", "gfec"}, {"version", GFEC_VERSION}}}};
}

void initialized(Session &, const json &) {}

json shutdown(Session &s, const json &) {
  s.shutdown_requested = true;
  return nullptr;
}

void ignore(Session &, const json &) {}

}  // namespace gfec::lsp::handlers
