#include "afp/link_trace.h"

#include <chrono>

#include "afp/plan.h"

namespace afp {

namespace {

// The wire format (docs/live.md "Plans"): the C engines' frame header, with kind bit 0x08.
constexpr unsigned char kSync0 = 0xA7, kSync1 = 0x5E, kVersion = 1;
constexpr unsigned char kKindPlan = 0x01 | 0x08;  // every plan frame is full: it holds the whole state
enum Record : unsigned { Started, Finished, Interrupted, Failed, Ended, State };

std::uint32_t fnv1a(const std::string& text) {
  std::uint32_t h = 2166136261u;
  for (unsigned char c : text) h = (h ^ c) * 16777619u;
  return h;
}

std::uint32_t crc32(const unsigned char* data, std::size_t n) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < n; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

void put32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<unsigned char>(v >> (8 * k)));
}

/// The index of `name` among `count` names, or `count` when it is none of them.
template <class NameOf>
std::uint32_t find(std::size_t count, std::string_view name, NameOf name_of) {
  for (std::size_t i = 0; i < count; ++i)
    if (name_of(i) == name) return static_cast<std::uint32_t>(i);
  return static_cast<std::uint32_t>(count);
}

}  // namespace

LinkTrace::LinkTrace(const Plan& plan, Write write, unsigned heartbeat_every)
    : write_(std::move(write)), heartbeat_every_(heartbeat_every > 0 ? heartbeat_every : 1) {
  std::string text = "gfec plan trace 1\n";
  describe(plan, "", text);
  fingerprint_ = fnv1a(text);
}

void LinkTrace::describe(const Plan& plan, const std::string& path, std::string& text) {
  levels_.push_back(Level{&plan});
  text += "plan " + plan.name() + "\n";
  for (std::size_t a = 0; a < plan.actor_count(); ++a)
    text += "actor " + plan.actor_name(a) + (plan.actor_at(a).nested_plan() ? " runs" : "") + "\n";
  for (std::size_t s = 0; s < plan.supervisor_count(); ++s) text += "supervisor " + plan.supervisor_name(s) + "\n";
  for (std::size_t a = 0; a < plan.actor_count(); ++a) {
    const Plan* sub = plan.actor_at(a).nested_plan();
    if (!sub) continue;
    const std::string inner = path + plan.actor_name(a);
    text += "instance " + inner + "\n";
    describe(*sub, inner + ".", text);
  }
}

std::size_t LinkTrace::level_of(const Plan& plan) const {
  for (std::size_t i = 0; i < levels_.size(); ++i)
    if (levels_[i].plan == &plan) return i;
  return levels_.size();
}

void LinkTrace::begin(Duration now, unsigned kind, std::size_t level) {
  payload_.clear();
  number(static_cast<std::uint32_t>(std::chrono::duration_cast<std::chrono::milliseconds>(now).count()));
  number(kind);
  number(static_cast<std::uint32_t>(level));
}

void LinkTrace::number(std::uint32_t value) {
  while (value >= 0x80) {
    payload_.push_back(static_cast<unsigned char>(value | 0x80));
    value >>= 7;
  }
  payload_.push_back(static_cast<unsigned char>(value));
}

void LinkTrace::signed_number(int value) {
  // Zigzag: 0, -1, 1, -2 ... as 0, 1, 2, 3 ...
  const auto v = static_cast<std::uint32_t>(value);
  number(value < 0 ? ((~v) << 1) | 1u : v << 1);
}

void LinkTrace::send() {
  for (const Level& l : levels_) number(l.active);
  frame_.clear();
  frame_.insert(frame_.end(), {kSync0, kSync1, kVersion, kKindPlan});
  frame_.push_back(static_cast<unsigned char>(payload_.size()));
  frame_.push_back(static_cast<unsigned char>(payload_.size() >> 8));
  put32(frame_, fingerprint_);
  put32(frame_, ++sequence_);
  frame_.insert(frame_.end(), payload_.begin(), payload_.end());
  put32(frame_, crc32(frame_.data(), frame_.size()));
  since_frame_ = 0;
  if (write_) write_(frame_.data(), frame_.size());
}

