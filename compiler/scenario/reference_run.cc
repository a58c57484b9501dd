#include "scenario/reference_run.h"

#include "interpreter/machine.h"

#include <fmt/format.h>

namespace gfec::scenario {

namespace {

/// The interface as a test sets it: `set` values for sensing functions (false/0 until set) and
/// for the chart's inputs (their initial values until set), every call recorded.
class TestEnvironment : public interp::Environment {
public:
  explicit TestEnvironment(const model::Model &model) : model_(model), values_(model.functions.size()) {}

  void set(const Step &step, const model::Chart &chart) {
    if (step.input) inputs_[&chart.vars.at(step.input)] = parse_value(step.value, chart.vars.at(step.input).type);
    else values_[step.function] = step.value;
  }
  std::optional<interp::Value> input(const model::Var &var, std::uint64_t) override {
    auto it = inputs_.find(&var);
    if (it == inputs_.end()) return std::nullopt;
    return it->second;
  }
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
  /// The inputs set so far, by the chart's declaration the interpreter passes to input().
  std::map<const model::Var *, interp::Value> inputs_;
  std::vector<Call> calls_;
};

/// The activation of every instance inside `e`, depth first in declaration order (instances_of).
void record_instances(const interp::Machine &e, std::vector<std::vector<unsigned>> &out) {
  for (model::PlaceId p : e.chart().places.ids()) {
    const interp::Machine *sub = e.instance(p);
    if (!sub) continue;
    std::vector<unsigned> av;
    for (model::PlaceId q : sub->chart().places.ids()) av.push_back(sub->activation(q));
    out.push_back(std::move(av));
    record_instances(*sub, out);
  }
}

Snapshot snapshot(const interp::Machine &e, std::vector<Call> calls) {
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
  record_instances(e, s.instances);
  s.agent = e.agent();
  return s;
}

}  // namespace

std::uint64_t total_ticks(const Test &test) {
  std::uint64_t n = 0;
  for (const Step &s : test.steps)
    if (s.kind == Step::Kind::Tick) n += s.count;
  return n;
}

std::set<std::uint64_t> expectation_ticks(const Test &test) {
  std::set<std::uint64_t> out;
  std::uint64_t tick = 0;
  for (const Step &s : test.steps) {
    if (s.kind == Step::Kind::Tick) tick += s.count;
    if (s.kind == Step::Kind::Expect) out.insert(tick);
  }
  return out;
}

void Run::record(std::vector<Snapshot> &&agents, KeptTicks keep, const model::Model &model, model::ChartId chart) {
  std::uint64_t d = 0;
  for (const Snapshot &s : agents) d = d * 1099511628211ULL ^ digest(s, model, chart);
  const std::uint64_t tick = digests.size();
  digests.push_back(d);
  if (!keep || keep->count(tick)) kept.emplace(tick, std::move(agents));
}

void settle_tick(std::vector<Snapshot> &agents, const std::vector<Instance> &instances, const model::Chart &chart) {
  for (Snapshot &s : agents) {
    settle_instances(s, instances);
    s.reports.assign(chart.team > 0 ? static_cast<std::size_t>(chart.team) : 0u, model::PlaceId::none());
    if (s.tick == 0) continue;
    for (std::size_t a = 0; a < agents.size() && a < s.reports.size(); ++a) s.reports[a] = agents[a].state;
  }
}

Run run_reference(const model::Model &model, const Test &test, KeptTicks keep) {
  Run run;
  const std::size_t n = static_cast<std::size_t>(std::max(test.agents, 1));
  const std::vector<Instance> instances = instances_of(model, test.chart);
  const model::Chart &chart = model.charts.at(test.chart);
  std::vector<TestEnvironment> envs(n, TestEnvironment(model));
  std::vector<interp::Machine> engines;
  engines.reserve(n);
  for (std::size_t a = 0; a < n; ++a) engines.emplace_back(model, test.chart);
  std::size_t agent = 0;
  auto record = [&] {
    std::vector<Snapshot> tick;
    for (std::size_t a = 0; a < n; ++a) tick.push_back(snapshot(engines[a], envs[a].take_calls()));
    settle_tick(tick, instances, chart);
    run.record(std::move(tick), keep, model, test.chart);
  };
  try {
    for (std::size_t a = 0; a < n; ++a) {
      engines[a].init();
      if (chart.team > 0) engines[a].set_agent(static_cast<int>(a));
    }
    record();
    for (const Step &step : test.steps) {
      if (step.kind == Step::Kind::Set)
        for (std::size_t a = 0; a < n; ++a)
          if (step.agent < 0 || static_cast<std::size_t>(step.agent) == a) envs[a].set(step, chart);
      if (step.kind != Step::Kind::Tick) continue;
      for (unsigned long i = 0; i < step.count; ++i) {
        for (agent = 0; agent < n; ++agent) engines[agent].run(envs[agent], nullptr);
        // The reference exchange (docs/language.md "Teams"): every agent's state to every other.
        if (chart.team > 0)
          for (std::size_t from = 0; from < n; ++from)
            for (std::size_t to = 0; to < n; ++to) engines[to].report(static_cast<int>(from), engines[from].state());
        record();
      }
    }
  } catch (const interp::RuntimeError &err) {
    run.error = n > 1 ? fmt::format("tick {} (agent {}): {}", run.recorded(), agent, err.what())
                      : fmt::format("tick {}: {}", run.recorded(), err.what());
    run.error_range = err.range;
    run.error_located = true;
  }
  return run;
}

std::optional<LastCall> last_call(const model::Model &model, const Test &test, model::FunctionId function,
                                  const std::optional<std::vector<std::string>> &args, std::size_t agent,
                                  std::uint64_t up_to, std::uint64_t window) {
  std::set<std::uint64_t> keep;
  for (std::uint64_t t = up_to; t >= 1 && up_to - t < window; --t) keep.insert(t);
  const Run run = run_reference(model, test, &keep);
  for (auto t = keep.rbegin(); t != keep.rend(); ++t) {
    const std::vector<Snapshot> *records = run.at(*t);
    if (!records || agent >= records->size()) continue;
    const std::vector<Call> &calls = (*records)[agent].calls;
    for (auto c = calls.rbegin(); c != calls.rend(); ++c)
      if (c->function == function && (!args || same_arguments(model.functions.at(function), c->args, *args)))
        return LastCall{*t, c->text};
  }
  return std::nullopt;
}

}  // namespace gfec::scenario
