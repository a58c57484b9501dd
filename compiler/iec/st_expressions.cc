// ST expressions as chart expressions: IEC's operators become the chart's with the range of what
// the user wrote (`AND`, `<>`, `MOD`), `Step.X` and `Step.T` become `active(Step)` and
// `elapsed(Step)`, TIME literals durations (docs/iec.md).
#include "iec/st_parser.h"
#include "iec/lower.h"
#include "iec/iec_text.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec::iec {

namespace {

ast::ExprPtr make(ast::Expr::Kind kind, const SourceRange &at) {
  auto e = std::make_unique<ast::Expr>();
  e->kind = kind;
  e->range = at;
  return e;
}

}  // namespace

StParser::StParser(std::string_view text, const FragmentPlace &place, std::deque<std::string> &strings,
                   Diagnostics &diag)
    : text_(text), place_(place), strings_(strings), diag_(diag), toks_(lex_st(text, place, diag)) {}

std::string StParser::quoted() const {
  if (at_end()) return "the end of the text";
  return fmt::format("'{}'", tok().text);
}

Diagnostic &StParser::error(const SourceRange &at, std::string message, ErrorKind kind) {
  static thread_local Diagnostic discarded;
  if (quiet_) {
    discarded = Diagnostic();
    return discarded;
  }
  quiet_ = true;
  return diag_.error(at, kind, std::move(message));
}

ast::ExprPtr StParser::expression() {
  if (!deeper(range(tok()), "expression")) return nullptr;
  Node n = or_expr();
  --depth_;
  return std::move(n.e);
}

StParser::Node StParser::binary(Node lhs, Node rhs, BinaryOp op, const StToken &at) {
  if (!lhs.e || !rhs.e) return {};
  int h = std::max(lhs.height, rhs.height) + 1;
  if (h > kMaxStNesting) {
    error(range(at), fmt::format("expression nested too deeply (more than {} levels)", kMaxStNesting),
          ErrorKind::Nesting);
    return {};
  }
  // IEC's precedence is C's but for XOR, which is `!=` here and binds looser than AND in IEC,
  // tighter than `&&` in C: an operand that C would read otherwise is bracketed, as the user
  // meant it, so the chart text, the engine and the tree all read it the same.
  auto bracket = [](ast::ExprPtr &x, bool when) {
    if (!when) return;
    auto p = make(ast::Expr::Kind::Paren, x->range);
    p->args.push_back(std::move(x));
    x = std::move(p);
  };
  bracket(lhs.e, lhs.e->kind == ast::Expr::Kind::Binary && precedence(lhs.e->binary_op) < precedence(op));
  bracket(rhs.e, rhs.e->kind == ast::Expr::Kind::Binary && precedence(rhs.e->binary_op) <= precedence(op));
  auto e = make(ast::Expr::Kind::Binary, lhs.e->range.to(rhs.e->range));
  e->binary_op = op;
  e->set_op_range(range(at));
  e->args.push_back(std::move(lhs.e));
  e->args.push_back(std::move(rhs.e));
  return {std::move(e), h};
}

StParser::Node StParser::or_expr() {
  Node lhs = xor_expr();
  while (lhs.e && keyword("OR")) {
    StToken op = tok();
    next();
    lhs = binary(std::move(lhs), xor_expr(), BinaryOp::Or, op);
  }
  return lhs;
}

// `a XOR b` is `!a != !b`: the inequality of two BOOLs, and on integers (IEC's bitwise XOR,
// which the chart language has not) a type error at the `XOR`, as for AND and OR, rather than
// an inequality of numbers.
StParser::Node StParser::xor_expr() {
  Node lhs = and_expr();
  while (lhs.e && keyword("XOR")) {
    StToken op = tok();
    next();
    Node rhs = and_expr();
    if (!rhs.e) return {};
    auto negate = [&](Node n) {
      if (n.e->kind == ast::Expr::Kind::Binary) {
        auto p = make(ast::Expr::Kind::Paren, n.e->range);
        p->args.push_back(std::move(n.e));
        n.e = std::move(p);
      }
      auto e = make(ast::Expr::Kind::Unary, n.e->range);
      e->unary_op = UnaryOp::Not;
      e->set_op_range(range(op));  // a message about it quotes the XOR the user wrote
      e->args.push_back(std::move(n.e));
      return Node{std::move(e), n.height + 2};
    };
    lhs = binary(negate(std::move(lhs)), negate(std::move(rhs)), BinaryOp::Ne, op);
  }
  return lhs;
}

