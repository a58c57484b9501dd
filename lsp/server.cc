#include "server.h"

#include "methods.h"
#include "publish_diagnostics.h"
#include "session.h"
#include "transport.h"

#include <istream>
#include <ostream>

namespace gfec::lsp {

namespace {

using nlohmann::json;

class Server {
public:
  Server(std::ostream &out, std::ostream &log, const FileSystem &disk, ToolRunner tools)
      : out_(out), log_(log), session_(disk, [this](const std::string &m, json p) { send_notification(m, p); }) {
    session_.tools = std::move(tools);
  }

  /// Handles one frame's body; false once `exit` came.
  bool handle(const std::string &body);
  void bad_frame(const std::string &why) {
    log_ << "gfec lsp: " << why << "\n";
    send_error(nullptr, error_code::kParseError, why);
  }
  int exit_code() const { return session_.shutdown_requested ? 0 : 1; }
  /// No message waits: the deferred analyses' turn (publish_diagnostics.h).
  void idle(const std::function<bool()> &input_waiting);

private:
  void send(const json &message) {
    // Source text need not be UTF-8; a byte that is not is sent as U+FFFD, never an exception.
    write_frame(out_, message.dump(-1, ' ', false, json::error_handler_t::replace));
  }
  void send_notification(const std::string &method, const json &params) {
    send({{"jsonrpc", "2.0"}, {"method", method}, {"params", params}});
  }
  void send_error(const json &id, int code, const std::string &message) {
    send({{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}});
  }
  void send_result(const json &id, json result) {
    // The result moved in, not copied by an initializer list: semantic tokens of a large chart
    // are an array of a few hundred thousand numbers.
    json message = {{"jsonrpc", "2.0"}, {"id", id}};
    message["result"] = std::move(result);
    send(message);
  }
  void request(const json &id, const std::string &method, const json &params);
  void notification(const std::string &method, const json &params);

  std::ostream &out_;
  std::ostream &log_;
  Session session_;
};

bool Server::handle(const std::string &body) {
  json message = json::parse(body, nullptr, false);
  if (message.is_discarded()) {
    bad_frame("the message is not JSON");
    return true;
  }
  if (!message.is_object()) {
    send_error(nullptr, error_code::kInvalidRequest, "a message is a JSON object");
    return true;
  }
  const bool has_id = message.contains("id");
  json id = has_id ? message["id"] : json();
  if (has_id && !id.is_string() && !id.is_number_integer() && !id.is_null()) {
    send_error(nullptr, error_code::kInvalidRequest, "a request's id is a number or a string");
    return true;
  }
  if (!message.contains("method")) {
    // A response to a request of ours: the server sends none that wait for an answer.
    if (!has_id || !(message.contains("result") || message.contains("error")))
      send_error(id, error_code::kInvalidRequest, "a message without a method is a response");
    return true;
  }
  if (!message["method"].is_string()) {
    if (has_id) send_error(id, error_code::kInvalidRequest, "the method is not a string");
    return true;
  }
  const std::string method = message["method"].get<std::string>();
  json params = message.contains("params") ? message["params"] : json::object();
  if (method == "exit") return false;
  if (has_id) request(id, method, params);
  else notification(method, params);
  return true;
}

void Server::request(const json &id, const std::string &method, const json &params) {
  const Method *m = find_method(method);
  if (!session_.initialized && method != "initialize") {
    send_error(id, error_code::kServerNotInitialized, "the server is not initialized yet");
    return;
  }
  if (session_.shutdown_requested) {
    send_error(id, error_code::kInvalidRequest, "the server is shut down; only 'exit' is answered");
    return;
  }
  if (!m) {
    send_error(id, error_code::kMethodNotFound, "no method '" + method + "'");
    return;
  }
  if (!m->request) {
    send_error(id, error_code::kInvalidRequest, "'" + method + "' is a notification: it takes no id");
    return;
  }
  if (method == "initialize" && session_.initialized) {
    send_error(id, error_code::kInvalidRequest, "the server is initialized already");
    return;
  }
  try {
    send_result(id, m->request(session_, params));
  } catch (const RequestError &e) { send_error(id, e.code, e.message); } catch (const json::exception &e) {
    send_error(id, error_code::kInvalidParams, std::string("invalid parameters: ") + e.what());
  } catch (const std::exception &e) { send_error(id, error_code::kInternalError, e.what()); }
}

void Server::notification(const std::string &method, const json &params) {
  // Before initialize every notification but exit is dropped (LSP 3.17 "initialize").
  if (!session_.initialized || session_.shutdown_requested) return;
  const Method *m = find_method(method);
  // An unknown notification is dropped; a request sent without an id cannot be answered.
  if (!m || !m->notification) return;
  try {
    m->notification(session_, params);
  } catch (const RequestError &e) {
    log_ << "gfec lsp: " << method << ": " << e.message << "\n";
  } catch (const std::exception &e) { log_ << "gfec lsp: " << method << ": " << e.what() << "\n"; }
}

void Server::idle(const std::function<bool()> &input_waiting) {
  if (!session_.initialized || session_.shutdown_requested) return;
  try {
    publish_analyses(session_, input_waiting);
  } catch (const std::exception &e) { log_ << "gfec lsp: the analyses: " << e.what() << "\n"; }
}

}  // namespace

int serve(std::istream &in, std::ostream &out, std::ostream &log, const FileSystem &disk, ToolRunner tools,
          std::function<bool()> input_waiting) {
  Server server(out, log, disk, std::move(tools));
  if (!input_waiting) input_waiting = [&in] { return in.rdbuf()->in_avail() > 0; };
  for (;;) {
    server.idle(input_waiting);
    Frame f = read_frame(in);
    if (f.status == Frame::Status::End) break;
    if (f.status == Frame::Status::BadHeader) {
      server.bad_frame(f.error);
      continue;
    }
    if (!server.handle(f.body)) break;
  }
  return server.exit_code();
}

}  // namespace gfec::lsp
