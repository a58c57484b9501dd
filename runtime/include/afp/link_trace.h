// The plan's trace over a link (a UART, a socket): a TraceObserver that encodes every event as
// one framed, checksummed binary record that `gfec monitor PLAN.plan` decodes (docs/live.md
// "Plans"). The plan analogue of a C engine's X_trace_write.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "afp/trace.h"

namespace afp {

/// Writes each event of a plan (and of its sub-plans) as one frame through `write`. Every frame
/// carries the fingerprint of the plan's shape (names of the plans, actors and supervisors, in
/// order), a sequence number and the active actor of every plan level, so a monitor that joins
/// late or loses bytes is exact again at the next intact frame.
///
/// Called by the executor's thread only, as every observer; heartbeat() must be called from that
/// same thread (with the SteppedExecutor: after step()).
class LinkTrace final : public TraceObserver {
 public:
  /// Receives one whole frame; copy or send it (the buffer is gone when it returns). It must not
  /// call back into the executor.
  using Write = std::function<void(const unsigned char* data, std::size_t length)>;

  /// The longest failure message a frame carries, in bytes; a longer one is cut.
  static constexpr std::size_t kMaxMessage = 200;

  /// Numbers the levels of `plan` (the plan, then each sub-plan actor's plan, depth first in
  /// declaration order). `heartbeat_every`: see heartbeat() (at least 1).
  LinkTrace(const Plan& plan, Write write, unsigned heartbeat_every = 32);

  /// The plan's fingerprint, as gfec computes it from the plan's text.
  std::uint32_t fingerprint() const { return fingerprint_; }

  /// Call once per executor step (optional): when `heartbeat_every` calls have passed without a
  /// frame, sends a frame of the plan's state alone, so that a monitor that joins while one actor
  /// runs for long learns what runs.
  void heartbeat(Duration now);

  void actor_started(const Plan& plan, std::string_view actor, Duration now) override;
  void actor_finished(const Plan& plan, std::string_view actor, int state, Duration now) override;
  void actor_interrupted(const Plan& plan, std::string_view actor, std::string_view supervisor, int event,
                         Duration now) override;
  void component_failed(const Plan& plan, std::string_view component, std::string_view what, Duration now) override;
  void plan_finished(const Plan& plan, Status status, Duration now) override;

 private:
  struct Level {
    const Plan* plan;
    std::uint32_t active = 0;  ///< the running actor's number + 1, 0 for none
  };
  void describe(const Plan& plan, const std::string& path, std::string& text);
  std::size_t level_of(const Plan& plan) const;
  /// Starts a frame's payload: the time, the record kind and the level.
  void begin(Duration now, unsigned kind, std::size_t level);
  void number(std::uint32_t value);
  void signed_number(int value);
  void send();

  Write write_;
  std::vector<Level> levels_;
  std::uint32_t fingerprint_ = 0;
  std::uint32_t sequence_ = 0;
  unsigned heartbeat_every_;
  unsigned since_frame_ = 0;
  std::vector<unsigned char> payload_;
  std::vector<unsigned char> frame_;
};

/// Fans an executor's one observer out to two (a LinkTrace and a log, say); either may be null.
class TraceTee final : public TraceObserver {
 public:
  TraceTee(TraceObserver* first, TraceObserver* second) : a_(first), b_(second) {}
  void actor_started(const Plan& plan, std::string_view actor, Duration now) override;
  void actor_finished(const Plan& plan, std::string_view actor, int state, Duration now) override;
  void actor_interrupted(const Plan& plan, std::string_view actor, std::string_view supervisor, int event,
                         Duration now) override;
  void component_failed(const Plan& plan, std::string_view component, std::string_view what, Duration now) override;
  void plan_finished(const Plan& plan, Status status, Duration now) override;

 private:
  TraceObserver* a_;
  TraceObserver* b_;
};

}  // namespace afp
