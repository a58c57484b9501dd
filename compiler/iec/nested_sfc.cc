// An SFC inside an action or a function block, compiled into one scan of statements
// (nested_sfc.h). The scan is docs/iec.md "The scan" written out: step timers, transitions on
// the step states at the start of the scan (a selection's first transition in order takes its
// step), the step update, then the action control of every action the SFC's steps hold and their
// bodies. Its steps are Boolean, as on a PLC (docs/iec.md "SFC inside actions and function
// blocks").
#include "iec/nested_sfc.h"

#include "did_you_mean.h"
#include "model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

namespace gfec::iec {

namespace {

/// Makes the generated tree. Every node gets the range of the SFC element it implements, so a
/// message about it points at what the user wrote.
class Builder {
public:
  Builder(ast::File &file, SourceRange at) : file_(file), at_(at) {}

  ast::ExprPtr name(std::string_view n) const {
    auto e = make(ast::Expr::Kind::Name);
    e->name = {n, at_};
    return e;
  }
  ast::ExprPtr boolean(bool b) const {
    auto e = make(ast::Expr::Kind::Bool);
    e->bool_value = b;
    return e;
  }
  ast::ExprPtr duration(double ms) const {
    auto e = make(ast::Expr::Kind::Duration);
    e->duration_ms = ms;
    e->name = {file_.strings.emplace_back(fmt::format("{}ms", ms)), at_};
    return e;
  }
  ast::ExprPtr now() const {
    auto e = make(ast::Expr::Kind::Call);
    e->name = {"now", at_};
    return e;
  }
  ast::ExprPtr negate(ast::ExprPtr x) const {
    auto e = make(ast::Expr::Kind::Unary);
    e->unary_op = UnaryOp::Not;
    e->name.range = at_;
    e->args.push_back(bracket(std::move(x)));
    return e;
  }
  /// `a op b`, with brackets where C's precedence needs them (the tree is printed as it stands),
  /// and none in a chain of one associative operator (`a && b && c`).
  ast::ExprPtr binary(BinaryOp op, ast::ExprPtr a, ast::ExprPtr b) const {
    auto e = make(ast::Expr::Kind::Binary);
    e->binary_op = op;
    e->name.range = at_;
    const bool chain = op == BinaryOp::And || op == BinaryOp::Or;
    auto operand = [&](ast::ExprPtr x, bool left) {
      if (x->kind == ast::Expr::Kind::Binary && !(chain && left && x->binary_op == op)) return bracket(std::move(x));
      return x;
    };
    e->args.push_back(operand(std::move(a), true));
    e->args.push_back(operand(std::move(b), false));
    return e;
  }
  /// `a || b`, where either may be absent (false).
  ast::ExprPtr any(ast::ExprPtr a, ast::ExprPtr b) const {
    if (!a) return b;
    if (!b) return a;
    return binary(BinaryOp::Or, std::move(a), std::move(b));
  }
  ast::ExprPtr all(ast::ExprPtr a, ast::ExprPtr b) const {
    if (!a) return b;
    if (!b) return a;
    return binary(BinaryOp::And, std::move(a), std::move(b));
  }
  ast::Stmt assign(std::string_view target, ast::ExprPtr value) const {
    ast::Stmt s;
    s.kind = ast::Stmt::Kind::Assign;
    s.range = at_;
    s.target.emplace(ast::Name{target, at_});
    s.value = std::move(value);
    return s;
  }
  ast::Stmt when(ast::ExprPtr condition, ast::Block then) const {
    ast::Stmt s;
    s.kind = ast::Stmt::Kind::If;
    s.range = at_;
    s.value = std::move(condition);
    for (ast::Stmt &t : then) s.then_block.push_back(std::move(t));
    return s;
  }

private:
  ast::ExprPtr make(ast::Expr::Kind k) const {
    auto e = std::make_unique<ast::Expr>();
    e->kind = k;
    e->range = at_;
    return e;
  }
  ast::ExprPtr bracket(ast::ExprPtr x) const {
    if (x->kind != ast::Expr::Kind::Binary) return x;
    auto e = make(ast::Expr::Kind::Paren);
    e->range = x->range;
    e->args.push_back(std::move(x));
    return e;
  }

