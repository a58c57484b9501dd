#include "analysis/condition_logic.h"

#include <fmt/format.h>

#include <map>
#include <vector>
#include <string>

namespace gfec::analysis {

namespace {

constexpr std::size_t kMaxAtoms = 14;  // 2^14 rows of the truth table at most

using model::Expr;

bool is_logic(const Expr &e) {
  switch (e.kind) {
  case Expr::Kind::Bool:
  case Expr::Kind::Paren: return true;
  case Expr::Kind::Unary: return e.unary_op == UnaryOp::Not;
  case Expr::Kind::Binary:
    if (e.binary_op == BinaryOp::And || e.binary_op == BinaryOp::Or) return true;
    return (e.binary_op == BinaryOp::Eq || e.binary_op == BinaryOp::Ne) && e.args.size() == 2 &&
           e.args[0].type == model::Type::Bool && e.args[1].type == model::Type::Bool;
  default: return false;
  }
}

template <typename Tag> std::string id_text(Id<Tag> id) { return id ? std::to_string(id.index()) : "-"; }

/// What `e` names (its kind tells the table), for its key; "" for a kind that names nothing.
std::string named(const Expr &e) {
  switch (e.kind) {
  case Expr::Kind::Var: return id_text(e.var());
  case Expr::Kind::Const: return id_text(e.constant());
  case Expr::Kind::Config: return id_text(e.config());
  case Expr::Kind::Call: return id_text(e.function());
  case Expr::Kind::Elapsed:
  case Expr::Kind::Succeeded:
  case Expr::Kind::Failed:
  case Expr::Kind::TeamCount: return id_text(e.place());
  case Expr::Kind::ActionQ:
  case Expr::Kind::ActionA: return id_text(e.action());
  default: return "";
  }
}

/// A spelling of an atom that is equal for equal expressions (brackets ignored).
std::string key(const Expr &e) {
  if (e.kind == Expr::Kind::Paren && !e.args.empty()) return key(e.args[0]);
  std::string k = fmt::format("{}:{}:{}:{}:{}:{}:{}", static_cast<int>(e.kind), named(e), e.text, e.bool_value, e.ticks,
                              static_cast<int>(e.unary_op), static_cast<int>(e.binary_op));
  if (e.kind == Expr::Kind::Builtin) k += model::builtin_name(e.builtin);  // max(a, b) is not min(a, b)
  for (const auto &a : e.args) k += "(" + key(a) + ")";
  // active(P.Q) and active(P.R) are different atoms: the path is part of the spelling.
  for (model::PlaceId p : e.path) k += fmt::format(".{}", p.index());
  return k;
}

class Atoms {
public:
  bool collect(const Expr &e) {
    if (!is_logic(e)) {
      // The first expression spelled this way stands for the atom; its bit is its rank.
      atoms_.try_emplace(key(e), Atom{atoms_.size(), &e});
      return atoms_.size() <= kMaxAtoms;
    }
    for (const auto &a : e.args)
      if (!collect(a)) return false;
    return true;
  }
  std::size_t size() const { return atoms_.size(); }
  /// The atoms' expressions, by their bit in a row.
  std::vector<const Expr *> list() const {
    std::vector<const Expr *> out(atoms_.size());
    for (const auto &[k, atom] : atoms_) out[atom.bit] = atom.first;
    return out;
  }

  bool eval(const Expr &e, unsigned row) const {
    switch (e.kind) {
    case Expr::Kind::Bool: return e.bool_value;
    case Expr::Kind::Paren: return eval(e.args.at(0), row);
    case Expr::Kind::Unary:
      if (e.unary_op == UnaryOp::Not) return !eval(e.args.at(0), row);
      break;
    case Expr::Kind::Binary:
      if (e.binary_op == BinaryOp::And) return eval(e.args[0], row) && eval(e.args[1], row);
      if (e.binary_op == BinaryOp::Or) return eval(e.args[0], row) || eval(e.args[1], row);
      if (is_logic(e)) return (eval(e.args[0], row) == eval(e.args[1], row)) == (e.binary_op == BinaryOp::Eq);
      break;
    default: break;
    }
    return (row >> atoms_.at(key(e)).bit) & 1u;
  }

private:
  struct Atom {
    std::size_t bit;    ///< its bit in a row of the truth table: the order atoms were met
    const Expr *first;  ///< the first expression spelled this way
  };
  std::map<std::string, Atom> atoms_;  ///< by key(): equal spellings are one atom
};

}  // namespace

std::optional<bool> implies(const Expr *a, const Expr *b) {
  if (!b) return true;  // anything implies `true`
  Atoms atoms;
  if ((a && !atoms.collect(*a)) || !atoms.collect(*b)) return std::nullopt;
  for (unsigned row = 0; row < (1u << atoms.size()); ++row) {
    bool ha = a ? atoms.eval(*a, row) : true;
    if (ha && !atoms.eval(*b, row)) return false;
  }
  return true;
}

std::optional<bool> needs_exclusive(const Expr &e, const std::function<bool(const Expr &, const Expr &)> &exclusive) {
  Atoms atoms;
  if (!atoms.collect(e)) return std::nullopt;
  const auto list = atoms.list();
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < list.size(); ++i)
    for (std::size_t j = i + 1; j < list.size(); ++j)
      if (exclusive(*list[i], *list[j])) pairs.emplace_back(i, j);
  if (pairs.empty()) return false;
  bool holds_somewhere = false;
  for (unsigned row = 0; row < (1u << atoms.size()); ++row) {
    if (!atoms.eval(e, row)) continue;
    bool possible = true;
    for (auto [i, j] : pairs) possible = possible && !(((row >> i) & 1u) && ((row >> j) & 1u));
    if (possible) return false;
    holds_somewhere = true;
  }
  return holds_somewhere;
}

}  // namespace gfec::analysis
