// An index from names to the positions of the elements that hold them, for tables of a million
// names (docs/performance.md, "(a) The compiler"): an open-addressing hash table of 32-bit
// positions and hashes (linear probing, a power-of-two capacity at most half full), 16 to
// 32 bytes a name where a node-based set or map takes 64 to 150. The table keeps no names of its own: `key(k)`
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
    return slots_.empty() ? kNone : slots_[slot_of(name, hash(name), key)].position;
  }
  /// Records that position `k` holds `name` and returns kNone, or returns the position that
  /// already holds it and records nothing: one probe where find() and then an insert take two.
  /// Positions are added in order (k is the number of positions before it), as a table grows by
  /// appending.
  template <typename Key> std::uint32_t insert(std::string_view name, std::uint32_t k, const Key &key) {
    if (2 * (std::size_t{k} + 1) > slots_.size()) grow();
    const std::uint32_t h = hash(name);
    Slot &slot = slots_[slot_of(name, h, key)];
    if (slot.position != kNone) return slot.position;
    slot = Slot{k, h};
    return kNone;
  }

  /// Room for `count` names in all without growing: a caller that knows how many names come
  /// saves the rehashes, each a pass of scattered writes over a table that outgrows the cache.
  /// Only ever grows, and to a power of two, so calling it again and again stays cheap.
  void reserve(std::size_t count) {
    std::size_t size = slots_.empty() ? 16 : slots_.size();
    while (2 * count > size) size *= 2;
    if (size > slots_.size()) rehash(size);
  }

private:
  // Each slot keeps its name's hash beside the position: a probe compares hashes and reads a
  // name (a cache miss into the table that owns it) only when they match, and growing the
  // index reads no names at all.
  struct Slot {
    std::uint32_t position = kNone;
    std::uint32_t hash = 0;
  };

  static std::uint32_t hash(std::string_view name) {
    return static_cast<std::uint32_t>(std::hash<std::string_view>{}(name));
  }
  void grow() { rehash(slots_.empty() ? 16 : 2 * slots_.size()); }
  void rehash(std::size_t size) {
    const std::vector<Slot> old = std::move(slots_);
    slots_.assign(size, Slot{});
    const std::size_t mask = slots_.size() - 1;
    for (const Slot &s : old) {
      if (s.position == kNone) continue;
      std::size_t i = s.hash & mask;
      while (slots_[i].position != kNone) i = (i + 1) & mask;
      slots_[i] = s;
    }
  }
  /// The slot `name` is in, or the empty slot where it would go. slots_ must not be empty.
  template <typename Key> std::size_t slot_of(std::string_view name, std::uint32_t h, const Key &key) const {
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = h & mask;
    while (slots_[i].position != kNone && (slots_[i].hash != h || std::string_view(key(slots_[i].position)) != name))
      i = (i + 1) & mask;
    return i;
  }

  std::vector<Slot> slots_;
};

}  // namespace gfec
