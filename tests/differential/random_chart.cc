#include "random_chart.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace gfec::diff {

namespace {

const char *type_word(Type t) { return model::type_name(t); }

Type promote(Type a, Type b) {
  if (a == Type::Double || b == Type::Double) return Type::Double;
  if (a == Type::Float || b == Type::Float) return Type::Float;
  return Type::Int;
}

// Names that are valid in the language but are also names the generated C uses for itself
// (engine fields and locals, API functions, macros of the headers it includes): the back end
// must keep them apart.
// (The validator rejects the engine's own names for places, e.g. `init` or `HOOKS`, and the
// macros and typedefs of the C headers, e.g. `NULL`, `UINT_MAX`, `assert`: docs/language.md §3.)
const std::vector<std::string> kTrickyPlaces = {"m",  "add",     "before",   "from",  "p",
                                                "av", "started", "timer_P0", "bool_", "R0"};
const std::vector<std::string> kTrickyVars = {"m",  "add",    "before",  "from",     "p",
                                              "av", "status", "started", "timer_P0", "timer_P1"};

const std::vector<std::string> kFloatLiterals = {"0.5",   "0.25", "1.5", "2.0", "0.1",  "3.75", "1e-1",
                                                 "2.5e0", "0.3",  "2.",  ".5",  "10.0", "0.0"};
const std::vector<std::string> kFloatInputs = {"0", "0.5", "0.25", "-1.5", "0.1", "3", "2.75", "-0.3"};
// Near the limits (GenOptions::limits): ints a 16-bit int cannot hold, INT32's ends; decimal
// constants that round differently if rounded twice (to double, then to float), or that need
// every digit of binary32; inputs likewise.
const std::vector<std::string> kIntLimits = {"40000",   "65535",      "65536", "100000", "32768",
                                             "1000000", "2147483647", "46341", "70000"};
const std::vector<std::string> kFloatLimits = {"1.00000005960464478", "16777217.0",     "0.1",
                                               "3.4028234e38",        "1.17549435e-38", "123456.789",
                                               "0.333333343267",      "1e-45",          "8388607.5"};
const std::vector<std::string> kIntInputLimits = {"100000",      "65536", "-40000", "2147483647",
                                                  "-2147483648", "32767", "-32769", "1000000"};
const std::vector<std::string> kFloatInputLimits = {"16777216", "1.00000012", "3.4e38", "-1e-30", "1234.5678"};

class Gen {
public:
  Gen(std::mt19937_64 &rng, GChart &c, const GenOptions &o, const std::vector<GChart> *pool = nullptr,
      int first_runnable = 0)
      : rng_(rng), c_(c), o_(o), pool_(pool), first_runnable_(first_runnable) {}

  void use_pool(const std::vector<GChart> *pool) { pool_ = pool; }

  /// Places (not terminal states) that run a chart of the pool, now and then.
  void assign_runs() {
    if (!pool_ || first_runnable_ >= static_cast<int>(pool_->size())) return;
    for (auto &p : c_.places)
      if (p.terminal == model::Terminal::None && chance(0.45))
        p.runs = uniform(first_runnable_, static_cast<int>(pool_->size()) - 1);
  }

  const GChart &runs_chart(const GPlace &p) const { return pool_->at(static_cast<std::size_t>(p.runs)); }

  /// active(P), active(P.Q.R), succeeded(P), failed(P), if the chart has places.
  std::optional<GExpr> activity() {
    if (c_.places.empty()) return std::nullopt;
    const GPlace *p = &pick(c_.places);
    if (!o_.dead_code && (c_.fsm || from_ >= 0)) {
      // Where the engine knows the state (an fsm's transition, a transition of what may be a
      // sequential sfc, an fsm's blocks), active(S) of this chart is a constant: dead code.
      // Read into the sub-chart of the state the transition leaves instead.
      if (from_ < 0) return std::nullopt;
      p = &c_.places[static_cast<std::size_t>(from_)];
      if (p->runs < 0) return std::nullopt;
      if (runs_chart(*p).fsm && chance(0.35))
        return GExpr{chance(0.6) ? GExpr::Kind::Succeeded : GExpr::Kind::Failed, Type::Bool, p->name, {}};
      const GChart &sub = runs_chart(*p);
      const GPlace &q = sub.places[static_cast<std::size_t>(uniform(0, static_cast<int>(sub.places.size()) - 1))];
      return GExpr{GExpr::Kind::Active, Type::Bool, p->name + "." + q.name, {}};
    }
    if (p->runs >= 0 && runs_chart(*p).fsm && chance(0.35))
      return GExpr{chance(0.6) ? GExpr::Kind::Succeeded : GExpr::Kind::Failed, Type::Bool, p->name, {}};
    std::string path = p->name;
    while (p->runs >= 0 && chance(0.6)) {
      const GChart &sub = runs_chart(*p);
      p = &sub.places[static_cast<std::size_t>(uniform(0, static_cast<int>(sub.places.size()) - 1))];
      path += "." + p->name;
    }
    return GExpr{GExpr::Kind::Active, Type::Bool, path, {}};
  }

