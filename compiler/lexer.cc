#include "lexer.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace gfec {

namespace {

struct Keyword {
  std::string_view text;
  Tok kind;
};

const Keyword kKeywords[] = {
    {"sfc", Tok::KwSfc},
    {"fsm", Tok::KwFsm},
    {"plan", Tok::KwPlan},
    {"toolbox", Tok::KwToolbox},
    {"interface", Tok::KwInterface},
    {"import", Tok::KwImport},
    {"var", Tok::KwVar},
    {"const", Tok::KwConst},
    {"initial", Tok::KwInitial},
    {"place", Tok::KwPlace},
    {"state", Tok::KwState},
    {"transition", Tok::KwTransition},
    {"when", Tok::KwWhen},
    {"success", Tok::KwSuccess},
    {"failure", Tok::KwFailure},
    {"post", Tok::KwPost},
    {"period", Tok::KwPeriod},
    {"actor", Tok::KwActor},
    {"computation", Tok::KwComputation},
    {"supervisor", Tok::KwSupervisor},
    {"supervise", Tok::KwSupervise},
    {"events", Tok::KwEvents},
    {"start", Tok::KwStart},
    {"terminate", Tok::KwTerminate},
    {"ignore", Tok::KwIgnore},
    {"config", Tok::KwConfig},
    {"in", Tok::KwIn},
    {"out", Tok::KwOut},
    {"inout", Tok::KwInOut},
    {"entry", Tok::KwEntry},
    {"exit", Tok::KwExit},
    {"true", Tok::KwTrue},
    {"false", Tok::KwFalse},
    {"runs", Tok::KwRuns},
    {"test", Tok::KwTest},
    {"if", Tok::KwIf},
    {"else", Tok::KwElse},
    {"while", Tok::KwWhile},
    {"do", Tok::KwDo},
    {"for", Tok::KwFor},
    {"break", Tok::KwBreak},
    {"return", Tok::KwReturn},
    {"team", Tok::KwTeam},
};

}  // namespace

bool is_chart_keyword(std::string_view word) {
  for (const auto &k : kKeywords)
    if (k.text == word) return true;
  return false;
}

