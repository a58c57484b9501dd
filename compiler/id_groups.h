// Items grouped by an id (the transitions leaving each state, the states each state leads to):
// one array of the items, group after group, and where each group starts, built by counting.
// A vector per group is a small allocation each: for a chart of a million states that is a
// million allocations and frees whose cost grows faster than the chart (malloc's bookkeeping,
// page faults; docs/performance.md, "Long fsms"), where this is two allocations.
#pragma once

#include "id.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace gfec {

template <typename GroupId, typename T> class IdGroups {
public:
  /// A group's items, in the order they were given.
  class Range {
  public:
    Range(const T *begin, const T *end) : begin_(begin), end_(end) {}
    const T *begin() const { return begin_; }
    const T *end() const { return end_; }
    std::size_t size() const { return static_cast<std::size_t>(end_ - begin_); }
    bool empty() const { return begin_ == end_; }
    const T &operator[](std::size_t k) const { return begin_[k]; }
    const T &front() const { return *begin_; }

  private:
    const T *begin_;
    const T *end_;
  };

  IdGroups() = default;
  /// `groups` groups (ids 0 .. groups - 1) of the `items` (a group's id, an item); each group
  /// keeps its items in the order of `items`.
  IdGroups(std::size_t groups, const std::vector<std::pair<GroupId, T>> &items)
      : first_(groups + 1, 0), items_(items.size()) {
    for (const auto &item : items) ++first_[item.first.index() + 1];
    for (std::size_t g = 1; g < first_.size(); ++g) first_[g] += first_[g - 1];
    std::vector<std::uint32_t> next(first_.begin(), first_.end() - 1);
    for (const auto &item : items) items_[next[item.first.index()]++] = item.second;
  }

  Range operator[](GroupId g) const {
    return Range(items_.data() + first_[g.index()], items_.data() + first_[g.index() + 1]);
  }

private:
  std::vector<std::uint32_t> first_;  ///< group g's items are items_[first_[g] .. first_[g + 1])
  std::vector<T> items_;
};

}  // namespace gfec
