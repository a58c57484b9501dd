// A small JSON reader that keeps where every value sits in the text: ALICA's plan files are
// JSON, and every diagnostic about them must point at the object it is about. Numbers keep
// their spelling, so 64-bit ids (most exceed 2^53) are never rounded through a double.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gfec::alica {

struct JsonValue {
  enum class Kind { Null, Bool, Number, String, Array, Object };
  /// A member whose name an earlier member of the same object already has (RFC 8259 leaves what
  /// that means to the reader: ALICA's engine takes the first, its plan designer the last).
  struct Duplicate {
    std::size_t first = 0, second = 0;                     ///< indices in `members`
    std::uint32_t first_key_begin = 0, first_key_end = 0;  ///< the first member's name, quotes included
    std::uint32_t key_begin = 0, key_end = 0;              ///< the later member's name
  };
  Kind kind = Kind::Null;
  std::uint32_t begin = 0;  ///< byte offset of the value's first character
  std::uint32_t end = 0;    ///< one past its last character
  bool boolean = false;
  std::string text;                                        ///< String: the decoded value; Number: the spelling
  std::vector<JsonValue> items;                            ///< Array
  std::vector<std::pair<std::string, JsonValue>> members;  ///< Object, in file order (a duplicate too)
  std::vector<Duplicate> duplicates;                       ///< Object: its members named twice, in file order
  /// Set when find() returns this value, so that the reader can tell whether a member named twice
  /// is one it read (the second one changing what gfec makes of the plan) or one it ignores.
  mutable bool looked_up = false;

  bool is_object() const { return kind == Kind::Object; }
  bool is_array() const { return kind == Kind::Array; }
  bool is_string() const { return kind == Kind::String; }
  bool is_null() const { return kind == Kind::Null; }
  /// The first member `key` of an object, or null (also when this is no object).
  const JsonValue *find(std::string_view key) const;
  /// The member `key` if it is a string, else "".
  std::string string_of(std::string_view key) const;
  /// An id: an integer number (or a string of digits), as its exact decimal spelling.
  std::optional<std::string> as_id() const;
};

struct JsonError {
  std::uint32_t offset = 0;
  std::string message;
};

/// Parses one JSON document (RFC 8259). On malformed text, returns nothing and says where.
std::optional<JsonValue> parse_json(std::string_view text, JsonError &error);

/// Whether two values are the same JSON: same kind, same spelling of numbers, members in the same order.
bool same_json(const JsonValue &a, const JsonValue &b);

}  // namespace gfec::alica