  int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool chance(double p) { return std::bernoulli_distribution(p)(rng_); }
  template <typename T> const T &pick(const std::vector<T> &v) {
    return v[static_cast<std::size_t>(uniform(0, static_cast<int>(v.size()) - 1))];
  }

  Type any_numeric() {
    int r = uniform(0, 9);
    return r < 5 ? Type::Int : r < 7 || !o_.doubles ? Type::Float : Type::Double;
  }
  Type any_type() { return chance(0.3) ? Type::Bool : any_numeric(); }

  /// A name not used yet in the chart: `base<i>` or, now and then, a tricky one.
  std::string fresh(const std::string &base, int i, const std::vector<std::string> &tricky) {
    if (!tricky.empty() && chance(0.12)) {
      const std::string &t = pick(tricky);
      if (used_.insert(t).second) return t;
    }
    std::string n = fmt::format("{}{}", base, i);
    while (!used_.insert(n).second) n += "_";
    return n;
  }

  /// A literal of type t. A floating literal is a double in the language (as in C): where
  /// doubles are off (a target whose double is binary32 refuses them) one in an expression
  /// becomes a float constant of the chart, `const float L<n> = 0.5;`, so that the arithmetic
  /// around it stays float. `in_expression` false: an initialiser, converted at compile time.
  GExpr literal(Type t, bool in_expression = true) {
    GExpr e;
    e.kind = GExpr::Kind::Lit;
    e.type = t;
    if (t == Type::Bool) e.text = chance(0.5) ? "true" : "false";
    else if (t == Type::Int && o_.limits && chance(0.2)) e.text = pick(kIntLimits);
    else if (t == Type::Int) e.text = chance(0.04) ? "010" : std::to_string(uniform(0, 12));
    else if (o_.limits && chance(0.2)) e.text = pick(kFloatLimits);
    else e.text = pick(kFloatLiterals);
    return in_expression ? float_named(std::move(e)) : e;
  }

  GExpr nonzero_literal(Type t) {
    GExpr e = literal(t, false);
    if (t == Type::Int) e.text = std::to_string(uniform(1, 9));
    else e.text = pick(std::vector<std::string>{"0.5", "2.0", "4.", "0.1", "3.0", "1e1"});
    return float_named(std::move(e));
  }

  GExpr float_named(GExpr e) {
    if (o_.doubles || e.type != Type::Float || e.kind != GExpr::Kind::Lit) return e;
    std::string name = fresh("L", static_cast<int>(c_.consts.size()), {});
    c_.consts.push_back({Type::Float, name, e.text, false});
    return {GExpr::Kind::Const, Type::Float, name, {}};
  }

  /// A variable, constant or call of exactly type t, if the chart has one. Calls nest only
  /// while `depth` lasts; below it their arguments are literals.
  std::optional<GExpr> named_leaf(Type t, int depth) {
    std::vector<GExpr> options;
    std::vector<const GFunction *> calls;
    for (const auto &v : c_.vars)
      if (v.type == t) options.push_back({GExpr::Kind::Var, t, v.name, {}});
    for (const auto &k : c_.consts)
      if (k.type == t) options.push_back({GExpr::Kind::Const, t, k.name, {}});
    for (const auto &f : c_.functions)
      if (f.result == t) calls.push_back(&f);
    if (c_.team > 0 && t == Type::Int && !c_.places.empty() && chance(0.6)) {
      // team(S) and agent() (docs/language.md "Teams"): the count changes with the exchange,
      // the number differs from agent to agent.
      if (chance(0.7)) return GExpr{GExpr::Kind::Team, Type::Int, pick(c_.places).name, {}};
      return GExpr{GExpr::Kind::Agent, Type::Int, "", {}};
    }
    const int n = static_cast<int>(options.size() + calls.size());
    if (n == 0) return std::nullopt;
    int i = uniform(0, n - 1);
    if (i < static_cast<int>(options.size())) return options[static_cast<std::size_t>(i)];
    return call(*calls[static_cast<std::size_t>(i) - options.size()], depth);
  }

  GExpr call(const GFunction &f, int depth) {
    GExpr e{GExpr::Kind::Call, f.result, f.name, {}};
    for (Type p : f.params) {
      bool ints = p == Type::Int;
      if (depth <= 0) e.args.push_back(literal(p == Type::Bool ? Type::Bool : ints ? Type::Int : any_numeric()));
      else e.args.push_back(p == Type::Bool ? boolean(std::min(depth, 1)) : number(std::min(depth, 1), ints));
    }
    return e;
  }