StParser::Node StParser::and_expr() {
  Node lhs = equality();
  while (lhs.e && (keyword("AND") || tok().kind == StTok::Amp)) {
    StToken op = tok();
    next();
    lhs = binary(std::move(lhs), equality(), BinaryOp::And, op);
  }
  return lhs;
}

StParser::Node StParser::equality() {
  Node lhs = comparison();
  while (lhs.e) {
    StToken op = tok();
    if (op.kind == StTok::EqEq || op.kind == StTok::BangEq) {
      const char *iec = op.kind == StTok::EqEq ? "=" : "<>";
      error(range(op), fmt::format("'{}' is not IEC 61131-3: structured text compares with '{}'", op.text, iec))
          .fix(range(op), iec);
      return {};
    }
    if (op.kind != StTok::Eq && op.kind != StTok::Ne) break;
    next();
    lhs = binary(std::move(lhs), comparison(), op.kind == StTok::Eq ? BinaryOp::Eq : BinaryOp::Ne, op);
  }
  return lhs;
}

StParser::Node StParser::comparison() {
  Node lhs = additive();
  while (lhs.e) {
    StToken op = tok();
    BinaryOp b;
    if (op.kind == StTok::Lt) b = BinaryOp::Lt;
    else if (op.kind == StTok::Le) b = BinaryOp::Le;
    else if (op.kind == StTok::Gt) b = BinaryOp::Gt;
    else if (op.kind == StTok::Ge) b = BinaryOp::Ge;
    else break;
    next();
    lhs = binary(std::move(lhs), additive(), b, op);
  }
  return lhs;
}

StParser::Node StParser::additive() {
  Node lhs = term();
  while (lhs.e && (tok().kind == StTok::Plus || tok().kind == StTok::Minus)) {
    StToken op = tok();
    next();
    lhs = binary(std::move(lhs), term(), op.kind == StTok::Plus ? BinaryOp::Add : BinaryOp::Sub, op);
  }
  return lhs;
}

StParser::Node StParser::term() {
  Node lhs = power();
  while (lhs.e && (tok().kind == StTok::Star || tok().kind == StTok::Slash || keyword("MOD"))) {
    StToken op = tok();
    next();
    BinaryOp b = op.kind == StTok::Star ? BinaryOp::Mul : op.kind == StTok::Slash ? BinaryOp::Div : BinaryOp::Mod;
    lhs = binary(std::move(lhs), power(), b, op);
  }
  return lhs;
}

StParser::Node StParser::power() {
  Node lhs = unary();
  if (lhs.e && tok().kind == StTok::Power) {
    not_supported(range(tok()), "the power operator '**' is not supported yet");
    return {};
  }
  return lhs;
}

StParser::Node StParser::unary() {
  StToken op = tok();
  bool neg = op.kind == StTok::Minus, plus = op.kind == StTok::Plus, not_ = keyword("NOT");
  if (!neg && !plus && !not_) return primary();
  if (!deeper(range(op), "expression")) { return {}; }
  next();
  Node operand = unary();
  --depth_;
  if (!operand.e || plus) return operand;
  auto e = make(ast::Expr::Kind::Unary, range(op).to(operand.e->range));
  e->unary_op = neg ? UnaryOp::Neg : UnaryOp::Not;
  e->set_op_range(range(op));
  e->args.push_back(std::move(operand.e));
  return {std::move(e), operand.height + 1};
}

