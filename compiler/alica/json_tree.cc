#include "alica/json_tree.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec::alica {

const JsonValue *JsonValue::find(std::string_view key) const {
  for (const auto &m : members)
    if (m.first == key) {
      m.second.looked_up = true;
      return &m.second;
    }
  return nullptr;
}

bool same_json(const JsonValue &a, const JsonValue &b) {
  if (a.kind != b.kind || a.boolean != b.boolean || a.text != b.text || a.items.size() != b.items.size() ||
      a.members.size() != b.members.size())
    return false;
  for (std::size_t i = 0; i < a.items.size(); ++i)
    if (!same_json(a.items[i], b.items[i])) return false;
  for (std::size_t i = 0; i < a.members.size(); ++i)
    if (a.members[i].first != b.members[i].first || !same_json(a.members[i].second, b.members[i].second)) return false;
  return true;
}

std::string JsonValue::string_of(std::string_view key) const {
  const JsonValue *v = find(key);
  return v && v->is_string() ? v->text : std::string();
}

std::optional<std::string> JsonValue::as_id() const {
  std::string_view s = text;
  if (kind != Kind::Number && kind != Kind::String) return std::nullopt;
  std::size_t i = !s.empty() && s[0] == '-' ? 1 : 0;
  if (i == s.size()) return std::nullopt;
  const std::size_t first = i;
  for (; i < s.size(); ++i)
    if (s[i] < '0' || s[i] > '9') return std::nullopt;
  // ALICA's ids are 64-bit: a longer number is none, not an id that no other could equal.
  std::string_view digits = s.substr(first);
  while (digits.size() > 1 && digits[0] == '0') digits.remove_prefix(1);
  std::string_view most = first ? "9223372036854775808" : "9223372036854775807";
  if (digits.size() > most.size() || (digits.size() == most.size() && digits > most)) return std::nullopt;
  return text;
}

namespace {

/// Nesting deeper than this is refused rather than risking the stack: no plan comes close.
constexpr int kMaxDepth = 256;

class Parser {
public:
  Parser(std::string_view text, JsonError &error) : s_(text), error_(error) {}

  std::optional<JsonValue> document() {
    // Editors on Windows save UTF-8 with a byte order mark: not JSON, but harmless.
    if (s_.substr(0, 3) == "\xef\xbb\xbf") pos_ = 3;
    skip_space();
    JsonValue v;
    if (!value(v, 0)) return std::nullopt;
    skip_space();
    if (pos_ < s_.size()) return fail("unexpected text after the JSON document");
    return v;
  }

private:
  std::nullopt_t fail(std::string message) {
    if (!failed_) error_ = {static_cast<std::uint32_t>(pos_), std::move(message)};
    failed_ = true;
    return std::nullopt;
  }
  bool error(std::string message) {
    fail(std::move(message));
    return false;
  }

  void skip_space() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n' || s_[pos_] == '\r')) ++pos_;
  }

  std::string describe_here() const {
    if (pos_ >= s_.size()) return "the end of the file";
    char c = s_[pos_];
    if (c >= 0x20 && c < 0x7f) return fmt::format("'{}'", c);
    return fmt::format("byte 0x{:02x}", static_cast<unsigned char>(c));
  }

  bool literal(std::string_view word) {
    if (s_.substr(pos_, word.size()) != word) return false;
    pos_ += word.size();
    return true;
  }

  bool value(JsonValue &v, int depth) {
    if (depth > kMaxDepth) return error(fmt::format("JSON nested more than {} deep", kMaxDepth));
    v.begin = static_cast<std::uint32_t>(pos_);
    bool ok = true;
    if (pos_ >= s_.size()) return error("expected a JSON value, found the end of the file");
    char c = s_[pos_];
    if (c == '{') ok = object(v, depth);
    else if (c == '[') ok = array(v, depth);
    else if (c == '"') {
      v.kind = JsonValue::Kind::String;
      ok = string(v.text);
    } else if (c == '-' || (c >= '0' && c <= '9')) ok = number(v);
    else if (literal("true")) {
      v.kind = JsonValue::Kind::Bool;
      v.boolean = true;
    } else if (literal("false")) {
      v.kind = JsonValue::Kind::Bool;
    } else if (literal("null")) {
      v.kind = JsonValue::Kind::Null;
    } else {
      return error(fmt::format("expected a JSON value, found {}", describe_here()));
    }
    v.end = static_cast<std::uint32_t>(pos_);
    return ok;
  }

