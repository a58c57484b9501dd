#include "c_floating_use.h"

namespace gfec::c_backend {

namespace {

using model::Expr;
using model::Type;

bool is_floating(Type t) { return t == Type::Float || t == Type::Double; }

/// Written by the engine as a literal: its value is fixed before any target computes it.
bool is_constant(const Expr &e) {
  switch (e.kind) {
  case Expr::Kind::Bool:
  case Expr::Kind::Int:
  case Expr::Kind::Float:
  case Expr::Kind::String:
  case Expr::Kind::Const:
  case Expr::Kind::Ticks: return true;
  default: return e.folded;
  }
}

class Walk {
public:
  explicit Walk(FloatingUse &use) : use_(use) {}

  void type(Type t) {
    use_.float_type |= t == Type::Float;
    use_.double_type |= t == Type::Double;
  }

  void expr(const Expr &e) {
    if (is_constant(e)) {
      // A float constant is written as a float literal; a double one only ever meets a double
      // at run time through an operator or a parameter, which count on their own.
      use_.float_type |= e.type == Type::Float;
      return;
    }
    type(e.type);
    if (e.kind == Expr::Kind::Convert && !e.args.empty() && is_floating(e.args[0].type) && !is_floating(e.type))
      use_.rounding = true;
    if (e.kind == Expr::Kind::Binary || e.kind == Expr::Kind::Unary) {
      for (const auto &a : e.args) {
        type(a.type);
        use_.arithmetic |= is_floating(a.type) && e.type == a.type;
      }
    }
    if (e.kind == Expr::Kind::Builtin) {  // abs, min, ... compare (and abs negates) in their type
      for (const auto &a : e.args) type(a.type);
      use_.arithmetic |= is_floating(e.type);
    }
    for (const auto &a : e.args) expr(a);
  }

  void statements(const EngineContext &c, const std::vector<model::Stmt> &list) {
    for (const auto &s : list) statement(c, s);
  }
  void statements(const EngineContext &c, const HeapVector<model::Stmt> &list) {
    for (const auto &s : list) statement(c, s);
  }

  void statement(const EngineContext &c, const model::Stmt &s) {
    switch (s.kind) {
    case model::Stmt::Kind::Verbatim: return;
    case model::Stmt::Kind::Assign:
      // `v += e` computes v + e in the wider of the two types.
      if (s.op != AssignOp::Set) {
        const Type v = c.chart.vars.at(s.var).type;
        if (is_floating(v) || is_floating(s.expr.type)) {
          type(v == Type::Double || s.expr.type == Type::Double ? Type::Double : Type::Float);
          use_.arithmetic = true;
        }
      }
      break;
    default: break;
    }
    expr(s.expr);
    statements(c, s.then_block);
    statements(c, s.else_block);
  }

  void chart(const EngineContext &c) {
    for (const auto &v : c.chart.vars) {
      type(v.type);
      if (v.init) expr(*v.init);
    }
    for (model::FunctionId f : c.chart.functions) {
      const auto &fn = c.model.functions.at(f);
      type(fn.result);
      for (const auto &p : fn.params) type(p.type);
    }
    for (const auto &p : c.chart.places) {
      statements(c, p.action);
      if (p.entry) statements(c, *p.entry);
      if (p.exit) statements(c, *p.exit);
      if (p.post) expr(*p.post);
    }
    for (const auto &t : c.chart.transitions)
      if (t.condition) expr(*t.condition);
    for (const auto &a : c.chart.actions) {
      // Named actions' bodies count for the rounding helper only: the floating flags stay as
      // they were for charts already generated.
      FloatingUse own;
      Walk(own).statements(c, a.body);
      use_.rounding |= own.rounding;
    }
    for (const auto &s : c.sub)
      if (s) chart(*s);
  }

private:
  FloatingUse &use_;
};

}  // namespace

FloatingUse floating_use(const EngineContext &root) {
  FloatingUse use;
  Walk(use).chart(root);
  return use;
}

}  // namespace gfec::c_backend
