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
  Substitution(const Snapshot &s, const model::Model &m, const model::Chart &c, std::vector<Instance> instances)
      : s_(s), m_(m), c_(c), instances_(std::move(instances)) {}

  model::Expr operator()(const Expect &e, std::vector<Operand> &operands) {
    switch (e.kind) {
    case Expect::Kind::Chart: return chart_part(e.chart, operands);
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
        if (e.call_args && !same_arguments(m_.functions.at(e.function), c.args, *e.call_args)) {
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
  /// A chart expression with what it reads of the sub-charts replaced by its value (the
  /// snapshot has no engine to ask), recording the operands it reads: variables, timers,
  /// sub-charts' states.
  model::Expr chart_part(const model::Expr &e, std::vector<Operand> &operands) {
    switch (e.kind) {
    case K::Var: operands.push_back({e.range, interp::format_value(s_.vars.at(e.var()))}); return e;
    case K::Elapsed: {
      std::uint32_t t = s_.timers.at(e.place());
      operands.push_back({e.range, c_.period_ms > 0 ? fmt::format("{} ms ({} ticks)", t * c_.period_ms, t)
                                                    : fmt::format("{} ticks", t)});
      return e;
    }
    case K::Active:
    case K::Succeeded:
    case K::Failed: {
      bool v = e.kind == K::Active ? active(e.path) : outcome(e.place(), e.kind == K::Succeeded);
      operands.push_back({e.range, v ? "true" : "false"});
      return literal_bool(v, e.range);
    }
    default: break;
    }
    model::Expr out = e;
    for (std::size_t i = 0; i < e.args.size(); ++i) out.args[i] = chart_part(e.args[i], operands);
    return out;
  }

  /// The instance that place `place` of instance `parent` (-1: the root) runs, or -1.
  int instance_of(int parent, model::PlaceId place) const {
    for (std::size_t i = 0; i < instances_.size(); ++i)
      if (instances_[i].parent == parent && instances_[i].place == place) return static_cast<int>(i);
    return -1;
  }

  unsigned activation(int instance, model::PlaceId place) const {
    if (instance < 0) return s_.activation.at(place);
    const auto &av = s_.instances.at(static_cast<std::size_t>(instance));
    return place.index() < av.size() ? av[place.index()] : 0u;
  }

  /// `active(P.Q.R)`: every place along the path active, each in the instance the previous runs.
  bool active(const HeapVector<model::PlaceId> &path) const {
    int instance = -1;
    for (std::size_t i = 0; i < path.size(); ++i) {
      if (activation(instance, path[i]) == 0) return false;
      if (i + 1 == path.size()) return true;
      if ((instance = instance_of(instance, path[i])) < 0) return false;
    }
    return false;
  }

  /// `succeeded(P)` / `failed(P)`: P active and its fsm instance in a success / failure state.
  bool outcome(model::PlaceId place, bool success) const {
    int instance = instance_of(-1, place);
    if (instance < 0 || activation(-1, place) == 0) return false;
    const model::Chart &sub = m_.charts.at(instances_[static_cast<std::size_t>(instance)].chart);
    const model::Terminal want = success ? model::Terminal::Success : model::Terminal::Failure;
    for (model::PlaceId q : sub.places.ids())
      if (sub.places[q].terminal == want && activation(instance, q) > 0) return true;
    return false;
  }

  const Snapshot &s_;
  const model::Model &m_;
  const model::Chart &c_;
  std::vector<Instance> instances_;
};

}  // namespace

/// Whether a call's arguments (as the engines print them) equal the expected ones (as `called F(ARGS)`
/// converted them to the parameter types), compared as values: `-0` is `0`, as in C.
bool same_arguments(const model::Function &f, const std::vector<std::string> &seen,
                    const std::vector<std::string> &want) {
  if (seen.size() != want.size() || seen.size() != f.params.size()) return false;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    const model::Type t = f.params[i].type;
    const interp::Value a = parse_value(seen[i], t), b = parse_value(want[i], t);
    const bool equal = t == Type::Bool                           ? a.b == b.b
                       : model::is_integer(t) || t == Type::Time ? a.i == b.i
                       : t == Type::Float || t == Type::Double   ? a.f == b.f
                                                                 : seen[i] == want[i];
    if (!equal) return false;
  }
  return true;
}

std::vector<Instance> instances_of(const model::Model &model, model::ChartId chart) {
  std::vector<Instance> out;
  // Depth first, in declaration order: an instance, then the instances inside it, then the next.
  struct Walk {
    const model::Model &model;
    std::vector<Instance> &out;
    void operator()(model::ChartId c, int parent) {
      const model::Chart &chart = model.charts.at(c);
      for (model::PlaceId p : chart.places.ids()) {
        if (!chart.places[p].runs) continue;
        out.push_back({chart.places[p].runs, parent, p});
        (*this)(chart.places[p].runs, static_cast<int>(out.size()) - 1);
      }
    }
  };
  Walk{model, out}(chart, -1);
  return out;
}

