// Internal: supervisors checked inside the level's step, at their period in
// plan time, in a fixed order (the stepped executor's determinism).
#pragma once

#include <optional>
#include <vector>

#include "services.h"

namespace afp::detail {

/// Checks due supervisors on poll(): global ones, then the actor's own, each
/// in declaration order; the first claim wins and the rest are not checked.
class StepWatchers final : public Watchers {
 public:
  explicit StepWatchers(Services& services) : services_(services) {}

  void start_global(const std::vector<Watch>& watches) override { start(global_, watches); }
  void start_local(const std::vector<Watch>& watches) override { start(local_, watches); }
  std::optional<Claim> poll() override;
  /// Nothing can claim between poll() and the actor's finish in one thread.
  std::optional<Claim> close() override { return std::nullopt; }
  void stop_local() override { stop(local_); }
  void stop_global() override { stop(global_); }

 private:
  struct Entry {
    Watch watch;
    Duration next_check;  // unused when the period is zero (every step)
    std::optional<Claim> start_failure;
  };

  void start(std::vector<Entry>& list, const std::vector<Watch>& watches);
  void stop(std::vector<Entry>& list);
  std::optional<Claim> poll(std::vector<Entry>& list, Duration now);

  Services& services_;
  std::vector<Entry> global_;
  std::vector<Entry> local_;
};

}  // namespace afp::detail
