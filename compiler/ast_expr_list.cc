#include "ast_expr_list.h"

#include "ast.h"

#include <algorithm>

namespace gfec::ast {

namespace {
/// The capacity of a heap array holding `n` (>= 2) expressions: the next power of two.
std::size_t capacity_for(std::size_t n) {
  std::size_t c = 2;
  while (c < n) c *= 2;
  return c;
}
}  // namespace

ExprList::ExprList(std::vector<std::unique_ptr<Expr>> items) : one_(nullptr) {
  if (items.size() == 1) {
    one_ = items[0].release();
  } else if (items.size() > 1) {
    many_ = new Expr *[capacity_for(items.size())];
    for (std::size_t i = 0; i < items.size(); ++i) many_[i] = items[i].release();
  }
  size_ = static_cast<std::uint32_t>(items.size());
}

ExprList &ExprList::operator=(ExprList &&other) noexcept {
  if (this != &other) {
    destroy();
    take(other);
  }
  return *this;
}

void ExprList::push_back(std::unique_ptr<Expr> e) {
  if (size_ == 0) {
    one_ = e.release();
  } else if (size_ == 1) {
    Expr **array = new Expr *[2];
    array[0] = one_;
    array[1] = e.release();
    many_ = array;
  } else {
    // The array of a list of n >= 2 always has capacity_for(n) slots: it is full when n is a
    // power of two.
    if (size_ == capacity_for(size_)) {
      Expr **array = new Expr *[capacity_for(size_ + 1)];
      std::copy(many_, many_ + size_, array);
      delete[] many_;
      many_ = array;
    }
    many_[size_] = e.release();
  }
  ++size_;
}

void ExprList::destroy() {
  for (Expr *e : *this) delete e;
  if (size_ >= 2) delete[] many_;
  forget();
}

}  // namespace gfec::ast
