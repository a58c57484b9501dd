// What the interpreter's and the analyses' tests share: chart text through the real front end
// and validator to a model, and an environment scripted per function and tick.
#pragma once

#include "interpreter/machine.h"
#include "interpreter/run_chart.h"
#include "support.h"

#include <catch2/catch.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace gfec::test {

/// A program compiled to its model; the model points into `sources`, so this never moves.
struct Compiled : Pipeline {
  /// `text` as t.sfc; a non-empty `iface` becomes bot.iface, which t.sfc imports.
  explicit Compiled(const std::string &text, const std::string &iface = "", WarningOptions w = {})
      : Pipeline("t.sfc",
                 files({{"t.sfc", iface.empty() ? text : "import \"bot.iface\";\n" + text}, {"bot.iface", iface}}), w) {
  }

  std::string diagnostics() const { return text(); }
  model::ChartId chart(const std::string &name) const {
    for (model::ChartId i : model.charts.ids())
      if (model.charts[i].name == name) return i;
    FAIL("no chart " << name);
    return {};
  }
  model::FunctionId function(const std::string &name) const {
    for (model::FunctionId i : model.functions.ids())
      if (model.functions[i].name == name) return i;
    return {};
  }
};

inline std::unique_ptr<Compiled> compile(const std::string &text, const std::string &iface = "") {
  auto c = std::make_unique<Compiled>(text, iface);
  INFO(c->diagnostics());
  REQUIRE_FALSE(c->diag.has_errors());
  return c;
}

/// Each function returns, at tick t, the t-th value of its script (the last one after the
/// end; 0 / false without a script).
class ScriptedEnv : public interp::Environment {
public:
  explicit ScriptedEnv(const Compiled &c) : c_(c) {}
  ScriptedEnv &script(const std::string &fn, std::vector<double> values) {
    model::FunctionId i = c_.function(fn);
    REQUIRE(i.valid());
    scripts_[i] = std::move(values);
    return *this;
  }
  interp::Value call(model::FunctionId function, const std::vector<interp::Value> &, std::uint64_t tick) override {
    const model::Type t = c_.model.functions.at(function).result;
    auto s = scripts_.find(function);
    double v = 0;
    if (s != scripts_.end() && !s->second.empty())
      v = s->second[std::min<std::size_t>(static_cast<std::size_t>(tick), s->second.size()) - 1];
    switch (t) {
    case model::Type::Bool: return interp::Value::of_bool(v != 0);
    case model::Type::Float: return interp::Value::of_float(static_cast<float>(v));
    case model::Type::Double: return interp::Value::of_double(v);
    default: return interp::Value::of_int(static_cast<std::int32_t>(v));
    }
  }

private:
  const Compiled &c_;
  std::map<model::FunctionId, std::vector<double>> scripts_;
};

/// Runs the only (or named) chart for `ticks` ticks; the log's selected layers as text.
inline std::string run_log(const Compiled &c, interp::Environment &env, std::uint64_t ticks,
                           interp::RenderOptions render = {}, const std::string &chart = "") {
  Diagnostics diag;
  model::ChartId root = chart.empty() ? model::ChartId(0) : c.chart(chart);
  interp::RunResult r = interp::run_chart(c.model, root, env, ticks, {}, diag);
  std::string out = r.log.render(render);
  for (const auto &d : diag.all()) out += render_text(d, c.sources);
  return out;
}

/// The line follower (samples/line_follower.sfc) in the tick its left sensor first sees the line,
/// every layer as `gfec run --hooks` prints it, after the tick's first lines: T0 fires, LeftFw's
/// exit, LeftStop's entry, the hooks, then the actions. Written by hand from docs/language.md §5.1;
/// the interpreter's test and `gfec run`'s both expect it.
inline const char *const kLineFollowerLeftSeesLine = "  cond T0 = true\n"
                                                     "    call Left_IR_Black() = true\n"
                                                     "  fire T0: LeftFw -> LeftStop\n"
                                                     "  cond T2 = false\n"
                                                     "    call Right_IR_Black() = false\n"
                                                     "  exit LeftFw\n"
                                                     "  entry LeftStop\n"
                                                     "  lost LeftFw\n"
                                                     "  gained LeftStop\n"
                                                     "  enabled T1\n"
                                                     "  action LeftStop\n"
                                                     "    call Left_Stop()\n"
                                                     "  action RightFw\n"
                                                     "    call Right_FW()\n"
                                                     "  av 0 1 1 0\n";

}  // namespace gfec::test
