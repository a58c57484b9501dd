// workspace/didChangeWatchedFiles: a file the client watches changed on disk (an interface a
// chart imports, saved by another program or switched by git). The open documents that read
// it are checked again; a file open in the editor is read from its buffer and changes nothing.
// The client chooses what to watch (the VS Code extension: the six kinds of chart text).
#include "methods.h"
#include "publish_diagnostics.h"
#include "uri.h"

#include <set>

namespace gfec::lsp::handlers {

void did_change_watched_files(Session &s, const nlohmann::json &params) {
  std::set<std::string> stale;
  for (const nlohmann::json &change : params.at("changes"))
    for (const std::string &uri : s.disk_file_changed(path_of_uri(change.at("uri").get<std::string>())))
      stale.insert(uri);
  for (const std::string &uri : stale) publish_document(s, uri);
}

}  // namespace gfec::lsp::handlers