  /// Two operands whose evaluation order C leaves open (not && or ||).
  template <typename Make> std::pair<GExpr, GExpr> operands(Make make) {
    GExpr a = make();
    GExpr b = make();
    return {a, b};
  }

  /// `a * b + c` of float operands (vars, constants, calls): a target with a fused
  /// multiply-add rounds it once if the compiler contracts it, the interpreter twice.
  std::optional<GExpr> float_multiply_add(int depth) {
    std::vector<GExpr> leaves;
    for (int i = 0; i < 3; ++i)
      if (auto leaf = named_leaf(Type::Float, depth - 1)) leaves.push_back(*leaf);
    if (leaves.empty()) return std::nullopt;
    while (leaves.size() < 3) leaves.push_back(pick(leaves));  // `v * v + v` will do
    GExpr product{GExpr::Kind::Binary, Type::Float, "*", {leaves[0], leaves[1]}};
    return GExpr{GExpr::Kind::Binary, Type::Float, chance(0.7) ? "+" : "-", {product, leaves[2]}};
  }

  /// A numeric expression (only ints when `ints`); its type follows C's conversions.
  GExpr number(int depth, bool ints) {
    if (o_.limits && !ints && depth > 0 && chance(0.15))
      if (auto fma = float_multiply_add(depth)) return *fma;
    if (depth <= 0 || chance(0.35)) {
      Type t = ints ? Type::Int : any_numeric();
      if (!chance(0.35))
        if (auto leaf = named_leaf(t, depth - 1)) return *leaf;
      return literal(t);
    }
    int r = uniform(0, 11);
    if (r < 6) {
      auto [a, b] = operands([&] { return number(depth - 1, ints); });
      Type t = promote(a.type, b.type);
      const char *op = r < 3 ? "+" : r < 5 ? "-" : "*";
      return {GExpr::Kind::Binary, t, op, {a, b}};
    }
    if (r < 8) {
      GExpr a = number(depth - 1, ints);
      GExpr b = nonzero_literal(ints ? Type::Int : any_numeric());
      return {GExpr::Kind::Binary, promote(a.type, b.type), "/", {a, b}};
    }
    if (r < 9) {
      GExpr a = number(depth - 1, true);
      return {GExpr::Kind::Binary, Type::Int, "%", {a, nonzero_literal(Type::Int)}};
    }
    if (r < 10) {
      GExpr a = number(depth - 1, ints);
      return {GExpr::Kind::Unary, a.type, "-", {a}};
    }
    GExpr a = number(depth - 1, ints);
    return {GExpr::Kind::Paren, a.type, "", {a}};
  }

  GExpr duration() {
    static const std::vector<std::string> d = {"0ms",  "5ms",   "10ms",  "15ms", "25ms",  "30ms",
                                               "50ms", "100ms", "0.05s", "1s",   "200ms", "1.5s"};
    return {GExpr::Kind::Lit, Type::Duration, pick(d), {}};
  }

  GExpr comparison(int depth) {
    static const std::vector<std::string> ops = {"<", "<=", ">", ">=", "==", "!="};
    if (c_.period_ms > 0 && !c_.places.empty() && chance(0.25)) {
      GExpr timer{GExpr::Kind::Elapsed, Type::Duration, pick(c_.places).name, {}};
      bool flip = chance(0.2);
      GExpr lhs = flip ? duration() : timer, rhs = flip ? timer : duration();
      return {GExpr::Kind::Binary, Type::Bool, chance(0.6) ? ">=" : pick(ops), {lhs, rhs}};
    }
    auto [a, b] = operands([&] { return number(depth, false); });
    return {GExpr::Kind::Binary, Type::Bool, pick(ops), {a, distinct(a, b, [&] { return number(depth, false); })}};
  }

  /// `b`, or another from `make` if it reads exactly as `a`: gcc and clang reject `x != x`
  /// under -Werror (-Wtautological-compare), which the back end cannot help.
  /// (Brackets do not make a different operand: `(v) != v` is `v != v` to the compilers.)
  template <typename Make> GExpr distinct(const GExpr &a, GExpr b, Make make) {
    auto same = [&] { return expr_text(unbracketed(a)) == expr_text(unbracketed(b)); };
    for (int i = 0; i < 8 && same(); ++i) b = make();
    while (same()) b = literal(b.type);
    return b;
  }

