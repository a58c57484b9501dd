// Hands a decoded run to two sinks at once: `gfec monitor --log --http` prints the log and
// feeds the live page from one reading of the stream.
#pragma once

#include "run_sink.h"

namespace gfec::live {

class TeeSink final : public monitor::RunSink {
public:
  TeeSink(monitor::RunSink &a, monitor::RunSink &b) : a_(a), b_(b) {}
  void started(std::size_t robot) override {
    a_.started(robot);
    b_.started(robot);
  }
  void tick(const monitor::DecodedTick &t) override {
    a_.tick(t);
    b_.tick(t);
  }
  void lost(std::size_t robot, std::uint64_t ticks_missing, const std::string &why) override {
    a_.lost(robot, ticks_missing, why);
    b_.lost(robot, ticks_missing, why);
  }
  void silent(double seconds) override {
    a_.silent(seconds);
    b_.silent(seconds);
  }
  void ended(const std::string &why) override {
    a_.ended(why);
    b_.ended(why);
  }

private:
  monitor::RunSink &a_, &b_;
};

}  // namespace gfec::live
