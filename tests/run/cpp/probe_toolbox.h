// A scripted Probe toolbox (tests/golden/cpp/probe.toolbox) for the compile-and-run test of
// tests/golden/cpp/formulas.plan: every component logs the inputs it reads, so the test sees
// how each formula was evaluated and converted.
//
//   Numbers, Texts  log their inputs; DONE at the first step
//   Things          `on` true: writes an object holding 42 and the label "made", MADE; else NOT_MADE
//   Watch           `fire`: writes its limit to `seen`, FIRED; `timeout`: TIMEOUT (period 1.5ms)
#ifndef PROBE_TOOLBOX_H
#define PROBE_TOOLBOX_H

#include <afp/afp.h>

#include <chrono>
#include <string>
#include <utility>

#include "scripted_env.h"

class Probe : public ScriptedEnv {};

class Numbers : public afp::Actor {
public:
  enum State { DONE };
  Numbers(Probe &ee, afp::In<int> half, afp::In<float> scaled, afp::In<double> negated, afp::In<int> folded,
          afp::In<float> parsed)
      : ee_(ee), half_(std::move(half)), scaled_(std::move(scaled)), negated_(std::move(negated)),
        folded_(std::move(folded)), parsed_(std::move(parsed)) {}
  void start(afp::Context &ctx) override {
    ee_.out << "  Numbers half=" << half_.read(ctx) << " scaled=" << scaled_.read(ctx)
            << " negated=" << negated_.read(ctx) << " folded=" << folded_.read(ctx) << " parsed=" << parsed_.read(ctx)
            << "\n";
  }
  afp::StepResult step(afp::Context &) override { return DONE; }

private:
  Probe &ee_;
  afp::In<int> half_;
  afp::In<float> scaled_;
  afp::In<double> negated_;
  afp::In<int> folded_;
  afp::In<float> parsed_;
};

class Texts : public afp::Actor {
public:
  enum State { DONE };
  Texts(Probe &ee, afp::In<std::string> lap, afp::In<std::string> where, afp::In<std::string> joined,
        afp::In<std::string> empty)
      : ee_(ee), lap_(std::move(lap)), where_(std::move(where)), joined_(std::move(joined)), empty_(std::move(empty)) {}
  void start(afp::Context &ctx) override {
    ee_.out << "  Texts lap=\"" << lap_.read(ctx) << "\" where=\"" << where_.read(ctx) << "\" joined=\""
            << joined_.read(ctx) << "\" empty=\"" << empty_.read(ctx) << "\"\n";
  }
  afp::StepResult step(afp::Context &) override { return DONE; }

private:
  Probe &ee_;
  afp::In<std::string> lap_, where_, joined_, empty_;
};

class Things : public afp::Actor {
public:
  enum State { MADE, NOT_MADE };
  Things(Probe &ee, afp::In<afp::Object> thing, afp::In<bool> on, afp::Out<afp::Object> made,
         afp::Out<std::string> label)
      : ee_(ee), thing_(std::move(thing)), on_(std::move(on)), made_(std::move(made)), label_(std::move(label)) {}
  void start(afp::Context &ctx) override {
    const afp::Object thing = thing_.read(ctx);
    on_now_ = on_.read(ctx);
    ee_.out << "  Things thing=" << (thing.get<int>() ? std::to_string(*thing.get<int>()) : "null")
            << " on=" << (on_now_ ? "true" : "false") << "\n";
  }
  afp::StepResult step(afp::Context &ctx) override {
    if (!on_now_) return NOT_MADE;
    made_.write(ctx, afp::make_object<int>(42));
    label_.write(ctx, "made");
    return MADE;
  }

private:
  Probe &ee_;
  afp::In<afp::Object> thing_;
  afp::In<bool> on_;
  afp::Out<afp::Object> made_;
  afp::Out<std::string> label_;
  bool on_now_ = false;
};

class Watch : public afp::Supervisor {
public:
  enum Event { FIRED, TIMEOUT };
  Watch(Probe &ee, afp::In<int> limit, afp::Out<int> seen)
      : afp::Supervisor(std::chrono::microseconds(1500)), ee_(ee), limit_(std::move(limit)), seen_(std::move(seen)) {}
  void start(afp::Context &ctx) override {
    limit_now_ = limit_.read(ctx);
    ee_.out << "  Watch limit=" << limit_now_ << "\n";
  }
  afp::CheckResult check(afp::Context &ctx) override {
    if (ee_.has("timeout")) return TIMEOUT;
    if (!ee_.has("fire")) return afp::no_event;
    seen_.write(ctx, limit_now_);
    return FIRED;
  }

private:
  Probe &ee_;
  afp::In<int> limit_;
  afp::Out<int> seen_;
  int limit_now_ = 0;
};

#endif  // PROBE_TOOLBOX_H
