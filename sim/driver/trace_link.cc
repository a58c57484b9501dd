#include "driver/trace_link.h"

#include <fmt/format.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>

namespace carbot::driver {

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

/// A socket listening on host:port, or -1 and `why`; `bound` gets the port (port 0: a free one).
int listen_on(const std::string& host, const std::string& port, int& bound, std::string& why) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE;
  addrinfo* found = nullptr;
  if (const int rc = getaddrinfo(host.c_str(), port.c_str(), &hints, &found); rc != 0) {
    why = gai_strerror(rc);
    return -1;
  }
  int fd = -1;
  for (addrinfo* a = found; a && fd < 0; a = a->ai_next) {
    fd = socket(a->ai_family, a->ai_socktype, a->ai_protocol);
    if (fd < 0) continue;
    int one = 1;
    setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (bind(fd, a->ai_addr, a->ai_addrlen) != 0 || listen(fd, 8) != 0) {
      why = std::strerror(errno);
      ::close(fd);
      fd = -1;
    }
  }
  freeaddrinfo(found);
  if (fd >= 0) {
    sockaddr_storage at{};
    socklen_t size = sizeof at;
    getsockname(fd, reinterpret_cast<sockaddr*>(&at), &size);
    bound = ntohs(at.ss_family == AF_INET6 ? reinterpret_cast<sockaddr_in6*>(&at)->sin6_port
                                           : reinterpret_cast<sockaddr_in*>(&at)->sin_port);
  }
  return fd;
}

}  // namespace

std::string TraceLinks::open(const std::string& spec, int robots, double period) {
  close();
  const std::size_t colon = spec.rfind(':');
  if (spec.rfind("tcp:", 0) != 0 || colon <= 4 || colon + 1 == spec.size())
    return fmt::format("--trace-to {}: not tcp:HOST:PORT (tcp:127.0.0.1:5000)", spec);
  std::string host = spec.substr(4, colon - 4);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);
  std::string why;
  int port = 0;
  const int listener = listen_on(host, spec.substr(colon + 1), port, why);
  if (listener < 0) return fmt::format("--trace-to {}: cannot listen: {}", spec, why);
  // The run starts once every robot's monitor is there: robot i is the i-th connection.
  std::fprintf(stderr, "carbot-sim: --trace-to: waiting on %s port %d for %d connection%s (gfec monitor CHART --tcp)\n",
               host.c_str(), port, robots, robots == 1 ? "" : "s");
  for (int i = 0; i < robots; ++i) {
    const int fd = accept(listener, nullptr, nullptr);
    if (fd < 0) {
      if (errno == EINTR) {
        --i;
        continue;
      }
      why = std::strerror(errno);
      ::close(listener);
      close();
      return fmt::format("--trace-to {}: accepting robot {}'s connection: {}", spec, i, why);
    }
    // Each frame sent at once rather than gathered.
    int one = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    sockets_.push_back(fd);
    broken_.push_back(false);
    if (robots > 1) std::fprintf(stderr, "carbot-sim: --trace-to: robot %d connected\n", i);
  }
  ::close(listener);
  period_ = period;
  ticks_ = 0;
  return "";
}

void TraceLinks::select(int robot) {
  current_ = robot;
  if (robot != 0 || sockets_.empty()) return;
  if (ticks_ == 0) start_ = now();
  const double due = start_ + static_cast<double>(ticks_) * period_, wait = due - now();
  if (wait > 0) std::this_thread::sleep_for(std::chrono::duration<double>(wait));
  ++ticks_;
}

void TraceLinks::write(const unsigned char* data, unsigned len) {
  if (current_ < 0 || static_cast<std::size_t>(current_) >= sockets_.size() || broken_[current_]) return;
  while (len > 0) {
    const ssize_t n = send(sockets_[current_], data, len, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      // The monitor went away: the run goes on without this robot's trace.
      std::fprintf(stderr, "carbot-sim: --trace-to: robot %d's link closed (%s); its trace stops\n", current_,
                   std::strerror(errno));
      broken_[current_] = true;
      return;
    }
    data += n;
    len -= static_cast<unsigned>(n);
  }
}

void TraceLinks::close() {
  for (int fd : sockets_) ::close(fd);
  sockets_.clear();
  broken_.clear();
}

TraceLinks& trace_links() {
  static TraceLinks links;
  return links;
}

}  // namespace carbot::driver

extern "C" void carbot_sim_trace(const unsigned char* data, unsigned len) {
  carbot::driver::trace_links().write(data, len);
}
