#include "iec/iec_text.h"

#include <cctype>

namespace gfec::iec {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char &c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

ast::ExprPtr clone(const ast::Expr &e) {
  auto c = std::make_unique<ast::Expr>();
  c->kind = e.kind;
  c->unary_op = e.unary_op;
  c->binary_op = e.binary_op;
  c->bool_value = e.bool_value;
  c->range = e.range;
  c->duration_ms = e.duration_ms;
  c->name = e.name;
  for (const ast::Expr *a : e.args) c->args.push_back(clone(*a));
  return c;
}

}  // namespace gfec::iec
