#include "iec/st_lexer.h"
#include "iec/iec_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

namespace gfec::iec {

namespace {

bool is_ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

class StLexer {
public:
  StLexer(std::string_view text, const FragmentPlace &place, Diagnostics &diag)
      : t_(text), place_(place), diag_(diag) {}

  std::vector<StToken> run() {
    std::vector<StToken> out;
    if (t_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;  // a UTF-8 byte-order mark, as editors on Windows write
    for (;;) {
      skip_blanks();
      StToken tok;
      tok.begin = static_cast<std::uint32_t>(i_);
      if (i_ >= t_.size()) {
        tok.kind = StTok::End;
        tok.end = tok.begin;
        out.push_back(tok);
        return out;
      }
      lex_one(tok);
      tok.end = static_cast<std::uint32_t>(i_);
      tok.text = t_.substr(tok.begin, tok.end - tok.begin);
      out.push_back(tok);
    }
  }

private:
  char at(std::size_t k) const { return k < t_.size() ? t_[k] : '\0'; }

  void error(std::size_t b, std::size_t e, std::string message) {
    b = std::min(b, t_.size());
    e = std::min(std::max(b, e), t_.size());
    diag_.error(place_.range(static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(e)), ErrorKind::Syntax,
                std::move(message));
  }

  void skip_blanks() {
    for (;;) {
      char c = at(i_);
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
        ++i_;
      } else if (c == '(' && at(i_ + 1) == '*') {
        skip_comment(i_, "*)", "a comment '(*' that is never closed");
      } else if (c == '/' && at(i_ + 1) == '*') {
        skip_comment(i_, "*/", "a comment '/*' that is never closed");
      } else if (c == '/' && at(i_ + 1) == '/') {
        while (i_ < t_.size() && t_[i_] != '\n') ++i_;
      } else if (c == '{' && at(i_ + 1) == '{') {
        // Beremiz's inline C, `{{ code }}`: run as written by Beremiz's runtime, which gfec's
        // engine cannot, so reported rather than skipped as a pragma is.
        const std::size_t start = i_;
        skip_comment(i_, "}}", "inline C code '{{' that is never closed");
        diag_.error(place_.range(static_cast<std::uint32_t>(start), static_cast<std::uint32_t>(start + 2)),
                    ErrorKind::NotSupported,
                    "inline C code ('{{ ... }}', a Beremiz extension) is not supported: gfec compiles the "
                    "program's IEC text");
      } else if (c == '{') {
        skip_comment(i_, "}", "a pragma '{' that is never closed");
      } else {
        return;
      }
    }
  }

  void skip_comment(std::size_t start, std::string_view close, const char *unterminated) {
    std::size_t end = t_.find(close, start + (close.size() == 1 ? 1 : 2));
    if (end == std::string_view::npos) {
      error(start, start + (close.size() == 1 ? 1 : 2), unterminated);
      i_ = t_.size();
    } else {
      i_ = end + close.size();
    }
  }

  /// Digits of `base` with `_` between them, from i_; false when there are none.
  bool digits(int base, long long &value, bool &overflow) {
    std::size_t start = i_;
    for (;;) {
      char c = at(i_);
      int d = -1;
      if (is_digit(c)) d = c - '0';
      else if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
      else if (c >= 'A' && c <= 'F') d = c - 'A' + 10;
      if (d >= 0 && d < base) {
        if (value > (std::numeric_limits<long long>::max() - d) / base) overflow = true;
        else value = value * base + d;
        ++i_;
      } else if (c == '_' && i_ > start) {
        ++i_;
      } else {
        break;
      }
    }
    return i_ > start;
  }