  /// `active(P.S) && active(P.T)` of one instance, S and T states of an fsm: always false, and
  /// clang rejects the engine's `m->P.state == X_P_S && m->P.state == X_P_T` under -Werror
  /// (-Wtautological-overlap-compare) as it does `x != x` (see distinct()).
  static bool exclusive(const GExpr &a, const GExpr &b) {
    const GExpr &x = unbracketed(a), &y = unbracketed(b);
    if (x.kind != GExpr::Kind::Active || y.kind != GExpr::Kind::Active || x.text == y.text) return false;
    auto prefix = [](const std::string &path) {
      auto dot = path.rfind('.');
      return dot == std::string::npos ? std::string() : path.substr(0, dot);
    };
    return prefix(x.text) == prefix(y.text);
  }

  static const GExpr &unbracketed(const GExpr &e) {
    return e.kind == GExpr::Kind::Paren && !e.args.empty() ? unbracketed(e.args[0]) : e;
  }

  GExpr boolean(int depth) {
    if (depth <= 0 || chance(0.3)) {
      int r = uniform(0, 9);
      if (r < 1) return literal(Type::Bool);
      if (pool_ && chance(0.3))
        if (auto a = activity()) return *a;
      if (r < 6)
        if (auto leaf = named_leaf(Type::Bool, depth - 1)) return *leaf;
      return comparison(0);
    }
    int r = uniform(0, 9);
    if (r < 2) {
      GExpr a = boolean(depth - 1);
      return {GExpr::Kind::Unary, Type::Bool, "!", {a}};
    }
    if (r < 4) {
      GExpr a = boolean(depth - 1), b = boolean(depth - 1);
      for (int tries = 0; tries < 8 && exclusive(a, b); ++tries) b = boolean(depth - 1);
      if (exclusive(a, b)) b = literal(Type::Bool);
      return {GExpr::Kind::Binary, Type::Bool, "&&", {a, b}};
    }
    if (r < 6) return {GExpr::Kind::Binary, Type::Bool, "||", {boolean(depth - 1), boolean(depth - 1)}};
    if (r < 7) {
      auto [a, b] = operands([&] { return boolean(depth - 1); });
      return {GExpr::Kind::Binary, Type::Bool, chance(0.5) ? "==" : "!=", {a, distinct(a, b, [&] {
                                                                             return boolean(depth - 1);
                                                                           })}};
    }
    if (r < 8) return {GExpr::Kind::Paren, Type::Bool, "", {boolean(depth - 1)}};
    return comparison(depth - 1);
  }

  /// A transition's condition; with dead code avoided, never a constant one.
  GExpr condition() {
    GExpr c = boolean(2);
    while (!o_.dead_code && (!varies(c) || constant_operand(c))) c = boolean(2);
    return c;
  }

  /// An operand of && or || that reads nothing that can change (`X && false`): cppcheck says
  /// the condition is known (knownConditionTrueFalse), as it should.
  static bool constant_operand(const GExpr &e) {
    if (e.kind == GExpr::Kind::Binary && (e.text == "&&" || e.text == "||"))
      for (const auto &a : e.args)
        if (!varies(a)) return true;
    for (const auto &a : e.args)
      if (constant_operand(a)) return true;
    return false;
  }

  /// Reads something that can change: a var, a call, a timer.
  static bool varies(const GExpr &e) {
    if (e.kind == GExpr::Kind::Var || e.kind == GExpr::Kind::Call || e.kind == GExpr::Kind::Elapsed ||
        e.kind == GExpr::Kind::Active || e.kind == GExpr::Kind::Succeeded || e.kind == GExpr::Kind::Failed ||
        e.kind == GExpr::Kind::Team || e.kind == GExpr::Kind::Agent)
      return true;
    for (const auto &a : e.args)
      if (varies(a)) return true;
    return false;
  }

