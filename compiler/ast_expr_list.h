// The operands of a syntax-tree expression. A chart may hold a million calls such as `Act(0)`:
// a std::vector would cost 24 bytes in the node and a heap block of its own for the one
// argument; this list is 16 bytes and keeps one operand inline (docs/performance.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

namespace gfec::ast {

struct Expr;

/// Owns its expressions. Elements are read as `Expr *` (`args[0]->kind`, `for (Expr *a : args)`);
/// empty, one inline, or a heap array whose capacity is the next power of two of the size, so
/// that appending stays linear however long a hostile argument list is.
class ExprList {
public:
  ExprList() noexcept : one_(nullptr) {}
  explicit ExprList(std::vector<std::unique_ptr<Expr>> items);
  ExprList(ExprList &&other) noexcept : one_(nullptr) { take(other); }
  ExprList &operator=(ExprList &&other) noexcept;
  ExprList(const ExprList &) = delete;
  ExprList &operator=(const ExprList &) = delete;
  ~ExprList() { destroy(); }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  Expr *const *begin() const { return size_ == 1 ? &one_ : size_ == 0 ? nullptr : many_; }
  Expr *const *end() const { return begin() + size_; }
  Expr *operator[](std::size_t i) const { return begin()[i]; }
  Expr *at(std::size_t i) const {
    if (i >= size_) throw std::out_of_range("ast::ExprList::at");
    return begin()[i];
  }
  Expr *front() const { return *begin(); }
  Expr *back() const { return end()[-1]; }
  void push_back(std::unique_ptr<Expr> e);

private:
  /// Moves `other`'s elements here (this list being empty), reading only its active member.
  void take(ExprList &other) noexcept {
    if (other.size_ == 1) one_ = other.one_;
    else many_ = other.many_;
    size_ = other.size_;
    other.forget();
  }
  void forget() {
    one_ = nullptr;
    size_ = 0;
  }
  void destroy();

  union {
    Expr *one_;    ///< size_ == 1
    Expr **many_;  ///< size_ >= 2 (null when empty)
  };
  std::uint32_t size_ = 0;
};

}  // namespace gfec::ast
