// A vector kept on the heap: a pointer wide when empty. For members of the model that most
// elements leave empty (the blocks of an `if`, the path of `active(P.Q)`), where a std::vector
// would cost three pointers in every statement and expression (docs/performance.md, "(a) The
// compiler"). It reads like the std::vector it holds, and converts to one for functions that
// take `const std::vector<T> &`.
#pragma once

#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

namespace gfec {

template <typename T> class HeapVector {
public:
  HeapVector() = default;
  HeapVector(std::initializer_list<T> items) { assign(std::vector<T>(items)); }
  HeapVector(std::vector<T> &&items) { assign(std::move(items)); }
  HeapVector(const std::vector<T> &items) { assign(std::vector<T>(items)); }
  HeapVector(const HeapVector &other) { assign(std::vector<T>(other.get())); }
  HeapVector(HeapVector &&) noexcept = default;
  HeapVector &operator=(const HeapVector &other) {
    if (this != &other) assign(std::vector<T>(other.get()));
    return *this;
  }
  HeapVector &operator=(HeapVector &&) noexcept = default;
  HeapVector &operator=(std::vector<T> &&items) {
    assign(std::move(items));
    return *this;
  }

  /// The elements as a vector (an empty one when there are none).
  const std::vector<T> &get() const { return items_ ? *items_ : none(); }
  operator const std::vector<T> &() const { return get(); }

  bool empty() const { return !items_; }
  std::size_t size() const { return items_ ? items_->size() : 0; }
  T &operator[](std::size_t i) { return (*items_)[i]; }
  const T &operator[](std::size_t i) const { return (*items_)[i]; }
  T &front() { return items_->front(); }
  const T &front() const { return items_->front(); }
  T &back() { return items_->back(); }
  const T &back() const { return items_->back(); }
  T *begin() { return items_ ? items_->data() : nullptr; }
  T *end() { return items_ ? items_->data() + items_->size() : nullptr; }
  const T *begin() const { return items_ ? items_->data() : nullptr; }
  const T *end() const { return items_ ? items_->data() + items_->size() : nullptr; }

  void push_back(const T &item) { vec().push_back(item); }
  void push_back(T &&item) { vec().push_back(std::move(item)); }

  friend bool operator==(const HeapVector &a, const HeapVector &b) { return a.get() == b.get(); }
  friend bool operator!=(const HeapVector &a, const HeapVector &b) { return !(a == b); }

private:
  static const std::vector<T> &none() {
    static const std::vector<T> nothing;
    return nothing;
  }
  std::vector<T> &vec() {
    if (!items_) items_ = std::make_unique<std::vector<T>>();
    return *items_;
  }
  // An empty vector is kept as no vector at all, so that empty() is the pointer's test.
  void assign(std::vector<T> &&items) {
    if (items.empty()) items_.reset();
    else items_ = std::make_unique<std::vector<T>>(std::move(items));
  }

  std::unique_ptr<std::vector<T>> items_;
};

}  // namespace gfec
