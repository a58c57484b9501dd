// IEC names are case-insensitive and the chart language's are not: one POU's scope of declared
// names by their upper-case spelling, which respells every use as its declaration (lower.cc).
#pragma once

#include "ast.h"
#include "iec/iec_text.h"

#include <map>
#include <string>
#include <string_view>

namespace gfec::iec {

/// Declared names by their upper-case spelling: IEC's case-insensitive scope of one POU.
class Spellings {
public:
  void declare(const ast::Name &n) { by_upper_.emplace(upper(n.text), n.text); }
  bool declared(std::string_view name) const { return by_upper_.count(upper(name)) != 0; }
  /// Respells `n` as its declaration, if it has one.
  void respell(ast::Name &n) const {
    auto it = by_upper_.find(upper(n.text));
    if (it != by_upper_.end()) n.text = it->second;
  }
  void respell(ast::Expr &e) const {
    if (e.kind == ast::Expr::Kind::Name || e.kind == ast::Expr::Kind::Path) respell(e.name);
    for (ast::Expr *a : e.args)
      if (a) respell(*a);
  }
  template <typename Stmts> void respell_block(Stmts &b) const {
    for (ast::Stmt &s : b) {
      if (s.call) respell(*s.call);
      if (s.value) respell(*s.value);
      if (s.target) respell(*s.target);
      respell_block(s.then_block);
      respell_block(s.else_block);
    }
  }

private:
  std::map<std::string, std::string_view> by_upper_;
};

}  // namespace gfec::iec
