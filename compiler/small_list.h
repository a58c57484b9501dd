// A short list of ids (a transition's input or output places) that keeps up to two inline and
// moves to the heap beyond. Nearly every transition has one or two of each: a
// std::vector would cost a heap block per list and 24 bytes in every transition, this costs 16
// and no allocation (docs/performance.md, "(a) The compiler"). It reads like std::vector<T>;
// T is a small trivially copyable type (an Id, compiler/id.h).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace gfec {

template <typename T> class SmallList {
  static_assert(std::is_trivially_copyable<T>::value, "kept by memcpy");

public:
  SmallList() = default;
  SmallList(std::initializer_list<T> items) { assign(items.begin(), items.end()); }
  SmallList(const std::vector<T> &items) { assign(items.data(), items.data() + items.size()); }
  SmallList(const SmallList &other) { assign(other.begin(), other.end()); }
  SmallList(SmallList &&other) noexcept { take(other); }
  SmallList &operator=(const SmallList &other) {
    if (this != &other) {
      release();
      assign(other.begin(), other.end());
    }
    return *this;
  }
  SmallList &operator=(SmallList &&other) noexcept {
    if (this != &other) {
      release();
      take(other);
    }
    return *this;
  }
  ~SmallList() { release(); }

  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  T *data() { return on_heap() ? storage_.heap : storage_.inline_items; }
  const T *data() const { return on_heap() ? storage_.heap : storage_.inline_items; }
  T &operator[](std::size_t i) { return data()[i]; }
  const T &operator[](std::size_t i) const { return data()[i]; }
  T *begin() { return data(); }
  T *end() { return data() + size_; }
  const T *begin() const { return data(); }
  const T *end() const { return data() + size_; }
  const T &at(std::size_t i) const {
    if (i >= size_) throw std::out_of_range("SmallList::at");
    return data()[i];
  }
  T front() const { return data()[0]; }
  T back() const { return data()[size_ - 1]; }

  void push_back(T item) {
    if (size_ == capacity()) grow(size_ * 2);
    data()[size_++] = item;
  }
  void reserve(std::size_t n) {
    if (n > capacity()) grow(static_cast<std::uint32_t>(n));
  }

  friend bool operator==(const SmallList &a, const SmallList &b) {
    return a.size_ == b.size_ && std::equal(a.begin(), a.end(), b.begin());
  }
  friend bool operator!=(const SmallList &a, const SmallList &b) { return !(a == b); }

private:
  static constexpr std::uint32_t kInline = 2;
  bool on_heap() const { return capacity_ > kInline; }
  std::uint32_t capacity() const { return capacity_; }
  void grow(std::uint32_t n) {
    T *bigger = new T[n];
    std::memcpy(bigger, data(), size_ * sizeof(T));
    release();
    storage_.heap = bigger;
    capacity_ = n;
  }
  void assign(const T *first, const T *last) {
    size_ = 0;
    reserve(static_cast<std::size_t>(last - first));
    std::copy(first, last, data());
    size_ = static_cast<std::uint32_t>(last - first);
  }
  void release() {
    if (on_heap()) delete[] storage_.heap;
    capacity_ = kInline;
  }
  void take(SmallList &other) {
    size_ = other.size_;
    capacity_ = other.capacity_;
    if (other.on_heap()) storage_.heap = other.storage_.heap;
    else std::copy(other.storage_.inline_items, other.storage_.inline_items + other.size_, storage_.inline_items);
    other.size_ = 0;
    other.capacity_ = kInline;
  }

  // Which member is in use is told by capacity_. The union has a constructor of its own so
  // that it may hold a T with a default member initializer (an Id).
  union Storage {
    Storage() : heap(nullptr) {}
    T inline_items[kInline];
    T *heap;
  } storage_;
  std::uint32_t size_ = 0;
  std::uint32_t capacity_ = kInline;
};

}  // namespace gfec