  ast::File &file_;
  SourceRange at_;
};

template <typename Stmts> void rewrite_block(Stmts &block, const InnerSfcs &sfcs) {
  for (ast::Stmt &s : block) {
    if (s.value) rewrite_inner_reads(*s.value, sfcs);
    if (s.call) rewrite_inner_reads(*s.call, sfcs);
    rewrite_block(s.then_block, sfcs);
    rewrite_block(s.else_block, sfcs);
  }
}

template <typename F> void each_expr(ast::Expr &e, const F &f) {
  f(e);
  for (ast::Expr *a : e.args)
    if (a) each_expr(*a, f);
}

template <typename Stmts, typename F> void each_expr_in(Stmts &block, const F &f) {
  for (ast::Stmt &s : block) {
    if (s.value) each_expr(*s.value, f);
    if (s.call) each_expr(*s.call, f);
    each_expr_in(s.then_block, f);
    each_expr_in(s.else_block, f);
  }
}

/// The qualifiers of one action's associations in one SFC, gathered for its control.
struct Held {
  std::size_t step;  ///< index into the SFC's steps
  model::Qualifier qualifier;
  double ms = 0;
  SourceRange range;
};

/// How deep SFCs may sit inside the SFCs of actions (docs/iec.md "SFC inside actions and
/// function blocks").
constexpr std::size_t kMaxDepth = 16;

/// One SFC being compiled: its steps' variables, by index of Step.
struct StepVars {
  std::string_view x, t, avail, add, was;
};

/// Makes the expression of an SFC action's Q, which its scan tests to stop the SFC.
using StopWhen = std::function<ast::ExprPtr(const Builder &)>;

class Compiler {
public:
  Compiler(Pou &pou, Spellings &names, ast::File &file, Diagnostics &diag, std::optional<double> period_ms,
           InnerSfcs &out)
      : pou_(pou), names_(names), file_(file), diag_(diag), period_ms_(period_ms), out_(out) {}

  void run(bool function_block);

private:
  /// The SFCs (by key: "" for the POU's own, else the upper-case name of the action whose body
  /// it is) and the actions each one's steps hold.
  struct Sfc {
    std::string key;
    std::string_view label;  ///< "action 'Seq'", "function block 'Light'"
    std::vector<Step> *steps = nullptr;
    std::vector<Transition> *transitions = nullptr;
    SourceRange range;
  };

  std::size_t action_index(std::string_view name) const {
    auto it = action_by_name_.find(upper(name));
    return it == action_by_name_.end() ? SIZE_MAX : it->second;
  }
  std::string_view fresh(std::string base) {
    while (names_.declared(base)) base += '_';
    std::string_view v = file_.strings.emplace_back(std::move(base));
    names_.declare(ast::Name{v, {}});
    return v;
  }
  std::string_view variable(std::string base, const char *type, SourceRange at, ast::ExprPtr init = nullptr) {
    std::string_view v = fresh(std::move(base));
    declare(v, type, at, std::move(init));
    return v;
  }
  void declare(std::string_view v, const char *type, SourceRange at, ast::ExprPtr init) {
    ast::ValueDecl &d = out_.variables.emplace_back();
    d.role = ast::VarRole::Local;
    d.type = {type, at};
    d.name = {v, at};
    d.range = at;
    d.init = std::move(init);
  }

  bool owners();
  bool check(const Sfc &g);
  /// One scan of `g`. `stop`: the Q of the action whose body it is (its SFC then starts over in
  /// the first run after a run with Q false); null for a function block's, which runs from its
  /// instance's start on.
  ast::Block scan(const Sfc &g, const StopWhen *stop);
  /// The time one scan of `g` adds to its timers: the period, or for a function block the time
  /// since its previous call (now()), kept in `last`.
  ast::ExprPtr step_time(const Builder &b, const Sfc &g);
  /// The body of action `i`: its own statements, or its SFC's scan, which stops after a run in
  /// which `q` (the action's Q) is false.
  ast::Block body_of(std::size_t i, const StopWhen &q);

