// Internal: decides, under one mutex, which single component ends the active
// actor in the threaded executor (docs/runtime.md 2.2).
#pragma once

#include <cstdint>
#include <mutex>
#include <optional>

#include "services.h"
#include "waker.h"

namespace afp::detail {

/// One per plan level. Each actor run is an epoch; the first claim for the
/// current epoch wins and closes it, as does the actor finishing first.
/// Failures are kept whatever the epoch: they end the level.
class Arbiter {
 public:
  explicit Arbiter(Waker& waker) : waker_(waker) {}

  /// A new actor runs: opens a new epoch with no claim; returns it.
  std::uint64_t open();

  /// The open epoch, or nothing between two actors.
  std::optional<std::uint64_t> current() const;

  /// Offers an interrupting claim for `epoch`; true if it won.
  bool claim(std::uint64_t epoch, Claim claim);

  /// Reports a supervisor's failure (the first one is kept).
  void fail(Claim failure);

  /// The failure or winning claim, if any (the executor's thread).
  std::optional<Claim> take();

  /// The actor finished: closes the epoch; returns a failure or a claim that
  /// came first, if any.
  std::optional<Claim> close();

 private:
  std::optional<Claim> take_locked();

  Waker& waker_;
  mutable std::mutex mutex_;
  std::uint64_t epoch_ = 0;
  bool open_ = false;
  std::optional<Claim> winner_;
  std::optional<Claim> failure_;
};

}  // namespace afp::detail
