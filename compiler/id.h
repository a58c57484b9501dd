// Typed references between the model's tables (docs/architecture.md, "The model"). A place
// refers to the chart it runs by a ChartId, a transition to its places by PlaceIds, an
// expression to its variable by a VarId: an id of one table does not index another, does not
// mix with a count or a position by accident, and "none" is a state of its own, not -1.
// Four bytes, as the int it replaces: a million-place chart stays as small (docs/performance.md).
#pragma once

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <utility>
#include <vector>

namespace gfec {

template <typename Tag> class Id {
public:
  /// None: refers to nothing.
  constexpr Id() = default;
  constexpr explicit Id(std::size_t position) : value_(static_cast<std::uint32_t>(position)) {
    assert(position < kNone);
  }
  static constexpr Id none() { return Id(); }

  constexpr bool valid() const { return value_ != kNone; }
  constexpr explicit operator bool() const { return valid(); }
  /// The position in its table; only for an id that is valid().
  constexpr std::size_t index() const {
    assert(valid());
    return value_;
  }

  friend constexpr bool operator==(Id a, Id b) { return a.value_ == b.value_; }
  friend constexpr bool operator!=(Id a, Id b) { return a.value_ != b.value_; }
  /// Table order; none sorts last.
  friend constexpr bool operator<(Id a, Id b) { return a.value_ < b.value_; }
  friend constexpr bool operator>(Id a, Id b) { return b < a; }
  friend constexpr bool operator<=(Id a, Id b) { return !(b < a); }
  friend constexpr bool operator>=(Id a, Id b) { return !(a < b); }

private:
  static constexpr std::uint32_t kNone = UINT32_MAX;
  std::uint32_t value_ = kNone;
};

/// The ids of a table of `count` elements, in order: `for (PlaceId p : chart.places.ids())`.
template <typename IdT> class IdRange {
public:
  class iterator {
  public:
    explicit iterator(std::size_t i) : i_(i) {}
    IdT operator*() const { return IdT(i_); }
    iterator &operator++() {
      ++i_;
      return *this;
    }
    bool operator!=(const iterator &o) const { return i_ != o.i_; }
    bool operator==(const iterator &o) const { return i_ == o.i_; }

  private:
    std::size_t i_;
  };
  explicit IdRange(std::size_t count) : count_(count) {}
  iterator begin() const { return iterator(0); }
  iterator end() const { return iterator(count_); }

private:
  std::size_t count_;
};

/// A table of the model: a vector indexed by its own kind of id. It is also a sequence, so
/// that a pass over every element reads as one (by range-for, or by position in a loop that
/// counts); what refers to an element holds an id, and an id of another table does not fit.
template <typename IdT, typename T> class Table {
public:
  using value_type = T;
  using id_type = IdT;
  using reference = typename std::vector<T>::reference;
  using const_reference = typename std::vector<T>::const_reference;
  using iterator = typename std::vector<T>::iterator;
  using const_iterator = typename std::vector<T>::const_iterator;

  Table() = default;
  Table(std::initializer_list<T> items) : items_(items) {}

  reference operator[](IdT id) { return items_[id.index()]; }
  const_reference operator[](IdT id) const { return items_[id.index()]; }
  reference at(IdT id) { return items_.at(id.index()); }
  const_reference at(IdT id) const { return items_.at(id.index()); }
  reference operator[](std::size_t position) { return items_[position]; }
  const_reference operator[](std::size_t position) const { return items_[position]; }
  reference at(std::size_t position) { return items_.at(position); }
  const_reference at(std::size_t position) const { return items_.at(position); }

  /// The id of an element of this table, given by reference.
  IdT id_of(const T &element) const { return IdT(static_cast<std::size_t>(&element - items_.data())); }
  /// The id the next element appended gets.
  IdT next_id() const { return IdT(items_.size()); }
  IdRange<IdT> ids() const { return IdRange<IdT>(items_.size()); }
  bool contains(IdT id) const { return id.valid() && id.index() < items_.size(); }

  bool empty() const { return items_.empty(); }
  std::size_t size() const { return items_.size(); }
  void reserve(std::size_t n) { items_.reserve(n); }
  void resize(std::size_t n) { items_.resize(n); }
  void assign(std::size_t n, const T &value) { items_.assign(n, value); }
  void clear() { items_.clear(); }
  void shrink_to_fit() { items_.shrink_to_fit(); }
  void push_back(T item) { items_.push_back(std::move(item)); }
  template <typename... Args> reference emplace_back(Args &&...args) {
    return items_.emplace_back(std::forward<Args>(args)...);
  }
  reference front() { return items_.front(); }
  const_reference front() const { return items_.front(); }
  reference back() { return items_.back(); }
  const_reference back() const { return items_.back(); }
  T *data() { return items_.data(); }
  const T *data() const { return items_.data(); }
  iterator begin() { return items_.begin(); }
  iterator end() { return items_.end(); }
  const_iterator begin() const { return items_.begin(); }
  const_iterator end() const { return items_.end(); }
  iterator erase(const_iterator first, const_iterator last) { return items_.erase(first, last); }

private:
  std::vector<T> items_;
};

/// Something kept per element of a table, beside it (a mark per place, a C name per variable):
/// a vector indexed by that table's id.
template <typename IdT, typename V> class IdMap {
public:
  using reference = typename std::vector<V>::reference;
  using const_reference = typename std::vector<V>::const_reference;

  IdMap() = default;
  explicit IdMap(std::size_t count, const V &value = V()) : items_(count, value) {}

  reference operator[](IdT id) { return items_[id.index()]; }
  const_reference operator[](IdT id) const { return items_[id.index()]; }
  reference at(IdT id) { return items_.at(id.index()); }
  const_reference at(IdT id) const { return items_.at(id.index()); }

  void assign(std::size_t count, const V &value) { items_.assign(count, value); }
  void resize(std::size_t count, const V &value = V()) { items_.resize(count, value); }
  void push_back(V value) { items_.push_back(std::move(value)); }
  void reserve(std::size_t count) { items_.reserve(count); }
  void clear() { items_.clear(); }
  bool empty() const { return items_.empty(); }
  std::size_t size() const { return items_.size(); }
  IdRange<IdT> ids() const { return IdRange<IdT>(items_.size()); }
  auto begin() { return items_.begin(); }
  auto end() { return items_.end(); }
  auto begin() const { return items_.begin(); }
  auto end() const { return items_.end(); }
  /// The values in id order, for code that takes a vector.
  const std::vector<V> &values() const { return items_; }

private:
  std::vector<V> items_;
};

}  // namespace gfec

namespace std {
template <typename Tag> struct hash<gfec::Id<Tag>> {
  std::size_t operator()(gfec::Id<Tag> id) const noexcept {
    return id.valid() ? id.index() : static_cast<std::size_t>(-1);
  }
};
}  // namespace std