  GStmt statement(int depth = 2) {
    // Drawn only with --loops, so that the charts of a seed without it stay what they were.
    if (o_.loops && depth > 0 && loops_ < 2 && chance(0.12)) {
      GStmt s;
      s.counter = fmt::format("{}_n{}", c_.prefix, loops_);
      c_.loop_counters = std::max(c_.loop_counters, loops_ + 1);
      s.bound = uniform(1, 4);  // not 0: cppcheck rightly flags a loop that never runs
      ++loops_;
      s.then_block = block(1, 3, depth - 1);
      --loops_;
      return s;
    }
    if (o_.loops && loops_ > 0 && chance(0.1)) {  // `if (c) { break; }`
      GStmt s;
      s.is_if = true;
      s.expr = boolean(2);
      for (int tries = 0; tries < 5 && !varies(s.expr); ++tries) s.expr = boolean(2);
      if (!varies(s.expr)) return statement(0);
      GStmt out;
      out.is_break = true;
      s.then_block.push_back(out);
      return s;
    }
    if (depth > 0 && chance(0.15)) {  // if / else if / else (docs/language.md "if and else")
      GStmt s;
      s.is_if = true;
      // A condition that reads something that changes: cppcheck rightly flags `if (false)` and
      // an inner `if` on the outer one's constant condition.
      s.expr = boolean(2);
      for (int tries = 0; tries < 5 && !varies(s.expr); ++tries) s.expr = boolean(2);
      if (!varies(s.expr)) return statement(0);
      s.then_block = block(0, 2, depth - 1);
      s.has_else = chance(0.5);
      if (s.has_else) {
        if (chance(0.4)) {
          GStmt inner = statement(depth - 1);
          if (inner.is_if) s.else_block.push_back(inner);
          else s.else_block = block(0, 2, depth - 1);
        } else {
          s.else_block = block(0, 2, depth - 1);
        }
      }
      return s;
    }
    if (!c_.vars.empty() && chance(0.4)) {
      const GValue &v = pick(c_.vars);
      GStmt s;
      s.assign = true;
      s.target = v.name;
      if (v.type == Type::Bool) {
        s.op = "=";
        s.expr = boolean(2);
      } else {
        int r = uniform(0, 9);
        s.op = r < 4 ? "=" : r < 7 ? "+=" : "-=";
        s.expr = number(2, v.type == Type::Int);
      }
      return s;
    }
    std::vector<const GFunction *> actions, any;
    for (const auto &f : c_.functions) {
      any.push_back(&f);
      if (f.result == Type::Void) actions.push_back(&f);
    }
    const GFunction &f = chance(0.85) && !actions.empty() ? *pick(actions) : *pick(any);
    GStmt s;
    s.expr = call(f, 2);
    return s;
  }

  std::vector<GStmt> block(int lo, int hi, int depth = 2) {
    std::vector<GStmt> b;
    for (int i = uniform(lo, hi); i > 0; --i) b.push_back(statement(depth));
    return b;
  }

  void interface() {
    for (int i = uniform(1, 4), k = 0; k < i; ++k) {
      GFunction f;
      f.name = fmt::format("{}_s{}", c_.prefix, k);
      int r = uniform(0, 9);
      f.result = r < 5 ? Type::Bool : r < 7 ? Type::Int : r < 8 || !o_.doubles ? Type::Float : Type::Double;
      if (chance(0.3)) f.params.push_back(chance(0.6) ? Type::Int : Type::Float);
      c_.functions.push_back(f);
    }
    for (int i = uniform(1, 3), k = 0; k < i; ++k) {
      GFunction f;
      f.name = fmt::format("{}_a{}", c_.prefix, k);
      for (int p = uniform(0, 2); p > 0; --p) f.params.push_back(any_type());
      c_.functions.push_back(f);
    }
  }

  void values() {
    for (int i = uniform(0, 1), k = 0; k < i; ++k) {
      Type t = any_type();
      c_.consts.push_back({t, fmt::format("{}_F{}", c_.prefix, k), literal(t, false).text, true});
    }
    for (int i = uniform(0, 2), k = 0; k < i; ++k) {
      Type t = any_type();
      c_.consts.push_back({t, fresh("K", k, {}), literal(t, false).text, false});
    }
    for (int i = uniform(0, 3), k = 0; k < i; ++k) {
      Type t = any_type();
      c_.vars.push_back({t, fresh("v", k, kTrickyVars), chance(0.6) ? literal(t, false).text : "", false});
    }
  }

  void sfc() {
    int n = uniform(2, 7);
    for (int i = 0; i < n; ++i) {
      GPlace p;
      p.name = fresh("P", i, kTrickyPlaces);
      p.initial = chance(0.35);
      c_.places.push_back(p);
    }
    if (std::none_of(c_.places.begin(), c_.places.end(), [](const GPlace &p) { return p.initial; }))
      c_.places[static_cast<std::size_t>(uniform(0, n - 1))].initial = true;
    assign_runs();
    // Bodies after all places exist: elapsed() may name any of them.
    for (auto &p : c_.places) {
      p.body = chance(0.8);
      if (!p.body) continue;
      p.action = block(0, 2);
      if (chance(0.25)) p.entry = block(1, 2);
      if (chance(0.25)) p.exit = block(1, 2);
    }
    for (int i = 0, count = uniform(1, 2 * n); i < count; ++i) {
      GTransition t;
      if (chance(0.25)) t.name = fresh("t", i, kTrickyPlaces);
      t.inputs = some_places(n);
      t.outputs = some_places(n);
      from_ = t.inputs.size() == 1 ? t.inputs.front() : -1;
      if (chance(0.8)) t.condition = condition();
      from_ = -1;
      c_.transitions.push_back(t);
    }
  }

  std::vector<int> some_places(int n) {
    int r = uniform(0, 99);
    int k = std::min(n, r < 70 ? 1 : r < 92 ? 2 : 3);
    std::vector<int> all(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) all[static_cast<std::size_t>(i)] = i;
    std::shuffle(all.begin(), all.end(), rng_);
    all.resize(static_cast<std::size_t>(k));
    return all;
  }

