#include "step_watchers.h"

#include <utility>

namespace afp::detail {

std::optional<Claim> StepWatchers::poll() {
  Duration now = services_.now();
  if (auto claim = poll(global_, now)) return claim;
  return poll(local_, now);
}

void StepWatchers::start(std::vector<Entry>& list, const std::vector<Watch>& watches) {
  Duration now = services_.now();
  for (const Watch& watch : watches)
    list.push_back(Entry{watch, now + watch.supervisor->period(), start_watch(watch, services_)});
}

void StepWatchers::stop(std::vector<Entry>& list) {
  for (const Entry& entry : list) stop_watch(entry.watch);
  list.clear();
}

std::optional<Claim> StepWatchers::poll(std::vector<Entry>& list, Duration now) {
  for (Entry& entry : list) {
    if (entry.start_failure) return std::exchange(entry.start_failure, std::nullopt);
    Duration period = entry.watch.supervisor->period();
    if (period > Duration::zero()) {
      if (now < entry.next_check) continue;
      // Stay on the grid start + k * period; a long step checks once, not once per missed period.
      while (entry.next_check <= now) entry.next_check += period;
    }
    if (auto claim = check_watch(entry.watch, services_)) return claim;
  }
  return std::nullopt;
}

}  // namespace afp::detail
