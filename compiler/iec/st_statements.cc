// ST statement lists as chart statements: assignments, IF/ELSIF/ELSE, and CASE as the chain of
// `if`s it means (its selector is read once per label, which is the same as IEC's one reading
// because ST expressions as gfec reads them have no side effects). Loops, calls and the rest are
// located "not supported yet" errors (docs/iec.md "What is not read yet").
#include "iec/st_parser.h"
#include "iec/iec_text.h"

#include <fmt/format.h>

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

}  // namespace

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
  for (const char *loop : {"FOR", "WHILE", "REPEAT"}) {
    if (!is_keyword(t, loop)) continue;
    not_supported(range(t), fmt::format("{} loops are not supported yet", loop));
    skip_block(is_keyword(t, "REPEAT") ? "REPEAT" : loop);
    return;
  }
  for (const char *k : {"RETURN", "EXIT", "CONTINUE", "JMP"}) {
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
    ast::ExprPtr value = expression();
    if (!value) {
      skip_statement();
      return;
    }
    const StToken last = tok();
    if (!expect_semi("the assignment")) {
      skip_statement();
      return;
    }
    ast::Stmt &s = out.emplace_back();
    s.kind = ast::Stmt::Kind::Assign;
    s.assign_op = AssignOp::Set;
    s.range = range(t, last);
    s.target.emplace(name(t));
    s.value = std::move(value);
    return;
  }
  if (after.kind == StTok::LParen) return block_call(out);
  if (after.kind == StTok::Dot && peek(2).kind == StTok::Ident && peek(3).kind == StTok::Assign) {
    // `inst.IN := x;` sets an input of a function-block instance (the validator checks it is one).
    const StToken member = peek(2);
    next();
    next();
    next();
    next();
    ast::ExprPtr value = expression();
    const StToken last = tok();
    if (!value || !expect_semi("the assignment")) {
      skip_statement();
      return;
    }
    ast::Stmt &s = out.emplace_back();
    s.kind = ast::Stmt::Kind::Assign;
    s.assign_op = AssignOp::Set;
    s.range = range(t, last);
    s.target.emplace(ast::Name{strings().emplace_back(fmt::format("{}.{}", t.text, member.text)), range(t, member)});
    s.value = std::move(value);
    return;
  }
  if (after.kind == StTok::Dot || after.kind == StTok::LBracket || after.kind == StTok::Caret)
    not_supported(
        range(t, after),
        fmt::format("assigning a member, an element or through a pointer of '{}' is not supported yet", t.text));
  else if (after.kind == StTok::Eq)
    error(range(after), fmt::format("'=' compares; an ST assignment is '{} := ...;'", t.text)).fix(range(after), ":=");
  else if (after.kind == StTok::Colon && (is_keyword(t, "ACTION") || is_keyword(t, "STEP")))
    error(range(t), fmt::format("expected a statement, not {}", quoted()));
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
    if (param.kind != StTok::Ident || (bind != StTok::Assign && bind != StTok::Arrow)) {
      not_supported(range(param), fmt::format("a parameter that is not named ({}) in the call of '{}' is not "
                                              "supported yet: write 'input := value' or 'output => variable'",
                                              quoted(), inst.text));
      skip_statement();
      return;
    }
    next();
    next();
    if (bind == StTok::Assign) {
      ast::ExprPtr value = expression();
      if (!value) {
        skip_statement();
        return;
      }
      ast::Stmt a;
      a.kind = ast::Stmt::Kind::Assign;
      a.target.emplace(name(param));
      a.range = {value->range.file, range(param).begin, value->range.end};
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
    if (++depth_ > kMaxStNesting) {
      --depth_;
      error(range(kw), fmt::format("statements nested too deeply (more than {} levels)", kMaxStNesting),
            ErrorKind::Nesting);
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
  if (++depth_ > kMaxStNesting) {
    --depth_;
    error(range(start), fmt::format("statements nested too deeply (more than {} levels)", kMaxStNesting),
          ErrorKind::Nesting);
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