  Pou &pou_;
  Spellings &names_;
  ast::File &file_;
  Diagnostics &diag_;
  std::optional<double> period_ms_;
  InnerSfcs &out_;
  bool function_block_ = false;
  std::vector<Sfc> sfcs_;
  std::map<std::string, std::string> owner_;       ///< action (upper case) -> the key of the SFC holding it
  std::map<std::string, SourceRange> owner_at_;    ///< where that SFC first holds it
  std::map<std::string, std::vector<Held>> held_;  ///< SFC key + '\n' + action -> its associations there
  std::set<std::string> timed_;                    ///< inner steps (upper case) whose `.T` is read
  std::string_view dt_;                            ///< a function block's: the time since its instance's previous call
  std::set<std::string> compiling_;                ///< SFC actions being compiled (a cycle check)
  std::map<std::string, std::size_t> action_by_name_;  ///< upper case -> index in Pou::actions
  bool period_reported_ = false;
  bool too_deep_ = false;  ///< reported once: the SFCs below it are not compiled
};

bool Compiler::owners() {
  bool ok = true;
  for (const Sfc &g : sfcs_)
    for (std::size_t s = 0; s < g.steps->size(); ++s)
      for (const ast::Association &as : (*g.steps)[s].associations) {
        const std::string a = upper(as.action.text);
        // The program's own SFC becomes the chart's places: the validator checks its associations.
        const bool checked_here = !g.key.empty() || function_block_;
        if (action_index(as.action.text) == SIZE_MAX) {
          if (!checked_here) continue;
          Diagnostic &d = diag_.error(as.action.range, ErrorKind::UnknownName,
                                      fmt::format("no action '{}' (step '{}' of the SFC of {})", as.action.text,
                                                  (*g.steps)[s].name.text, g.label));
          suggest_nearest(d, as.action, pou_.actions, [](const Action &x) -> const ast::Name & { return x.name; });
          ok = false;
          continue;
        }
        auto [it, fresh] = owner_.emplace(a, g.key);
        if (fresh) owner_at_.emplace(a, as.action.range);
        if (it->second != g.key) {
          diag_
              .error(as.action.range, ErrorKind::NotSupported,
                     fmt::format("action '{}' is held by steps of two SFCs: an action belongs to the one SFC whose "
                                 "steps hold it (its action control is that SFC's); one held by two is not "
                                 "supported yet",
                                 as.action.text))
              .note(owner_at_[a], "held here too");
          ok = false;
          continue;
        }
        const std::optional<model::Qualifier> q = model::qualifier_named(upper(as.qualifier.text));
        if (!q) continue;  // the reader reported it
        held_[g.key + '\n' + a].push_back({s, *q, as.duration_ms.value_or(0), as.range});
        if (checked_here && model::is_timed(*q) != as.duration_ms.has_value()) {
          diag_.error(as.range, ErrorKind::QualifierTime,
                      model::is_timed(*q)
                          ? fmt::format("qualifier {} needs a duration ('{}({}, T#1s)')", upper(as.qualifier.text),
                                        as.action.text, upper(as.qualifier.text))
                          : fmt::format("qualifier {} takes no duration", upper(as.qualifier.text)));
          ok = false;
        }
      }
  // An action whose SFC holds it, directly or through others', would run inside itself.
  for (const auto &[a, key] : owner_) {
    std::string at = key;
    for (std::size_t hops = 0; !at.empty() && hops <= owner_.size(); ++hops) {
      if (at == a) {
        diag_.error(owner_at_[a], ErrorKind::NotSupported,
                    fmt::format("action '{}' is held by a step of its own SFC (directly or through the SFCs of other "
                                "actions): it would run inside itself",
                                pou_.actions[action_index(a)].name.text));
        return false;
      }
      auto up = owner_.find(at);
      at = up == owner_.end() ? std::string() : up->second;
    }
  }
  return ok;
}

bool Compiler::check(const Sfc &g) {
  bool ok = true, initial = false;
  std::map<std::string, const Step *> steps;
  for (const Step &s : *g.steps) {
    initial = initial || s.initial;
    auto [it, fresh] = steps.emplace(upper(s.name.text), &s);
    if (!fresh) {
      diag_.error(s.name.range, ErrorKind::DuplicateName, fmt::format("step '{}' is declared twice", s.name.text))
          .note(it->second->name.range, "the first declaration");
      ok = false;
    }
  }
  if (!initial) {
    diag_.error(g.range, ErrorKind::InitialState, fmt::format("the SFC of {} has no initial step", g.label))
        .note("IEC 61131-3 starts an SFC at its INITIAL_STEP");
    ok = false;
  }
  for (const Transition &t : *g.transitions)
    for (const std::vector<ast::Name> *side : {&t.from, &t.to})
      for (const ast::Name &n : *side) {
        if (steps.count(upper(n.text))) continue;
        Diagnostic &d = diag_.error(
            n.range, ErrorKind::UnknownName,
            fmt::format("no step '{}' in the SFC of {}: a transition links steps of its own SFC", n.text, g.label));
        suggest_nearest(d, n, *g.steps, [](const Step &x) -> const ast::Name & { return x.name; });
        ok = false;
      }
  return ok;
}

ast::ExprPtr Compiler::step_time(const Builder &b, const Sfc &g) {
  if (function_block_) return b.name(dt_);
  if (!period_ms_ || *period_ms_ != std::floor(*period_ms_)) {
    if (!period_reported_)
      diag_
          .error(g.range, period_ms_ ? ErrorKind::NotSupported : ErrorKind::MissingPeriod,
                 period_ms_ ? fmt::format("the SFC of {} times its steps, in whole milliseconds: a period of {} ms "
                                          "is not supported there",
                                          g.label, *period_ms_)
                            : fmt::format("the SFC of {} reads a time, but no TASK with an INTERVAL runs program '{}'",
                                          g.label, pou_.name.text))
          .note(pou_.name.range, "give the program a task with an INTERVAL, or the period on the command line: "
                                 "'--period 10ms'");
    period_reported_ = out_.period_reported = true;
    return b.duration(1);
  }
  return b.duration(*period_ms_);
}

ast::Block Compiler::body_of(std::size_t i, const StopWhen &q) {
  Action &a = pou_.actions[i];
  if (!a.sfc()) return std::move(a.body);
  const std::string key = upper(a.name.text);
  auto g = std::find_if(sfcs_.begin(), sfcs_.end(), [&](const Sfc &s) { return s.key == key; });
  if (g == sfcs_.end() || !compiling_.insert(key).second) return {};
  if (compiling_.size() > kMaxDepth || too_deep_) {
    compiling_.erase(key);
    if (too_deep_) return {};
    too_deep_ = true;
    // Each level is an `if` around the next one's scan: the tree's depth, which every later
    // stage walks recursively, stays bounded whatever a file holds.
    diag_.error(a.name.range, ErrorKind::Nesting,
                fmt::format("action '{}' runs an SFC inside the SFCs of {} other actions: more than {} levels are "
                            "not supported",
                            a.name.text, compiling_.size(), kMaxDepth));
    return {};
  }
  ast::Block body = scan(*g, &q);
  compiling_.erase(key);
  return body;
}

ast::Block Compiler::scan(const Sfc &g, const StopWhen *stop) {
  std::vector<Step> &steps = *g.steps;
  std::vector<Transition> &transitions = *g.transitions;
  ast::Block out;
  const Builder sfc(file_, g.range);
  // The actions this SFC's steps hold, in the POU's declaration order: the order they run in.
  std::vector<std::size_t> held;
  for (std::size_t i = 0; i < pou_.actions.size(); ++i) {
    auto it = owner_.find(upper(pou_.actions[i].name.text));
    if (it != owner_.end() && it->second == g.key) held.push_back(i);
  }
  auto associations = [&](std::size_t i) -> const std::vector<Held> & {
    static const std::vector<Held> none;
    auto it = held_.find(g.key + '\n' + upper(pou_.actions[i].name.text));
    return it == held_.end() ? none : it->second;
  };
  // Which steps need which variables.
  std::vector<bool> input(steps.size()), output(steps.size()), timed(steps.size()), edge(steps.size());
  auto index = [&](const ast::Name &n) {
    for (std::size_t s = 0; s < steps.size(); ++s)
      if (upper(steps[s].name.text) == upper(n.text)) return s;
    return SIZE_MAX;
  };
  for (const Transition &t : transitions) {
    for (const ast::Name &n : t.from) input[index(n)] = true;
    for (const ast::Name &n : t.to) output[index(n)] = true;
  }
  bool acted = false, stored_timers = false;
  for (std::size_t i : held)
    for (const Held &h : associations(i)) {
      using Q = model::Qualifier;
      const Q q = h.qualifier;
      timed[h.step] = timed[h.step] || q == Q::L || q == Q::D || q == Q::DS;
      edge[h.step] = edge[h.step] || q == Q::P || q == Q::P1 || q == Q::P0;
      acted = acted || (q == Q::P0 && steps[h.step].initial);
      stored_timers = stored_timers || q == Q::SD || q == Q::SL;
    }
  std::vector<StepVars> vars(steps.size());
  const std::string prefix = stop ? std::string(pou_.actions[action_index(g.key)].name.text) : "SFC";
  for (std::size_t s = 0; s < steps.size(); ++s) {
    Step &st = steps[s];
    const Builder b(file_, st.range);
    const std::string key = upper(st.name.text);
    timed[s] = timed[s] || timed_.count(key);
    // The step is its X: a BOOL of its own name (declared already, as a step).
    vars[s].x = st.name.text;
    declare(st.name.text, "bool", st.range, b.boolean(st.initial && !stop));
    out_.x.emplace(key, st.name.text);
    if (timed[s]) {
      vars[s].t = variable(std::string(st.name.text) + "_T", "time", st.range, b.duration(0));
      out_.t.emplace(key, vars[s].t);
    }
    if (input[s]) vars[s].avail = variable(std::string(st.name.text) + "_avail", "bool", st.range);
    if (output[s]) vars[s].add = variable(std::string(st.name.text) + "_add", "bool", st.range);
    if (edge[s]) vars[s].was = variable(std::string(st.name.text) + "_was", "bool", st.range);
  }
  std::string_view acted_var, start_var;
  if (acted) acted_var = variable(prefix + "_acted", "bool", g.range);
  // The actions' variables: Q and A always, the stored flags and their timers as used.
  struct ActionVars {
    std::string_view q, a, s, sd, sd_t, ds, sl, sl_t;
    double sd_ms = 0, sl_ms = 0;
  };
  std::map<std::size_t, ActionVars> avars;
  for (std::size_t i : held) {
    const Action &a = pou_.actions[i];
    const std::string key = upper(a.name.text);
    const std::string base(a.name.text);
    ActionVars &v = avars[i];
    v.q = variable(base + "_Q", "bool", a.range);
    v.a = variable(base + "_A", "bool", a.range);
    out_.q.emplace(key, v.q);
    out_.a.emplace(key, v.a);
    out_.inner.insert(key);
    std::optional<double> sd, sl;
    for (const Held &h : associations(i)) {
      using Q = model::Qualifier;
      if (h.qualifier == Q::S && v.s.empty()) v.s = variable(base + "_S", "bool", a.range);
      if (h.qualifier == Q::DS && v.ds.empty()) v.ds = variable(base + "_DS", "bool", a.range);
      for (auto [q, flag, timer, ms, name] :
           {std::tuple{Q::SD, &v.sd, &v.sd_t, &sd, "_SD"}, std::tuple{Q::SL, &v.sl, &v.sl_t, &sl, "_SL"}}) {
        if (h.qualifier != q) continue;
        if (flag->empty()) {
          *flag = variable(base + name, "bool", a.range);
          *timer = variable(base + name + "_T", "time", a.range, sfc.duration(0));
        }
        if (*ms && **ms != h.ms)
          diag_.error(h.range, ErrorKind::QualifierTime,
                      fmt::format("action '{}' is held under {} for two durations: its timer is the action's",
                                  a.name.text, model::qualifier_name(q)));
        *ms = h.ms;
      }
    }
    v.sd_ms = sd.value_or(0);
    v.sl_ms = sl.value_or(0);
  }
  if (stop) {
    // The first run after a stop (and the first ever) starts from the initial steps, whose
    // timers then count this scan as their first, as a program's initial steps do in scan 1.
    start_var = variable(prefix + "_start", "bool", g.range, sfc.boolean(true));
    ast::Block begin;
    for (std::size_t s = 0; s < steps.size(); ++s) {
      if (!steps[s].initial) continue;
      const Builder b(file_, steps[s].range);
      begin.push_back(b.assign(vars[s].x, b.boolean(true)));
      if (!vars[s].t.empty()) begin.push_back(b.assign(vars[s].t, b.duration(0)));
    }
    if (!acted_var.empty()) begin.push_back(sfc.assign(acted_var, sfc.boolean(false)));
    begin.push_back(sfc.assign(start_var, sfc.boolean(false)));
    out.push_back(sfc.when(sfc.name(start_var), std::move(begin)));
  }
  // 1. The timers of the steps active at the start of the scan.
  for (std::size_t s = 0; s < steps.size(); ++s) {
    if (vars[s].t.empty()) continue;
    const Builder b(file_, steps[s].range);
    ast::Block grow;
    grow.push_back(b.assign(vars[s].t, b.binary(BinaryOp::Add, b.name(vars[s].t), step_time(b, g))));
    out.push_back(b.when(b.name(vars[s].x), std::move(grow)));
  }
  // 2. The transitions in order (PRIORITY first within a divergence, as the program's), on the
  // step states at the start of the scan: a step taken by one is not there for the next.
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const Builder b(file_, steps[s].range);
    if (!vars[s].avail.empty()) out.push_back(b.assign(vars[s].avail, b.name(vars[s].x)));
    if (!vars[s].add.empty()) out.push_back(b.assign(vars[s].add, b.boolean(false)));
  }
  order_by_priority(transitions);
  for (Transition &t : transitions) {
    const Builder b(file_, t.range);
    ast::ExprPtr open;
    for (const ast::Name &n : t.from) open = b.all(std::move(open), b.name(vars[index(n)].avail));
    if (t.condition) open = b.all(std::move(open), std::move(t.condition));
    if (!open) open = b.boolean(true);  // a transition from no step (a reader's recovery)
    ast::Block fire;
    for (const ast::Name &n : t.from) fire.push_back(b.assign(vars[index(n)].avail, b.boolean(false)));
    for (const ast::Name &n : t.to) fire.push_back(b.assign(vars[index(n)].add, b.boolean(true)));
    out.push_back(b.when(std::move(open), std::move(fire)));
  }
  // 3. The step update: a step entered (not active before) starts its timer at 0.
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const StepVars &v = vars[s];
    const Builder b(file_, steps[s].range);
    if (!v.add.empty() && !v.t.empty()) {
      ast::Block enter;
      enter.push_back(b.assign(v.t, b.duration(0)));
      out.push_back(b.when(b.all(b.name(v.add), b.negate(b.name(v.x))), std::move(enter)));
    }
    if (v.avail.empty() && v.add.empty()) continue;
    out.push_back(
        b.assign(v.x, b.any(b.name(v.avail.empty() ? v.x : v.avail), v.add.empty() ? nullptr : b.name(v.add))));
  }
  // 4. The action control of each action the steps hold (docs/iec.md "Action control"), then
  // their bodies in declaration order: a body reads every action's Q and A of this scan.
  for (std::size_t i : held) {
    const ActionVars &v = avars[i];
    const Builder b(file_, pou_.actions[i].range);
    using Q = model::Qualifier;
    auto x = [&](const Held &h) { return b.name(vars[h.step].x); };
    auto any_of = [&](Q q) {
      ast::ExprPtr e;
      for (const Held &h : associations(i))
        if (h.qualifier == q) e = b.any(std::move(e), x(h));
      return e;
    };
    out.push_back(b.assign(v.a, b.name(v.q)));  // the previous scan's Q, for the final run
    for (auto [flag, timer] : {std::pair{v.sd, v.sd_t}, std::pair{v.sl, v.sl_t}}) {
      if (flag.empty()) continue;
      ast::Block grow;
      grow.push_back(b.assign(timer, b.binary(BinaryOp::Add, b.name(timer), step_time(b, g))));
      out.push_back(b.when(b.name(flag), std::move(grow)));
    }
    if (ast::ExprPtr set = any_of(Q::S)) {
      ast::Block raise;
      raise.push_back(b.assign(v.s, b.boolean(true)));
      out.push_back(b.when(std::move(set), std::move(raise)));
    }
    // A set starts the timer only as the flag rises.
    for (auto [q, flag, timer] : {std::tuple{Q::SD, v.sd, v.sd_t}, std::tuple{Q::SL, v.sl, v.sl_t}}) {
      ast::ExprPtr set = any_of(q);
      if (!set) continue;
      ast::Block raise;
      raise.push_back(b.assign(flag, b.boolean(true)));
      raise.push_back(b.assign(timer, b.duration(0)));
      out.push_back(b.when(b.all(std::move(set), b.negate(b.name(flag))), std::move(raise)));
    }
    ast::ExprPtr ds;
    for (const Held &h : associations(i))
      if (h.qualifier == Q::DS)
        ds = b.any(std::move(ds), b.all(x(h), b.binary(BinaryOp::Ge, b.name(vars[h.step].t), b.duration(h.ms))));
    if (ds) {
      ast::Block raise;
      raise.push_back(b.assign(v.ds, b.boolean(true)));
      out.push_back(b.when(std::move(ds), std::move(raise)));
    }
    if (ast::ExprPtr reset = any_of(Q::R)) {
      ast::Block clear;  // reset dominates: after the sets
      for (std::string_view flag : {v.s, v.sd, v.ds, v.sl})
        if (!flag.empty()) clear.push_back(b.assign(flag, b.boolean(false)));
      if (!clear.empty()) out.push_back(b.when(std::move(reset), std::move(clear)));
    }
    ast::ExprPtr q, edges;
    for (const Held &h : associations(i)) {
      const StepVars &sv = vars[h.step];
      switch (h.qualifier) {
      case Q::N: q = b.any(std::move(q), x(h)); break;
      case Q::P: q = b.any(std::move(q), b.all(x(h), b.negate(b.name(sv.was)))); break;
      case Q::L: q = b.any(std::move(q), b.all(x(h), b.binary(BinaryOp::Lt, b.name(sv.t), b.duration(h.ms)))); break;
      case Q::D: q = b.any(std::move(q), b.all(x(h), b.binary(BinaryOp::Ge, b.name(sv.t), b.duration(h.ms)))); break;
      case Q::P1: edges = b.any(std::move(edges), b.all(x(h), b.negate(b.name(sv.was)))); break;
      case Q::P0: {
        // An initial step left in the SFC's first scan falls in it (docs/iec.md "The initial step").
        ast::ExprPtr before = b.name(sv.was);
        if (steps[h.step].initial) before = b.any(std::move(before), b.negate(b.name(acted_var)));
        edges = b.any(std::move(edges), b.all(b.negate(x(h)), std::move(before)));
        break;
      }
      default: break;
      }
    }
    if (!v.s.empty()) q = b.any(std::move(q), b.name(v.s));
    if (!v.sd.empty())
      q = b.any(std::move(q), b.all(b.name(v.sd), b.binary(BinaryOp::Ge, b.name(v.sd_t), b.duration(v.sd_ms))));
    if (!v.ds.empty()) q = b.any(std::move(q), b.name(v.ds));
    if (!v.sl.empty())
      q = b.any(std::move(q), b.all(b.name(v.sl), b.binary(BinaryOp::Lt, b.name(v.sl_t), b.duration(v.sl_ms))));
    out.push_back(b.assign(v.q, q ? std::move(q) : b.boolean(false)));
    // Q, its final run as Q falls, or an edge of P1 / P0: at most one run per scan.
    out.push_back(b.assign(v.a, b.any(b.any(b.name(v.q), b.name(v.a)), std::move(edges))));
  }
  for (std::size_t s = 0; s < steps.size(); ++s)
    if (!vars[s].was.empty()) out.push_back(Builder(file_, steps[s].range).assign(vars[s].was, sfc.name(vars[s].x)));
  if (!acted_var.empty()) out.push_back(sfc.assign(acted_var, sfc.boolean(true)));
  for (std::size_t i : held) {
    const Builder b(file_, pou_.actions[i].range);
    const std::string key = upper(pou_.actions[i].name.text);
    const StopWhen q = [this, key](const Builder &b) { return b.name(out_.q.at(key)); };  // this scan's Q
    out.push_back(b.when(b.name(avars[i].a), body_of(i, q)));
  }
  if (stop) {
    // A run with the action's Q false was its last: the SFC stops, every step and action off,
    // and starts over at its next run.
    ast::Block end;
    for (std::size_t s = 0; s < steps.size(); ++s) {
      end.push_back(sfc.assign(vars[s].x, sfc.boolean(false)));
      if (!vars[s].was.empty()) end.push_back(sfc.assign(vars[s].was, sfc.boolean(false)));
    }
    for (std::size_t i : held)
      for (std::string_view flag : {avars[i].q, avars[i].a, avars[i].s, avars[i].sd, avars[i].ds, avars[i].sl})
        if (!flag.empty()) end.push_back(sfc.assign(flag, sfc.boolean(false)));
    end.push_back(sfc.assign(start_var, sfc.boolean(true)));
    out.push_back(sfc.when(sfc.negate((*stop)(sfc)), std::move(end)));
  }
  return out;
}

