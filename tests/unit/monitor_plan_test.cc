// A plan's live trace (docs/live.md "Plans"): the afp runtime's LinkTrace, wired by hand as the cpp
// back end wires a plan, against gfec's own reading of the same plan text: the two fingerprints
// agree (and differ for another plan), the frames are laid out byte for byte as documented, and
// the decoder gives the events back as an observer's log — read in any chunking, after garbled
// bytes, joined late, or refused for another plan. Runs of generated plans are
// tests/cli/monitor_plan.sh's.
#include "../run/cpp_backend_support.h"

#include "plan_decoder.h"
#include "plan_log_sink.h"
#include "plan_trace_format.h"

#include <afp/afp.h>

#include <catch2/catch.hpp>

#include <sstream>

using namespace cppt;
using namespace std::chrono_literals;

namespace {

const char *const kToolbox = R"(toolbox Bot {
  actor Go() -> DONE | AGAIN;
  supervisor Bump() events HIT;
}
)";

// Outer runs Inner as its actor `sub`; supervisors: g (global), t (x's), then Inner's s.
const char *const kPlans = R"(import "bot.toolbox";
plan Inner {
  supervise s: Bump() { HIT -> terminate; }
  start a;
  actor a: Go() { DONE -> terminate; AGAIN -> b; }
  actor b: Go() { DONE -> terminate; AGAIN -> a; }
}
plan Outer {
  supervise g: Bump() { HIT -> terminate; }
  start x;
  actor x: Go() {
    DONE -> sub; AGAIN -> x;
    supervise t: Bump() { HIT -> x; }
  }
  actor sub: Inner() { OK -> terminate; INTERRUPTED -> x; ERROR -> terminate; }
}
)";

struct Go : afp::Actor {
  afp::StepResult step(afp::Context &) override { return 0; }
};
struct Bump : afp::Supervisor {
  afp::CheckResult check(afp::Context &) override { return afp::no_event; }
};

/// Outer as gfec's cpp back end adds its instances: actors in declaration order, supervisors
/// global first, then each actor's.
std::unique_ptr<afp::Plan> wire_outer(const std::string &renamed_actor = "x") {
  auto inner = std::make_unique<afp::Plan>("Inner");
  auto *s = inner->add_supervisor("s", std::make_unique<Bump>());
  auto *a = inner->add_actor("a", std::make_unique<Go>());
  auto *b = inner->add_actor("b", std::make_unique<Go>());
  inner->define_first_actor(a);
  inner->define_global_supervision(s, 0, afp::terminate);
  inner->define_subsequent(a, 0, afp::terminate);
  inner->define_subsequent(b, 0, afp::terminate);
  auto outer = std::make_unique<afp::Plan>("Outer");
  auto *x = outer->add_actor(renamed_actor, std::make_unique<Go>());
  auto *sub = outer->add_actor("sub", std::make_unique<afp::SubPlan>(std::move(inner)));
  auto *g = outer->add_supervisor("g", std::make_unique<Bump>());
  auto *t = outer->add_supervisor("t", std::make_unique<Bump>());
  outer->define_first_actor(x);
  outer->define_global_supervision(g, 0, afp::terminate);
  outer->define_subsequent(x, 0, sub);
  outer->define_supervision(x, t, 0, x);
  outer->define_subsequent(sub, afp::SubPlan::OK, afp::terminate);
  return outer;
}

struct Model {
  std::unique_ptr<Compiled> compiled;
  model::PlanId outer;
  trace::PlanLayout layout;
};

Model compile_plans(const std::string &plans = kPlans) {
  Model m;
  m.compiled = compile({{"bot.toolbox", kToolbox}, {"plans.plan", plans}}, "plans.plan", "plans.cpp");
  INFO(m.compiled->errors);
  REQUIRE(!m.compiled->diag.has_errors());
  for (model::PlanId id : m.compiled->model.plans.ids())
    if (m.compiled->model.plans[id].name == "Outer") m.outer = id;
  REQUIRE(m.outer.valid());
  m.layout = trace::plan_layout_of(m.compiled->model, m.outer);
  return m;
}

/// The frames a LinkTrace writes for a scripted series of events, each frame kept apart.
struct Recorded {
  std::unique_ptr<afp::Plan> plan = wire_outer();
  std::vector<std::string> frames;
  afp::LinkTrace link{*plan, [this](const unsigned char *d, std::size_t n) {
                        frames.emplace_back(reinterpret_cast<const char *>(d), n);
                      }};
  const afp::Plan &inner() const { return *plan->actor_at(1).nested_plan(); }
  std::string bytes() const {
    std::string all;
    for (const auto &f : frames) all += f;
    return all;
  }
};