StParser::Node StParser::literal() {
  const StToken t = tok();
  next();
  switch (t.kind) {
  case StTok::Int: {
    if (t.overflow) {
      error(range(t), fmt::format("integer literal '{}' does not fit 64 bits", t.text));
      return {};
    }
    auto e = make(ast::Expr::Kind::Int, range(t));
    // The chart's Int is its decimal spelling; `1_000`, `16#FF`, `DINT#5` are made decimal, and
    // `DINT#-5` the negation of 5.
    const bool negative = t.int_value < 0;
    std::string decimal =
        negative ? std::to_string(0 - static_cast<unsigned long long>(t.int_value)) : std::to_string(t.int_value);
    e->name.text = decimal == t.text ? t.text : std::string_view(strings_.emplace_back(std::move(decimal)));
    if (!negative) return {std::move(e), 0};
    auto neg = make(ast::Expr::Kind::Unary, range(t));
    neg->unary_op = UnaryOp::Neg;
    neg->args.push_back(std::move(e));
    return {std::move(neg), 1};
  }
  case StTok::Real: {
    auto e = make(ast::Expr::Kind::Float, range(t));
    std::string_view s = t.text;
    if (auto hash = s.find('#'); hash != std::string_view::npos) s = s.substr(hash + 1);
    if (s.find('_') != std::string_view::npos) {
      std::string clean;
      for (char c : s)
        if (c != '_') clean += c;
      s = strings_.emplace_back(std::move(clean));
    }
    e->name.text = s;
    return {std::move(e), 0};
  }
  case StTok::Time: {
    auto e = make(ast::Expr::Kind::Duration, range(t));
    e->duration_ms = t.ms;
    e->name.text = t.text;
    if (t.ms < 0) {
      not_supported(range(t), fmt::format("a negative TIME literal ('{}') is not supported", t.text));
      return {};
    }
    return {std::move(e), 0};
  }
  case StTok::Typed:
    not_supported(range(t), fmt::format("the typed literal '{}' is not supported yet", t.text));
    return {};
  case StTok::String: not_supported(range(t), "STRING values are not supported yet"); return {};
  default: break;
  }
  return {};
}

StParser::Node StParser::primary() {
  const StToken t = tok();
  switch (t.kind) {
  case StTok::Int:
  case StTok::Real:
  case StTok::Time:
  case StTok::Typed:
  case StTok::String: return literal();
  case StTok::LParen: {
    next();
    if (!deeper(range(t), "expression")) { return {}; }
    Node inner = or_expr();
    --depth_;
    if (!inner.e) return {};
    if (tok().kind != StTok::RParen) {
      error(range(tok()), fmt::format("expected ')' to close the '(' here, not {}", quoted()))
          .note(range(t), "the '(' it closes");
      return {};
    }
    const StToken close = tok();
    next();
    auto e = make(ast::Expr::Kind::Paren, range(t, close));
    e->args.push_back(std::move(inner.e));
    return {std::move(e), inner.height + 1};
  }
  case StTok::Ident: return name_use();
  case StTok::Direct:
    not_supported(range(t), fmt::format("direct address '{}' is not supported yet", t.text));
    return {};
  default: break;
  }
  error(range(t), fmt::format("expected an expression, not {}", quoted()));
  return {};
}

