#include "c_expr.h"

#include <fmt/format.h>

#include <optional>
#include <utility>

namespace gfec::c_backend {

namespace {

using model::Expr;

// Binding strength of what an expression renders to: binary operators use precedence() (1-7).
constexpr int kUnary = 90;
constexpr int kPrimary = 100;

struct Rendered {
  std::string text;
  int prec = kPrimary;
};

Rendered render(const Context &c, const Expr &e);

std::string bracket(const std::string &s) { return "(" + s + ")"; }

bool is_comparison(BinaryOp op) {
  switch (op) {
  case BinaryOp::Lt: case BinaryOp::Le: case BinaryOp::Gt: case BinaryOp::Ge: case BinaryOp::Eq: case BinaryOp::Ne:
    return true;
  default:
    return false;
  }
}

/// Brackets C does not need but gcc and clang ask for at -Wall (-Wparentheses,
/// -Wlogical-not-parentheses): `a || (b && c)`, `(a < b) == c`, `(!a) == b`. They change nothing.
bool wanted_by_compilers(BinaryOp op, const Expr &operand, bool left) {
  if (operand.kind == Expr::Kind::Binary) {
    if (op == BinaryOp::Or && operand.binary_op == BinaryOp::And) return true;
    if (is_comparison(op) && is_comparison(operand.binary_op)) return true;
  }
  return left && is_comparison(op) && operand.kind == Expr::Kind::Unary && operand.unary_op == UnaryOp::Not;
}

/// A literal; a folded constant may be negative, and then binds like a unary minus.
Rendered literal(const Expr &e) {
  switch (e.kind) {
  case Expr::Kind::Bool: return {e.bool_value ? "true" : "false"};
  case Expr::Kind::String: return {c_string_literal(e.text)};
  default: return {e.text, !e.text.empty() && e.text[0] == '-' ? kUnary : kPrimary};
  }
}

/// A constant is written as its folded value, named in a comment: no C name of the chart's can
/// collide with it (a constant called `m` would otherwise hide the engine parameter).
Rendered constant(const Context &c, const Expr &e) {
  const auto &k = c.model.consts.at(static_cast<std::size_t>(e.index));
  Rendered v = literal(k.value);
  v.text += fmt::format(" /* {} */", k.name);
  return v;
}

Rendered call(const Context &c, const Expr &e) {
  std::string args;
  for (const auto &a : e.args) args += (args.empty() ? "" : ", ") + render(c, a).text;
  return {fmt::format("{}({})", c.model.functions.at(static_cast<std::size_t>(e.index)).name, args)};
}

Rendered unary(const Context &c, const Expr &e) {
  Rendered operand = render(c, e.args.at(0));
  // `- -x` must not become the decrement `--x`.
  bool minus_minus = e.unary_op == UnaryOp::Neg && !operand.text.empty() && operand.text[0] == '-';
  if (operand.prec < kUnary || minus_minus) operand.text = bracket(operand.text);
  return {spelling(e.unary_op) + operand.text, kUnary};
}

const Expr &unbracketed(const Expr &e) { return e.kind == Expr::Kind::Paren ? unbracketed(e.args.at(0)) : e; }

BinaryOp mirrored(BinaryOp op) {
  switch (op) {
  case BinaryOp::Lt: return BinaryOp::Gt;
  case BinaryOp::Le: return BinaryOp::Ge;
  case BinaryOp::Gt: return BinaryOp::Lt;
  case BinaryOp::Ge: return BinaryOp::Le;
  default: return op;
  }
}

/// A comparison of a duration with a constant that the compilers can decide, and warn about
/// (-Wtype-limits): timers are uint32_t, so `elapsed(P) >= 0ms` always holds, and a constant
/// beyond UINT32_MAX ticks is never reached (timers saturate there). Such a comparison is written
/// as its value; durations are read from timers and have no side effects to keep.
std::optional<bool> settled(const Expr &e) {
  if (!is_comparison(e.binary_op)) return std::nullopt;
  const Expr *l = &unbracketed(e.args.at(0)), *r = &unbracketed(e.args.at(1));
  BinaryOp op = e.binary_op;
  if (l->kind == Expr::Kind::Ticks) {
    std::swap(l, r);
    op = mirrored(op);
  }
  if (r->kind != Expr::Kind::Ticks || l->kind == Expr::Kind::Ticks || l->type != model::Type::Duration)
    return std::nullopt;
  if (r->ticks == 0 && (op == BinaryOp::Ge || op == BinaryOp::Lt)) return op == BinaryOp::Ge;
  if (r->ticks > 0xFFFFFFFFul) return op == BinaryOp::Lt || op == BinaryOp::Le || op == BinaryOp::Ne;
  return std::nullopt;
}

Rendered binary(const Context &c, const Expr &e) {
  if (auto value = settled(e))
    return {*value ? "true /* always: timers count from 0 to UINT32_MAX */"
                   : "false /* never: timers count from 0 to UINT32_MAX */"};
  const int prec = precedence(e.binary_op);
  Rendered l = render(c, e.args.at(0));
  Rendered r = render(c, e.args.at(1));
  // The model keeps the user's brackets as Paren nodes; these only restore what the tree says
  // (operators are left-associative) and quiet the compilers.
  if (l.prec < prec || wanted_by_compilers(e.binary_op, e.args[0], true)) l.text = bracket(l.text);
  if (r.prec <= prec || wanted_by_compilers(e.binary_op, e.args[1], false)) r.text = bracket(r.text);
  return {fmt::format("{} {} {}", l.text, spelling(e.binary_op), r.text), prec};
}

Rendered render(const Context &c, const Expr &e) {
  switch (e.kind) {
  case Expr::Kind::Bool:
  case Expr::Kind::Int:
  case Expr::Kind::Float:
  case Expr::Kind::String: return literal(e);
  case Expr::Kind::Ticks: return {fmt::format("{}u /* {}ms */", e.ticks, e.ms)};
  case Expr::Kind::Var: return {c.field(c.var_field.at(static_cast<std::size_t>(e.index)))};
  case Expr::Kind::Const: return constant(c, e);
  case Expr::Kind::Call: return call(c, e);
  case Expr::Kind::Elapsed: return {c.timer_of(e.index)};
  case Expr::Kind::Unary: return unary(c, e);
  case Expr::Kind::Binary: return binary(c, e);
  case Expr::Kind::Paren: return {bracket(render(c, e.args.at(0)).text)};
  case Expr::Kind::Config: break;  // plans only: the validator keeps it out of charts
  }
  return {"0"};
}

std::string statement(const Context &c, const model::Stmt &s) {
  if (s.kind == model::Stmt::Kind::Call) return render(c, s.call).text + ";";
  return fmt::format("{} {} {};", c.field(c.var_field.at(static_cast<std::size_t>(s.var))), spelling(s.op),
                     render(c, s.value).text);
}

bool blank(std::string_view s) { return s.find_first_not_of(" \t\r\f\v") == std::string_view::npos; }

} // namespace

const char *c_type(model::Type type) {
  switch (type) {
  case model::Type::Bool: return "bool";
  case model::Type::Int: return "int";
  case model::Type::Float: return "float";
  case model::Type::Double: return "double";
  case model::Type::Void: return "void";
  default: return "int";  // strings, objects and durations never reach a chart's C
  }
}

std::string c_expr(const Context &c, const Expr &e) { return render(c, e).text; }

std::string c_condition(const Context &c, const Expr &e) {
  std::string text = render(c, e).text;
  return e.kind == Expr::Kind::Paren ? text : bracket(text);
}

std::string c_prototype(const model::Function &f) {
  std::string params;
  for (const auto &p : f.params) {
    params += params.empty() ? "" : ", ";
    params += p.name.empty() ? c_type(p.type) : fmt::format("{} {}", c_type(p.type), p.name);
  }
  return fmt::format("{} {}({})", c_type(f.result), f.name, params.empty() ? "void" : params);
}

void emit_statements(CodeWriter &w, const Context &c, const std::vector<model::Stmt> &stmts) {
  const SourceManager *sources = c.model.sources;
  // The chart line the next output line stands for; a #line is needed only when it is not
  // the statement's own line (0: unknown).
  FileId file = 0;
  std::uint32_t next = 0;
  for (const auto &s : stmts) {
    if (s.kind == model::Stmt::Kind::Verbatim) {
      emit_verbatim(w, sources, s.range, s.verbatim);
      next = 0;
      continue;
    }
    if (sources) {
      std::uint32_t line = sources->begin_of(s.range).line;
      if (next == 0 || s.range.file != file || line != next) w.line_from(*sources, s.range);
      file = s.range.file;
      next = line + 1;
    }
    w.line(statement(c, s));
  }
}

void emit_verbatim(CodeWriter &w, const SourceManager *sources, const SourceRange &range, std::string_view text) {
  // Find where the text starts in the chart, so #line names the right line: just after `%{`.
  std::uint32_t start = range.begin;
  if (sources) {
    const std::string &chart = sources->file(range.file).text();
    auto open = chart.find("%{", range.begin);
    if (open != std::string::npos && chart.compare(open + 2, text.size(), text) == 0)
      start = static_cast<std::uint32_t>(open + 2);
  }
  // Drop the rest of the `%{` line and the indentation before `%}` when they are blank.
  auto first_nl = text.find('\n');
  if (first_nl != std::string_view::npos && blank(text.substr(0, first_nl))) {
    text.remove_prefix(first_nl + 1);
    start += static_cast<std::uint32_t>(first_nl + 1);
  }
  auto last_nl = text.rfind('\n');
  if (last_nl != std::string_view::npos && blank(text.substr(last_nl + 1))) text = text.substr(0, last_nl + 1);
  if (blank(text)) return;

  if (sources) w.line_from(*sources, {range.file, start, start});
  std::string_view body = text.back() == '\n' ? text.substr(0, text.size() - 1) : text;
  if (body.find('\n') == std::string_view::npos) {
    // One line: indented like the code around it.
    auto b = body.find_first_not_of(" \t");
    auto e = body.find_last_not_of(" \t\r");
    w.line(body.substr(b, e - b + 1));
  } else {
    w.raw(text);  // several lines: exactly as the user laid them out
  }
}

} // namespace gfec::c_backend