/// A run of Outer: x twice (interrupted by t once), then the sub-plan to its end; a failure
/// inside it with a message that needs cleaning and cutting.
void play(Recorded &r) {
  const afp::Plan &o = *r.plan, &in = r.inner();
  r.link.actor_started(o, "x", 0ms);
  r.link.actor_interrupted(o, "x", "t", 0, 30ms);
  r.link.actor_started(o, "x", 30ms);
  r.link.actor_finished(o, "x", -3, 1500ms);  // a state no toolbox has: numbers go as they are
  r.link.actor_started(o, "sub", 1500ms);
  r.link.actor_started(in, "a", 1500ms);
  r.link.component_failed(in, "s", "bad\nline " + std::string(300, 'z'), 1510ms);
  r.link.plan_finished(in, afp::Status::Failed, 1510ms);
  r.link.actor_finished(o, "sub", afp::SubPlan::ERROR, 1510ms);
  r.link.plan_finished(o, afp::Status::Succeeded, 1510ms);
}

const std::string kPlayed = "0 start Outer.x\n"
                            "30 interrupt Outer.x by t event 0\n"
                            "30 start Outer.x\n"
                            "1500 finish Outer.x state -3\n"
                            "1500 start Outer.sub\n"
                            "1500 start Inner.a\n"
                            "1510 fail Inner.s: bad line " +
                            std::string(200 - 9, 'z') +
                            "\n"
                            "1510 end Inner failed\n"
                            "1510 finish Outer.sub state 2\n"
                            "1510 end Outer succeeded\n";

struct Decoded {
  std::string log;
  std::unique_ptr<monitor::PlanLogSink> sink;
  std::unique_ptr<monitor::PlanTraceDecoder> decoder;
  std::ostringstream out;
};

std::string decode(const Model &m, const std::string &bytes, std::size_t chunk, std::string *refusal = nullptr) {
  std::ostringstream out;
  monitor::PlanLogSink sink(m.compiled->model, m.layout, out);
  monitor::PlanTraceDecoder d(m.compiled->model, m.layout, sink);
  for (std::size_t at = 0; at < bytes.size(); at += chunk)
    d.feed(reinterpret_cast<const std::uint8_t *>(bytes.data()) + at, std::min(chunk, bytes.size() - at));
  d.finish();
  if (refusal) *refusal = d.refusal();
  return out.str();
}

}  // namespace

TEST_CASE("plan trace: gfec's fingerprint is the runtime's, and another plan's differs", "[monitor][plan]") {
  const Model m = compile_plans();
  Recorded r;
  CHECK(r.link.fingerprint() == m.layout.fingerprint);
  REQUIRE(m.layout.levels.size() == 2);
  CHECK(m.layout.levels[1].path == "sub");
  CHECK(m.layout.levels[0].supervisors == std::vector<std::string>{"g", "t"});
  // An actor renamed: another fingerprint on either side.
  auto renamed = wire_outer("y");
  afp::LinkTrace other(*renamed, nullptr);
  CHECK(other.fingerprint() != m.layout.fingerprint);
  std::string text = kPlans;
  text.replace(text.find("start x;"), 8, "start y;");
  for (std::size_t at; (at = text.find("actor x:")) != std::string::npos;) text.replace(at, 8, "actor y:");
  text.replace(text.find("AGAIN -> x;"), 11, "AGAIN -> y;");
  text.replace(text.find("HIT -> x;"), 9, "HIT -> y;");
  text.replace(text.find("INTERRUPTED -> x;"), 17, "INTERRUPTED -> y;");
  CHECK(compile_plans(text).layout.fingerprint == other.fingerprint());
}

TEST_CASE("plan trace: a sub-plan's sub-plan, two levels down", "[monitor][plan]") {
  Model m = compile_plans(std::string(kPlans) + "plan Deep {\n  start d;\n  actor d: Outer() { OK -> terminate; "
                                                "INTERRUPTED -> terminate; ERROR -> terminate; }\n}\n");
  model::PlanId deep;
  for (model::PlanId id : m.compiled->model.plans.ids())
    if (m.compiled->model.plans[id].name == "Deep") deep = id;
  const trace::PlanLayout layout = trace::plan_layout_of(m.compiled->model, deep);
  REQUIRE(layout.levels.size() == 3);
  CHECK(layout.levels[1].path == "d");
  CHECK(layout.levels[2].path == "d.sub");
  CHECK(layout.levels[0].children == std::vector<std::size_t>{1});
  auto plan = std::make_unique<afp::Plan>("Deep");
  auto *d = plan->add_actor("d", std::make_unique<afp::SubPlan>(wire_outer()));
  plan->define_first_actor(d);
  plan->define_subsequent(d, afp::SubPlan::OK, afp::terminate);
  std::string bytes;
  afp::LinkTrace link(
      *plan, [&](const unsigned char *data, std::size_t n) { bytes.append(reinterpret_cast<const char *>(data), n); });
  CHECK(link.fingerprint() == layout.fingerprint);
  const afp::Plan &outer = *plan->actor_at(0).nested_plan();
  const afp::Plan &inner = *outer.actor_at(1).nested_plan();
  link.actor_started(*plan, "d", 0ms);
  link.actor_started(outer, "sub", 0ms);
  link.actor_started(inner, "b", 0ms);
  m.layout = layout;
  std::ostringstream out;
  monitor::PlanLogSink sink(m.compiled->model, layout, out);
  monitor::PlanTraceDecoder decoder(m.compiled->model, layout, sink);
  // From the third frame on: the state says every level's running actor.
  const std::size_t third = bytes.size() / 3 * 2;
  decoder.feed(reinterpret_cast<const std::uint8_t *>(bytes.data()) + third, bytes.size() - third);
  CHECK(out.str() == "# lost 2 events: the stream joined the run at event 3\n"
                     "# at 0 ms running: Deep.d Outer.sub Inner.b\n"
                     "0 start Inner.b\n");
}

