// carbot-sim --trace-to tcp:HOST:PORT (docs/live.md "The simulator live"): each robot's engine is
// built with gfec --trace, and the frames it writes through its X_trace_write go down a TCP
// connection of that robot's own, as a robot's would: carbot-sim listens on HOST:PORT, and the run
// starts once one `gfec monitor CHART --tcp HOST:PORT` per robot has connected. At real time.
#pragma once

#include <string>
#include <vector>

namespace carbot::driver {

class TraceLinks {
 public:
  /// Listens on `spec` ("tcp:HOST:PORT", port 0: a free one, printed) and accepts `robots`
  /// connections, robot 0's first; "" or why not.
  std::string open(const std::string& spec, int robots, double period);
  bool active() const { return !sockets_.empty(); }
  /// The robot whose engine ticks next: its frames go to its connection. Robot 0's ticks keep
  /// the run at real time: the k-th waits until k periods have passed since the first, so the
  /// page shows the run as it goes (by ticks, not frames: a plan writes a frame per event).
  void select(int robot);
  /// A frame from the selected robot's engine.
  void write(const unsigned char* data, unsigned len);
  void close();
  ~TraceLinks() { close(); }

 private:
  std::vector<int> sockets_;
  std::vector<bool> broken_;
  int current_ = 0;
  double period_ = 0.01;
  long ticks_ = 0;
  double start_ = 0;
};

/// The run's links (the engines' shims call carbot_sim_trace, which writes to them).
TraceLinks& trace_links();

}  // namespace carbot::driver

/// Called by a traced engine's shim with each frame (exported from carbot-sim).
extern "C" void carbot_sim_trace(const unsigned char* data, unsigned len);
