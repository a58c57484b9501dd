// Internal: wakes the threaded executor's main loop before its period ends.
#pragma once

#include <condition_variable>
#include <mutex>

#include "afp/context.h"

namespace afp::detail {

/// A signal the executor's thread sleeps on between actor steps; a winning
/// claim or a stop request raises it, so reactions do not wait a whole period.
class Waker {
 public:
  /// Raises the signal (any thread).
  void notify() {
    {
      std::lock_guard lock(mutex_);
      signaled_ = true;
    }
    cv_.notify_all();
  }

  /// Sleeps until the signal or `timeout`, then lowers the signal.
  void wait_for(Duration timeout) {
    std::unique_lock lock(mutex_);
    cv_.wait_for(lock, timeout, [this] { return signaled_; });
    signaled_ = false;
  }

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  bool signaled_ = false;
};

}  // namespace afp::detail