StParser::Node StParser::name_use() {
  const StToken t = tok();
  if (is_keyword(t, "TRUE") || is_keyword(t, "FALSE")) {
    next();
    auto e = make(ast::Expr::Kind::Bool, range(t));
    e->bool_value = is_keyword(t, "TRUE");
    return {std::move(e), 0};
  }
  static const char *const kReserved[] = {
      "THEN", "ELSE", "ELSIF", "END_IF", "DO", "OF",   "END_CASE",       "AND",
      "OR",   "XOR",  "MOD",   "NOT",    "TO", "FROM", "END_TRANSITION", "END_ACTION"};
  for (const char *k : kReserved)
    if (is_keyword(t, k) && !(is_keyword(t, "MOD") && peek().kind == StTok::LParen)) {  // MOD(a, b): a function
      error(range(t), fmt::format("expected an expression, not the keyword '{}'", t.text));
      return {};
    }
  next();
  if (tok().kind == StTok::Dot && peek().kind == StTok::Ident) {
    const StToken member = peek();
    next();
    next();
    if (tok().kind == StTok::Dot || tok().kind == StTok::LBracket) {
      // `a.b.c`, `a.b[1]`: a structure's field, an instance inside an instance, an array member.
      const bool field = tok().kind == StTok::Dot && peek().kind == StTok::Ident;
      not_supported(range(t, field ? peek() : tok()),
                    fmt::format("'{}.{}{}{}': a member of a member (a structure's field, an instance inside an "
                                "instance, an element of an array) is not supported yet",
                                t.text, member.text, field ? "." : "[", field ? peek().text : "...]"));
      return {};
    }
    bool x = is_keyword(member, "X"), time = is_keyword(member, "T");
    if (x || time) {
      // `Step.X` is active(Step), `Step.T` elapsed(Step) (docs/iec.md); an unknown step is the
      // validator's to report, as for chart text.
      auto e = make(ast::Expr::Kind::Call, range(t, member));
      e->name = {x ? std::string_view("active") : std::string_view("elapsed"), range(member)};
      auto arg = make(ast::Expr::Kind::Name, range(t));
      arg->name = name(t);
      e->args.push_back(std::move(arg));
      return {std::move(e), 1};
    }
    if (is_keyword(member, "Q") || is_keyword(member, "A")) {
      // An action's flag, if `t` is an action, or an instance's output Q (A): the lowering knows
      // the POU's actions and instances, and makes it `active(t)`, `running(t)` or `t.Q`, or
      // reports what else it is (lower.cc, action_flags).
      auto e = make(ast::Expr::Kind::Call, range(t, member));
      e->name = {is_keyword(member, "Q") ? std::string_view(".Q") : std::string_view(".A"), range(member)};
      auto arg = make(ast::Expr::Kind::Name, range(t));
      arg->name = name(t);
      e->args.push_back(std::move(arg));
      auto spelled = make(ast::Expr::Kind::Name, range(member));
      spelled->name = name(member);  // the member as written, for `t.Q` of an instance
      e->args.push_back(std::move(spelled));
      return {std::move(e), 1};
    }
    // `inst.Q`: an output of a function-block instance (the validator says what else it is).
    auto e = make(ast::Expr::Kind::Path, range(t, member));
    for (const StToken *part : {&t, &member}) {
      auto n = make(ast::Expr::Kind::Name, range(*part));
      n->name = name(*part);
      e->args.push_back(std::move(n));
    }
    return {std::move(e), 1};
  }
  if (tok().kind == StTok::LParen && is_keyword(t, "MOD")) {
    // The standard function MOD(a, b) is the operator `a MOD b`: C's `%` (docs/iec.md).
    next();
    Node a = or_expr();
    if (!a.e) return {};
    if (tok().kind != StTok::Comma) {
      error(range(tok()), fmt::format("expected ',' after the first argument of 'MOD', not {}", quoted()));
      return {};
    }
    next();
    Node b = or_expr();
    if (!b.e) return {};
    if (tok().kind != StTok::RParen) {
      error(range(tok()),
            fmt::format("expected ')' after the second argument of 'MOD' (it takes two), not {}", quoted()));
      return {};
    }
    const StToken close = tok();
    next();
    Node mod = binary(std::move(a), std::move(b), BinaryOp::Mod, t);
    if (!mod.e) return {};
    mod.e->range = range(t, close);
    auto e = make(ast::Expr::Kind::Paren, range(t, close));
    e->args.push_back(std::move(mod.e));
    return {std::move(e), mod.height + 1};
  }
  if (tok().kind == StTok::LParen) {
    // `<T1>_TO_<T2>(x)`, the standard's type conversions, is the chart language's `t2(x)`
    // (docs/iec.md): exact between integers and TIME, rounded from REAL and LREAL.
    const std::string call = upper(t.text);
    const std::size_t to = call.find("_TO_");
    const char *from_type = to == std::string::npos ? nullptr : chart_type(call.substr(0, to));
    const char *to_type = to == std::string::npos ? nullptr : chart_type(call.substr(to + 4));
    if (from_type && to_type && std::string_view(from_type) != "bool" && std::string_view(to_type) != "bool") {
      next();  // (
      if (!deeper(range(t), "expression")) { return {}; }
      Node arg = or_expr();
      --depth_;
      if (!arg.e) return {};
      if (tok().kind != StTok::RParen) {
        error(range(tok()), fmt::format("expected ')' to close the call of '{}', not {}", t.text, quoted()));
        return {};
      }
      const StToken close = tok();
      next();
      auto e = make(ast::Expr::Kind::Call, range(t, close));
      e->name = {std::string_view(to_type), range(t)};
      e->args.push_back(std::move(arg.e));
      return {std::move(e), arg.height + 1};
    }
    // ABS, MIN, MAX, LIMIT, SEL and MUX are the chart language's standard functions (docs/iec.md).
    static const char *const kStandard[] = {"abs", "min", "max", "limit", "sel", "mux"};
    for (const char *f : kStandard)
      if (call == upper(f)) return standard_call(t, f);
    not_supported(range(t), fmt::format("calling '{}' is not supported yet: gfec reads no functions or function "
                                        "blocks in structured text",
                                        t.text));
    return {};
  }
  if (tok().kind == StTok::LBracket) {
    not_supported(range(t), fmt::format("'{}[...]': arrays are not supported yet", t.text));
    return {};
  }
  if (tok().kind == StTok::Caret) {
    not_supported(range(t), fmt::format("'{}^': pointers are not supported", t.text));
    return {};
  }
  auto e = make(ast::Expr::Kind::Name, range(t));
  e->name = name(t);
  return {std::move(e), 0};
}

