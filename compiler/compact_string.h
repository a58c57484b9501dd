// A string in sixteen bytes, where std::string takes thirty-two: up to 14 characters inline,
// longer ones in a heap block of their own. For the spelling of a model literal ("42", "0.5"),
// one of four million expressions in a large chart (docs/performance.md, "(a) The compiler").
// It is assigned from any string and read as a std::string_view; it is always NUL-terminated;
// it holds at most 2^32 - 1 characters (a source file is smaller: source.h).
#pragma once

#include <cstdint>
#include <cstring>
#include <fmt/format.h>
#include <ostream>
#include <string>
#include <string_view>

namespace gfec {

class CompactString {
public:
  CompactString() noexcept { set_inline_size(0); }
  explicit CompactString(std::string_view s) { assign(s); }
  CompactString(const CompactString &other) { assign(other.view()); }
  CompactString(CompactString &&other) noexcept {
    std::memcpy(bytes_, other.bytes_, sizeof bytes_);
    other.set_inline_size(0);
  }
  CompactString &operator=(const CompactString &other) { return *this = other.view(); }
  CompactString &operator=(CompactString &&other) noexcept {
    if (this != &other) {
      release();
      std::memcpy(bytes_, other.bytes_, sizeof bytes_);
      other.set_inline_size(0);
    }
    return *this;
  }
  CompactString &operator=(std::string_view s) {
    CompactString copy(s);  // `s` may view this string
    return *this = std::move(copy);
  }
  CompactString &operator=(const std::string &s) { return *this = std::string_view(s); }
  CompactString &operator=(const char *s) { return *this = std::string_view(s); }
  ~CompactString() { release(); }

  const char *data() const { return on_heap() ? heap_data() : bytes_; }
  const char *c_str() const { return data(); }
  std::size_t size() const { return on_heap() ? heap_size() : static_cast<unsigned char>(bytes_[kTag]); }
  bool empty() const { return size() == 0; }
  std::string_view view() const { return {data(), size()}; }
  operator std::string_view() const { return view(); }
  std::string str() const { return std::string(view()); }

  friend bool operator==(const CompactString &a, std::string_view b) { return a.view() == b; }
  friend bool operator!=(const CompactString &a, std::string_view b) { return a.view() != b; }
  friend bool operator==(std::string_view a, const CompactString &b) { return a == b.view(); }
  friend bool operator!=(std::string_view a, const CompactString &b) { return a != b.view(); }
  friend bool operator==(const CompactString &a, const CompactString &b) { return a.view() == b.view(); }
  friend bool operator!=(const CompactString &a, const CompactString &b) { return a.view() != b.view(); }
  friend bool operator==(const CompactString &a, const char *b) { return a.view() == b; }
  friend bool operator!=(const CompactString &a, const char *b) { return a.view() != b; }
  friend bool operator==(const CompactString &a, const std::string &b) { return a.view() == b; }
  friend bool operator!=(const CompactString &a, const std::string &b) { return a.view() != b; }
  friend std::string operator+(const std::string &a, const CompactString &b) { return a + std::string(b.view()); }
  friend std::string operator+(const CompactString &a, const std::string &b) { return std::string(a.view()) + b; }
  friend std::string operator+(const char *a, const CompactString &b) { return a + std::string(b.view()); }
  friend std::string operator+(const CompactString &a, const char *b) { return std::string(a.view()) + b; }
  friend std::ostream &operator<<(std::ostream &out, const CompactString &s) { return out << s.view(); }

private:
  // Layout: inline, bytes_[0..size] hold the characters and their NUL and bytes_[kTag] the
  // size; on the heap, bytes_ begin with the block's address and its size, and bytes_[kTag]
  // is kHeap. The fields are read with memcpy, which is how C++ reads bytes as a pointer.
  static constexpr std::size_t kTag = 15;
  static constexpr std::size_t kInline = kTag - 1;  // room for the NUL
  static constexpr unsigned char kHeap = 0xFF;

  bool on_heap() const { return static_cast<unsigned char>(bytes_[kTag]) == kHeap; }
  char *heap_data() const {
    char *p;
    std::memcpy(&p, bytes_, sizeof p);
    return p;
  }
  std::size_t heap_size() const {
    std::uint32_t n;
    std::memcpy(&n, bytes_ + sizeof(char *), sizeof n);
    return n;
  }
  void set_inline_size(std::size_t n) {
    bytes_[n] = '\0';
    bytes_[kTag] = static_cast<char>(n);
  }
  void assign(std::string_view s) {
    if (s.size() <= kInline) {
      // An empty view may have no data at all, and memcpy must not be given a null pointer.
      if (!s.empty()) std::memcpy(bytes_, s.data(), s.size());
      set_inline_size(s.size());
      return;
    }
    char *p = new char[s.size() + 1];
    std::memcpy(p, s.data(), s.size());
    p[s.size()] = '\0';
    const auto n = static_cast<std::uint32_t>(s.size());
    std::memcpy(bytes_, &p, sizeof p);
    std::memcpy(bytes_ + sizeof p, &n, sizeof n);
    bytes_[kTag] = static_cast<char>(kHeap);
  }
  void release() {
    if (on_heap()) delete[] heap_data();
    set_inline_size(0);
  }

  alignas(8) char bytes_[16];
};

}  // namespace gfec

template <> struct fmt::formatter<gfec::CompactString> : fmt::formatter<fmt::string_view> {
  template <typename Context> auto format(const gfec::CompactString &s, Context &ctx) const {
    return fmt::formatter<fmt::string_view>::format(fmt::string_view(s.data(), s.size()), ctx);
  }
};
