#include "scenario/snapshot.h"

#include "interpreter/evaluator.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

namespace gfec::scenario {

namespace {

using model::Type;
using K = model::Expr::Kind;

model::Expr literal_bool(bool v, SourceRange range) {
  model::Expr e;
  e.kind = K::Bool;
  e.type = Type::Bool;
  e.bool_value = v;
  e.range = range;
  return e;
}

model::Expr literal_int(long long v, SourceRange range) {
  model::Expr e;
  e.kind = K::Int;
  e.type = Type::Int;
  e.text = std::to_string(v < 0 ? -v : v);
  e.int_value = static_cast<std::int32_t>(v < 0 ? -v : v);  // a count or a status: within int
  e.range = range;
  if (v >= 0) return e;
  model::Expr neg;
  neg.kind = K::Unary;
  neg.type = Type::Int;
  neg.unary_op = UnaryOp::Neg;
  neg.range = range;
  neg.args.push_back(std::move(e));
  return neg;
}

const char *status_word(int status) {
  return status > 0 ? "1 (succeeded)" : status < 0 ? "-1 (failed)" : "0 (running)";
}

/// A state as the engines number it, -1 for none.
std::string state_number(model::PlaceId s) { return s ? std::to_string(s.index()) : "-1"; }

/// Replaces the test-only operands by their values, so that the interpreter's evaluator (C's
/// semantics, once, in one place) computes the rest; records every operand's value.
class Substitution {
public:
  Substitution(const Snapshot &s, const model::Model &m, const model::Chart &c) : s_(s), m_(m), c_(c) {}

  model::Expr operator()(const Expect &e, std::vector<Operand> &operands) {
    switch (e.kind) {
    case Expect::Kind::Chart: chart_operands(e.chart, operands); return e.chart;
    case Expect::Kind::Active: {
      bool v = s_.activation.at(e.place) > 0;
      operands.push_back({e.range, v ? "true" : "false"});
      return literal_bool(v, e.range);
    }
    case Expect::Kind::State: {
      bool v = s_.state == e.place;
      std::string current = c_.places.contains(s_.state) ? c_.places[s_.state].name.str() : "?";
      operands.push_back({e.range, fmt::format("{} (the current state is '{}')", v ? "true" : "false", current)});
      return literal_bool(v, e.range);
    }
    case Expect::Kind::Status:
      operands.push_back({e.range, status_word(s_.status)});
      return literal_int(s_.status, e.range);
    case Expect::Kind::Called:
    case Expect::Kind::Calls: {
      long long n = 0;
      std::string seen;
      for (const Call &c : s_.calls) {
        if (c.function != e.function) continue;
        if (e.call_args && c.args != *e.call_args) {
          seen += fmt::format("{}'{}'", seen.empty() ? "" : ", ", c.text);
          continue;
        }
        ++n;
      }
      std::string value = e.kind == Expect::Kind::Calls ? std::to_string(n) : n > 0 ? "true" : "false";
      if (n == 0 && !seen.empty()) value += fmt::format(" (called as {})", seen);
      operands.push_back({e.range, value});
      return e.kind == Expect::Kind::Calls ? literal_int(n, e.range) : literal_bool(n > 0, e.range);
    }
    case Expect::Kind::Unary:
    case Expect::Kind::Binary:
    case Expect::Kind::Paren: {
      model::Expr out;
      out.kind = e.kind == Expect::Kind::Unary ? K::Unary : e.kind == Expect::Kind::Binary ? K::Binary : K::Paren;
      out.type = e.type;
      out.range = e.range;
      out.unary_op = e.unary_op;
      out.binary_op = e.binary_op;
      for (const Expect &a : e.args) out.args.push_back((*this)(a, operands));
      return out;
    }
    }
    return literal_bool(false, e.range);
  }

private:
  /// The state a chart expression reads: its variables and timers.
  void chart_operands(const model::Expr &e, std::vector<Operand> &operands) {
    if (e.kind == K::Var) {
      operands.push_back({e.range, interp::format_value(s_.vars.at(e.var()))});
    } else if (e.kind == K::Elapsed) {
      std::uint32_t t = s_.timers.at(e.place());
      operands.push_back({e.range, c_.period_ms > 0 ? fmt::format("{} ms ({} ticks)", t * c_.period_ms, t)
                                                    : fmt::format("{} ticks", t)});
    }
    for (const auto &a : e.args) chart_operands(a, operands);
  }