namespace {

/// The formal names of a standard function's inputs (IEC 61131-3's, as MatIEC spells them), the
/// position of `formal` among them; -1 if it has none of that name. MIN, MAX and MUX are
/// extensible: IN1, IN2, ... and IN0, IN1, ...
int formal_position(std::string_view function, const std::string &formal) {
  auto numbered = [&](int first) {
    if (formal.size() < 3 || formal.compare(0, 2, "IN") != 0 || formal.size() > 5) return -1;
    int n = 0;
    for (char c : formal.substr(2)) {
      if (c < '0' || c > '9') return -1;
      n = n * 10 + (c - '0');
    }
    return n >= first ? n - first : -1;
  };
  if (function == "abs") return formal == "IN" ? 0 : -1;
  if (function == "min" || function == "max") return numbered(1);
  if (function == "limit") return formal == "MN" ? 0 : formal == "IN" ? 1 : formal == "MX" ? 2 : -1;
  if (function == "sel") return formal == "G" ? 0 : formal == "IN0" ? 1 : formal == "IN1" ? 2 : -1;
  if (function == "mux") return formal == "K" ? 0 : numbered(0) < 0 ? -1 : numbered(0) + 1;
  return -1;
}

const char *formal_names(std::string_view function) {
  if (function == "abs") return "IN";
  if (function == "min" || function == "max") return "IN1, IN2, ...";
  if (function == "limit") return "MN, IN, MX";
  if (function == "sel") return "G, IN0, IN1";
  return "K, IN0, IN1, ...";
}

}  // namespace

StParser::Node StParser::standard_call(const StToken &t, const char *chart) {
  next();  // (
  if (!deeper(range(t), "expression")) { return {}; }
  struct Argument {
    std::string formal;  ///< upper case; empty when positional
    SourceRange at;
    ast::ExprPtr e;
  };
  std::vector<Argument> args;
  int height = 0;
  while (tok().kind != StTok::RParen) {
    Argument a;
    if (tok().kind == StTok::Ident && peek().kind == StTok::Assign) {
      a.formal = upper(tok().text);
      a.at = range(tok());
      next();
      next();
    }
    Node v = or_expr();
    if (!v.e) {
      --depth_;
      return {};
    }
    if (a.formal.empty()) a.at = v.e->range;
    height = std::max(height, v.height);
    a.e = std::move(v.e);
    args.push_back(std::move(a));
    if (tok().kind == StTok::Comma) {
      next();
      continue;
    }
    if (tok().kind != StTok::RParen) {
      --depth_;
      error(range(tok()), fmt::format("expected ',' or ')' in the call of '{}', not {}", t.text, quoted()));
      return {};
    }
  }
  --depth_;
  const StToken close = tok();
  next();
  auto e = make(ast::Expr::Kind::Call, range(t, close));
  e->name = {std::string_view(chart), range(t)};
  const bool formal = !args.empty() && !args[0].formal.empty();
  std::vector<ast::ExprPtr> placed;
  for (Argument &a : args) {
    if (a.formal.empty() == formal) {
      error(a.at, fmt::format("the call of '{}' mixes formal ('IN := x') and positional arguments", t.text));
      return {};
    }
    if (!formal) {
      e->args.push_back(std::move(a.e));
      continue;
    }
    const int at = formal_position(chart, a.formal);
    if (a.formal == "EN" || a.formal == "ENO") {
      not_supported(a.at, fmt::format("'{}' of '{}' is not supported yet", a.formal, t.text));
      return {};
    }
    if (at < 0) {
      error(a.at, fmt::format("'{}' has no input '{}' (its inputs: {})", t.text, a.formal, formal_names(chart)));
      return {};
    }
    const auto i = static_cast<std::size_t>(at);
    if (i >= placed.size()) placed.resize(i + 1);
    if (placed[i]) {
      error(a.at, fmt::format("input '{}' of '{}' is given twice", a.formal, t.text));
      return {};
    }
    placed[i] = std::move(a.e);
  }
  for (auto &p : placed) {
    if (!p) {
      error(range(t, close),
            fmt::format("the call of '{}' leaves out an input (its inputs: {})", t.text, formal_names(chart)));
      return {};
    }
    e->args.push_back(std::move(p));
  }
  return {std::move(e), height + 1};
}

}  // namespace gfec::iec
