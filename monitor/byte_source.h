// Where a live trace comes from (docs/live.md): stdin, a serial port (termios, raw mode), or a
// TCP connection the monitor opens to the robot or simulator, which listens. Each gives a file
// descriptor that read_stream() reads until the end, reporting silence.
#pragma once

#include "run_sink.h"

#include <functional>
#include <string>

namespace gfec::monitor {

/// Opens `device` as a serial port at `baud` (raw, 8N1, no flow control); -1 and `error` set when
/// it cannot (not a terminal, a rate Linux does not have).
int open_serial(const std::string &device, long baud, std::string &error);
/// Connects to "HOST:PORT"; -1 and `error` set when it cannot.
int open_tcp(const std::string &address, std::string &error);

/// Reads `fd` until its end, giving every chunk to `feed`; after `silence` seconds (> 0) with no
/// byte, and again each further `silence` seconds, calls sink.silent(time), and silent(0) when
/// bytes come again. Returns "" at the end of the stream, else the read error; stops early when
/// `stop` returns true.
std::string read_stream(int fd, double silence, RunSink &sink,
                        const std::function<void(const unsigned char *, std::size_t)> &feed,
                        const std::function<bool()> &stop);

}  // namespace gfec::monitor