  void fsm() {
    int n = uniform(2, 6);
    for (int i = 0; i < n; ++i) {
      GPlace s;
      s.name = fresh("S", i, kTrickyPlaces);
      s.initial = i == 0;
      if (i >= 2 && chance(0.3)) s.terminal = chance(0.6) ? model::Terminal::Success : model::Terminal::Failure;
      c_.places.push_back(s);
    }
    auto terminal = [&](int i) { return c_.places[static_cast<std::size_t>(i)].terminal != model::Terminal::None; };
    assign_runs();
    for (int i = 0; i < n; ++i) {
      GPlace &s = c_.places[static_cast<std::size_t>(i)];
      if (terminal(i)) {
        s.body = false;
        if (chance(0.4)) s.post = boolean(1);
        continue;
      }
      s.body = chance(0.85);
      if (!s.body) continue;
      s.action = block(0, 2);
      if (chance(0.25)) s.entry = block(1, 2);  // docs/language.md "fsm entry and exit"
      if (chance(0.25)) s.exit = block(1, 2);
    }
    // A spanning tree first (every state weakly connected), then extra transitions; never from
    // a terminal state, never to itself, at most one per ordered pair.
    std::set<std::pair<int, int>> pairs;
    for (int i = 1; i < n; ++i) {
      std::vector<int> sources;
      for (int j = 0; j < i; ++j)
        if (!terminal(j)) sources.push_back(j);
      int j = pick(sources);
      if (!terminal(i) && o_.dead_code && chance(0.4)) pairs.insert({i, j});
      else pairs.insert({j, i});
    }
    for (int extra = uniform(0, n); extra > 0; --extra) {
      int a = uniform(0, n - 1), b = uniform(0, n - 1);
      if (a != b && !terminal(a)) pairs.insert({a, b});
    }
    std::vector<std::pair<int, int>> order(pairs.begin(), pairs.end());
    std::shuffle(order.begin(), order.end(), rng_);
    int i = 0;
    for (auto [a, b] : order) {
      GTransition t;
      if (chance(0.15)) t.name = fresh("t", i, {});
      t.inputs = {a};
      t.outputs = {b};
      from_ = a;
      if (chance(0.85) || !o_.dead_code) t.condition = condition();
      from_ = -1;
      c_.transitions.push_back(t);
      ++i;
    }
  }

private:
  std::mt19937_64 &rng_;
  GChart &c_;
  const GenOptions &o_;
  std::set<std::string> used_;
  const std::vector<GChart> *pool_ = nullptr;
  int first_runnable_ = 0;
  int loops_ = 0;  ///< the loops around the statement being made

public:
  int from_ = -1;  ///< while a transition's condition is made: its one input, else -1
};

int precedence(const std::string &op) {
  if (op == "||") return 1;
  if (op == "&&") return 2;
  if (op == "==" || op == "!=") return 3;
  if (op == "<" || op == "<=" || op == ">" || op == ">=") return 4;
  if (op == "+" || op == "-") return 5;
  return 6;
}

std::string block_text(const std::vector<GStmt> &b) {
  std::string s;
  for (const auto &st : b) {
    if (st.is_break) {
      s += "break; ";
      continue;
    }
    if (!st.counter.empty()) {
      s += fmt::format("for ({0} = 0; {0} < {1}; {0} += 1) {{ {2}}} ", st.counter, st.bound, block_text(st.then_block));
      continue;
    }
    if (st.is_if) {
      s += fmt::format("if ({}) {{ {}}} ", expr_text(st.expr), block_text(st.then_block));
      if (!st.has_else) continue;
      const bool chain = st.else_block.size() == 1 && st.else_block[0].is_if;
      s += chain ? "else " + block_text(st.else_block) : fmt::format("else {{ {}}} ", block_text(st.else_block));
      continue;
    }
    s += st.assign ? fmt::format("{} {} {}; ", st.target, st.op, expr_text(st.expr)) : expr_text(st.expr) + "; ";
  }
  return s;
}

std::string side(const GChart &c, const std::vector<int> &places) {
  std::string s;
  for (int p : places) s += (s.empty() ? "" : ", ") + c.places[static_cast<std::size_t>(p)].name;
  return places.size() == 1 ? s : "(" + s + ")";
}

}  // namespace

