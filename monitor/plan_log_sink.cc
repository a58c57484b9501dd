#include "plan_log_sink.h"

#include <fmt/format.h>

namespace gfec::monitor {

void PlanLogSink::event(const DecodedPlanEvent &e) {
  std::string text;
  if (say_state_) {
    // The frame's state: what runs, so that the lines after a loss can be read.
    std::string running;
    for (std::size_t i = 0; i < e.active.size() && i < layout_.levels.size(); ++i)
      if (e.active[i] > 0)
        running += fmt::format(" {}.{}", model_.plans.at(layout_.levels[i].plan).name,
                               layout_.levels[i].actors[e.active[i] - 1]);
    text += fmt::format("# at {} ms running:{}\n", e.ms, running.empty() ? " nothing" : running);
    say_state_ = false;
  }
  if (!e.text.empty()) text += fmt::format("{} {}\n", e.ms, e.text);
  out_ << text;
  out_.flush();  // a live log: each event as it arrives
}

void PlanLogSink::lost(std::size_t, std::uint64_t events_missing, const std::string &why) {
  if (events_missing > 0)
    out_ << fmt::format("# lost {} event{}: {}\n", events_missing, events_missing == 1 ? "" : "s", why);
  else out_ << fmt::format("# lost: {}\n", why);
  out_.flush();
  say_state_ = true;
}

void PlanLogSink::silent(double seconds) {
  if (seconds > 0) out_ << fmt::format("# silent for {:.1f} s\n", seconds);
  else out_ << "# data again\n";
  out_.flush();
}

}  // namespace gfec::monitor
