// The live page's HTTP server (docs/live.md "The live page"): cpp-httplib serving the run
// viewer's page with its recording so far, and the updates the page polls for.
#pragma once

#include "live_recording.h"

#include <memory>
#include <string>

namespace gfec::live {

/// "127.0.0.1", "127.x.y.z", "::1", "localhost": an address only this machine reaches.
bool is_loopback(const std::string &host);

/// "" when the page may be served on `host`, else why not: not loopback, and not `allow_remote`.
std::string refuse_host(const std::string &host, bool allow_remote);

/// Splits "HOST:PORT" ("[::1]:8080" for IPv6); "" when it is not of that form, else the error.
std::string parse_address(const std::string &text, std::string &host, int &port);

class LiveServer {
public:
  explicit LiveServer(const LiveRecording &recording);
  ~LiveServer();
  LiveServer(const LiveServer &) = delete;
  LiveServer &operator=(const LiveServer &) = delete;

  /// Binds HOST:PORT (PORT 0: a free port); "" or why it could not. A host that is not loopback
  /// is refused unless `allow_remote` (the page has no login: anyone reaching it sees the run).
  std::string bind(const std::string &host, int port, bool allow_remote);
  /// Serves on a thread of its own until stop() (or the destructor).
  void start();
  void stop();
  int port() const { return port_; }
  /// The page's address, "http://127.0.0.1:PORT/".
  std::string url() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int port_ = 0;
  std::string host_;
};

}  // namespace gfec::live
