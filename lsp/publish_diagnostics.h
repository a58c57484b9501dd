// textDocument/publishDiagnostics as `gfec --check` gives them: each diagnostic located in the
// document, its severity, `code` the check name (SARIF's ruleId, JSON's "check"), `source`
// "gfec", its notes as relatedInformation (in any file) and the message.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace gfec::lsp {

class Session;
class CompiledDocument;

/// The PublishDiagnosticsParams of a compiled document.
nlohmann::json diagnostics_of(const CompiledDocument &doc, long long version);
/// Compiles `uri` (if its compilation is stale) and publishes its diagnostics, then those of the
/// open documents whose compilation read it.
void publish_diagnostics(Session &session, const std::string &uri);

}  // namespace gfec::lsp
