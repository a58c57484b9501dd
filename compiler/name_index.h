// An index from names to the positions of the elements that hold them, for tables of a million
// names (docs/performance.md, "(a) The compiler"): an open-addressing hash table of 32-bit
// positions (linear probing, a power-of-two capacity at most half full), 8 to 16 bytes a name
// where a node-based set or map takes 64 to 150. The table keeps no names of its own: `key(k)`
// gives the name at position k, so the elements own their names and the index only points.
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

namespace gfec {

class NameIndex {
public:
  static constexpr std::uint32_t kNone = UINT32_MAX;

  /// The position holding `name`, or kNone.
  template <typename Key> std::uint32_t find(std::string_view name, const Key &key) const {
    return slots_.empty() ? kNone : slots_[slot_of(name, key)];
  }
  /// Records that position `k` holds `name`, which no position holds yet; positions are added
  /// in order (k is the number of positions before it), as a table grows by appending.
  template <typename Key> void insert(std::string_view name, std::uint32_t k, const Key &key) {
    if (2 * (std::size_t{k} + 1) > slots_.size()) {
      slots_.assign(slots_.empty() ? 16 : 2 * slots_.size(), kNone);
      for (std::uint32_t j = 0; j < k; ++j) slots_[slot_of(key(j), key)] = j;
    }
    slots_[slot_of(name, key)] = k;
  }

private:
  /// The slot `name` is in, or the empty slot where it would go. slots_ must not be empty.
  template <typename Key> std::size_t slot_of(std::string_view name, const Key &key) const {
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = std::hash<std::string_view>{}(name)&mask;
    while (slots_[i] != kNone && std::string_view(key(slots_[i])) != name) i = (i + 1) & mask;
    return i;
  }

  std::vector<std::uint32_t> slots_;
};

}  // namespace gfec