void Compiler::run(bool function_block) {
  function_block_ = function_block;
  if (function_block && (!pou_.steps.empty() || !pou_.transitions.empty()))
    sfcs_.push_back({"", file_.strings.emplace_back(fmt::format("function block '{}'", pou_.name.text)), &pou_.steps,
                     &pou_.transitions, pou_.name.range});
  else sfcs_.push_back({"", "the program", &pou_.steps, &pou_.transitions, pou_.name.range});
  for (Action &a : pou_.actions)
    if (a.sfc())
      sfcs_.push_back({upper(a.name.text), file_.strings.emplace_back(fmt::format("action '{}'", a.name.text)),
                       &a.steps, &a.transitions, a.name.range});
  if (sfcs_.size() == 1 && !function_block) return;
  for (std::size_t i = 0; i < pou_.actions.size(); ++i)
    if (!action_by_name_.emplace(upper(pou_.actions[i].name.text), i).second) {
      // An action declared twice: the validator reports it, and which one a step holds is moot.
      for (Action &x : pou_.actions) x.steps.clear(), x.transitions.clear();
      return;
    }
  // Which inner steps have their `.T` read anywhere in the POU.
  std::set<std::string> inner_steps;
  for (std::size_t k = function_block ? 0 : 1; k < sfcs_.size(); ++k)
    for (const Step &s : *sfcs_[k].steps) inner_steps.insert(upper(s.name.text));
  auto note_reads = [&](ast::Expr &e) {
    if (e.kind == ast::Expr::Kind::Call && e.name.text == "elapsed" && e.args.size() == 1 && e.args[0] &&
        inner_steps.count(upper(e.args[0]->name.text)))
      timed_.insert(upper(e.args[0]->name.text));
  };
  for (const Sfc &g : sfcs_)
    for (Transition &t : *g.transitions)
      if (t.condition) each_expr(*t.condition, note_reads);
  for (Action &a : pou_.actions) each_expr_in(a.body, note_reads);
  if (pou_.body) each_expr_in(*pou_.body, note_reads);
  bool ok = owners();
  for (std::size_t k = function_block ? 0 : 1; k < sfcs_.size(); ++k) ok = check(sfcs_[k]) && ok;
  if (!ok) {
    // Reported; what is left is dropped, so nothing else reports on a broken SFC.
    for (Action &a : pou_.actions) a.steps.clear(), a.transitions.clear();
    return;
  }
  if (function_block) {
    // Its timers count the time between calls, which the instance does not see: it reads now()
    // at each call, and only when some timer needs it (now() asks the holder for a period).
    bool timers = !timed_.empty();
    for (const auto &[key, list] : held_)
      for (const Held &h : list) timers = timers || model::is_timed(h.qualifier);
    ast::Block body;
    if (timers) {
      const Builder b(file_, pou_.name.range);
      const std::string_view last = variable("SFC_last", "time", pou_.name.range, b.duration(0));
      dt_ = variable("SFC_dt", "time", pou_.name.range, b.duration(0));
      body.push_back(b.assign(dt_, b.binary(BinaryOp::Sub, b.now(), b.name(last))));
      body.push_back(b.assign(last, b.now()));
    }
    for (ast::Stmt &st : scan(sfcs_.front(), nullptr)) body.push_back(std::move(st));
    pou_.body = std::move(body);
  }
  // An SFC action that no inner SFC holds is the program's: its body becomes its scan, which
  // stops when its own Q (`active(A)`, this scan's) is false.
  for (std::size_t i = 0; i < pou_.actions.size(); ++i) {
    Action &a = pou_.actions[i];
    const std::string key = upper(a.name.text);
    auto held = owner_.find(key);
    if (!a.sfc() || out_.inner.count(key) || (held != owner_.end() && !held->second.empty())) continue;
    const StopWhen q = [&a](const Builder &b) {
      auto e = std::make_unique<ast::Expr>();
      e->kind = ast::Expr::Kind::Call;
      e->range = a.name.range;
      e->name = {"active", a.name.range};
      e->args.push_back(b.name(a.name.text));
      return e;
    };
    a.body = body_of(i, q);
  }
  for (Action &a : pou_.actions) a.steps.clear(), a.transitions.clear();
}

}  // namespace

