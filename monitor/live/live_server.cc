#include "live_server.h"

#include "viewer_page.h"

#include <httplib.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <set>
#include <sstream>
#include <thread>

namespace gfec::live {

namespace {

/// A query parameter as a count; absent or not a number: 0 (the page then gets everything).
std::size_t count_param(const httplib::Request &req, const char *name) {
  if (!req.has_param(name)) return 0;
  const std::string v = req.get_param_value(name);
  char *end = nullptr;
  const unsigned long long n = std::strtoull(v.c_str(), &end, 10);
  return end && *end == '\0' && !v.empty() && v[0] != '-' ? static_cast<std::size_t>(n) : 0;
}

}  // namespace

bool is_loopback(const std::string &host) {
  if (host == "localhost" || host == "::1") return true;
  // 127.0.0.0/8, written as four decimal numbers.
  std::istringstream in(host);
  int parts[4];
  char dot = '.';
  for (int i = 0; i < 4; ++i) {
    if (i > 0 && (!(in >> dot) || dot != '.')) return false;
    if (!(in >> parts[i]) || parts[i] < 0 || parts[i] > 255) return false;
  }
  return in.peek() == EOF && parts[0] == 127;
}

std::string refuse_host(const std::string &host, bool allow_remote) {
  if (allow_remote || is_loopback(host)) return "";
  return "'" + host +
         "' is not a loopback address: the live page has no login, so anyone who reaches it sees the run; "
         "--http-remote serves it there anyway";
}

std::string parse_address(const std::string &text, std::string &host, int &port) {
  const std::size_t colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
    return "'" + text + "' is not HOST:PORT (127.0.0.1:8080; port 0 picks a free port)";
  host = text.substr(0, colon);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);
  const std::string p = text.substr(colon + 1);
  if (p.size() > 5 || p.find_first_not_of("0123456789") != std::string::npos || std::stoi(p) > 65535)
    return "'" + p + "' is not a port (0 to 65535)";
  port = std::stoi(p);
  return "";
}

struct LiveServer::Impl {
  const LiveRecording &recording;
  httplib::Server server;
  std::thread thread;
  std::set<std::string> hosts;  ///< the Host headers accepted (empty: any)
};

LiveServer::LiveServer(const LiveRecording &recording) : impl_(new Impl{recording, {}, {}, {}}) {
  Impl &s = *impl_;
  // A page on another site may not read the run through a name that resolves to this machine
  // (DNS rebinding): bound to loopback, only the loopback names are answered.
  s.server.set_pre_routing_handler([this](const httplib::Request &req, httplib::Response &res) {
    if (impl_->hosts.empty() || impl_->hosts.count(req.get_header_value("Host")))
      return httplib::Server::HandlerResponse::Unhandled;
    res.status = 403;
    res.set_content("gfec monitor answers only to its loopback address\n", "text/plain");
    return httplib::Server::HandlerResponse::Handled;
  });
  s.server.Get("/", [this](const httplib::Request &, httplib::Response &res) {
    res.set_header("Cache-Control", "no-store");
    res.set_content(viewer::page(impl_->recording.page_data()), "text/html; charset=utf-8");
  });
  // Browsers ask for an icon; the page has none, and says so without an error.
  s.server.Get("/favicon.ico", [](const httplib::Request &, httplib::Response &res) { res.status = 204; });
  // The page's poll: what it lacks beyond the counts it names (docs/viewer.md "Live mode").
  s.server.Get("/live", [this](const httplib::Request &req, httplib::Response &res) {
    viewer::RecordingBuilder::Cursor c;
    c.frames = static_cast<long>(count_param(req, "frames"));
    c.events = count_param(req, "events");
    std::istringstream texts(req.has_param("texts") ? req.get_param_value("texts") : "");
    for (std::string n; std::getline(texts, n, ',');)
      c.texts.push_back(static_cast<std::size_t>(std::strtoull(n.c_str(), nullptr, 10)));
    res.set_header("Cache-Control", "no-store");
    res.set_content(impl_->recording.update(c).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                    "application/json");
  });
}

LiveServer::~LiveServer() { stop(); }

std::string LiveServer::bind(const std::string &host, int port, bool allow_remote) {
  if (std::string why = refuse_host(host, allow_remote); !why.empty()) return why;
  Impl &s = *impl_;
  port_ = port == 0 ? s.server.bind_to_any_port(host) : (s.server.bind_to_port(host, port) ? port : -1);
  if (port_ < 0) {
    port_ = 0;
    return "cannot listen on " + host + ":" + std::to_string(port) + ": " + std::strerror(errno);
  }
  host_ = host;
  if (!allow_remote) {
    const std::string p = ":" + std::to_string(port_);
    const std::string h = host.find(':') != std::string::npos ? "[" + host + "]" : host;
    s.hosts = {h + p, "localhost" + p, "127.0.0.1" + p, "[::1]" + p};
  }
  return "";
}

void LiveServer::start() {
  impl_->thread = std::thread([this] { impl_->server.listen_after_bind(); });
}

void LiveServer::stop() {
  if (!impl_) return;
  impl_->server.stop();
  if (impl_->thread.joinable()) impl_->thread.join();
}

std::string LiveServer::url() const {
  const std::string h = host_.find(':') != std::string::npos ? "[" + host_ + "]" : host_;
  return "http://" + h + ":" + std::to_string(port_) + "/";
}

}  // namespace gfec::live
