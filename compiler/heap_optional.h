// An optional value kept on the heap: a pointer wide when absent. For members of the model that
// most elements leave empty (a place's `post`), where std::optional would hold a whole
// expression inline in every element (docs/performance.md, "(a) The compiler").
// It reads like std::optional: `if (x)`, `*x`, `x->`, has_value(), reset(), emplace(), and it is
// assigned from a value, a std::optional or std::nullopt.
#pragma once

#include <memory>
#include <optional>
#include <utility>

namespace gfec {

template <typename T> class HeapOptional {
public:
  HeapOptional() = default;
  HeapOptional(std::nullopt_t) {}
  HeapOptional(const T &value) : value_(std::make_unique<T>(value)) {}
  HeapOptional(T &&value) : value_(std::make_unique<T>(std::move(value))) {}
  HeapOptional(const std::optional<T> &value) {
    if (value) value_ = std::make_unique<T>(*value);
  }
  HeapOptional(std::optional<T> &&value) {
    if (value) value_ = std::make_unique<T>(std::move(*value));
  }
  HeapOptional(const HeapOptional &other) : value_(other.value_ ? std::make_unique<T>(*other.value_) : nullptr) {}
  HeapOptional(HeapOptional &&) noexcept = default;
  HeapOptional &operator=(const HeapOptional &other) {
    if (this != &other) value_ = other.value_ ? std::make_unique<T>(*other.value_) : nullptr;
    return *this;
  }
  HeapOptional &operator=(HeapOptional &&) noexcept = default;

  bool has_value() const { return value_ != nullptr; }
  explicit operator bool() const { return has_value(); }
  T &operator*() { return *value_; }
  const T &operator*() const { return *value_; }
  T *operator->() { return value_.get(); }
  const T *operator->() const { return value_.get(); }
  T &value() { return *value_; }
  const T &value() const { return *value_; }
  void reset() { value_.reset(); }
  template <typename... Args> T &emplace(Args &&...args) {
    value_ = std::make_unique<T>(std::forward<Args>(args)...);
    return *value_;
  }

private:
  std::unique_ptr<T> value_;
};

}  // namespace gfec
