#include "scenario/reference_run.h"

#include "interpreter/engine.h"

#include <fmt/format.h>

namespace gfec::scenario {

namespace {

/// The interface as a test sets it: `set` values for sensing functions (false/0 until set),
/// every call recorded.
class TestEnvironment : public interp::Environment {
public:
  explicit TestEnvironment(const model::Model &model) : model_(model), values_(model.functions.size()) {}

  void set(model::FunctionId function, const std::string &value) { values_[function] = value; }
  std::vector<Call> take_calls() { return std::move(calls_); }

  interp::Value call(model::FunctionId function, const std::vector<interp::Value> &args, std::uint64_t) override {
    const model::Function &f = model_.functions.at(function);
    Call c;
    c.function = function;
    for (const auto &a : args) c.args.push_back(interp::format_value(a));
    std::string list;
    for (const auto &a : c.args) list += (list.empty() ? "" : ", ") + a;
    c.text = fmt::format("{}({})", f.name, list);
    calls_.push_back(std::move(c));
    if (f.result == model::Type::Void) return interp::Value::zero(model::Type::Int);
    const std::string &v = values_[function];
    return v.empty() ? interp::Value::zero(f.result) : parse_value(v, f.result);
  }

private:
  const model::Model &model_;
  IdMap<model::FunctionId, std::string> values_;  ///< as `set` formatted it; "" until set
  std::vector<Call> calls_;
};

Snapshot snapshot(const interp::Engine &e, std::vector<Call> calls) {
  Snapshot s;
  s.tick = e.ticks();
  for (model::PlaceId p : e.chart().places.ids()) {
    s.activation.push_back(e.activation(p));
    s.timers.push_back(e.timer(p));
  }
  s.vars = e.vars();
  if (e.is_fsm()) {
    s.state = e.state();
    s.status = e.status();
  }
  s.calls = std::move(calls);
  return s;
}

}  // namespace

std::uint64_t total_ticks(const Test &test) {
  std::uint64_t n = 0;
  for (const Step &s : test.steps)
    if (s.kind == Step::Kind::Tick) n += s.count;
  return n;
}

Run run_reference(const model::Model &model, const Test &test) {
  Run run;
  TestEnvironment env(model);
  interp::Engine engine(model, test.chart);
  try {
    engine.init();
    run.ticks.push_back(snapshot(engine, {}));
    for (const Step &step : test.steps) {
      if (step.kind == Step::Kind::Set) env.set(step.function, step.value);
      if (step.kind != Step::Kind::Tick) continue;
      for (unsigned long i = 0; i < step.count; ++i) {
        engine.run(env, nullptr);
        run.ticks.push_back(snapshot(engine, env.take_calls()));
      }
    }
  } catch (const interp::RuntimeError &err) {
    run.error = fmt::format("tick {}: {}", run.ticks.size(), err.what());
    run.error_range = err.range;
    run.error_located = true;
  }
  return run;
}

}  // namespace gfec::scenario