  /// A number at i_: an integer (`1_000`, `16#FF`) or a REAL (`1.5`, `2.0E-3`).
  void number(StToken &tok) {
    std::size_t start = i_;
    long long v = 0;
    bool overflow = false;
    digits(10, v, overflow);
    if (at(i_) == '#') {
      long long base = v;
      if (overflow || (base != 2 && base != 8 && base != 16)) {
        ++i_;
        while (is_ident_char(at(i_))) ++i_;
        error(start, i_, "an IEC based integer is 2#..., 8#... or 16#...");
        tok.kind = StTok::Int;
        return;
      }
      ++i_;
      long long value = 0;
      bool of = false;
      if (!digits(static_cast<int>(base), value, of)) error(start, i_, "a based integer without digits");
      if (is_ident_char(at(i_))) {
        while (is_ident_char(at(i_))) ++i_;
        error(start, i_, fmt::format("'{}' is not a base-{} integer", t_.substr(start, i_ - start), base));
      }
      tok.kind = StTok::Int;
      tok.int_value = value;
      tok.overflow = of;
      return;
    }
    bool real = false;
    if (at(i_) == '.' && is_digit(at(i_ + 1))) {
      real = true;
      ++i_;
      long long ignored = 0;
      bool of = false;
      digits(10, ignored, of);
    }
    if ((at(i_) == 'e' || at(i_) == 'E') &&
        (is_digit(at(i_ + 1)) || ((at(i_ + 1) == '+' || at(i_ + 1) == '-') && is_digit(at(i_ + 2))))) {
      real = true;
      i_ += is_digit(at(i_ + 1)) ? 1 : 2;
      long long ignored = 0;
      bool of = false;
      digits(10, ignored, of);
    }
    tok.kind = real ? StTok::Real : StTok::Int;
    tok.int_value = v;
    tok.overflow = overflow;
    if (is_ident_char(at(i_))) {
      std::size_t b = i_;
      while (is_ident_char(at(i_))) ++i_;
      error(b, i_, fmt::format("'{}' after a number", t_.substr(b, i_ - b)));
    }
  }

  /// The duration after `T#` at i_: `1d2h3m4s5ms`, `1.5s`, `-2s`, underscores between parts.
  void duration(StToken &tok, std::size_t start) {
    bool negative = false;
    if (at(i_) == '-') {
      negative = true;
      ++i_;
    } else if (at(i_) == '+') {
      ++i_;
    }
    double ms = 0;
    int parts = 0;
    for (;;) {
      if (at(i_) == '_' && parts > 0) ++i_;
      if (!is_digit(at(i_))) break;
      std::size_t b = i_;
      while (is_digit(at(i_)) || at(i_) == '_') ++i_;
      if (at(i_) == '.' && is_digit(at(i_ + 1))) {
        ++i_;
        while (is_digit(at(i_)) || at(i_) == '_') ++i_;
      }
      std::string num;
      for (std::size_t k = b; k < i_; ++k)
        if (t_[k] != '_') num += t_[k];
      double n = std::strtod(num.c_str(), nullptr);
      std::size_t u = i_;
      while (std::isalpha(static_cast<unsigned char>(at(i_)))) ++i_;
      std::string unit = upper(t_.substr(u, i_ - u));
      double scale = 0;
      if (unit == "D") scale = 86400000.0;
      else if (unit == "H") scale = 3600000.0;
      else if (unit == "M") scale = 60000.0;
      else if (unit == "S") scale = 1000.0;
      else if (unit == "MS") scale = 1.0;
      else if (unit == "US") scale = 0.001;
      else if (unit == "NS") scale = 0.000001;
      else {
        error(u, i_ == u ? u + 1 : i_,
              fmt::format("a TIME literal's unit is d, h, m, s, ms, us or ns, not '{}'", t_.substr(u, i_ - u)));
        tok.kind = StTok::Time;
        return;
      }
      ms += n * scale;
      ++parts;
    }
    if (parts == 0) error(start, i_ > start ? i_ : start + 1, "a TIME literal without a duration: 'T#1s', 'T#250ms'");
    tok.kind = StTok::Time;
    tok.ms = negative ? -ms : ms;
  }

