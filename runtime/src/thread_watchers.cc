#include "thread_watchers.h"

namespace afp::detail {

using Clock = std::chrono::steady_clock;

WatchThread::WatchThread(Watch watch, Services& services, Arbiter& arbiter, std::optional<std::uint64_t> epoch,
                         Duration period)
    : watch_(watch), services_(services), arbiter_(arbiter), epoch_(epoch), period_(period), thread_([this] {
        run();
      }) {}

WatchThread::~WatchThread() {
  request_stop();
  thread_.join();
}

void WatchThread::request_stop() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  cv_.notify_all();
}

void WatchThread::run() {
  if (auto failure = start_watch(watch_, services_)) {
    arbiter_.fail(std::move(*failure));
  } else {
    for (auto next = Clock::now() + period_; sleep_until(next) && check();) {
      // Stay on the grid start + k * period; after an overrun, skip to the next slot.
      auto now = Clock::now();
      while (next <= now) next += period_;
    }
  }
  stop_watch(watch_);
}

bool WatchThread::sleep_until(Clock::time_point time) {
  std::unique_lock lock(mutex_);
  return !cv_.wait_until(lock, time, [this] { return stop_; });
}

bool WatchThread::check() {
  std::optional<std::uint64_t> epoch = epoch_ ? epoch_ : arbiter_.current();
  if (!epoch) return true;  // between two actors: nothing to interrupt
  auto claim = check_watch(watch_, services_);
  if (!claim) return true;
  if (claim->failed) {
    arbiter_.fail(std::move(*claim));
    return false;
  }
  // A local watch is over once it interrupted its actor; a global one goes on.
  return !arbiter_.claim(*epoch, std::move(*claim)) || !epoch_;
}

ThreadWatchers::~ThreadWatchers() {
  stop(local_);
  stop(global_);
}

void ThreadWatchers::start_global(const std::vector<Watch>& watches) { start(global_, watches, std::nullopt); }

void ThreadWatchers::start_local(const std::vector<Watch>& watches) { start(local_, watches, arbiter_.open()); }

void ThreadWatchers::start(std::vector<std::unique_ptr<WatchThread>>& list, const std::vector<Watch>& watches,
                           std::optional<std::uint64_t> epoch) {
  for (const Watch& watch : watches) {
    Duration period = watch.supervisor->period();
    if (period <= Duration::zero()) period = default_period_;
    list.push_back(std::make_unique<WatchThread>(watch, services_, arbiter_, epoch, period));
  }
}

void ThreadWatchers::stop(std::vector<std::unique_ptr<WatchThread>>& list) {
  for (auto& watch : list) watch->request_stop();  // all at once, then join each
  list.clear();
}

}  // namespace afp::detail
