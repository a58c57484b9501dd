// The server's state between messages: whether it was initialized or shut down, the workspace
// folders, the open documents over the disk (an OverlayFileSystem: imports read open buffers
// first) and each document's last compilation, made when first asked for and dropped when a
// buffer it read changes.
#pragma once

#include "backend.h"
#include "compiled_document.h"
#include "file_system.h"

#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace gfec::lsp {

/// A JSON-RPC error a handler throws: the server answers the request with it.
struct RequestError {
  int code;
  std::string message;
};

/// The error codes of JSON-RPC 2.0 and LSP 3.17.
namespace error_code {
inline constexpr int kParseError = -32700;
inline constexpr int kInvalidRequest = -32600;
inline constexpr int kMethodNotFound = -32601;
inline constexpr int kInvalidParams = -32602;
inline constexpr int kInternalError = -32603;
inline constexpr int kServerNotInitialized = -32002;
inline constexpr int kRequestFailed = -32803;
}  // namespace error_code

struct Document {
  std::string uri;
  std::string path;  ///< what the compiler is given (path_of_uri)
  std::string text;
  long long version = 0;
};

class Session {
public:
  /// `notify(method, params)` sends a notification to the client.
  Session(const FileSystem &disk, std::function<void(const std::string &, nlohmann::json)> notify);

  bool initialized = false;
  bool shutdown_requested = false;
  /// The client's capabilities, as sent with initialize.
  nlohmann::json client_capabilities = nlohmann::json::object();
  /// The workspace folders' paths (rename looks for files that are not open below them).
  std::vector<std::string> workspace_folders;
  /// What every compilation is given: -I folders and warnings from initializationOptions.
  pipeline::FrontEndOptions front_end;
  /// Runs the external tools a picture goes through (Graphviz's dot for gfec/chartPicture): the
  /// driver's run_external_tool, with its time limit. Empty: no picture, a note says so.
  ToolRunner tools;

  void notify(const std::string &method, nlohmann::json params) const { notify_(method, std::move(params)); }

  // ---- documents
  /// didOpen, or a full-text didChange.
  void set_text(const std::string &uri, std::string text, long long version);
  void close(const std::string &uri);
  /// The open document of `uri`, or null.
  Document *document(const std::string &uri);
  /// The open document of `uri`; a RequestError (InvalidParams) if it is not open.
  Document &open_document(const std::string &uri);
  std::vector<std::string> open_uris() const;
  /// The open buffers over the disk.
  const FileSystem &files() const { return overlay_; }

  // ---- compilations
  /// The compilation of the open document `uri` (made now if the cached one is stale), its
  /// static analyses run; throws RequestError when it is not open.
  const CompiledDocument &compiled(const std::string &uri);
  /// The same, but the analyses may not have run yet (analysis_pending()): what the first
  /// publish of a change reports, and all that the requests which read only the syntax tree,
  /// the names and the model need.
  const CompiledDocument &validated(const std::string &uri);
  /// Whether `uri`'s diagnostics were published without the analyses': those are to be run and
  /// published when the input is idle (publish_analyses), in the order deferred.
  void set_deferred(const std::string &uri, bool deferred);
  bool has_deferred() const { return !deferred_.empty(); }
  /// The oldest deferred document, taken off the list; "" when there is none.
  std::string next_deferred();
  /// The open documents other than `uri` whose last compilation read `uri`'s file: they are
  /// checked again when it changes. (Documents not compiled yet are not listed.)
  std::vector<std::string> dependents(const std::string &uri) const;
  /// A file on disk changed (workspace/didChangeWatchedFiles): the open documents whose last
  /// compilation read it, now stale. A file with an open buffer is read from the buffer: none.
  std::vector<std::string> disk_file_changed(const std::string &path);
  /// The URI of a path: the open document's own when one has that path, else a file:// URI.
  std::string uri_of_path(const std::string &path) const;

private:
  struct Cached {
    std::unique_ptr<CompiledDocument> document;
    bool stale = false;  ///< a buffer it read changed: made again when next asked for
  };
  /// Marks stale every compilation that read `path`, and `uri`'s own.
  void invalidate(const std::string &uri, const std::string &path);

  const FileSystem &disk_;
  OverlayFileSystem overlay_;
  std::function<void(const std::string &, nlohmann::json)> notify_;
  std::map<std::string, Document> documents_;  ///< by URI
  std::map<std::string, Cached> compiled_;     ///< by URI, open documents only
  std::vector<std::string> deferred_;          ///< URIs whose analyses wait for idle input
};

/// The parameters' textDocument.uri; InvalidParams if missing.
std::string document_uri(const nlohmann::json &params);

}  // namespace gfec::lsp
