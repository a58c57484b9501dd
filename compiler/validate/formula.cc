#include "validate/formula.h"

#include "validate/expr.h"
#include "validate/fold.h"
#include "validate/types.h"

#include <fmt/format.h>

namespace gfec::validation {

namespace {

using K = model::Expr::Kind;
using model::Type;

model::Expr make(K kind, Type type, SourceRange range) {
  model::Expr e;
  e.kind = kind;
  e.type = type;
  e.range = range;
  return e;
}

std::nullopt_t not_allowed(Context &cx, SourceRange at, const std::string &what) {
  cx.diag.error(at, ErrorKind::Formula, fmt::format("{} cannot be used in a plan argument", what))
      .note("a plan argument is a formula over config entries and constants: + - * / and brackets");
  return std::nullopt;
}

std::optional<model::Expr> lower_name(const ast::Expr &e, Context &cx, PlanScope &s, bool constant) {
  const ast::Name &name = e.name;
  if (name.text.empty()) return std::nullopt;
  if (const Symbol *sym = s.names.resolve(name)) {
    if (sym->kind != Sym::ConfigEntry) {
      cx.diag
          .error(name.range, ErrorKind::TypeMismatch,
                 fmt::format("'{}' is {}, not a config entry", name.text, with_article(sym->kind)))
          .note(sym->range, fmt::format("'{}' declared here", name.text));
      return std::nullopt;
    }
    if (constant) {
      cx.diag.error(name.range, ErrorKind::NotConstant,
                    fmt::format("a config initializer cannot read config entry '{}'", name.text));
      return std::nullopt;
    }
    if (sym->index < 0) return std::nullopt;  // its declaration has an error
    const model::ConfigId entry = sym->id<model::ConfigId>();
    model::Expr x = make(K::Config, s.out.config[entry].type, e.range);
    x.refer_to(entry);
    return x;
  }
  if (const Symbol *sym = cx.c_names.resolve(name); sym && sym->kind == Sym::Const) {
    cx.consts[sym->id<model::ConstId>()].used = true;
    const model::Expr *value = fold_const(cx, sym->id<model::ConstId>());
    if (!value) return std::nullopt;
    model::Expr x = *value;
    x.range = e.range;
    return x;
  }
  report_unknown(cx.diag, s.unknown, name, "config entry", s.names.of({Sym::ConfigEntry}));
  return std::nullopt;
}

std::optional<Type> formula_type(BinaryOp op, Type a, Type b) {
  bool numbers = model::is_numeric(a) && model::is_numeric(b);
  if (numbers) return promote(a, b);
  // `+` joins strings, converting a number on either side to text.
  bool text =
      (a == Type::String && (b == Type::String || model::is_numeric(b))) || (b == Type::String && model::is_numeric(a));
  if (op == BinaryOp::Add && text) return Type::String;
  return std::nullopt;
}

std::optional<model::Expr> lower_binary(const ast::Expr &e, Context &cx, PlanScope &s, bool constant) {
  BinaryOp op = e.binary_op;
  if (op != BinaryOp::Add && op != BinaryOp::Sub && op != BinaryOp::Mul && op != BinaryOp::Div)
    return not_allowed(cx, e.range, fmt::format("operator '{}'", written_operator(e, cx.sources)));
  if (e.args.size() != 2) return std::nullopt;
  auto a = lower_formula(e.args[0], cx, s, constant);
  auto b = lower_formula(e.args[1], cx, s, constant);
  if (!a || !b) return std::nullopt;
  auto type = formula_type(op, a->type, b->type);
  if (!type) {
    cx.diag.error(e.range, ErrorKind::TypeMismatch,
                  fmt::format("invalid operands to binary '{}' (have {} and {})", written_operator(e, cx.sources),
                              quoted(a->type), quoted(b->type)));
    return std::nullopt;
  }
  if (divides_by_zero(op, *a, *b, e.range, cx)) return std::nullopt;
  model::Expr x = make(K::Binary, *type, e.range);
  x.binary_op = op;
  x.args.push_back(std::move(*a));
  x.args.push_back(std::move(*b));
  return x;
}

std::optional<model::Expr> lower_unary(const ast::Expr &e, Context &cx, PlanScope &s, bool constant) {
  if (e.unary_op != UnaryOp::Neg)
    return not_allowed(cx, e.range, fmt::format("operator '{}'", written_operator(e, cx.sources)));
  if (e.args.size() != 1) return std::nullopt;
  auto operand = lower_formula(e.args[0], cx, s, constant);
  if (!operand) return std::nullopt;
  if (!model::is_numeric(operand->type)) {
    cx.diag.error(e.range, ErrorKind::TypeMismatch,
                  fmt::format("invalid operand to unary '-' (have {})", quoted(operand->type)));
    return std::nullopt;
  }
  model::Expr x = make(K::Unary, operand->type, e.range);
  x.unary_op = UnaryOp::Neg;
  x.args.push_back(std::move(*operand));
  return x;
}

}  // namespace

bool convertible(Type to, Type from) {
  bool number_or_text_to = model::is_numeric(to) || to == Type::String;
  bool number_or_text_from = model::is_numeric(from) || from == Type::String;
  if (number_or_text_to && number_or_text_from) return true;
  return to == from && (to == Type::Bool || to == Type::Object);
}

std::optional<model::Expr> lower_formula(const ast::Expr *e, Context &cx, PlanScope &s, bool constant) {
  if (!e) return std::nullopt;
  switch (e->kind) {
  case ast::Expr::Kind::Bool: {
    model::Expr x = make(K::Bool, Type::Bool, e->range);
    x.bool_value = e->bool_value;
    return x;
  }
  case ast::Expr::Kind::Int:
  case ast::Expr::Kind::Float: {
    auto x = number_literal(*e, cx.diag);
    if (x && x->type == Type::Int64) {  // plans have no sized integers: int's range is the limit
      cx.diag.error(e->range, ErrorKind::NotConstant,
                    fmt::format("integer constant '{}' is too large for 'int'", e->text()));
      return std::nullopt;
    }
    return x;
  }
  case ast::Expr::Kind::String: {
    model::Expr x = make(K::String, Type::String, e->range);
    x.text = e->text();
    return x;
  }
  case ast::Expr::Kind::Duration: return not_allowed(cx, e->range, "a duration");
  case ast::Expr::Kind::Call: return not_allowed(cx, e->range, "a function call");
  case ast::Expr::Kind::Path: return not_allowed(cx, e->range, "a path to a sub-chart's place");
  case ast::Expr::Kind::Name: return lower_name(*e, cx, s, constant);
  case ast::Expr::Kind::Unary: return check_constant(lower_unary(*e, cx, s, constant), cx.model, cx.diag);
  case ast::Expr::Kind::Binary: return check_constant(lower_binary(*e, cx, s, constant), cx.model, cx.diag);
  case ast::Expr::Kind::Paren: {
    if (e->args.size() != 1) return std::nullopt;
    auto inner = lower_formula(e->args[0], cx, s, constant);
    if (!inner) return std::nullopt;
    model::Expr x = make(K::Paren, inner->type, e->range);
    x.args.push_back(std::move(*inner));
    return check_constant(std::move(x), cx.model, cx.diag);  // folded with its operand
  }
  }
  return std::nullopt;
}

}  // namespace gfec::validation
