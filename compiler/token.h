// Tokens of the chart language (docs/language.md §1).
#pragma once

#include "source.h"

#include <string>
#include <string_view>

namespace gfec {

// clang-format off
enum class Tok {
  End, Ident, Int, Float, String, Duration, Verbatim,
  // keywords
  KwSfc, KwFsm, KwPlan, KwToolbox, KwInterface, KwImport, KwVar, KwConst, KwInitial, KwPlace,
  KwState, KwTransition, KwWhen, KwSuccess, KwFailure, KwPost, KwPeriod, KwActor, KwComputation,
  KwSupervisor, KwSupervise, KwEvents, KwStart, KwTerminate, KwIgnore, KwConfig, KwIn, KwOut, KwInOut,
  KwEntry, KwExit, KwTrue, KwFalse, KwRuns, KwTest,
  KwIf, KwElse, KwWhile, KwDo, KwFor, KwBreak, KwReturn,  // statements (§10)
  KwTeam,  // team machines (§11)
  // punctuation
  LBrace, RBrace, LParen, RParen, Semi, Comma, Colon, Arrow, Assign, PlusAssign, MinusAssign,
  Plus, Minus, Star, Slash, Percent, Lt, Le, Gt, Ge, EqEq, NotEq, AndAnd, OrOr, Not, Pipe, Dot,
  Error,  ///< a lexical error, already reported
};
// clang-format on

struct Token {
  Tok kind = Tok::End;
  SourceRange range;
  std::string_view text;       ///< the token as written (points into the SourceFile)
  std::string value;           ///< String: the decoded text; Verbatim: the code between %{ and %}
  double duration_ms = 0;      ///< Duration
  bool follows_error = false;  ///< a lexical error was reported just before this token
};

/// How a token kind reads in a message: "identifier", "'{'", "keyword 'sfc'".
std::string describe(Tok kind);

}  // namespace gfec
