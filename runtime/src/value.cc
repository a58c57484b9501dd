#include "afp/value.h"

#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <string_view>
#include <system_error>

namespace afp {
namespace {

[[noreturn]] void fail(const Value& from, Type to, std::string_view why = {}) {
  std::string text = std::string("cannot convert ") + to_string(from.type());
  if (const auto* s = from.get_if<std::string>()) text += " \"" + *s + "\"";
  text += std::string(" to ") + to_string(to);
  if (!why.empty()) text += std::string(": ") + std::string(why);
  throw ConversionError(text);
}

bool is_number(Type t) { return t == Type::Int || t == Type::Float || t == Type::Double; }

double as_double(const Value& v) {
  if (const auto* i = v.get_if<int>()) return *i;
  if (const auto* f = v.get_if<float>()) return *f;
  return *v.get_if<double>();
}

// Truncates toward zero as a C cast does, but refuses what C leaves undefined.
int to_int(double d, const Value& from) {
  if (std::isnan(d) || d <= double(std::numeric_limits<int>::min()) - 1.0 ||
      d >= double(std::numeric_limits<int>::max()) + 1.0)
    fail(from, Type::Int, "out of range");
  return static_cast<int>(d);
}

// Shortest text that reads back as the same number ("30", "0.1", "1e+20").
template <class T>
std::string number_text(T n) {
  std::array<char, 64> buf;
  auto res = std::to_chars(buf.data(), buf.data() + buf.size(), n);
  return std::string(buf.data(), res.ptr);
}

// The text without surrounding blanks and one leading '+', or empty when it
// cannot be a decimal number (from_chars alone would accept "inf" and "nan").
std::string_view number_body(std::string_view s) {
  const char* blanks = " \t\r\n\f\v";
  auto first = s.find_first_not_of(blanks);
  if (first == std::string_view::npos) return {};
  s = s.substr(first, s.find_last_not_of(blanks) - first + 1);
  std::string_view digits = s;
  if (!digits.empty() && (digits[0] == '+' || digits[0] == '-')) digits.remove_prefix(1);
  if (digits.empty() || !(std::isdigit(static_cast<unsigned char>(digits[0])) || digits[0] == '.')) return {};
  return s[0] == '+' ? digits : s;
}

template <class T>
bool parse_whole(std::string_view s, T& out) {
  auto res = std::from_chars(s.data(), s.data() + s.size(), out);
  return res.ec == std::errc() && res.ptr == s.data() + s.size();
}

Value from_string(const Value& from, Type to) {
  const std::string& text = *from.get_if<std::string>();
  if (to == Type::Bool) {
    if (text == "true") return true;
    if (text == "false") return false;
    fail(from, to);
  }
  if (to == Type::Object) fail(from, to);
  std::string_view body = number_body(text);
  if (body.empty()) fail(from, to, "not a number");
  if (to == Type::Int) {
    int i = 0;
    if (parse_whole(body, i)) return i;
  }
  double d = 0;
  if (!parse_whole(body, d)) fail(from, to, "not a number");
  if (to == Type::Int) return to_int(d, from);
  if (to == Type::Float) return static_cast<float>(d);
  return d;
}

Value from_number(const Value& from, Type to) {
  switch (to) {
    case Type::Int:
      if (const auto* i = from.get_if<int>()) return *i;
      return to_int(as_double(from), from);
    case Type::Float: return static_cast<float>(as_double(from));
    case Type::Double: return as_double(from);
    case Type::String:
      if (const auto* i = from.get_if<int>()) return std::to_string(*i);
      if (const auto* f = from.get_if<float>()) return number_text(*f);
      return number_text(*from.get_if<double>());
    case Type::Bool:
    case Type::Object: break;
  }
  fail(from, to);
}

}  // namespace

const char* to_string(Type type) {
  switch (type) {
    case Type::Int: return "int";
    case Type::Float: return "float";
    case Type::Double: return "double";
    case Type::Bool: return "bool";
    case Type::String: return "string";
    case Type::Object: return "object";
  }
  return "?";
}

Value default_value(Type type) {
  switch (type) {
    case Type::Int: return 0;
    case Type::Float: return 0.0f;
    case Type::Double: return 0.0;
    case Type::Bool: return false;
    case Type::String: return std::string();
    case Type::Object: return Object();
  }
  return 0;
}

Value convert(const Value& value, Type to) {
  Type from = value.type();
  if (from == to) return value;
  if (is_number(from)) return from_number(value, to);
  if (from == Type::String) return from_string(value, to);
  if (from == Type::Bool && to == Type::String) return std::string(*value.get_if<bool>() ? "true" : "false");
  fail(value, to);
}

}  // namespace afp
