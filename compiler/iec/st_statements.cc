// ST statement lists as chart statements: assignments, IF/ELSIF/ELSE, and CASE as the chain of
// `if`s it means (its selector is read once per label, which is the same as IEC's one reading
// because ST expressions as gfec reads them have no side effects), FOR, WHILE and REPEAT as the
// chart's `for`, `while` and `do ... while`, EXIT and RETURN as `break` and `return` (docs/iec.md
// "Loops"). Calls and the rest are located "not supported yet" errors (docs/iec.md "What is not
// read yet").
#include "iec/st_parser.h"
#include "iec/iec_text.h"

#include <fmt/format.h>

#include <optional>

namespace gfec::iec {

namespace {

ast::ExprPtr made_binary(ast::ExprPtr a, ast::ExprPtr b, BinaryOp op, const SourceRange &at) {
  auto e = std::make_unique<ast::Expr>();
  e->kind = ast::Expr::Kind::Binary;
  e->binary_op = op;
  e->range = at;
  e->args.push_back(std::move(a));
  e->args.push_back(std::move(b));
  return e;
}

ast::ExprPtr paren(ast::ExprPtr inner) {
  auto e = std::make_unique<ast::Expr>();
  e->kind = ast::Expr::Kind::Paren;
  e->range = inner->range;
  e->args.push_back(std::move(inner));
  return e;
}

ast::ExprPtr made_name(const ast::Name &n) {
  auto e = std::make_unique<ast::Expr>();
  e->kind = ast::Expr::Kind::Name;
  e->range = n.range;
  e->name = n;
  return e;
}

ast::ExprPtr made_int(std::string_view text, const SourceRange &at) {
  auto e = std::make_unique<ast::Expr>();
  e->kind = ast::Expr::Kind::Int;
  e->range = at;
  e->name.text = text;
  return e;
}

ast::Stmt made_assign(const ast::Name &target, AssignOp op, ast::ExprPtr value, const SourceRange &at) {
  ast::Stmt s;
  s.kind = ast::Stmt::Kind::Assign;
  s.assign_op = op;
  s.range = at;
  s.target.emplace(target);
  s.value = std::move(value);
  return s;
}

/// A step written as a literal: 1 for `5`, -1 for `-5`, 0 for `0`; none when it is no literal.
std::optional<int> literal_sign(const ast::Expr &e) {
  if (e.kind == ast::Expr::Kind::Paren && e.args.size() == 1) return literal_sign(*e.args[0]);
  if (e.kind == ast::Expr::Kind::Int) return e.text().find_first_not_of('0') == std::string_view::npos ? 0 : 1;
  if (e.kind == ast::Expr::Kind::Unary && e.unary_op == UnaryOp::Neg && e.args.size() == 1)
    if (auto inner = literal_sign(*e.args[0])) return -*inner;
  return std::nullopt;
}

/// The literal under a sign and brackets: the 5 of `-(5)`.
const ast::Expr &magnitude(const ast::Expr &e) {
  if ((e.kind == ast::Expr::Kind::Paren || e.kind == ast::Expr::Kind::Unary) && e.args.size() == 1)
    return magnitude(*e.args[0]);
  return e;
}

}  // namespace

bool StParser::for_header(ast::Stmt &loop, const StToken &start) {
  const StToken var = tok();
  if (var.kind != StTok::Ident || peek().kind != StTok::Assign) {
    error(range(var), fmt::format("expected the control variable and ':=' after 'FOR', not {}", quoted()));
    return false;
  }
  next();
  next();
  ast::ExprPtr first = expression();
  if (!first) return false;
  if (!keyword("TO")) {
    error(range(tok()), fmt::format("expected 'TO' after the initial value of 'FOR', not {}", quoted()));
    return false;
  }
  next();
  ast::ExprPtr end = expression();
  if (!end) return false;
  ast::ExprPtr by;
  if (keyword("BY")) {
    next();
    by = expression();
    if (!by) return false;
  }
  if (!keyword("DO")) {
    error(range(tok()), fmt::format("expected 'DO' after the header of 'FOR', not {}", quoted()));
    return false;
  }
  next();
  const ast::Name i = name(var);
  const SourceRange header = range(start).to(end->range);
  // `FOR i := a TO b BY s`: `i = a`; while the end is not passed, the body, then `i += s`; the
  // end and the step are evaluated before each pass (as MatIEC's C reads them). A step written
  // as a literal picks the comparison at compile time; another picks it by its sign each pass.
  std::optional<int> sign = by ? literal_sign(*by) : std::optional<int>(1);
  if (sign && *sign == 0) {
    error(by->range, "the step of 'FOR' is 0: the loop would never end", ErrorKind::Loop);
    return false;
  }
  loop.else_block.push_back(made_assign(i, AssignOp::Set, std::move(first), header));
  ast::ExprPtr step_value;
  AssignOp step_op = AssignOp::Add;
  if (!by) {
    loop.value = made_binary(made_name(i), std::move(end), BinaryOp::Le, header);
    step_value = made_int("1", range(var));
  } else if (sign) {
    loop.value = made_binary(made_name(i), std::move(end), *sign > 0 ? BinaryOp::Le : BinaryOp::Ge, header);
    step_value = made_int(magnitude(*by).text(), by->range);
    step_op = *sign > 0 ? AssignOp::Add : AssignOp::Sub;
  } else {
    auto zero = [&] { return made_int("0", by->range); };
    auto up = made_binary(made_binary(clone(*by), zero(), BinaryOp::Gt, header),
                          made_binary(made_name(i), clone(*end), BinaryOp::Le, header), BinaryOp::And, header);
    auto down = made_binary(made_binary(clone(*by), zero(), BinaryOp::Lt, header),
                            made_binary(made_name(i), std::move(end), BinaryOp::Ge, header), BinaryOp::And, header);
    loop.value = made_binary(paren(std::move(up)), paren(std::move(down)), BinaryOp::Or, header);
    step_value = std::move(by);
  }
  loop.else_block.push_back(made_assign(i, step_op, std::move(step_value), header));
  return true;
}

namespace {

/// The IL operators that begin a line of an Instruction List body (`LD x`, `ST y`, `CAL t`): a
/// body so written is IL, not a malformed ST assignment.
bool il_operator(const StToken &t) {
  for (const char *op : {"LD", "LDN", "ST", "STN", "CAL", "CALC", "CALCN", "JMP", "JMPC", "JMPCN", "ANDN", "ORN",
                         "XORN", "ADD", "SUB", "MUL", "DIV", "RET"})
    if (is_keyword(t, op)) return true;
  return false;
}

}  // namespace

bool StParser::deeper(const SourceRange &at, const char *what) {
  if (++depth_ <= kMaxStNesting) return true;
  --depth_;
  error(at, fmt::format("{} nested too deeply (more than {} levels)", what, kMaxStNesting), ErrorKind::Nesting);
  return false;
}

void StParser::loop_statement(ast::Block &out) {
  const StToken start = tok();
  const std::string_view kind = is_keyword(start, "FOR") ? "FOR" : is_keyword(start, "WHILE") ? "WHILE" : "REPEAT";
  next();
  ast::Stmt loop;
  loop.kind = kind == "FOR"     ? ast::Stmt::Kind::For
              : kind == "WHILE" ? ast::Stmt::Kind::While
                                : ast::Stmt::Kind::DoWhile;
  bool ok = true;
  if (kind == "FOR") {
    ok = for_header(loop, start);
  } else if (kind == "WHILE") {
    loop.value = expression();
    if (loop.value && !keyword("DO"))
      error(range(tok()), fmt::format("expected 'DO' after the condition of 'WHILE', not {}", quoted()));
    if (!loop.value || !keyword("DO")) ok = false;
    else next();
  }
  if (!ok) {
    skip_block(kind);
    return;
  }
  if (!deeper(range(start), "statements")) {
    skip_block(kind);
    return;
  }
  ++loops_;
  loop.then_block = statements();
  --loops_;
  --depth_;
  if (kind == "REPEAT") {
    if (!keyword("UNTIL")) {
      error(range(tok()), fmt::format("expected 'UNTIL' to end the body of 'REPEAT', not {}", quoted()))
          .note(range(start), "the 'REPEAT' it ends");
      skip_block(kind);
      return;
    }
    const StToken until = tok();
    next();
    ast::ExprPtr condition = expression();
    if (!condition) {
      skip_block(kind);
      return;
    }
    // REPEAT ... UNTIL c: the body runs again while c is false.
    auto negated = std::make_unique<ast::Expr>();
    negated->kind = ast::Expr::Kind::Unary;
    negated->unary_op = UnaryOp::Not;
    negated->range = range(until).to(condition->range);
    negated->set_op_range(range(until));
    negated->args.push_back(paren(std::move(condition)));
    loop.value = std::move(negated);
  }
  const std::string end = "END_" + std::string(kind);
  if (!keyword(end)) {
    error(range(tok()), fmt::format("expected '{}' to close the '{}', not {}", end, kind, quoted()))
        .note(range(start), fmt::format("the '{}' it closes", kind));
    return;
  }
  const StToken last = tok();
  next();
  if (tok().kind == StTok::Semi) next();
  loop.range = range(start, last);
  out.push_back(std::move(loop));
}

void StParser::assignment(ast::Block &out, const StToken &first, const ast::Name &target) {
  ast::ExprPtr value = expression();
  const StToken last = tok();
  if (!value || !expect_semi("the assignment")) {
    skip_statement();
    return;
  }
  ast::Stmt &s = out.emplace_back();
  s.kind = ast::Stmt::Kind::Assign;
  s.assign_op = AssignOp::Set;
  s.range = range(first, last);
  s.target.emplace(target);
  s.value = std::move(value);
}

bool StParser::block_end() const {
  if (at_end()) return true;
  if (tok().kind != StTok::Ident) return false;
  std::string_view s = tok().text;
  if (s.size() > 4 && (s[0] == 'E' || s[0] == 'e') && (s[1] == 'N' || s[1] == 'n') && (s[2] == 'D' || s[2] == 'd') &&
      s[3] == '_')
    return true;
  for (const char *k : {"ELSIF", "ELSE", "UNTIL", "INITIAL_STEP", "STEP", "TRANSITION", "ACTION"})
    if (keyword(k)) return true;
  return false;
}

void StParser::skip_statement() {
  int depth = 0;
  while (!at_end()) {
    if (tok().kind == StTok::LParen || tok().kind == StTok::LBracket) ++depth;
    if ((tok().kind == StTok::RParen || tok().kind == StTok::RBracket) && depth > 0) --depth;
    if (depth == 0 && tok().kind == StTok::Semi) {
      next();
      return;
    }
    if (depth == 0 && block_end()) return;
    next();
  }
}

void StParser::skip_block(std::string_view what) {
  const std::string end = "END_" + std::string(what);
  int depth = 0;
  while (!at_end()) {
    if (keyword(what)) ++depth;
    if (keyword(end) && --depth <= 0) {
      next();
      if (tok().kind == StTok::Semi) next();
      return;
    }
    next();
  }
}

bool StParser::expect_semi(const char *after) {
  if (tok().kind == StTok::Semi) {
    next();
    return true;
  }
  error(range(tok()), fmt::format("expected ';' after {}, not {}", after, quoted()));
  return false;
}

bool StParser::case_label_ahead() const {
  std::size_t k = 0;
  if (tok().kind == StTok::Minus) k = 1;
  const StToken &first = peek(k);
  if (first.kind != StTok::Int && first.kind != StTok::Ident) return false;
  StTok after = peek(k + 1).kind;
  return after == StTok::Colon || after == StTok::Comma || after == StTok::DotDot;
}

ast::Block StParser::statements(bool in_case) {
  ast::Block out;
  while (!block_end()) {
    if (in_case && case_label_ahead()) break;
    std::size_t before = pos_;
    resync();
    statement(out);
    if (pos_ == before) next();  // never loop on a token nothing consumed
  }
  resync();
  return out;
}

void StParser::statement(ast::Block &out) {
  const StToken t = tok();
  if (t.kind == StTok::Semi) {
    next();
    return;
  }
  if (is_keyword(t, "IF")) return if_statement(out);
  if (is_keyword(t, "CASE")) return case_statement(out);
  if (is_keyword(t, "FOR") || is_keyword(t, "WHILE") || is_keyword(t, "REPEAT")) return loop_statement(out);
  if (is_keyword(t, "EXIT") || is_keyword(t, "RETURN")) {
    const bool exit = is_keyword(t, "EXIT");
    next();
    if (exit && loops_ == 0) {
      error(range(t), "'EXIT' outside a loop: it ends the innermost FOR, WHILE or REPEAT", ErrorKind::Loop);
      skip_statement();
      return;
    }
    if (!expect_semi(exit ? "'EXIT'" : "'RETURN'")) {
      skip_statement();
      return;
    }
    ast::Stmt &s = out.emplace_back();
    s.kind = exit ? ast::Stmt::Kind::Break : ast::Stmt::Kind::Return;
    s.range = range(t);
    return;
  }
  for (const char *k : {"CONTINUE", "JMP"}) {
    if (!is_keyword(t, k)) continue;
    not_supported(range(t), fmt::format("'{}' is not supported yet", t.text));
    skip_statement();
    return;
  }
  if (t.kind != StTok::Ident) {
    error(range(t), fmt::format("expected a statement, not {}", quoted()));
    skip_statement();
    return;
  }
  const StToken &after = peek();
  if (after.kind == StTok::Assign) {
    next();
    next();
    return assignment(out, t, name(t));
  }
  if (after.kind == StTok::LParen) return block_call(out);
  if (after.kind == StTok::Dot && peek(2).kind == StTok::Ident && peek(3).kind == StTok::Assign) {
    // `inst.IN := x;` sets an input of a function-block instance (the validator checks it is one).
    const StToken member = peek(2);
    next();
    next();
    next();
    next();
    return assignment(out, t,
                      ast::Name{strings().emplace_back(fmt::format("{}.{}", t.text, member.text)), range(t, member)});
  }
  if (after.kind == StTok::Dot || after.kind == StTok::LBracket || after.kind == StTok::Caret)
    not_supported(
        range(t, after),
        fmt::format("assigning a member, an element or through a pointer of '{}' is not supported yet", t.text));
  else if (after.kind == StTok::Eq)
    error(range(after), fmt::format("'=' compares; an ST assignment is '{} := ...;'", t.text)).fix(range(after), ":=");
  else if (after.kind == StTok::Colon && (is_keyword(t, "ACTION") || is_keyword(t, "STEP")))
    error(range(t), fmt::format("expected a statement, not {}", quoted()));
  else if (il_operator(t) && (after.kind == StTok::Ident || after.kind == StTok::Int || after.kind == StTok::Real ||
                              after.kind == StTok::Time || after.kind == StTok::Direct))
    not_supported(range(t, after), fmt::format("'{} {}' is Instruction List (IL): an IL body is not supported yet; "
                                               "gfec reads ST, FBD, LD and SFC",
                                               t.text, after.text));
  else error(range(after), fmt::format("expected ':=' after '{}', not '{}'", t.text, after.text));
  skip_statement();
}

void StParser::block_call(ast::Block &out) {
  const StToken inst = tok();
  next();
  next();  // the name and '('
  ast::Stmt call;
  call.kind = ast::Stmt::Kind::Invoke;
  call.target.emplace(name(inst));
  std::vector<ast::Stmt> outputs;  // `Q => v`: assignments `v := inst.Q` after the call
  while (tok().kind != StTok::RParen) {
    const StToken param = tok();
    const StTok bind = peek().kind;
    const bool formal = param.kind == StTok::Ident && (bind == StTok::Assign || bind == StTok::Arrow);
    if (formal) {
      next();
      next();
    }
    if (!formal || bind == StTok::Assign) {
      ast::ExprPtr value = expression();
      if (!value) {
        skip_statement();
        return;
      }
      ast::Stmt a;
      a.kind = ast::Stmt::Kind::Assign;
      a.range = value->range;
      // A non-formal argument (`CU_T(CU);`) is an Assign without a target, bound by the validator
      // to the block's inputs in declaration order (docs/iec.md "Function blocks").
      if (formal) {
        a.target.emplace(name(param));
        a.range.begin = range(param).begin;
      }
      a.value = std::move(value);
      call.then_block.push_back(std::move(a));
    } else {
      const StToken var = tok();
      if (var.kind != StTok::Ident) {
        error(range(var),
              fmt::format("expected the variable that receives '{}' after '=>', not {}", param.text, quoted()));
        skip_statement();
        return;
      }
      next();
      ast::Stmt &o = outputs.emplace_back();
      o.kind = ast::Stmt::Kind::Assign;
      o.target.emplace(name(var));
      o.range = range(param, var);
      auto path = std::make_unique<ast::Expr>();
      path->kind = ast::Expr::Kind::Path;
      path->range = range(param);
      for (const StToken *part : {&inst, &param}) {
        auto n = std::make_unique<ast::Expr>();
        n->kind = ast::Expr::Kind::Name;
        n->range = range(*part);
        n->name = name(*part);
        path->args.push_back(std::move(n));
      }
      o.value = std::move(path);
    }
    if (tok().kind == StTok::Comma) next();
    else if (tok().kind != StTok::RParen) {
      error(range(tok()), fmt::format("expected ',' or ')' in the call of '{}', not {}", inst.text, quoted()));
      skip_statement();
      return;
    }
  }
  next();  // ')'
  const StToken last = tok();
  if (!expect_semi("the call")) {
    skip_statement();
    return;
  }
  call.range = range(inst, last);
  out.push_back(std::move(call));
  for (ast::Stmt &o : outputs) out.push_back(std::move(o));
}

void StParser::if_statement(ast::Block &out) {
  struct Branch {
    ast::ExprPtr condition;  ///< null: ELSE
    ast::Block body;
    SourceRange range;
  };
  std::vector<Branch> branches;
  const StToken start = tok();
  bool ok = true;
  for (;;) {
    const StToken kw = tok();
    next();  // IF or ELSIF
    ast::ExprPtr c = expression();
    if (!c) ok = false;
    if (c && !keyword("THEN")) {
      error(range(tok()), fmt::format("expected 'THEN' after the condition of '{}', not {}", kw.text, quoted()));
      ok = false;
    }
    if (keyword("THEN")) next();
    if (!deeper(range(kw), "statements")) {
      skip_block("IF");
      return;
    }
    ast::Block body = statements();
    --depth_;
    branches.push_back({std::move(c), std::move(body), range(kw)});
    if (keyword("ELSIF")) {
      if (branches.size() >= 1024) {
        error(range(tok()), "an ELSIF chain longer than 1024 branches", ErrorKind::Nesting);
        skip_block("IF");
        return;
      }
      continue;
    }
    break;
  }
  if (keyword("ELSE")) {
    const StToken kw = tok();
    next();
    ++depth_;
    ast::Block body = statements();
    --depth_;
    branches.push_back({nullptr, std::move(body), range(kw)});
  }
  if (!keyword("END_IF")) {
    error(range(tok()), fmt::format("expected 'END_IF' to close the 'IF', not {}", quoted()))
        .note(range(start), "the 'IF' it closes");
    return;
  }
  const StToken end = tok();
  next();
  if (tok().kind == StTok::Semi) next();
  if (!ok) return;
  // ELSIF c is `else if (c)`: built from the last branch back.
  std::vector<ast::Stmt> tail;
  bool tail_is_else = false;
  for (std::size_t k = branches.size(); k-- > 0;) {
    Branch &b = branches[k];
    if (!b.condition) {
      tail = std::move(b.body);
      tail_is_else = true;
      continue;
    }
    ast::Stmt s;
    s.kind = ast::Stmt::Kind::If;
    s.range = b.range.to(range(end));
    s.value = std::move(b.condition);
    s.then_block = std::move(b.body);
    if (k + 1 < branches.size()) {
      s.has_else = true;
      s.else_if = !tail_is_else;
      s.else_block = std::move(tail);
    }
    tail.clear();
    tail.push_back(std::move(s));
    tail_is_else = false;
  }
  for (ast::Stmt &s : tail) out.push_back(std::move(s));
}

void StParser::case_statement(ast::Block &out) {
  const StToken start = tok();
  next();
  ast::ExprPtr selector = expression();
  if (!selector) {
    skip_block("CASE");
    return;
  }
  if (!keyword("OF")) {
    error(range(tok()), fmt::format("expected 'OF' after the selector of 'CASE', not {}", quoted()));
    skip_block("CASE");
    return;
  }
  next();
  struct Branch {
    ast::ExprPtr condition;
    ast::Block body;
    SourceRange range;
  };
  std::vector<Branch> branches;
  ast::Block otherwise;
  if (!deeper(range(start), "statements")) {
    skip_block("CASE");
    return;
  }
  --depth_;
  while (!keyword("END_CASE") && !at_end()) {
    if (keyword("ELSE")) {
      next();
      otherwise = statements(true);
      break;
    }
    if (!case_label_ahead()) {
      error(range(tok()), fmt::format("expected a CASE label ('1:', '2, 3:', '4..6:'), not {}", quoted()));
      skip_block("CASE");
      return;
    }
    // The labels, each `selector = v` or `(selector >= lo AND selector <= hi)`, joined with OR.
    ast::ExprPtr cond;
    const StToken first = tok();
    for (;;) {
      ast::ExprPtr lo = expression();
      if (!lo) {
        skip_block("CASE");
        return;
      }
      ast::ExprPtr test;
      if (tok().kind == StTok::DotDot) {
        next();
        ast::ExprPtr hi = expression();
        if (!hi) {
          skip_block("CASE");
          return;
        }
        SourceRange r = lo->range.to(hi->range);
        test = paren(made_binary(made_binary(clone(*selector), std::move(lo), BinaryOp::Ge, r),
                                 made_binary(clone(*selector), std::move(hi), BinaryOp::Le, r), BinaryOp::And, r));
      } else {
        SourceRange r = lo->range;
        test = made_binary(clone(*selector), std::move(lo), BinaryOp::Eq, r);
      }
      cond = cond ? made_binary(std::move(cond), std::move(test), BinaryOp::Or, range(first).to(test->range))
                  : std::move(test);
      if (tok().kind == StTok::Comma) {
        next();
        continue;
      }
      break;
    }
    if (tok().kind != StTok::Colon) {
      error(range(tok()), fmt::format("expected ':' after the CASE label, not {}", quoted()));
      skip_block("CASE");
      return;
    }
    next();
    if (branches.size() >= 1024) {
      error(range(first), "a CASE with more than 1024 branches", ErrorKind::Nesting);
      skip_block("CASE");
      return;
    }
    ++depth_;
    ast::Block body = statements(true);
    --depth_;
    branches.push_back({std::move(cond), std::move(body), range(first)});
  }
  if (!keyword("END_CASE")) {
    error(range(tok()), fmt::format("expected 'END_CASE' to close the 'CASE', not {}", quoted()))
        .note(range(start), "the 'CASE' it closes");
    return;
  }
  const StToken end = tok();
  next();
  if (tok().kind == StTok::Semi) next();
  std::vector<ast::Stmt> tail = std::move(otherwise);
  bool any = false;
  for (std::size_t k = branches.size(); k-- > 0;) {
    ast::Stmt s;
    s.kind = ast::Stmt::Kind::If;
    s.range = (k == 0 ? range(start) : branches[k].range).to(range(end));
    s.value = std::move(branches[k].condition);
    s.then_block = std::move(branches[k].body);
    if (!tail.empty()) {
      s.has_else = true;
      s.else_if = any;
      s.else_block = std::move(tail);
    }
    tail.clear();
    tail.push_back(std::move(s));
    any = true;
  }
  // A CASE without labels runs its ELSE (or nothing).
  for (ast::Stmt &s : tail) out.push_back(std::move(s));
}

}  // namespace gfec::iec