std::string expr_text(const GExpr &e) {
  switch (e.kind) {
  case GExpr::Kind::Lit:
  case GExpr::Kind::Var:
  case GExpr::Kind::Const: return e.text;
  case GExpr::Kind::Elapsed: return "elapsed(" + e.text + ")";
  case GExpr::Kind::Active: return "active(" + e.text + ")";
  case GExpr::Kind::Succeeded: return "succeeded(" + e.text + ")";
  case GExpr::Kind::Failed: return "failed(" + e.text + ")";
  case GExpr::Kind::Team: return "team(" + e.text + ")";
  case GExpr::Kind::Agent: return "agent()";
  case GExpr::Kind::Call: {
    std::string args;
    for (const auto &a : e.args) args += (args.empty() ? "" : ", ") + expr_text(a);
    return e.text + "(" + args + ")";
  }
  case GExpr::Kind::Paren: return "(" + expr_text(e.args.at(0)) + ")";
  case GExpr::Kind::Unary: {
    const GExpr &a = e.args.at(0);
    std::string inner = expr_text(a);
    bool wrap = a.kind == GExpr::Kind::Binary || inner[0] == '-';
    return e.text + (wrap ? "(" + inner + ")" : inner);
  }
  case GExpr::Kind::Binary: {
    // Brackets only where the tree needs them (operators are left-associative).
    const int p = precedence(e.text);
    const GExpr &l = e.args.at(0), &r = e.args.at(1);
    std::string a = expr_text(l), b = expr_text(r);
    if (l.kind == GExpr::Kind::Binary && precedence(l.text) < p) a = "(" + a + ")";
    if (r.kind == GExpr::Kind::Binary && precedence(r.text) <= p) b = "(" + b + ")";
    return a + " " + e.text + " " + b;
  }
  }
  return "";
}

GChart random_chart(std::mt19937_64 &rng, int id, const GenOptions &options) {
  GChart c;
  c.fsm = options.fsm;
  c.name = fmt::format("R{}", id);
  c.prefix = fmt::format("c{}", id);
  Gen g(rng, c, options);
  c.period_ms = g.chance(0.7) ? g.pick(std::vector<int>{1, 10, 20, 100}) : 0;
  g.interface();
  g.values();
  if (options.fsm && options.agents >= 2) {
    // A team machine: declared for as many agents as run it, or more.
    c.agents = options.agents;
    c.team = options.agents + (g.chance(0.3) ? g.uniform(1, 2) : 0);
  }
  if (options.subcharts > 0) {
    // The sub-charts, deepest first: pool[j] may run pool[j+1..]. They share the root's
    // interface and period (a sub-chart has its parent's period).
    c.pool.resize(static_cast<std::size_t>(g.uniform(1, options.subcharts)));
    for (int j = static_cast<int>(c.pool.size()) - 1; j >= 0; --j) {
      GChart &s = c.pool[static_cast<std::size_t>(j)];
      s.fsm = g.chance(0.5);
      s.name = fmt::format("R{}s{}", id, j);
      s.prefix = fmt::format("c{}s{}", id, j);
      s.period_ms = c.period_ms;
      s.functions = c.functions;
      Gen gs(rng, s, options, &c.pool, j + 1);
      gs.values();
      if (s.fsm) gs.fsm();
      else gs.sfc();
    }
    g.use_pool(&c.pool);  // the same generator: its names already taken (vars) stay taken
    if (c.fsm) g.fsm();
    else g.sfc();
    return c;
  }
  if (c.fsm) g.fsm();
  else g.sfc();
  return c;
}

GTrace random_trace(std::mt19937_64 &rng, const GChart &chart, bool limits) {
  GTrace t;
  std::uniform_int_distribution<int> near_limits(0, 99);
  // An int or float input: now and then (limits) one near the limits.
  auto number = [&](Type type, auto &&usual) {
    if (limits && near_limits(rng) < 20) {
      const auto &list = type == Type::Int ? kIntInputLimits : kFloatInputLimits;
      return list[std::uniform_int_distribution<std::size_t>(0, list.size() - 1)(rng)];
    }
    return usual();
  };
  std::uniform_int_distribution<int> ticks(3, 25), small(-3, 9), coin(0, 99);
  std::uniform_int_distribution<std::size_t> floats(0, kFloatInputs.size() - 1);
  t.ticks = ticks(rng);
  for (const auto &f : chart.functions) {
    std::vector<std::string> v;
    bool level = coin(rng) < 50;
    for (int k = 0; k < t.ticks && f.result != Type::Void; ++k) {
      if (f.result == Type::Bool) {
        if (coin(rng) < 35) level = !level;  // runs, so that places stay active a while
        v.push_back(level ? "1" : "0");
      } else if (f.result == Type::Int) {
        v.push_back(number(Type::Int, [&] { return std::to_string(small(rng)); }));
      } else {
        v.push_back(number(Type::Float, [&] { return kFloatInputs[floats(rng)]; }));
      }
    }
    t.values.push_back(v);
  }
  // A team run: each other agent has its own values of some functions, and shares the rest
  // (agents told the same thing tend to reach the same states: team(S) then counts them).
  for (int k = 1; k < chart.agents; ++k) {
    std::vector<std::vector<std::string>> own;
    for (const auto &f : chart.functions) {
      std::vector<std::string> v;
      if (f.result != Type::Void && coin(rng) < 60) {
        bool level = coin(rng) < 50;
        for (int i = 0; i < t.ticks; ++i) {
          if (f.result == Type::Bool) {
            if (coin(rng) < 35) level = !level;
            v.push_back(level ? "1" : "0");
          } else if (f.result == Type::Int) {
            v.push_back(number(Type::Int, [&] { return std::to_string(small(rng)); }));
          } else {
            v.push_back(number(Type::Float, [&] { return kFloatInputs[floats(rng)]; }));
          }
        }
      }
      own.push_back(v);
    }
    t.agents.push_back(own);
  }
  return t;
}