  bool object(JsonValue &v, int depth) {
    v.kind = JsonValue::Kind::Object;
    ++pos_;
    skip_space();
    if (pos_ < s_.size() && s_[pos_] == '}') {
      ++pos_;
      return true;
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> names;  // where each member's name is
    for (;;) {
      skip_space();
      if (pos_ >= s_.size() || s_[pos_] != '"')
        return error(fmt::format("expected a member name in quotes, found {}", describe_here()));
      std::string key;
      auto key_begin = static_cast<std::uint32_t>(pos_);
      if (!string(key)) return false;
      names.emplace_back(key_begin, static_cast<std::uint32_t>(pos_));
      skip_space();
      if (pos_ >= s_.size() || s_[pos_] != ':')
        return error(fmt::format("expected ':' after member \"{}\", found {}", key, describe_here()));
      ++pos_;
      skip_space();
      JsonValue member;
      if (!value(member, depth + 1)) return false;
      v.members.emplace_back(std::move(key), std::move(member));
      skip_space();
      if (pos_ < s_.size() && s_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (pos_ < s_.size() && s_[pos_] == '}') {
        ++pos_;
        find_duplicates(v, names);
        return true;
      }
      return error(fmt::format("expected ',' or '}}' in an object, found {}", describe_here()));
    }
  }

  /// The members of `v` named like an earlier one, in file order, found by sorting the names:
  /// linear-logarithmic however large the object (a plan may hold thousands of states, each an
  /// object; a hand-made file one object of a million members).
  static void find_duplicates(JsonValue &v, const std::vector<std::pair<std::uint32_t, std::uint32_t>> &names) {
    auto add = [&](std::size_t first, std::size_t second) {
      v.duplicates.push_back(
          {first, second, names[first].first, names[first].second, names[second].first, names[second].second});
    };
    const auto &m = v.members;
    if (m.size() < 2) return;
    std::vector<std::size_t> order(m.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    // Stable: among members of one name, file order, so the first of a run is the first written.
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return m[a].first < m[b].first; });
    for (std::size_t i = 1, first = order[0]; i < order.size(); ++i) {
      if (m[order[i]].first == m[first].first) add(first, order[i]);
      else first = order[i];
    }
    std::sort(v.duplicates.begin(), v.duplicates.end(),
              [](const JsonValue::Duplicate &a, const JsonValue::Duplicate &b) { return a.second < b.second; });
  }

  bool array(JsonValue &v, int depth) {
    v.kind = JsonValue::Kind::Array;
    ++pos_;
    skip_space();
    if (pos_ < s_.size() && s_[pos_] == ']') {
      ++pos_;
      return true;
    }
    for (;;) {
      skip_space();
      JsonValue item;
      if (!value(item, depth + 1)) return false;
      v.items.push_back(std::move(item));
      skip_space();
      if (pos_ < s_.size() && s_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (pos_ < s_.size() && s_[pos_] == ']') {
        ++pos_;
        return true;
      }
      return error(fmt::format("expected ',' or ']' in an array, found {}", describe_here()));
    }
  }

  bool number(JsonValue &v) {
    v.kind = JsonValue::Kind::Number;
    std::size_t start = pos_;
    if (s_[pos_] == '-') ++pos_;
    auto digits = [&] {
      std::size_t from = pos_;
      while (pos_ < s_.size() && s_[pos_] >= '0' && s_[pos_] <= '9') ++pos_;
      return pos_ > from;
    };
    if (!digits()) return error("expected digits in a number");
    if (pos_ < s_.size() && s_[pos_] == '.') {
      ++pos_;
      if (!digits()) return error("expected digits after '.' in a number");
    }
    if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) ++pos_;
      if (!digits()) return error("expected digits in a number's exponent");
    }
    v.text = std::string(s_.substr(start, pos_ - start));
    return true;
  }

  static void put_utf8(std::string &out, unsigned cp) {
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xc0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3f));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xe0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
      out += static_cast<char>(0x80 | (cp & 0x3f));
    } else {
      out += static_cast<char>(0xf0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3f));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
      out += static_cast<char>(0x80 | (cp & 0x3f));
    }
  }

  bool hex4(unsigned &cp) {
    if (pos_ + 4 > s_.size()) return error("expected four hex digits after '\\u'");
    cp = 0;
    for (int i = 0; i < 4; ++i) {
      char c = s_[pos_++];
      cp <<= 4;
      if (c >= '0' && c <= '9') cp |= static_cast<unsigned>(c - '0');
      else if (c >= 'a' && c <= 'f') cp |= static_cast<unsigned>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F') cp |= static_cast<unsigned>(c - 'A' + 10);
      else {
        --pos_;
        return error("expected four hex digits after '\\u'");
      }
    }
    return true;
  }

  bool string(std::string &out) {
    ++pos_;  // the opening quote
    for (;;) {
      if (pos_ >= s_.size()) return error("unterminated string: the file ends inside it");
      char c = s_[pos_];
      if (c == '"') {
        ++pos_;
        return true;
      }
      if (static_cast<unsigned char>(c) < 0x20)
        return error("control character inside a string (write it as an escape)");
      if (c != '\\') {
        out += c;
        ++pos_;
        continue;
      }
      ++pos_;
      if (pos_ >= s_.size()) return error("unterminated string: the file ends inside it");
      char e = s_[pos_++];
      switch (e) {
      case '"': out += '"'; break;
      case '\\': out += '\\'; break;
      case '/': out += '/'; break;
      case 'b': out += '\b'; break;
      case 'f': out += '\f'; break;
      case 'n': out += '\n'; break;
      case 'r': out += '\r'; break;
      case 't': out += '\t'; break;
      case 'u': {
        unsigned cp = 0;
        if (!hex4(cp)) return false;
        if (cp >= 0xd800 && cp < 0xdc00 && s_.substr(pos_, 2) == "\\u") {
          // Only a low surrogate completes the pair: any other escape after a high surrogate is
          // a character of its own, read on the next turn ("\ud800\u0041" keeps its 'A').
          std::size_t at = pos_;
          pos_ += 2;
          unsigned low = 0;
          if (!hex4(low)) return false;
          if (low >= 0xdc00 && low < 0xe000) cp = 0x10000 + ((cp - 0xd800) << 10) + (low - 0xdc00);
          else pos_ = at;
        }
        // A surrogate left unpaired is no character: U+FFFD, as a UTF-8 decoder writes for one,
        // rather than bytes that are not UTF-8.
        if (cp >= 0xd800 && cp < 0xe000) cp = 0xfffd;
        put_utf8(out, cp);
        break;
      }
      default: --pos_; return error(fmt::format("unknown escape '\\{}' in a string", e));
      }
    }
  }

  std::string_view s_;
  JsonError &error_;
  std::size_t pos_ = 0;
  bool failed_ = false;
};

}  // namespace

std::optional<JsonValue> parse_json(std::string_view text, JsonError &error) { return Parser(text, error).document(); }

}  // namespace gfec::alica
