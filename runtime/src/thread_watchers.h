// Internal: supervisors polled by their own threads (the threaded executor).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "arbiter.h"
#include "services.h"
#include "waker.h"

namespace afp::detail {

/// One supervisor's thread: start(), check() every period, stop(), all in
/// that thread, so a supervisor object is never used by two threads at once.
class WatchThread {
 public:
  /// Starts the thread. A local watch claims for `epoch` (its actor's run);
  /// a global one (no epoch) for whichever actor runs when it checks.
  WatchThread(Watch watch, Services& services, Arbiter& arbiter, std::optional<std::uint64_t> epoch, Duration period);
  /// Stops and joins.
  ~WatchThread();
  WatchThread(const WatchThread&) = delete;
  WatchThread& operator=(const WatchThread&) = delete;

  /// Asks the thread to end (returns at once).
  void request_stop();

 private:
  void run();
  bool sleep_until(std::chrono::steady_clock::time_point time);  // false when asked to stop
  bool check();                                                  // false when the watch is over

  Watch watch_;
  Services& services_;
  Arbiter& arbiter_;
  const std::optional<std::uint64_t> epoch_;
  const Duration period_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool stop_ = false;
  std::thread thread_;  // last: starts once every member above is ready
};

/// The threaded Watchers: one WatchThread per active supervisor, one Arbiter.
class ThreadWatchers final : public Watchers {
 public:
  /// Watchers whose claims wake `waker`; `default_period` replaces a zero period.
  ThreadWatchers(Services& services, Waker& waker, Duration default_period)
      : services_(services), arbiter_(waker), default_period_(default_period) {}
  ~ThreadWatchers() override;

  void start_global(const std::vector<Watch>& watches) override;
  void start_local(const std::vector<Watch>& watches) override;
  std::optional<Claim> poll() override { return arbiter_.take(); }
  std::optional<Claim> close() override { return arbiter_.close(); }
  void stop_local() override { stop(local_); }
  void stop_global() override { stop(global_); }

 private:
  void start(std::vector<std::unique_ptr<WatchThread>>& list, const std::vector<Watch>& watches,
             std::optional<std::uint64_t> epoch);
  static void stop(std::vector<std::unique_ptr<WatchThread>>& list);

  Services& services_;
  Arbiter arbiter_;
  const Duration default_period_;
  std::vector<std::unique_ptr<WatchThread>> global_;
  std::vector<std::unique_ptr<WatchThread>> local_;
};

}  // namespace afp::detail