namespace {

std::string chart_body(const GChart &c, const std::vector<GChart> &pool) {
  std::string s = fmt::format("{} {} {{\n", c.fsm ? "fsm" : "sfc", c.name);
  if (c.team) s += fmt::format("  team {};\n", c.team);
  if (c.period_ms) s += fmt::format("  period {}ms;\n", c.period_ms);
  for (const auto &k : c.consts)
    if (!k.file_level) s += fmt::format("  const {} {} = {};\n", type_word(k.type), k.name, k.init);
  for (const auto &v : c.vars)
    s += fmt::format("  var {} {}{};\n", type_word(v.type), v.name, v.init.empty() ? "" : " = " + v.init);
  for (int k = 0; k < c.loop_counters; ++k) s += fmt::format("  var int {}_n{};\n", c.prefix, k);
  for (const auto &p : c.places) {
    std::string head = c.fsm ? (p.terminal == model::Terminal::Success   ? "success state"
                                : p.terminal == model::Terminal::Failure ? "failure state"
                                : p.initial                              ? "initial state"
                                                                         : "state")
                             : (p.initial ? "initial place" : "place");
    s += "  " + head + " " + p.name;
    if (p.runs >= 0) s += " runs " + pool.at(static_cast<std::size_t>(p.runs)).name;
    if (p.post) s += " post " + expr_text(*p.post);
    if (!p.body) {
      s += ";\n";
      continue;
    }
    s += " { ";
    if (p.entry) s += "entry { " + block_text(*p.entry) + "} ";
    s += block_text(p.action);
    if (p.exit) s += "exit { " + block_text(*p.exit) + "} ";
    s += "}\n";
  }
  for (const auto &t : c.transitions) {
    s += "  ";
    if (!t.name.empty()) s += "transition " + t.name + ": ";
    else if (!c.fsm) s += "transition ";
    s += side(c, t.inputs) + " -> " + side(c, t.outputs);
    if (t.condition) s += " when " + expr_text(*t.condition);
    s += ";\n";
  }
  return s + "}\n";
}

}  // namespace

std::string chart_text(const GChart &c) {
  std::string s = fmt::format("interface I{} {{\n", c.name.substr(1));
  for (const auto &f : c.functions) {
    std::string params;
    for (std::size_t i = 0; i < f.params.size(); ++i)
      params += fmt::format("{}{} p{}", i ? ", " : "", type_word(f.params[i]), i);
    s += fmt::format("  {} {}({});\n", type_word(f.result), f.name, params);
  }
  s += "}\n";
  for (const auto &k : c.consts)
    if (k.file_level) s += fmt::format("const {} {} = {};\n", type_word(k.type), k.name, k.init);
  for (const auto &sub : c.pool)
    for (const auto &k : sub.consts)
      if (k.file_level) s += fmt::format("const {} {} = {};\n", type_word(k.type), k.name, k.init);
  for (const auto &sub : c.pool) s += chart_body(sub, c.pool);
  return s + chart_body(c, c.pool);
}

std::string trace_csv(const GChart &c, const GTrace &t) {
  std::string header = "tick", rows;
  for (const auto &f : c.functions)
    if (f.result != Type::Void) header += ", " + f.name;
  for (std::size_t a = 0; a < t.agents.size(); ++a)
    for (std::size_t f = 0; f < c.functions.size(); ++f)
      if (!t.agents[a][f].empty()) header += fmt::format(", {}@{}", c.functions[f].name, a + 1);
  for (int k = 0; k < t.ticks; ++k) {
    const auto tick = static_cast<std::size_t>(k);
    rows += std::to_string(k + 1);
    for (std::size_t f = 0; f < c.functions.size(); ++f)
      if (c.functions[f].result != Type::Void) rows += ", " + t.values[f][tick];
    for (const auto &own : t.agents)
      for (const auto &v : own)
        if (!v.empty()) rows += ", " + v[tick];
    rows += "\n";
  }
  return header + "\n" + rows;
}

}  // namespace gfec::diff