void settle_instances(Snapshot &s, const std::vector<Instance> &instances) {
  // Parents come before their instances, and a stopped parent is zeroed already: an instance
  // runs exactly when the place that runs it is active.
  s.instances.resize(instances.size());
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const Instance &in = instances[i];
    const std::size_t place = in.place.index();
    const std::vector<unsigned> *parent = in.parent < 0 ? nullptr : &s.instances[static_cast<std::size_t>(in.parent)];
    const unsigned owner = !parent ? s.activation.at(in.place) : place < parent->size() ? (*parent)[place] : 0u;
    if (owner == 0) std::fill(s.instances[i].begin(), s.instances[i].end(), 0u);
  }
}

Verdict evaluate(const Expect &e, const Snapshot &s, const model::Model &model, model::ChartId chart) {
  const model::Chart &c = model.charts.at(chart);
  Verdict v;
  std::vector<Operand> operands;
  model::Expr expr = Substitution(s, model, c, instances_of(model, chart))(e, operands);
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
  if (c.team > 0) {  // team(S) and agent() as this agent sees them
    frame.agent = s.agent;
    frame.reports = &s.reports;
  }
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
  const std::vector<Instance> instances = instances_of(model, chart);
  for (std::size_t i = 0; i < instances.size() && i < x.instances.size() && i < y.instances.size(); ++i) {
    const model::Chart &sub = model.charts.at(instances[i].chart);
    for (model::PlaceId q : sub.places.ids()) {
      const std::size_t k = q.index();
      const unsigned vx = k < x.instances[i].size() ? x.instances[i][k] : 0u;
      const unsigned vy = k < y.instances[i].size() ? y.instances[i][k] : 0u;
      if (vx != vy)
        return fmt::format("activation of '{}' in the instance of '{}' that '{}' runs: {} {}, {} {}",
                           sub.places[q].name, sub.name, instance_path(model, chart, instances, i), a, vx, b, vy);
    }
  }
  return "";
}

std::uint64_t digest(const Snapshot &s, const model::Model &model, model::ChartId chart) {
  const model::Chart &c = model.charts.at(chart);
  std::uint64_t h = 14695981039346656037ULL;  // FNV-1a
  auto bytes = [&](std::string_view text) {
    for (char ch : text) h = (h ^ static_cast<unsigned char>(ch)) * 1099511628211ULL;
    h = (h ^ 0xFFu) * 1099511628211ULL;  // a separator no text byte sequence imitates
  };
  auto number = [&](std::uint64_t v) {
    for (int k = 0; k < 8; ++k, v >>= 8) h = (h ^ (v & 0xFFu)) * 1099511628211ULL;
  };
  for (const Call &call : s.calls) bytes(call.text);
  bytes("|");
  for (model::PlaceId p : c.places.ids()) number(s.activation.at(p));
  if (c.kind == model::Chart::Kind::Fsm) {
    number(s.state ? s.state.index() + 1 : 0);
    number(static_cast<std::uint64_t>(s.status + 1));
  }
  for (model::VarId i : c.vars.ids()) bytes(interp::format_value(s.vars.at(i)));
  for (model::PlaceId p : c.places.ids())
    if (c.places[p].timed) number(s.timers.at(p));
  for (const auto &instance : s.instances) {
    bytes("/");
    for (unsigned v : instance) number(v);
  }
  return h;
}

std::string instance_path(const model::Model &model, model::ChartId chart, const std::vector<Instance> &instances,
                          std::size_t i) {
  std::string path;
  for (int k = static_cast<int>(i); k >= 0; k = instances[static_cast<std::size_t>(k)].parent) {
    const Instance &in = instances[static_cast<std::size_t>(k)];
    const model::Chart &owner =
        model.charts.at(in.parent < 0 ? chart : instances[static_cast<std::size_t>(in.parent)].chart);
    path = owner.places.at(in.place).name.str() + (path.empty() ? "" : "." + path);
  }
  return path;
}

interp::Value parse_value(const std::string &text, model::Type t) {
  switch (t) {
  case Type::Bool: return interp::Value::of_bool(text == "true");
  case Type::Int: return interp::Value::of_int(static_cast<std::int32_t>(std::strtol(text.c_str(), nullptr, 10)));
  case Type::Float: return interp::Value::of_float(std::strtof(text.c_str(), nullptr));
  case Type::Double: return interp::Value::of_double(std::strtod(text.c_str(), nullptr));
  case Type::Time:  // as the harness prints it: T#<ms>ms
    return interp::Value::of_time(std::strtoll(text.c_str() + (text.rfind("T#", 0) == 0 ? 2 : 0), nullptr, 10));
  default:
    // The sized integers, whole: an unsigned 64-bit value keeps its bits.
    if (model::is_unsigned(t))
      return interp::Value::of_integer(t, static_cast<std::int64_t>(std::strtoull(text.c_str(), nullptr, 10)));
    if (model::is_integer(t)) return interp::Value::of_integer(t, std::strtoll(text.c_str(), nullptr, 10));
    return interp::Value::zero(t);
  }
}

}  // namespace gfec::scenario
