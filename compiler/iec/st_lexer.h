// The tokens of IEC 61131-3 structured text (with the textual SFC of the standard). Keywords are
// identifiers to the lexer: the parser compares them case-insensitively (is_keyword), as IEC
// keywords are. Comments `(* *)` (not nested, as the standard says), `/* */` and `//` (IEC's
// third edition) and pragmas `{ }` are skipped.
#pragma once

#include "diagnostics.h"
#include "iec/st_fragment.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace gfec::iec {

enum class StTok : std::uint8_t {
  End,
  Ident,     ///< identifiers and keywords
  Int,       ///< `42`, `1_000`, `16#FF`, `DINT#5`: value in int_value (when it fits)
  Real,      ///< `1.5`, `1.0E3`, `REAL#1.5`
  Time,      ///< `T#1s200ms`, `TIME#5ms`: milliseconds in ms
  Typed,     ///< another typed literal (`TOD#…`, `D#…`, `STRING#…`, `BOOL#1`): not read yet
  String,    ///< `'text'` or `"text"`
  Direct,    ///< `%IX0.0`: a direct address
  Assign,    ///< :=
  Arrow,     ///< => (an output binding)
  Colon,     ///< :
  Semi,      ///< ;
  Comma,     ///< ,
  Dot,       ///< .
  DotDot,    ///< ..
  LParen,    ///< (
  RParen,    ///< )
  LBracket,  ///< [
  RBracket,  ///< ]
  Eq,        ///< =
  Ne,        ///< <>
  Lt,        ///< <
  Le,        ///< <=
  Gt,        ///< >
  Ge,        ///< >=
  Plus,      ///< +
  Minus,     ///< -
  Star,      ///< *
  Power,     ///< **
  Slash,     ///< /
  Amp,       ///< &
  Caret,     ///< ^ (dereference)
  EqEq,      ///< == (not IEC: reported, naming `=`)
  BangEq,    ///< != (not IEC: reported, naming `<>`)
  Other,     ///< any other character
};

struct StToken {
  StTok kind = StTok::End;
  std::uint32_t begin = 0, end = 0;  ///< fragment offsets
  std::string_view text;
  long long int_value = 0;
  bool overflow = false;  ///< Int: the value does not fit 64 bits
  double ms = 0;          ///< Time
};

/// The tokens of `text` up to and including End. Lexical errors (an unterminated comment or
/// string, a malformed literal) go to `diag` at file positions through `place`.
std::vector<StToken> lex_st(std::string_view text, const FragmentPlace &place, Diagnostics &diag);

/// Whether `t` is the identifier `keyword` (upper case), in any case.
bool is_keyword(const StToken &t, std::string_view keyword);

}  // namespace gfec::iec
