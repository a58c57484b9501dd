#include "log_sink.h"

#include <fmt/format.h>

namespace gfec::monitor {

LogSink::LogSink(const model::Model &model, model::ChartId chart, std::ostream &out) : out_(out) {
  const model::Chart &c = model.charts.at(chart);
  places_ = c.places.size();
  team_ = c.team > 0;
  if (c.kind == model::Chart::Kind::Fsm)
    for (const auto &p : c.places) states_.push_back(p.name.str());
}

void LogSink::tick(const DecodedTick &t) {
  std::string text = fmt::format("tick {}\n", t.tick);
  if (team_) text += fmt::format("agent {}\n", t.agent);
  for (const auto &call : t.calls) text += "call " + call + "\n";
  text += "av";
  for (std::size_t p = 0; p < places_ && p < t.activation.size(); ++p) text += fmt::format(" {}", t.activation[p]);
  text += "\n";
  if (!states_.empty()) {
    std::string state = "?";
    for (std::size_t p = 0; p < places_ && p < t.activation.size(); ++p)
      if (t.activation[p] != 0) state = states_[p];
    text += fmt::format("state {} {}\n", state, t.status);
  }
  out_ << text;
  out_.flush();  // a live log: each tick as it arrives
}

void LogSink::lost(std::size_t, std::uint64_t ticks_missing, const std::string &why) {
  if (ticks_missing > 0)
    out_ << fmt::format("# lost {} tick{}: {}\n", ticks_missing, ticks_missing == 1 ? "" : "s", why);
  else out_ << fmt::format("# lost: {}\n", why);
  out_.flush();
}

void LogSink::silent(double seconds) {
  if (seconds > 0) out_ << fmt::format("# silent for {:.1f} s\n", seconds);
  else out_ << "# data again\n";
  out_.flush();
}

}  // namespace gfec::monitor