  void identifier(StToken &tok) {
    std::size_t start = i_;
    while (is_ident_char(at(i_))) ++i_;
    tok.kind = StTok::Ident;
    if (at(i_) != '#') return;
    std::string prefix = upper(t_.substr(start, i_ - start));
    ++i_;  // '#'
    if (prefix == "T" || prefix == "TIME" || prefix == "LT" || prefix == "LTIME") {
      duration(tok, start);
      return;
    }
    static const char *const kInts[] = {"SINT",  "INT",   "DINT", "LINT", "USINT", "UINT",
                                        "UDINT", "ULINT", "BYTE", "WORD", "DWORD", "LWORD"};
    bool integer = false;
    for (const char *k : kInts) integer = integer || prefix == k;
    bool real = prefix == "REAL" || prefix == "LREAL";
    if ((integer || real) && (is_digit(at(i_)) || ((at(i_) == '-' || at(i_) == '+') && is_digit(at(i_ + 1))))) {
      bool neg = at(i_) == '-';
      if (!is_digit(at(i_))) ++i_;
      number(tok);
      if (integer && tok.kind == StTok::Real)
        error(start, i_, fmt::format("'{}' is an integer type: its literal has no fraction", prefix));
      if (real) tok.kind = StTok::Real;
      if (neg) tok.int_value = -tok.int_value;
      return;
    }
    // Another typed literal (BOOL#1, TOD#..., D#..., STRING#'...'): its text, for a located
    // "not supported yet".
    if (at(i_) == '\'' || at(i_) == '"') {
      string_literal(tok);
    } else {
      while (is_ident_char(at(i_)) || at(i_) == '-' || at(i_) == ':' || at(i_) == '.' ||
             ((at(i_) == '+') && i_ > start))
        ++i_;
    }
    tok.kind = StTok::Typed;
  }

  void string_literal(StToken &tok) {
    std::size_t start = i_;
    char q = t_[i_++];
    while (i_ < t_.size() && t_[i_] != q && t_[i_] != '\n') {
      if (t_[i_] == '$') ++i_;
      ++i_;
    }
    if (i_ >= t_.size() || t_[i_] != q) {
      error(start, start + 1, "a string without its closing quote");
    } else {
      ++i_;
    }
    tok.kind = StTok::String;
  }

  void lex_one(StToken &tok) {
    char c = t_[i_];
    char n = at(i_ + 1);
    if (is_ident_start(c)) return identifier(tok);
    if (is_digit(c)) return number(tok);
    if (c == '\'' || c == '"') return string_literal(tok);
    if (c == '%') {
      ++i_;
      while (is_ident_char(at(i_)) || at(i_) == '.' || at(i_) == '*') ++i_;
      tok.kind = StTok::Direct;
      return;
    }
    auto two = [&](StTok k) {
      i_ += 2;
      tok.kind = k;
    };
    auto one = [&](StTok k) {
      i_ += 1;
      tok.kind = k;
    };
    switch (c) {
    case ':': return n == '=' ? two(StTok::Assign) : one(StTok::Colon);
    case '=': return n == '>' ? two(StTok::Arrow) : n == '=' ? two(StTok::EqEq) : one(StTok::Eq);
    case '<': return n == '>' ? two(StTok::Ne) : n == '=' ? two(StTok::Le) : one(StTok::Lt);
    case '>': return n == '=' ? two(StTok::Ge) : one(StTok::Gt);
    case '!': return n == '=' ? two(StTok::BangEq) : one(StTok::Other);
    case '*': return n == '*' ? two(StTok::Power) : one(StTok::Star);
    case '.': return n == '.' ? two(StTok::DotDot) : one(StTok::Dot);
    case ';': return one(StTok::Semi);
    case ',': return one(StTok::Comma);
    case '(': return one(StTok::LParen);
    case ')': return one(StTok::RParen);
    case '[': return one(StTok::LBracket);
    case ']': return one(StTok::RBracket);
    case '+': return one(StTok::Plus);
    case '-': return one(StTok::Minus);
    case '/': return one(StTok::Slash);
    case '&': return one(StTok::Amp);
    case '^': return one(StTok::Caret);
    default: break;
    }
    // One character that starts no token: a whole UTF-8 sequence, so the message quotes it whole.
    std::size_t len = 1;
    unsigned char u = static_cast<unsigned char>(c);
    if (u >= 0xC0) len = u >= 0xF0 ? 4 : u >= 0xE0 ? 3 : 2;
    i_ = std::min(t_.size(), i_ + len);
    tok.kind = StTok::Other;
  }

  std::string_view t_;
  const FragmentPlace &place_;
  Diagnostics &diag_;
  std::size_t i_ = 0;
};

}  // namespace

std::vector<StToken> lex_st(std::string_view text, const FragmentPlace &place, Diagnostics &diag) {
  return StLexer(text, place, diag).run();
}

bool is_keyword(const StToken &t, std::string_view keyword) {
  if (t.kind != StTok::Ident || t.text.size() != keyword.size()) return false;
  for (std::size_t i = 0; i < keyword.size(); ++i)
    if (std::toupper(static_cast<unsigned char>(t.text[i])) != keyword[i]) return false;
  return true;
}

}  // namespace gfec::iec
