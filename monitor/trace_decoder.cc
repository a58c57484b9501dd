#include "trace_decoder.h"

#include "interpreter/value.h"
#include "plan_trace_format.h"

#include <fmt/format.h>

#include <cstring>

namespace gfec::monitor {

namespace {

/// The longest plan frame payload read to refuse it: a plan of several hundred levels.
constexpr std::size_t kMaxPlanFrameRead = 4096;

}  // namespace

TraceDecoder::TraceDecoder(const model::Model &model, const trace::Layout &layout, RunSink &sink, std::size_t robot)
    : model_(model), layout_(layout), sink_(sink), robot_(robot), values_(layout.values, 0),
      scratch_(layout.values, 0) {}

std::optional<std::size_t> TraceDecoder::max_payload(std::uint8_t kind) const {
  // A plan's frame (afp::LinkTrace) is read only to refuse the stream with a clear message.
  if (kind == (trace::kFlagFull | trace::kFlagPlan)) return kMaxPlanFrameRead;
  if ((kind & ~(trace::kFlagFull | trace::kFlagCalls | trace::kFlagCallsCut)) != 0) return std::nullopt;
  return layout_.max_payload();
}

int TraceDecoder::frame_at_front() {
  Frame f;
  if (const int r = intact_frame_at_front(f); r <= 0) return r;
  const std::uint8_t *p = f.p;
  const bool plan = p[3] == (trace::kFlagFull | trace::kFlagPlan);
  // A whole frame, intact: now its version and chart count.
  if (p[2] != trace::kVersion) {
    refusal_ = fmt::format("the stream's frames are of format version {}; this gfec reads version {}", p[2],
                           static_cast<int>(trace::kVersion));
    sink_.ended(refusal_);
    return 1;
  }
  if (plan) {
    refusal_ = fmt::format("the stream comes from a plan's afp::LinkTrace (fingerprint {:08x}), not from a chart's "
                           "engine (give the monitor the plan the program was built from)",
                           le32(p + 6));
    sink_.ended(refusal_);
    return 1;
  }
  if (le32(p + 6) != layout_.fingerprint) {
    refusal_ = fmt::format("the stream comes from another chart: its fingerprint is {:08x}, the chart's {:08x} "
                           "(rebuild the engine from this chart with --trace, or give the monitor the chart it "
                           "was built from)",
                           le32(p + 6), layout_.fingerprint);
    sink_.ended(refusal_);
    return 1;
  }
  const std::size_t before = at_;
  frame(p[3], le32(p + 10), p + trace::kHeaderBytes, f.length);
  if (at_ == before) at_ += f.size;
  return 1;
}

bool TraceDecoder::read_calls(const std::uint8_t *payload, std::size_t length, std::size_t &at) {
  std::uint32_t size = 0;
  if (!read_number(payload, length, at, size) || size > length - at) return false;
  const std::size_t end = at + size;
  if (calls_cut_) {  // cut anywhere, even inside a record: nothing of it is shown
    at = end;
    return true;
  }
  while (at < end) {
    std::uint32_t index = 0;
    if (!read_number(payload, end, at, index) || index >= model_.functions.size()) return false;
    const model::Function &f = model_.functions.at(model::FunctionId(index));
    auto value = [&](model::Type type, interp::Value &v) {
      std::uint32_t n = 0;
      switch (type) {
      case model::Type::Bool:
        if (!read_number(payload, end, at, n) || n > 1) return false;
        v = interp::Value::of_bool(n != 0);
        return true;
      case model::Type::Float: {
        if (end - at < 4) return false;
        float x = 0;
        std::uint8_t bytes[4];
        for (int k = 0; k < 4; ++k) bytes[k] = payload[at + static_cast<std::size_t>(k)];
        std::memcpy(&x, bytes, 4);
        at += 4;
        v = interp::Value::of_float(x);
        return true;
      }
      case model::Type::Double: {
        if (end - at < 8) return false;
        double x = 0;
        std::uint8_t bytes[8];
        for (int k = 0; k < 8; ++k) bytes[k] = payload[at + static_cast<std::size_t>(k)];
        std::memcpy(&x, bytes, 8);
        at += 8;
        v = interp::Value::of_double(x);
        return true;
      }
      default:
        if (!read_number(payload, end, at, n)) return false;
        // 0, 1, 2, 3 ... are 0, -1, 1, -2 ...
        v = interp::Value::of_int((n & 1u) != 0 ? -static_cast<std::int32_t>(n >> 1) - 1
                                                : static_cast<std::int32_t>(n >> 1));
        return true;
      }
    };
    std::string text = f.name + "(";
    for (std::size_t i = 0; i < f.params.size(); ++i) {
      interp::Value v;
      if (!value(f.params[i].type, v)) return false;
      text += (i ? ", " : "") + interp::format_value(v);
    }
    text += ")";
    if (f.result != model::Type::Void) {
      interp::Value v;
      if (!value(f.result, v)) return false;
      text += " = " + interp::format_value(v);
    }
    calls_.push_back(std::move(text));
  }
  return at == end;
}

void TraceDecoder::frame(std::uint8_t kind, std::uint32_t tick, const std::uint8_t *payload, std::size_t length) {
  if (!started_) {
    started_ = true;
    sink_.started(robot_);
  }
  const bool full = (kind & trace::kFlagFull) != 0;
  has_calls_ = (kind & trace::kFlagCalls) != 0;
  calls_cut_ = (kind & trace::kFlagCallsCut) != 0;
  calls_.clear();
  std::size_t at = 0;
  bool ok = !has_calls_ || read_calls(payload, length, at);
  if (full) {
    for (std::size_t i = 0; ok && i < layout_.values; ++i) ok = read_number(payload, length, at, scratch_[i]);
  } else {
    ok = ok && exact_ && tick == last_seen_ + 1;
    if (ok) scratch_ = values_;
    while (ok && at < length) {
      std::uint32_t index = 0, value = 0;
      ok = read_number(payload, length, at, index) && index < layout_.values && read_number(payload, length, at, value);
      if (ok) scratch_[index] = value;
    }
  }
  ok = ok && at == length;
  last_seen_ = tick;
  exact_ = ok;
  if (!ok) return;  // lost: said when the next tick is shown
  values_.swap(scratch_);
  show(tick);
}

void TraceDecoder::show(std::uint32_t tick) {
  if (tick != last_shown_ + 1 || garbled_ > 0) {
    std::string why;
    std::uint64_t missing = tick > last_shown_ ? tick - last_shown_ - 1 : 0;
    if (tick <= last_shown_) why = fmt::format("the engine started again (tick {} after {})", tick, last_shown_);
    else if (last_shown_ == 0 && garbled_ == 0) why = fmt::format("the stream joined the run at tick {}", tick);
    else if (garbled_ > 0) why = fmt::format("bad CRC or garbled bytes ({} skipped)", garbled_);
    else why = "frames missing from the stream";
    if (missing > 0 || garbled_ > 0 || tick <= last_shown_) sink_.lost(robot_, missing, why);
    lost_ += missing;
  }
  garbled_ = 0;
  last_shown_ = tick;
  ++shown_;
  DecodedTick t;
  t.robot = robot_;
  t.tick = tick;
  t.has_calls = has_calls_ && !calls_cut_;
  t.calls_cut = calls_cut_;
  t.calls = calls_;
  std::size_t activation = layout_.values;
  if (layout_.status >= 0) activation = static_cast<std::size_t>(layout_.status);
  else if (layout_.agent >= 0) activation = static_cast<std::size_t>(layout_.agent);
  t.activation.assign(values_.begin(), values_.begin() + static_cast<std::ptrdiff_t>(activation));
  if (layout_.status >= 0) {
    const std::uint32_t s = values_[static_cast<std::size_t>(layout_.status)];
    t.status = s == 0 ? "running" : s == 1 ? "succeeded" : "failed";
  }
  if (layout_.agent >= 0) {
    const auto a = static_cast<std::size_t>(layout_.agent);
    t.agent = static_cast<int>(values_[a]);
    for (std::size_t k = 0; k < layout_.team; ++k)
      t.reports.push_back(static_cast<std::int32_t>(values_[a + 1 + k]) - 1);
  }
  sink_.tick(t);
}

void TraceDecoder::finish() {
  if (refused()) return;
  const std::size_t rest = drop_rest();
  if (rest > 0 || garbled_ > 0) {
    sink_.lost(robot_, 0,
               rest > 0 ? fmt::format("the stream ended inside a frame ({} bytes)", rest)
                        : fmt::format("garbled bytes at the end of the stream ({} skipped)", garbled_));
  }
  garbled_ = 0;
}

}  // namespace gfec::monitor
