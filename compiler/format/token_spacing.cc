#include "token_spacing.h"

namespace gfec::format {

bool is_unary_position(Tok previous) {
  switch (previous) {
  case Tok::Ident:
  case Tok::Int:
  case Tok::Float:
  case Tok::String:
  case Tok::Duration:
  case Tok::RParen:
  case Tok::KwTrue:
  case Tok::KwFalse: return false;
  default: return true;
  }
}

bool space_between(Tok left, bool left_unary, Tok right) {
  switch (right) {
  case Tok::Semi:
  case Tok::Comma:
  case Tok::RParen:
  case Tok::Dot:
  case Tok::Colon: return false;  // `transition Go: A -> B`, `actor a: Act()`
  default: break;
  }
  if (left == Tok::LParen || left == Tok::Dot) return false;
  if (left == Tok::LBrace && right == Tok::RBrace) return false;  // an empty block: `place C {}`
  if (left_unary) return false;                                   // `-speed`, `!(a && b)`
  // A call, and `team(S)` and the scenario tests' `state(S)` hug their bracket; `if (`, `-> (`, `&& (` do not.
  if (right == Tok::LParen) return left != Tok::Ident && left != Tok::KwState && left != Tok::KwTeam;
  return true;
}

}  // namespace gfec::format
