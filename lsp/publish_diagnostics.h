// textDocument/publishDiagnostics as `gfec --check` gives them: each diagnostic located in the
// document, its severity, `code` the check name (SARIF's ruleId, JSON's "check"), `source`
// "gfec", its notes as relatedInformation (in any file) and the message.
//
// In two steps (docs/editors.md "Speed"): a change publishes what the front end found at once;
// the static analyses, most of a large chart's time, run when no message waits, and their
// warnings come in a second publish of the same version.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace gfec::lsp {

class Session;
class CompiledDocument;

/// The PublishDiagnosticsParams of a compiled document.
nlohmann::json diagnostics_of(const CompiledDocument &doc, long long version);
/// Compiles the open document `uri` (if its compilation is stale) through the front end and
/// publishes its diagnostics; its analyses, if they have not run, are deferred.
void publish_document(Session &session, const std::string &uri);
/// publish_document for `uri`, then for the open documents whose compilation read it.
void publish_diagnostics(Session &session, const std::string &uri);
/// While `input_waiting()` says no message waits: runs the deferred analyses, a document at a
/// time in the order deferred, and publishes again (with the same version) each document whose
/// analyses reported something.
void publish_analyses(Session &session, const std::function<bool()> &input_waiting);

}  // namespace gfec::lsp