TEST_CASE("plan trace: a frame byte by byte, as docs/live.md lays it out", "[monitor][plan]") {
  Recorded r;
  r.link.actor_started(*r.plan, "sub", 1500ms);
  REQUIRE(r.frames.size() == 1);
  const std::string &f = r.frames[0];
  const auto byte = [&](std::size_t i) { return static_cast<unsigned>(static_cast<unsigned char>(f[i])); };
  // header: sync, version 1, kind full|plan, length 7
  REQUIRE(f.size() == 14 + 7 + 4);
  CHECK(byte(0) == 0xA7);
  CHECK(byte(1) == 0x5E);
  CHECK(byte(2) == 1);
  CHECK(byte(3) == 0x09);
  CHECK(byte(4) == 7);
  CHECK(byte(5) == 0);
  const std::uint32_t fp = byte(6) | byte(7) << 8 | byte(8) << 16 | byte(9) << 24;
  CHECK(fp == r.link.fingerprint());
  CHECK(byte(10) == 1);  // the first frame
  CHECK((byte(11) | byte(12) | byte(13)) == 0);
  // 1500 ms (DC 0B), record 0 started, level 0, actor 1, then the active actors: sub (2), none
  const std::vector<unsigned> payload{0xDC, 0x0B, 0, 0, 1, 2, 0};
  for (std::size_t i = 0; i < payload.size(); ++i) CHECK(byte(14 + i) == payload[i]);
  const std::uint32_t crc = byte(21) | byte(22) << 8 | byte(23) << 16 | byte(24) << 24;
  CHECK(crc == trace::crc32(reinterpret_cast<const std::uint8_t *>(f.data()), 21));
}

TEST_CASE("plan trace: the decoder gives the observer's log back, in any chunking", "[monitor][plan]") {
  const Model m = compile_plans();
  Recorded r;
  play(r);
  for (std::size_t chunk : {std::size_t(1), std::size_t(5), std::size_t(64), std::size_t(100000)}) {
    INFO("chunk " << chunk);
    CHECK(decode(m, r.bytes(), chunk) == kPlayed);
  }
}

TEST_CASE("plan trace: heartbeats, a late monitor, garbled bytes and another plan", "[monitor][plan]") {
  const Model m = compile_plans();
  Recorded r;
  r.link.actor_started(*r.plan, "sub", 0ms);
  r.link.actor_started(r.inner(), "b", 0ms);
  for (int step = 1; step <= 64; ++step) r.link.heartbeat(step * 10ms);
  REQUIRE(r.frames.size() == 4);  // the two events, then a state frame every 32 steps
  r.link.actor_finished(r.inner(), "b", 0, 650ms);

  SECTION("a state frame shows no line; after a late join it says what runs") {
    const std::string late = r.frames[2] + r.frames[3] + r.frames[4];
    CHECK(decode(m, late, 7) == "# lost 2 events: the stream joined the run at event 3\n"
                                "# at 320 ms running: Outer.sub Inner.b\n"
                                "650 finish Inner.b state 0\n");
  }
  SECTION("a garbled frame is lost and said; the next frame is exact again") {
    std::string bytes = r.bytes();
    const std::size_t second = r.frames[0].size();
    bytes[second + 16] ^= 0x40;  // inside the second frame's payload: its CRC fails
    CHECK(decode(m, bytes, 3) == "0 start Outer.sub\n"
                                 "# lost 1 event: bad CRC or garbled bytes (" +
                                     std::to_string(r.frames[1].size()) +
                                     " skipped)\n"
                                     "# at 320 ms running: Outer.sub Inner.b\n"
                                     "650 finish Inner.b state 0\n");
  }
  SECTION("a stream cut inside a frame") {
    const std::string bytes = r.bytes();
    CHECK(decode(m, bytes.substr(0, r.frames[0].size() + 10), 4) ==
          "0 start Outer.sub\n# lost: the stream ended inside a frame (10 bytes)\n");
  }
  SECTION("another plan's stream is refused") {
    auto renamed = wire_outer("y");
    std::string bytes;
    afp::LinkTrace other(
        *renamed, [&](const unsigned char *d, std::size_t n) { bytes.append(reinterpret_cast<const char *>(d), n); });
    other.actor_started(*renamed, "y", 0ms);
    other.actor_finished(*renamed, "y", 0, 10ms);
    std::string refusal;
    CHECK(decode(m, bytes, 2, &refusal).empty());
    CHECK_THAT(refusal,
               Catch::StartsWith("the stream comes from another plan: its fingerprint is " +
                                 fmt::format("{:08x}, the plan's {:08x}", other.fingerprint(), m.layout.fingerprint)));
  }
}
