// A short list of table indices (a transition's input or output places) that keeps up to two
// inline and moves to the heap beyond. Nearly every transition has one or two of each: a
// std::vector would cost a heap block per list and 24 bytes in every transition, this costs 16
// and no allocation (docs/performance.md, "(a) The compiler"). It reads like std::vector<int>.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <stdexcept>
#include <vector>

namespace gfec {

class IndexList {
public:
  IndexList() = default;
  IndexList(std::initializer_list<int> items) { assign(items.begin(), items.end()); }
  IndexList(const std::vector<int> &items) { assign(items.data(), items.data() + items.size()); }
  IndexList(const IndexList &other) { assign(other.begin(), other.end()); }
  IndexList(IndexList &&other) noexcept { take(other); }
  IndexList &operator=(const IndexList &other) {
    if (this != &other) {
      release();
      assign(other.begin(), other.end());
    }
    return *this;
  }
  IndexList &operator=(IndexList &&other) noexcept {
    if (this != &other) {
      release();
      take(other);
    }
    return *this;
  }
  ~IndexList() { release(); }

  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  int *data() { return on_heap() ? heap_ : inline_; }
  const int *data() const { return on_heap() ? heap_ : inline_; }
  int &operator[](std::size_t i) { return data()[i]; }
  const int &operator[](std::size_t i) const { return data()[i]; }
  int *begin() { return data(); }
  int *end() { return data() + size_; }
  const int *begin() const { return data(); }
  const int *end() const { return data() + size_; }
  const int &at(std::size_t i) const {
    if (i >= size_) throw std::out_of_range("IndexList::at");
    return data()[i];
  }
  int front() const { return data()[0]; }
  int back() const { return data()[size_ - 1]; }

  void push_back(int item) {
    if (size_ == capacity()) grow(size_ * 2);
    data()[size_++] = item;
  }
  void reserve(std::size_t n) {
    if (n > capacity()) grow(static_cast<std::uint32_t>(n));
  }

  friend bool operator==(const IndexList &a, const IndexList &b) {
    return a.size_ == b.size_ && std::equal(a.begin(), a.end(), b.begin());
  }
  friend bool operator!=(const IndexList &a, const IndexList &b) { return !(a == b); }

private:
  static constexpr std::uint32_t kInline = 2;
  bool on_heap() const { return capacity_ > kInline; }
  std::uint32_t capacity() const { return capacity_; }
  void grow(std::uint32_t n) {
    int *bigger = new int[n];
    std::memcpy(bigger, data(), size_ * sizeof(int));
    release();
    heap_ = bigger;
    capacity_ = n;
  }
  void assign(const int *first, const int *last) {
    size_ = 0;
    reserve(static_cast<std::size_t>(last - first));
    std::copy(first, last, data());
    size_ = static_cast<std::uint32_t>(last - first);
  }
  void release() {
    if (on_heap()) delete[] heap_;
    capacity_ = kInline;
  }
  void take(IndexList &other) {
    size_ = other.size_;
    capacity_ = other.capacity_;
    if (other.on_heap()) heap_ = other.heap_;
    else std::copy(other.inline_, other.inline_ + other.size_, inline_);
    other.size_ = 0;
    other.capacity_ = kInline;
  }

  union {
    int inline_[kInline];
    int *heap_;
  };
  std::uint32_t size_ = 0;
  std::uint32_t capacity_ = kInline;
};

}  // namespace gfec