namespace {

bool is_ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::string describe(Tok kind) {
  for (const auto &k : kKeywords)
    if (k.kind == kind) return fmt::format("keyword '{}'", k.text);
  switch (kind) {
  case Tok::End: return "end of file";
  case Tok::Ident: return "identifier";
  case Tok::Int: return "integer";
  case Tok::Float: return "number";
  case Tok::String: return "string";
  case Tok::Duration: return "duration";
  case Tok::Verbatim: return "verbatim block";
  case Tok::LBrace: return "'{'";
  case Tok::RBrace: return "'}'";
  case Tok::LParen: return "'('";
  case Tok::RParen: return "')'";
  case Tok::Semi: return "';'";
  case Tok::Comma: return "','";
  case Tok::Colon: return "':'";
  case Tok::Arrow: return "'->'";
  case Tok::Assign: return "'='";
  case Tok::PlusAssign: return "'+='";
  case Tok::MinusAssign: return "'-='";
  case Tok::Plus: return "'+'";
  case Tok::Minus: return "'-'";
  case Tok::Star: return "'*'";
  case Tok::Slash: return "'/'";
  case Tok::Percent: return "'%'";
  case Tok::Lt: return "'<'";
  case Tok::Le: return "'<='";
  case Tok::Gt: return "'>'";
  case Tok::Ge: return "'>='";
  case Tok::EqEq: return "'=='";
  case Tok::NotEq: return "'!='";
  case Tok::AndAnd: return "'&&'";
  case Tok::OrOr: return "'||'";
  case Tok::Not: return "'!'";
  case Tok::Pipe: return "'|'";
  case Tok::Dot: return "'.'";
  default: return "token";
  }
}

Lexer::Lexer(const SourceManager &sources, FileId file, Diagnostics &diag)
    : file_(file), text_(sources.file(file).text()), diag_(diag) {
  // A UTF-8 byte-order mark, as some Windows editors write, is not part of the text.
  if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
}

Token Lexer::make(Tok kind, std::uint32_t begin) {
  Token t;
  t.kind = kind;
  t.range = {file_, begin, pos_};
  t.text = text_.substr(begin, pos_ - begin);
  return t;
}

Token Lexer::error(std::uint32_t begin, std::uint32_t end, std::string message) {
  diag_.error({file_, begin, end}, ErrorKind::Syntax, std::move(message));
  Token t = make(Tok::Error, begin);
  return t;
}

void Lexer::skip_space_and_comments() {
  for (;;) {
    char c = peek();
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (c == '/' && peek(1) == '/') {
      std::uint32_t begin = pos_;
      while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
      if (comments_) comments_->push_back({file_, begin, pos_});
    } else if (c == '/' && peek(1) == '*') {
      std::uint32_t begin = pos_;
      auto close = text_.find("*/", pos_ + 2);
      if (close == std::string_view::npos) {
        pos_ = static_cast<std::uint32_t>(text_.size());
        diag_.error({file_, begin, begin + 2}, ErrorKind::Syntax, "unterminated comment");
        return;
      }
      pos_ = static_cast<std::uint32_t>(close + 2);
      if (comments_) comments_->push_back({file_, begin, pos_});
    } else {
      return;
    }
  }
}

Token Lexer::next() {
  skip_space_and_comments();
  std::uint32_t begin = pos_;
  if (pos_ >= text_.size()) return make(Tok::End, begin);
  char c = peek();
  if (is_ident_start(c)) return word(begin);
  if (is_digit(c) || (c == '.' && is_digit(peek(1)))) return number(begin);
  if (c == '"') return string(begin);
  if (c == '%' && peek(1) == '{') return verbatim(begin);

  auto two = [&](char second, Tok both, Tok one) {
    if (peek(1) == second) {
      pos_ += 2;
      return make(both, begin);
    }
    ++pos_;
    return make(one, begin);
  };
  switch (c) {
  case '{': ++pos_; return make(Tok::LBrace, begin);
  case '}': ++pos_; return make(Tok::RBrace, begin);
  case '(': ++pos_; return make(Tok::LParen, begin);
  case ')': ++pos_; return make(Tok::RParen, begin);
  case ';': ++pos_; return make(Tok::Semi, begin);
  case ',': ++pos_; return make(Tok::Comma, begin);
  case ':': ++pos_; return make(Tok::Colon, begin);
  case '.': ++pos_; return make(Tok::Dot, begin);  // `active(P.Q)`; `.5` is a number (above)
  case '*': ++pos_; return make(Tok::Star, begin);
  case '/': ++pos_; return make(Tok::Slash, begin);
  case '%': ++pos_; return make(Tok::Percent, begin);
  case '+': return two('=', Tok::PlusAssign, Tok::Plus);
  case '-':
    if (peek(1) == '>') {
      pos_ += 2;
      return make(Tok::Arrow, begin);
    }
    return two('=', Tok::MinusAssign, Tok::Minus);
  case '<': return two('=', Tok::Le, Tok::Lt);
  case '>': return two('=', Tok::Ge, Tok::Gt);
  case '=': return two('=', Tok::EqEq, Tok::Assign);
  case '!': return two('=', Tok::NotEq, Tok::Not);
  case '&':
    if (peek(1) == '&') {
      pos_ += 2;
      return make(Tok::AndAnd, begin);
    }
    ++pos_;
    diag_.error({file_, begin, pos_}, ErrorKind::Syntax, "'&' is not an operator here; did you mean '&&'?")
        .fix({file_, begin, pos_}, "&&");
    return make(Tok::Error, begin);
  case '|': return two('|', Tok::OrOr, Tok::Pipe);
  case '`': {
    // `place`: an identifier spelled as a keyword, as --emit=chart writes an imported IEC name
    // that is one (docs/language.md §14). The token's text is the name without the backquotes.
    ++pos_;
    if (!is_ident_start(peek()))
      return error(begin, pos_, "expected an identifier after '`' (a name written as a keyword: `place`)");
    while (is_ident_char(peek())) ++pos_;
    if (peek() != '`') return error(begin, pos_, "expected '`' to close the quoted name");
    ++pos_;
    Token t = make(Tok::Ident, begin);
    t.text = text_.substr(begin + 1, pos_ - begin - 2);
    return t;
  }
  default: break;
  }
  // One whole UTF-8 sequence, so the caret and the message show a character, not a byte.
  std::uint32_t end = pos_ + 1;
  while (end < text_.size() && (static_cast<unsigned char>(text_[end]) & 0xC0) == 0x80) ++end;
  pos_ = end;
  std::string shown = std::isprint(static_cast<unsigned char>(c))
                          ? fmt::format("'{}'", c)
                          : fmt::format("byte 0x{:02x}", static_cast<unsigned char>(c));
  if (static_cast<unsigned char>(c) >= 0x80) shown = fmt::format("'{}'", text_.substr(begin, end - begin));
  return error(begin, end, fmt::format("unexpected character {}", shown));
}

Token Lexer::word(std::uint32_t begin) {
  while (is_ident_char(peek())) ++pos_;
  std::string_view w = text_.substr(begin, pos_ - begin);
  for (const auto &k : kKeywords)
    if (k.text == w) return make(k.kind, begin);
  return make(Tok::Ident, begin);
}

Token Lexer::number(std::uint32_t begin) {
  bool is_float = false;
  while (is_digit(peek())) ++pos_;
  if (peek() == '.' && is_digit(peek(1))) {
    is_float = true;
    ++pos_;
    while (is_digit(peek())) ++pos_;
  } else if (peek() == '.' && !is_ident_start(peek(1))) {
    is_float = true;  // "1." as in C
    ++pos_;
  }
  if ((peek() == 'e' || peek() == 'E') &&
      (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
    is_float = true;
    pos_ += 2;
    while (is_digit(peek())) ++pos_;
  }
  std::uint32_t number_end = pos_;
  if (is_ident_start(peek())) {
    std::uint32_t suffix_begin = pos_;
    while (is_ident_char(peek())) ++pos_;
    std::string_view suffix = text_.substr(suffix_begin, pos_ - suffix_begin);
    if (suffix == "ms" || suffix == "s") {
      double value = std::strtod(std::string(text_.substr(begin, number_end - begin)).c_str(), nullptr);
      const double ms = suffix == "s" ? value * 1000.0 : value;
      // As for numbers: a duration that overflows (1e999s) or underflows (1e-999ms, which would
      // read as 0) is an error where it is written, never infinity or nothing.
      const std::string_view written = text_.substr(begin, pos_ - begin);
      if (!std::isfinite(ms)) return error(begin, pos_, fmt::format("duration '{}' is too large", written));
      const std::string_view digits = text_.substr(begin, number_end - begin);
      if (ms == 0 && digits.find_first_of("123456789") < digits.find_first_of("eE"))
        return error(begin, pos_, fmt::format("duration '{}' is too small: it would read as 0", written));
      Token t = make(Tok::Duration, begin);
      t.duration_ms = ms;
      return t;
    }
    return error(begin, pos_,
                 fmt::format("invalid suffix '{}' on number; durations are written like 10ms or 1.5s", suffix));
  }
  Token t = make(is_float ? Tok::Float : Tok::Int, begin);
  if (!is_float && t.text.size() > 18) return error(begin, pos_, "integer literal is too large");
  return t;
}

Token Lexer::string(std::uint32_t begin) {
  ++pos_;  // opening quote
  std::string value;
  for (;;) {
    char c = peek();
    if (pos_ >= text_.size() || c == '\n' || c == '\r') {
      return error(begin, pos_, "missing terminating '\"' character");
    }
    ++pos_;
    if (c == '"') break;
    if (c != '\\') {
      value += c;
      continue;
    }
    // A backslash that ends the file escapes nothing: the string is unterminated.
    if (pos_ >= text_.size()) return error(begin, pos_, "missing terminating '\"' character");
    char e = peek();
    ++pos_;
    switch (e) {
    case 'n': value += '\n'; break;
    case 't': value += '\t'; break;
    case 'r': value += '\r'; break;
    case '0': value += '\0'; break;
    case '\\': value += '\\'; break;
    case '"': value += '"'; break;
    case '\'': value += '\''; break;
    case 'a': value += '\a'; break;
    case 'b': value += '\b'; break;
    case 'f': value += '\f'; break;
    case 'v': value += '\v'; break;
    default: {
      // Keep scanning to the closing quote so one bad escape is one error.
      std::uint32_t at = pos_ - 2;
      diag_.error({file_, at, pos_}, ErrorKind::Syntax,
                  fmt::format("unknown escape sequence '\\{}'", e == '\0' ? ' ' : e));
    }
    }
  }
  Token t = make(Tok::String, begin);
  t.value = std::move(value);
  return t;
}

Token Lexer::verbatim(std::uint32_t begin) {
  auto close = text_.find("%}", pos_ + 2);
  if (close == std::string_view::npos) {
    pos_ = static_cast<std::uint32_t>(text_.size());
    diag_.error({file_, begin, begin + 2}, ErrorKind::Syntax, "unterminated verbatim block: missing '%}'");
    return make(Tok::Error, begin);
  }
  Token t;
  t.kind = Tok::Verbatim;
  t.value = std::string(text_.substr(begin + 2, close - begin - 2));
  pos_ = static_cast<std::uint32_t>(close + 2);
  t.range = {file_, begin, pos_};
  t.text = text_.substr(begin, pos_ - begin);
  return t;
}

}  // namespace gfec
