#include "shrink.h"

#include <functional>

namespace gfec::diff {

namespace {

using Mutation = std::function<bool(Case &)>;  ///< false: nothing to change at this index

/// Every expression of the chart, in a fixed order.
void for_each_expr(GChart &c, const std::function<void(GExpr &)> &f) {
  std::function<void(GExpr &)> walk = [&](GExpr &e) {
    f(e);
    for (auto &a : e.args) walk(a);
  };
  std::function<void(std::vector<GStmt> &)> block = [&](std::vector<GStmt> &b) {
    for (auto &s : b) {
      walk(s.expr);
      block(s.then_block);
      block(s.else_block);
    }
  };
  for (auto &p : c.places) {
    block(p.action);
    if (p.entry) block(*p.entry);
    if (p.exit) block(*p.exit);
    if (p.post) walk(*p.post);
  }
  for (auto &t : c.transitions)
    if (t.condition) walk(*t.condition);
}

/// The statement blocks of the chart, in a fixed order.
std::vector<std::vector<GStmt> *> blocks(GChart &c) {
  std::vector<std::vector<GStmt> *> out;
  // A block, then the branches of its ifs.
  std::function<void(std::vector<GStmt> &)> add = [&](std::vector<GStmt> &b) {
    out.push_back(&b);
    for (auto &s : b) {
      if (!s.is_if && s.counter.empty()) continue;
      add(s.then_block);
      add(s.else_block);
    }
  };
  for (auto &p : c.places) {
    add(p.action);
    if (p.entry) add(*p.entry);
    if (p.exit) add(*p.exit);
  }
  return out;
}

bool remove_place(GChart &c, int p) {
  if (c.places.size() <= 1 || (c.fsm && c.places[static_cast<std::size_t>(p)].initial)) return false;
  c.places.erase(c.places.begin() + p);
  std::vector<GTransition> kept;
  for (auto t : c.transitions) {
    bool touches = false;
    for (int q : t.inputs) touches = touches || q == p;
    for (int q : t.outputs) touches = touches || q == p;
    if (touches) continue;
    for (int &q : t.inputs) q -= q > p;
    for (int &q : t.outputs) q -= q > p;
    kept.push_back(t);
  }
  c.transitions = kept;
  bool initial = false;
  for (const auto &pl : c.places) initial = initial || pl.initial;
  if (!initial) c.places.front().initial = true;
  return true;
}

GExpr literal_of(Type t) {
  GExpr e;
  e.type = t;
  e.text = t == Type::Bool ? "false" : t == Type::Int ? "0" : t == Type::Duration ? "0ms" : "0.5";
  return e;
}

/// The mutations, coarse ones first. Each is (kind, index): an index past the end does nothing.
std::vector<std::function<bool(Case &, int)>> mutations() {
  return {
      // Fewer ticks.
      [](Case &c, int i) {
        int to = i == 0 ? 1 : i == 1 ? c.trace.ticks / 2 : i == 2 ? c.trace.ticks - 1 : -1;
        if (to < 1 || to >= c.trace.ticks) return false;
        c.trace.ticks = to;
        for (auto &v : c.trace.values)
          if (!v.empty()) v.resize(static_cast<std::size_t>(to));
        return true;
      },
      [](Case &c, int i) {  // a transition
        if (i >= static_cast<int>(c.chart.transitions.size())) return false;
        c.chart.transitions.erase(c.chart.transitions.begin() + i);
        return true;
      },
      [](Case &c, int i) {  // a place and its transitions
        return i < static_cast<int>(c.chart.places.size()) && remove_place(c.chart, i);
      },
      [](Case &c, int i) {  // a whole block emptied
        auto b = blocks(c.chart);
        if (i >= static_cast<int>(b.size()) || b[static_cast<std::size_t>(i)]->empty()) return false;
        b[static_cast<std::size_t>(i)]->clear();
        return true;
      },
      [](Case &c, int i) {  // entry and exit blocks, bodies, postconditions
        int k = 0;
        for (auto &p : c.chart.places) {
          if (p.entry && k++ == i) return p.entry.reset(), true;
          if (p.exit && k++ == i) return p.exit.reset(), true;
          if (p.post && k++ == i) return p.post.reset(), true;
          if (p.body && p.action.empty() && !p.entry && !p.exit && k++ == i) return p.body = false, true;
        }
        return false;
      },
      [](Case &c, int i) {  // one statement
        for (auto *b : blocks(c.chart)) {
          if (i < static_cast<int>(b->size())) return b->erase(b->begin() + i), true;
          i -= static_cast<int>(b->size());
        }
        return false;
      },
      [](Case &c, int i) {  // a condition
        int k = 0;
        for (auto &t : c.chart.transitions)
          if (t.condition && k++ == i) return t.condition.reset(), true;
        return false;
      },
      [](Case &c, int i) {  // a fork's or join's extra place
        for (auto &t : c.chart.transitions)
          for (auto *side : {&t.inputs, &t.outputs}) {
            if (side->size() > 1 && i < static_cast<int>(side->size())) return side->erase(side->begin() + i), true;
            if (side->size() > 1) i -= static_cast<int>(side->size());
          }
        return false;
      },
      [](Case &c, int i) {  // an expression replaced by one of its operands
        int k = 0;
        bool done = false;
        for_each_expr(c.chart, [&](GExpr &e) {
          for (std::size_t a = 0; a < e.args.size() && !done; ++a)
            if (k++ == i) {
              GExpr child = e.args[a];
              e = child;
              done = true;
            }
        });
        return done;
      },
      [](Case &c, int i) {  // an expression replaced by a literal
        int k = 0;
        bool done = false;
        for_each_expr(c.chart, [&](GExpr &e) {
          if (done || e.kind == GExpr::Kind::Lit || k++ != i) return;
          e = literal_of(e.type);
          done = true;
        });
        return done;
      },
      [](Case &c, int i) {  // a var, const or function nobody uses any more
        if (i < static_cast<int>(c.chart.vars.size())) return c.chart.vars.erase(c.chart.vars.begin() + i), true;
        i -= static_cast<int>(c.chart.vars.size());
        if (i < static_cast<int>(c.chart.consts.size())) return c.chart.consts.erase(c.chart.consts.begin() + i), true;
        i -= static_cast<int>(c.chart.consts.size());
        if (i < static_cast<int>(c.chart.functions.size())) {
          c.chart.functions.erase(c.chart.functions.begin() + i);
          c.trace.values.erase(c.trace.values.begin() + i);
          for (auto &own : c.trace.agents) own.erase(own.begin() + i);
          return true;
        }
        return false;
      },
      [](Case &c, int i) {  // an input value set to zero
        for (auto &v : c.trace.values)
          for (auto &x : v)
            if (x != "0" && i-- == 0) return x = "0", true;
        return false;
      },
      [](Case &c, int i) {  // var initialisers, the period
        if (i < static_cast<int>(c.chart.vars.size())) {
          auto &v = c.chart.vars[static_cast<std::size_t>(i)];
          if (v.init.empty()) return false;
          v.init.clear();
          return true;
        }
        if (i == static_cast<int>(c.chart.vars.size()) && c.chart.period_ms) return c.chart.period_ms = 0, true;
        return false;
      },
      // Hierarchical programs: a place of the root or of a sub-chart that runs nothing any more
      // (expressions that read into it make the candidate invalid, and it is not taken).
      [](Case &c, int i) {
        std::vector<GChart *> charts{&c.chart};
        for (auto &s : c.chart.pool) charts.push_back(&s);
        for (GChart *g : charts)
          for (auto &p : g->places)
            if (p.runs >= 0 && i-- == 0) return p.runs = -1, true;
        return false;
      },
      // A sub-chart's own places and blocks, as the root's above.
      [](Case &c, int i) {
        for (auto &s : c.chart.pool) {
          auto b = blocks(s);
          for (auto *block : b)
            if (!block->empty() && i-- == 0) return block->clear(), true;
          for (int p = 0; p < static_cast<int>(s.places.size()); ++p)
            if (i-- == 0) return remove_place(s, p);
          for (std::size_t t = 0; t < s.transitions.size(); ++t)
            if (i-- == 0) return s.transitions.erase(s.transitions.begin() + static_cast<std::ptrdiff_t>(t)), true;
        }
        return false;
      },
  };
}

/// More than the number of elements any mutation can index.
int size_hint(Case &c) {
  int n = 4 + static_cast<int>(c.chart.places.size() * 4 + c.chart.transitions.size() * 8 + c.chart.vars.size() +
                               c.chart.consts.size() + c.chart.functions.size());
  for (auto *b : blocks(c.chart)) n += static_cast<int>(b->size());
  for_each_expr(c.chart, [&](GExpr &e) { n += 1 + static_cast<int>(e.args.size()); });
  for (const auto &v : c.trace.values) n += static_cast<int>(v.size());
  for (auto &sub : c.chart.pool) {
    n += static_cast<int>(sub.places.size() * 2 + sub.transitions.size());
    n += static_cast<int>(blocks(sub).size());
  }
  return n;
}

}  // namespace

/// The warning a compile error is about ("-Wliteral-conversion"), to stay with one bug.
std::string warning_of(const std::string &compiler_output) {
  auto at = compiler_output.find("[-W");
  if (at == std::string::npos) return "";
  auto end = compiler_output.find(']', at);
  std::string w = compiler_output.substr(at + 1, end - at - 1);
  auto comma = w.rfind(",-W");  // clang: [-Werror,-Wname]; gcc: [-Werror=name]
  if (comma != std::string::npos) return w.substr(comma + 1);
  if (w.rfind("-Werror=", 0) == 0) return "-W" + w.substr(8);
  return w;
}

Outcome shrink(const Harness &h, Case &c, const Config &config, Verdict verdict, int *steps) {
  Outcome last;
  std::string warning;  // for compile errors: the warning of the first outcome
  int tries = 0;
  auto still_fails = [&](Case &candidate) {
    ++tries;
    if (h.prepare(candidate).verdict != Verdict::Pass) return false;
    Outcome o =
        verdict == Verdict::Lint ? h.lint_batch({&candidate}, "shrink").at(0) : h.run_one(candidate, config, "shrink");
    if (o.verdict != verdict) return false;
    if (verdict == Verdict::CompileError) {
      if (tries == 1) warning = warning_of(o.detail);
      else if (warning_of(o.detail) != warning) return false;
    }
    last = o;
    return true;
  };
  // The case as it is, so that `last` describes it even if nothing can be removed.
  still_fails(c);
  const auto all = mutations();
  for (bool progress = true; progress;) {
    progress = false;
    for (const auto &m : all) {
      // Indices past what the case holds change nothing; the case only shrinks meanwhile.
      for (int i = 0; i < size_hint(c); ++i) {
        Case candidate = c;
        candidate.prepared.reset();
        if (!m(candidate, i)) continue;
        if (still_fails(candidate)) {
          c = candidate;
          progress = true;
          --i;  // the same index now names the next element
        }
      }
    }
  }
  h.prepare(c);
  if (steps) *steps = tries;
  return last;
}

}  // namespace gfec::diff