void LinkTrace::heartbeat(Duration now) {
  if (++since_frame_ < heartbeat_every_) return;
  begin(now, State, 0);
  send();
}

void LinkTrace::actor_started(const Plan& plan, std::string_view actor, Duration now) {
  const std::size_t level = level_of(plan);
  if (level == levels_.size()) return;  // not a plan of this trace's tree
  const std::uint32_t a = find(plan.actor_count(), actor, [&](std::size_t i) { return plan.actor_name(i); });
  levels_[level].active = a + 1;
  begin(now, Started, level);
  number(a);
  send();
}

void LinkTrace::actor_finished(const Plan& plan, std::string_view actor, int state, Duration now) {
  const std::size_t level = level_of(plan);
  if (level == levels_.size()) return;
  levels_[level].active = 0;
  begin(now, Finished, level);
  number(find(plan.actor_count(), actor, [&](std::size_t i) { return plan.actor_name(i); }));
  signed_number(state);
  send();
}

void LinkTrace::actor_interrupted(const Plan& plan, std::string_view actor, std::string_view supervisor, int event,
                                  Duration now) {
  const std::size_t level = level_of(plan);
  if (level == levels_.size()) return;
  levels_[level].active = 0;
  begin(now, Interrupted, level);
  number(find(plan.actor_count(), actor, [&](std::size_t i) { return plan.actor_name(i); }));
  number(find(plan.supervisor_count(), supervisor, [&](std::size_t i) { return plan.supervisor_name(i); }));
  signed_number(event);
  send();
}

void LinkTrace::component_failed(const Plan& plan, std::string_view component, std::string_view what, Duration now) {
  const std::size_t level = level_of(plan);
  if (level == levels_.size()) return;
  // Actors are numbered first, then supervisors after them.
  std::uint32_t c = find(plan.actor_count(), component, [&](std::size_t i) { return plan.actor_name(i); });
  if (c == plan.actor_count())
    c += find(plan.supervisor_count(), component, [&](std::size_t i) { return plan.supervisor_name(i); });
  std::size_t n = what.size() < kMaxMessage ? what.size() : kMaxMessage;
  // Never cut inside a UTF-8 sequence.
  while (n < what.size() && n > 0 && (static_cast<unsigned char>(what[n]) & 0xC0) == 0x80) --n;
  begin(now, Failed, level);
  number(c);
  number(static_cast<std::uint32_t>(n));
  payload_.insert(payload_.end(), what.begin(), what.begin() + static_cast<std::ptrdiff_t>(n));
  send();
}

void LinkTrace::plan_finished(const Plan& plan, Status status, Duration now) {
  const std::size_t level = level_of(plan);
  if (level == levels_.size()) return;
  levels_[level].active = 0;
  begin(now, Ended, level);
  number(static_cast<std::uint32_t>(status));
  send();
}

void TraceTee::actor_started(const Plan& plan, std::string_view actor, Duration now) {
  if (a_) a_->actor_started(plan, actor, now);
  if (b_) b_->actor_started(plan, actor, now);
}
void TraceTee::actor_finished(const Plan& plan, std::string_view actor, int state, Duration now) {
  if (a_) a_->actor_finished(plan, actor, state, now);
  if (b_) b_->actor_finished(plan, actor, state, now);
}
void TraceTee::actor_interrupted(const Plan& plan, std::string_view actor, std::string_view supervisor, int event,
                                 Duration now) {
  if (a_) a_->actor_interrupted(plan, actor, supervisor, event, now);
  if (b_) b_->actor_interrupted(plan, actor, supervisor, event, now);
}
void TraceTee::component_failed(const Plan& plan, std::string_view component, std::string_view what, Duration now) {
  if (a_) a_->component_failed(plan, component, what, now);
  if (b_) b_->component_failed(plan, component, what, now);
}
void TraceTee::plan_finished(const Plan& plan, Status status, Duration now) {
  if (a_) a_->plan_finished(plan, status, now);
  if (b_) b_->plan_finished(plan, status, now);
}

}  // namespace afp
