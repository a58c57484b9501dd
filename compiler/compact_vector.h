// A vector in sixteen bytes: a pointer and two 32-bit counts, where std::vector keeps three
// pointers. For the operands of a model expression: a chart may hold four million expressions,
// most with no operand or one (docs/performance.md, "(a) The compiler"). It reads like the
// std::vector it replaces; at most 2^32 - 1 elements, which no list in a chart comes near.
#pragma once

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

namespace gfec {

template <typename T> class CompactVector {
public:
  CompactVector() noexcept = default;
  CompactVector(std::initializer_list<T> items) { append_copies(items.begin(), items.end()); }
  CompactVector(const std::vector<T> &items) { append_copies(items.data(), items.data() + items.size()); }
  CompactVector(std::vector<T> &&items) {
    reserve(items.size());
    for (T &item : items) push_back(std::move(item));
  }
  CompactVector(const CompactVector &other) { append_copies(other.begin(), other.end()); }
  CompactVector(CompactVector &&other) noexcept { take(other); }
  CompactVector &operator=(const CompactVector &other) {
    if (this != &other) {
      CompactVector copy(other);
      release();
      take(copy);
    }
    return *this;
  }
  CompactVector &operator=(CompactVector &&other) noexcept {
    if (this != &other) {
      release();
      take(other);
    }
    return *this;
  }
  ~CompactVector() { release(); }

  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  T *data() { return items_; }
  const T *data() const { return items_; }
  T *begin() { return items_; }
  T *end() { return items_ + size_; }
  const T *begin() const { return items_; }
  const T *end() const { return items_ + size_; }
  T &operator[](std::size_t i) { return items_[i]; }
  const T &operator[](std::size_t i) const { return items_[i]; }
  T &at(std::size_t i) { return items_[checked(i)]; }
  const T &at(std::size_t i) const { return items_[checked(i)]; }
  T &front() { return items_[0]; }
  const T &front() const { return items_[0]; }
  T &back() { return items_[size_ - 1]; }
  const T &back() const { return items_[size_ - 1]; }

  void reserve(std::size_t n) {
    if (n > capacity_) grow(n);
  }
  void push_back(const T &item) { emplace_back(item); }
  void push_back(T &&item) { emplace_back(std::move(item)); }
  template <typename... Args> T &emplace_back(Args &&...args) {
    if (size_ == capacity_) {
      // Build the element before moving the others: `args` may refer to one of them.
      T item(std::forward<Args>(args)...);
      grow(capacity_ == 0 ? 1 : std::size_t{capacity_} * 2);
      ::new (static_cast<void *>(items_ + size_)) T(std::move(item));
    } else {
      ::new (static_cast<void *>(items_ + size_)) T(std::forward<Args>(args)...);
    }
    return items_[size_++];
  }
  void clear() {
    std::destroy(begin(), end());
    size_ = 0;
  }

  friend bool operator==(const CompactVector &a, const CompactVector &b) {
    return a.size_ == b.size_ && std::equal(a.begin(), a.end(), b.begin());
  }
  friend bool operator!=(const CompactVector &a, const CompactVector &b) { return !(a == b); }

private:
  std::size_t checked(std::size_t i) const {
    if (i >= size_) throw std::out_of_range("CompactVector::at");
    return i;
  }
  template <typename It> void append_copies(It first, It last) {
    reserve(static_cast<std::size_t>(last - first));
    for (; first != last; ++first) emplace_back(*first);
  }
  void grow(std::size_t n) {
    if (n > UINT32_MAX) throw std::length_error("CompactVector: more than 2^32 - 1 elements");
    T *bigger = std::allocator<T>().allocate(n);
    std::uninitialized_move(begin(), end(), bigger);
    std::destroy(begin(), end());
    if (items_) std::allocator<T>().deallocate(items_, capacity_);
    items_ = bigger;
    capacity_ = static_cast<std::uint32_t>(n);
  }
  void release() {
    clear();
    if (items_) std::allocator<T>().deallocate(items_, capacity_);
    items_ = nullptr;
    capacity_ = 0;
  }
  void take(CompactVector &other) noexcept {
    items_ = std::exchange(other.items_, nullptr);
    size_ = std::exchange(other.size_, 0);
    capacity_ = std::exchange(other.capacity_, 0);
  }

  T *items_ = nullptr;
  std::uint32_t size_ = 0;
  std::uint32_t capacity_ = 0;
};

}  // namespace gfec
