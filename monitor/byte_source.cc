#include "byte_source.h"

#include <fmt/format.h>

#include <arpa/inet.h>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

namespace gfec::monitor {

namespace {

/// The rates termios names on Linux.
speed_t speed_of(long baud) {
  switch (baud) {
  case 1200: return B1200;
  case 2400: return B2400;
  case 4800: return B4800;
  case 9600: return B9600;
  case 19200: return B19200;
  case 38400: return B38400;
  case 57600: return B57600;
  case 115200: return B115200;
  case 230400: return B230400;
  case 460800: return B460800;
  case 500000: return B500000;
  case 576000: return B576000;
  case 921600: return B921600;
  case 1000000: return B1000000;
  case 1152000: return B1152000;
  case 1500000: return B1500000;
  case 2000000: return B2000000;
  default: return B0;
  }
}

}  // namespace

int open_serial(const std::string &device, long baud, std::string &error) {
  const speed_t speed = speed_of(baud);
  if (speed == B0) {
    error =
        fmt::format("--baud {}: not a rate of a Linux serial port (1200, 2400, ... 115200, 230400, ... 2000000)", baud);
    return -1;
  }
  const int fd = ::open(device.c_str(), O_RDONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    error = fmt::format("cannot open '{}': {}", device, std::strerror(errno));
    return -1;
  }
  termios tio{};
  if (!::isatty(fd) || ::tcgetattr(fd, &tio) != 0) {
    error = fmt::format("'{}' is not a serial port (not a terminal device)", device);
    ::close(fd);
    return -1;
  }
  ::cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | PARENB | CRTSCTS);
  tio.c_cc[VMIN] = 1;
  tio.c_cc[VTIME] = 0;
  if (::cfsetispeed(&tio, speed) != 0 || ::cfsetospeed(&tio, speed) != 0 || ::tcsetattr(fd, TCSANOW, &tio) != 0) {
    error = fmt::format("cannot set '{}' to {} baud: {}", device, baud, std::strerror(errno));
    ::close(fd);
    return -1;
  }
  return fd;
}

int open_tcp(const std::string &address, std::string &error) {
  const std::size_t colon = address.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == address.size()) {
    error = fmt::format("--tcp '{}': give HOST:PORT, e.g. 127.0.0.1:5760", address);
    return -1;
  }
  std::string host = address.substr(0, colon);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);
  const std::string port = address.substr(colon + 1);
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo *found = nullptr;
  if (int e = ::getaddrinfo(host.c_str(), port.c_str(), &hints, &found); e != 0) {
    error = fmt::format("--tcp '{}': {}", address, ::gai_strerror(e));
    return -1;
  }
  int fd = -1;
  std::string why = "no address";
  for (addrinfo *a = found; a != nullptr && fd < 0; a = a->ai_next) {
    fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    if (::connect(fd, a->ai_addr, a->ai_addrlen) != 0) {
      why = std::strerror(errno);
      ::close(fd);
      fd = -1;
    }
  }
  ::freeaddrinfo(found);
  if (fd < 0) error = fmt::format("cannot connect to {}: {}", address, why);
  return fd;
}

std::string read_stream(int fd, double silence, RunSink &sink,
                        const std::function<void(const unsigned char *, std::size_t)> &feed,
                        const std::function<bool()> &stop) {
  using clock = std::chrono::steady_clock;
  unsigned char chunk[4096];
  auto last = clock::now();
  double reported = 0;  // the silence last reported, 0: none
  while (!stop()) {
    pollfd p{fd, POLLIN, 0};
    const int wait_ms = silence > 0 ? 100 : -1;
    const int r = ::poll(&p, 1, wait_ms);
    if (r < 0) {
      if (errno == EINTR) continue;
      return std::strerror(errno);
    }
    if (r == 0) {
      const double quiet = std::chrono::duration<double>(clock::now() - last).count();
      if (quiet >= reported + silence) {
        reported = quiet;
        sink.silent(quiet);
      }
      continue;
    }
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      return std::strerror(errno);
    }
    if (n == 0) return "";
    if (reported > 0) sink.silent(0);
    reported = 0;
    last = clock::now();
    feed(chunk, static_cast<std::size_t>(n));
  }
  return "";
}

}  // namespace gfec::monitor
