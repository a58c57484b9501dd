#include "plan_decoder.h"

#include <fmt/format.h>

namespace gfec::monitor {

namespace {

int zigzag(std::uint32_t n) { return (n & 1u) != 0 ? -static_cast<int>(n >> 1) - 1 : static_cast<int>(n >> 1); }

/// afp::to_string of the runtime's Status, by its number.
const char *const kStatus[] = {"not started", "running", "succeeded", "interrupted", "failed", "stopped"};

constexpr std::uint8_t kPlanKind = trace::kFlagFull | trace::kFlagPlan;
constexpr std::uint8_t kChartKinds = trace::kFlagFull | trace::kFlagCalls | trace::kFlagCallsCut;

}  // namespace

PlanTraceDecoder::PlanTraceDecoder(const model::Model &model, const trace::PlanLayout &layout, PlanSink &sink)
    : model_(model), layout_(layout), sink_(sink) {}

std::optional<std::size_t> PlanTraceDecoder::max_payload(std::uint8_t kind) const {
  // A chart engine's frame (any kind without kFlagPlan) is read only to refuse the stream.
  if (kind != kPlanKind && (kind & ~kChartKinds) != 0) return std::nullopt;
  return layout_.max_payload();
}

int PlanTraceDecoder::frame_at_front() {
  Frame f;
  if (const int r = intact_frame_at_front(f); r <= 0) return r;
  const std::uint8_t *p = f.p;
  if (p[2] != trace::kVersion) {
    refusal_ = fmt::format("the stream's frames are of format version {}; this gfec reads version {}", p[2],
                           static_cast<int>(trace::kVersion));
    sink_.ended(refusal_);
    return 1;
  }
  if (p[3] != kPlanKind) {
    refusal_ = fmt::format("the stream comes from the C engine of a chart (fingerprint {:08x}), not from a plan's "
                           "afp::LinkTrace (give the monitor the chart the engine was built from)",
                           le32(p + 6));
    sink_.ended(refusal_);
    return 1;
  }
  if (le32(p + 6) != layout_.fingerprint) {
    refusal_ = fmt::format("the stream comes from another plan: its fingerprint is {:08x}, the plan's {:08x} "
                           "(rebuild the program from this plan's generated wiring, or give the monitor the plan "
                           "it was built from)",
                           le32(p + 6), layout_.fingerprint);
    sink_.ended(refusal_);
    return 1;
  }
  if (!started_) {
    started_ = true;
    sink_.started(0);
  }
  DecodedPlanEvent e;
  e.sequence = le32(p + 10);
  if (decode(p + trace::kHeaderBytes, f.length, e)) show(e);
  else ++bad_;  // intact but not this plan's record: said with the next event shown
  at_ += f.size;
  return 1;
}

bool PlanTraceDecoder::decode(const std::uint8_t *payload, std::size_t length, DecodedPlanEvent &e) const {
  std::size_t at = 0;
  std::uint32_t record = 0, level = 0;
  if (!read_number(payload, length, at, e.ms) || !read_number(payload, length, at, record) ||
      record > static_cast<std::uint32_t>(trace::PlanRecord::State) || !read_number(payload, length, at, level) ||
      level >= layout_.levels.size())
    return false;
  e.record = static_cast<trace::PlanRecord>(record);
  e.level = level;
  const trace::PlanLevel &l = layout_.levels[level];
  const std::string plan = model_.plans.at(l.plan).name;
  std::uint32_t a = 0, b = 0, c = 0;
  switch (e.record) {
  case trace::PlanRecord::Started:
    if (!read_number(payload, length, at, a) || a >= l.actors.size()) return false;
    e.text = fmt::format("start {}.{}", plan, l.actors[a]);
    e.actor = a;
    break;
  case trace::PlanRecord::Finished:
    if (!read_number(payload, length, at, a) || a >= l.actors.size() || !read_number(payload, length, at, b))
      return false;
    e.text = fmt::format("finish {}.{} state {}", plan, l.actors[a], zigzag(b));
    e.actor = a;
    break;
  case trace::PlanRecord::Interrupted:
    if (!read_number(payload, length, at, a) || a >= l.actors.size() || !read_number(payload, length, at, b) ||
        b >= l.supervisors.size() || !read_number(payload, length, at, c))
      return false;
    e.text = fmt::format("interrupt {}.{} by {} event {}", plan, l.actors[a], l.supervisors[b], zigzag(c));
    e.actor = a;
    e.supervisor = b;
    break;
  case trace::PlanRecord::Failed: {
    if (!read_number(payload, length, at, a) || a >= l.actors.size() + l.supervisors.size() ||
        !read_number(payload, length, at, b) || b > trace::kMaxPlanMessage || b > length - at)
      return false;
    const std::string &who = a < l.actors.size() ? l.actors[a] : l.supervisors[a - l.actors.size()];
    // A control character would break the log's lines (or fake a monitor's `#` line): a blank.
    std::string what(reinterpret_cast<const char *>(payload + at), static_cast<std::size_t>(b));
    for (char &ch : what)
      if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7F) ch = ' ';
    e.text = fmt::format("fail {}.{}: {}", plan, who, what);
    at += b;
    break;
  }
  case trace::PlanRecord::Ended:
    if (!read_number(payload, length, at, a) || a >= std::size(kStatus)) return false;
    e.text = fmt::format("end {} {}", plan, kStatus[a]);
    e.status = kStatus[a];
    break;
  case trace::PlanRecord::State: break;
  }
  e.active.assign(layout_.levels.size(), 0);
  for (std::size_t i = 0; i < layout_.levels.size(); ++i)
    if (!read_number(payload, length, at, e.active[i]) || e.active[i] > layout_.levels[i].actors.size()) return false;
  return at == length;
}

void PlanTraceDecoder::show(DecodedPlanEvent &e) {
  const std::uint32_t seq = e.sequence;
  if (seq != last_shown_ + 1 || garbled_ > 0 || bad_ > 0) {
    std::string why;
    const std::uint64_t missing = seq > last_shown_ ? seq - last_shown_ - 1 : 0;
    if (seq <= last_shown_) why = fmt::format("the plan's trace started again (event {} after {})", seq, last_shown_);
    else if (last_shown_ == 0 && garbled_ == 0 && bad_ == 0)
      why = fmt::format("the stream joined the run at event {}", seq);
    else if (garbled_ > 0) why = fmt::format("bad CRC or garbled bytes ({} skipped)", garbled_);
    else if (bad_ > 0) why = fmt::format("{} frame{} this plan cannot decode", bad_, bad_ == 1 ? "" : "s");
    else why = "frames missing from the stream";
    if (missing > 0 || garbled_ > 0 || bad_ > 0 || seq <= last_shown_) sink_.lost(0, missing, why);
    lost_ += missing;
  }
  garbled_ = 0;
  bad_ = 0;
  last_shown_ = seq;
  ++shown_;
  if (e.record != trace::PlanRecord::State) ++events_;
  sink_.event(e);
}

void PlanTraceDecoder::finish() {
  if (refused()) return;
  const std::size_t rest = drop_rest();
  if (rest > 0 || garbled_ > 0 || bad_ > 0) {
    sink_.lost(0, 0,
               rest > 0       ? fmt::format("the stream ended inside a frame ({} bytes)", rest)
               : garbled_ > 0 ? fmt::format("garbled bytes at the end of the stream ({} skipped)", garbled_)
                              : "a frame at the end of the stream this plan cannot decode");
  }
  garbled_ = 0;
  bad_ = 0;
}

}  // namespace gfec::monitor