  const Snapshot &s_;
  const model::Model &m_;
  const model::Chart &c_;
};

}  // namespace

Verdict evaluate(const Expect &e, const Snapshot &s, const model::Model &model, model::ChartId chart) {
  const model::Chart &c = model.charts.at(chart);
  Verdict v;
  std::vector<Operand> operands;
  model::Expr expr = Substitution(s, model, c)(e, operands);
  // Each operand once, in source order.
  std::stable_sort(operands.begin(), operands.end(),
                   [](const Operand &a, const Operand &b) { return a.range.begin < b.range.begin; });
  for (const Operand &o : operands) {
    bool dup = false;
    for (const Operand &p : v.operands) dup = dup || (p.range.begin == o.range.begin && p.range.end == o.range.end);
    if (!dup) v.operands.push_back(o);
  }
  IdMap<model::VarId, interp::Value> vars = s.vars;
  interp::Frame frame{model, c, vars, s.timers};
  try {
    interp::Value result = interp::evaluate(expr, frame);
    v.holds = result.type == Type::Bool && result.b;
  } catch (const interp::RuntimeError &err) { v.error = err.what(); }
  return v;
}

std::string compare(const Snapshot &x, const Snapshot &y, const model::Model &model, model::ChartId chart,
                    const char *a, const char *b) {
  const model::Chart &c = model.charts.at(chart);
  std::size_t n = std::max(x.calls.size(), y.calls.size());
  for (std::size_t i = 0; i < n; ++i) {
    std::string cx = i < x.calls.size() ? "'" + x.calls[i].text + "'" : "no call";
    std::string cy = i < y.calls.size() ? "'" + y.calls[i].text + "'" : "no call";
    if (cx != cy) return fmt::format("call {}: {} {}, {} {}", i + 1, a, cx, b, cy);
  }
  for (model::PlaceId p : c.places.ids())
    if (x.activation.at(p) != y.activation.at(p))
      return fmt::format("activation of '{}': {} {}, {} {}", c.places[p].name, a, x.activation[p], b, y.activation[p]);
  if (c.kind == model::Chart::Kind::Fsm && (x.state != y.state || x.status != y.status))
    return fmt::format("state: {} {} status {}, {} {} status {}", a, state_number(x.state), x.status, b,
                       state_number(y.state), y.status);
  for (model::VarId i : c.vars.ids()) {
    std::string vx = interp::format_value(x.vars.at(i)), vy = interp::format_value(y.vars.at(i));
    if (vx != vy) return fmt::format("variable '{}': {} {}, {} {}", c.vars[i].name, a, vx, b, vy);
  }
  for (model::PlaceId p : c.places.ids())
    if (c.places[p].timed && x.timers.at(p) != y.timers.at(p))
      return fmt::format("timer of '{}': {} {}, {} {}", c.places[p].name, a, x.timers[p], b, y.timers[p]);
  return "";
}

interp::Value parse_value(const std::string &text, model::Type t) {
  switch (t) {
  case Type::Bool: return interp::Value::of_bool(text == "true");
  case Type::Int: return interp::Value::of_int(static_cast<std::int32_t>(std::strtol(text.c_str(), nullptr, 10)));
  case Type::Float: return interp::Value::of_float(std::strtof(text.c_str(), nullptr));
  case Type::Double: return interp::Value::of_double(std::strtod(text.c_str(), nullptr));
  default: return interp::Value::zero(t);
  }
}

}  // namespace gfec::scenario
