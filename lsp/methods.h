// The table of methods the server answers: one row per LSP method, each handled by one small
// function in lsp/handlers/ (one file per feature). Adding a feature is a handler file and a row
// in methods.cc; its row also adds its capability to initialize's answer, so the server never
// advertises what it does not do.
#pragma once

#include "session.h"

#include <nlohmann/json.hpp>
#include <vector>

namespace gfec::lsp {

/// A request's handler: its result, or a RequestError thrown. A nlohmann::json::exception it
/// lets out (params of the wrong shape) is answered as InvalidParams.
using RequestHandler = nlohmann::json (*)(Session &, const nlohmann::json &params);
/// A notification's handler: no answer.
using NotificationHandler = void (*)(Session &, const nlohmann::json &params);
/// Adds the method's entries to the ServerCapabilities object.
using Advertise = void (*)(nlohmann::json &capabilities);

struct Method {
  const char *name;
  RequestHandler request = nullptr;            ///< set for a request
  NotificationHandler notification = nullptr;  ///< set for a notification
  Advertise advertise = nullptr;
};

const std::vector<Method> &methods();
/// The row of `name`, or null.
const Method *find_method(const std::string &name);
/// The ServerCapabilities of every row.
nlohmann::json server_capabilities();

// The handlers (lsp/handlers/*.cc), declared here so the table names them.
namespace handlers {
nlohmann::json initialize(Session &, const nlohmann::json &);
void initialized(Session &, const nlohmann::json &);
nlohmann::json shutdown(Session &, const nlohmann::json &);
void did_open(Session &, const nlohmann::json &);
void did_change(Session &, const nlohmann::json &);
void did_close(Session &, const nlohmann::json &);
void did_save(Session &, const nlohmann::json &);
void advertise_text_sync(nlohmann::json &);
void ignore(Session &, const nlohmann::json &);
void did_change_watched_files(Session &, const nlohmann::json &);
nlohmann::json hover(Session &, const nlohmann::json &);
void advertise_hover(nlohmann::json &);
nlohmann::json definition(Session &, const nlohmann::json &);
void advertise_definition(nlohmann::json &);
nlohmann::json references(Session &, const nlohmann::json &);
void advertise_references(nlohmann::json &);
nlohmann::json prepare_rename(Session &, const nlohmann::json &);
nlohmann::json rename(Session &, const nlohmann::json &);
void advertise_rename(nlohmann::json &);
nlohmann::json document_symbol(Session &, const nlohmann::json &);
void advertise_document_symbol(nlohmann::json &);
nlohmann::json workspace_symbol(Session &, const nlohmann::json &);
void advertise_workspace_symbol(nlohmann::json &);
}  // namespace handlers

}  // namespace gfec::lsp
