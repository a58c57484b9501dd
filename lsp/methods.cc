#include "methods.h"

namespace gfec::lsp {

namespace h = handlers;

const std::vector<Method> &methods() {
  // `exit` is not here: it ends the server's loop (server.cc).
  static const std::vector<Method> table = {
      {"initialize", h::initialize},
      {"initialized", nullptr, h::initialized},
      {"shutdown", h::shutdown},
      {"textDocument/didOpen", nullptr, h::did_open, h::advertise_text_sync},
      {"textDocument/didChange", nullptr, h::did_change},
      {"textDocument/didClose", nullptr, h::did_close},
      {"textDocument/didSave", nullptr, h::did_save},
      {"textDocument/hover", h::hover, nullptr, h::advertise_hover},
      {"textDocument/definition", h::definition, nullptr, h::advertise_definition},
      {"textDocument/references", h::references, nullptr, h::advertise_references},
      {"textDocument/prepareRename", h::prepare_rename, nullptr, h::advertise_rename},
      {"textDocument/rename", h::rename},
      {"textDocument/documentSymbol", h::document_symbol, nullptr, h::advertise_document_symbol},
      {"workspace/symbol", h::workspace_symbol, nullptr, h::advertise_workspace_symbol},
      // Answered before its request is read on (single-threaded): nothing left to cancel.
      {"$/cancelRequest", nullptr, h::ignore},
      {"$/setTrace", nullptr, h::ignore},
      {"workspace/didChangeConfiguration", nullptr, h::ignore},
      {"workspace/didChangeWatchedFiles", nullptr, h::did_change_watched_files},
  };
  return table;
}

const Method *find_method(const std::string &name) {
  for (const Method &m : methods())
    if (name == m.name) return &m;
  return nullptr;
}

nlohmann::json server_capabilities() {
  nlohmann::json caps = {{"positionEncoding", "utf-16"}};
  for (const Method &m : methods())
    if (m.advertise) m.advertise(caps);
  return caps;
}

}  // namespace gfec::lsp
