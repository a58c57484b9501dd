// Typed values of the configuration and the conversions between them (docs/runtime.md
// 3: int <-> float, number -> string, string -> number).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

namespace afp {

/// Base of every error the runtime reports by exception.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A value cannot be converted to the requested type (e.g. "abc" to float).
class ConversionError : public Error {
 public:
  using Error::Error;
};

/// The types a configuration entry, an In or an Out parameter can have.
enum class Type { Int, Float, Double, Bool, String, Object };

/// The type's name as written in a chart ("int", "float", ..., "object").
const char* to_string(Type type);

/// An opaque object shared through the configuration (`object` in docs/language.md 8):
/// only the actors that made it know its structure; the type is checked on access.
class Object {
 public:
  /// The null object (the default value of an Object entry).
  Object() = default;

  /// Wraps a shared pointer; the pointee's type is remembered for get().
  template <class T>
  Object(std::shared_ptr<T> ptr) : ptr_(std::move(ptr)), type_(type_tag<std::remove_cv_t<T>>()) {}

  /// The object as a T, or nullptr when it is null or holds another type.
  template <class T>
  T* get() const {
    return ptr_ && type_ == type_tag<std::remove_cv_t<T>>() ? static_cast<T*>(ptr_.get()) : nullptr;
  }

  /// True unless null.
  explicit operator bool() const { return ptr_ != nullptr; }

  /// Same pointee (identity, not contents).
  friend bool operator==(const Object& a, const Object& b) { return a.ptr_ == b.ptr_; }
  friend bool operator!=(const Object& a, const Object& b) { return !(a == b); }

 private:
  /// One address per type, standing in for typeid so that the runtime builds with -fno-rtti
  /// (an inline function's static is one object in the whole program).
  template <class T>
  static const void* type_tag() {
    static const char tag = 0;
    return &tag;
  }

  std::shared_ptr<void> ptr_;
  const void* type_ = nullptr;
};

/// Makes an Object holding a new T (like std::make_shared).
template <class T, class... Args>
Object make_object(Args&&... args) {
  return Object(std::make_shared<T>(std::forward<Args>(args)...));
}

/// One typed value. Constructors are implicit so that formulas can return
/// plain C++ values; `const char*` is accepted so that "text" is a string, not a bool.
class Value {
 public:
  /// The int 0.
  Value() = default;
  Value(int v) : v_(v) {}
  Value(float v) : v_(v) {}
  Value(double v) : v_(v) {}
  Value(bool v) : v_(v) {}
  Value(std::string v) : v_(std::move(v)) {}
  Value(const char* v) : v_(std::string(v)) {}
  Value(Object v) : v_(std::move(v)) {}

  /// The type of the value held.
  Type type() const { return static_cast<Type>(v_.index()); }

  /// The value if it holds exactly a T, else nullptr (no conversion).
  template <class T>
  const T* get_if() const {
    return std::get_if<T>(&v_);
  }

  /// Same type and same value.
  friend bool operator==(const Value& a, const Value& b) { return a.v_ == b.v_; }
  friend bool operator!=(const Value& a, const Value& b) { return !(a == b); }

 private:
  // Order matches enum Type, so type() is the variant's index.
  std::variant<int, float, double, bool, std::string, Object> v_;
};

/// True for the C++ types a Value can hold (the T of In<T>, Out<T>, get<T>).
template <class T>
inline constexpr bool is_value_type_v =
    std::is_same_v<T, int> || std::is_same_v<T, float> || std::is_same_v<T, double> || std::is_same_v<T, bool> ||
    std::is_same_v<T, std::string> || std::is_same_v<T, Object>;

/// The default value of a type: 0, 0.0, false, "" or the null object.
Value default_value(Type type);

/// Converts a value to a type, following docs/runtime.md 3: numbers convert
/// among themselves as in C (float -> int truncates toward zero), a number
/// becomes its shortest decimal text, a string becomes a number only when its
/// whole text (surrounding blanks allowed) is a decimal number; bool converts
/// only to and from "true"/"false"; objects do not convert.
/// Throws ConversionError otherwise (including NaN or out-of-range -> int).
Value convert(const Value& value, Type to);

/// The Type of the C++ type T (one of is_value_type_v).
template <class T>
constexpr Type type_of() {
  static_assert(is_value_type_v<T>, "afp values are int, float, double, bool, std::string or afp::Object");
  return std::is_same_v<T, int>           ? Type::Int
         : std::is_same_v<T, float>       ? Type::Float
         : std::is_same_v<T, double>      ? Type::Double
         : std::is_same_v<T, bool>        ? Type::Bool
         : std::is_same_v<T, std::string> ? Type::String
                                          : Type::Object;
}

/// convert() to the C++ type T (one of is_value_type_v).
template <class T>
T convert(const Value& value) {
  return *convert(value, type_of<T>()).template get_if<T>();
}

}  // namespace afp