InnerSfcs compile_inner_sfcs(Pou &pou, bool function_block, Spellings &names, ast::File &file, Diagnostics &diag,
                             std::optional<double> period_ms) {
  InnerSfcs out;
  Compiler(pou, names, file, diag, period_ms, out).run(function_block);
  return out;
}

void rewrite_inner_reads(ast::Expr &e, const InnerSfcs &sfcs) {
  for (ast::Expr *a : e.args)
    if (a) rewrite_inner_reads(*a, sfcs);
  if (e.kind != ast::Expr::Kind::Call || e.args.size() != 1 || !e.args[0] || e.args[0]->kind != ast::Expr::Kind::Name)
    return;
  const std::map<std::string, std::string_view> *table = e.name.text == "active"    ? &sfcs.x
                                                         : e.name.text == "elapsed" ? &sfcs.t
                                                         : e.name.text == "running" ? &sfcs.a
                                                                                    : nullptr;
  if (!table) return;
  const std::string key = upper(e.args[0]->name.text);
  auto it = table->find(key);
  if (it == table->end() && e.name.text == "active") {
    it = sfcs.q.find(key);  // `A.Q` of an inner action
    if (it == sfcs.q.end()) return;
  } else if (it == table->end()) {
    return;
  }
  e.kind = ast::Expr::Kind::Name;
  e.name = {it->second, e.range};
  e.args = ast::ExprList();
}

void rewrite_inner_reads(std::vector<ast::Stmt> &block, const InnerSfcs &sfcs) { rewrite_block(block, sfcs); }

}  // namespace gfec::iec
