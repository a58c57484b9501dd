// `gfec monitor --log`: the decoded run in gfec run's observable log format (docs/verification.md
// "The log"), so that it can be diffed against the reference interpreter's. What the monitor adds
// (loss, silence) are lines beginning with `#`, which no log line does.
#pragma once

#include "model.h"
#include "run_sink.h"

#include <ostream>
#include <string>
#include <vector>

namespace gfec::monitor {

class LogSink : public RunSink {
public:
  LogSink(const model::Model &model, model::ChartId chart, std::ostream &out);
  void started(std::size_t) override {}
  void tick(const DecodedTick &t) override;
  void lost(std::size_t robot, std::uint64_t ticks_missing, const std::string &why) override;
  void silent(double seconds) override;
  void ended(const std::string &) override {}

private:
  std::vector<std::string> states_;  ///< an fsm's state names, empty for an sfc
  std::size_t places_ = 0;
  bool team_ = false;
  std::ostream &out_;
};

}  // namespace gfec::monitor
