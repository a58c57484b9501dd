#include "cpp_formula.h"

#include "code_writer.h"
#include "cpp_names.h"

#include <fmt/format.h>

#include <cmath>
#include <climits>

namespace gfec::cpp_backend {

namespace {

using model::Expr;
using model::Type;

// Binding strength of what an expression renders to: binary operators use precedence() (1-7).
constexpr int kUnary = 90;
constexpr int kPrimary = 100;

struct Rendered {
  std::string text;
  int prec = kPrimary;
  bool char_array = false;  ///< a bare string literal: `+` needs a std::string on one side
};

std::string float_spelling(std::string text) {
  if (text.find_first_of(".eE") == std::string::npos) text += ".0";
  return text;
}

/// A float config value as C++ converts `float x = 0.1;`: the literal is a double, rounded to
/// float. Spelling it `0.1f` would round the decimal to float directly, which differs in rare
/// cases (1.00000005960464477550 is 1.0f through a double, 1.00000012f directly); so the float
/// is computed here, from the value the model stores beside the spelling, and written in the
/// fewest digits that give it back exactly.
std::string float_value(const model::Expr &literal) {
  const float value = static_cast<float>(literal.float_value);
  if (!std::isfinite(value)) return fmt::format("static_cast<float>({})", float_spelling(literal.text.str()));
  return float_spelling(fmt::format("{}", value)) + "f";
}

/// Renders the inside of one formula lambda; `c` is the lambda's afp::ConfigView.
class Formula {
public:
  Formula(const model::Plan &plan, FormulaHelpers &helpers) : plan_(plan), helpers_(helpers) {}

  Rendered render(const Expr &e) {
    switch (e.kind) {
    case Expr::Kind::Bool: return {e.bool_value ? "true" : "false"};
    case Expr::Kind::Int: return int_literal(e.int_value);
    case Expr::Kind::Float: {
      // A `float` value (a file-level `const float`, folded) is a float in C++ too: written as
      // its double spelling it would take part in the arithmetic as a double (§4, as in C).
      std::string text = e.type == Type::Float ? float_value(e) : e.text.str();
      const int prec = text.rfind('-', 0) == 0 ? kUnary : kPrimary;
      return {std::move(text), prec};
    }
    case Expr::Kind::String: return {c_string_literal(e.text.str()), kPrimary, true};
    case Expr::Kind::Config: return {entry(e, cpp_type(e.type))};
    case Expr::Kind::Unary: return unary(e);
    case Expr::Kind::Binary: return e.type == Type::String ? join(e) : arithmetic(e);
    case Expr::Kind::Paren: {
      Rendered inner = render(e.args.at(0));
      return {"(" + inner.text + ")", kPrimary, inner.char_array};
    }
    default: break;  // calls, variables, timers: the validator keeps them out of formulas
    }
    return {"0"};
  }

  /// The formula read a config entry, so the lambda names its parameter.
  bool reads_config() const { return reads_config_; }

private:
  static Rendered int_literal(std::int32_t v) {
    // Literals are decimal (`010` is 10; C++ would read 8): written by their value, which the
    // validator parsed. -2147483648 is `-(2147483648)` in C++, a long: spell INT_MIN so that it
    // stays an int.
    if (v == INT_MIN) return {"(-2147483647 - 1)"};
    return {std::to_string(v), v < 0 ? kUnary : kPrimary};
  }

  std::string entry(const Expr &e, const char *type) {
    reads_config_ = true;
    return fmt::format("c.get<{}>({})", type, c_string_literal(name_of(e)));
  }

  const std::string &name_of(const Expr &e) const { return plan_.config.at(e.config()).name; }

  Rendered unary(const Expr &e) {
    Rendered operand = render(e.args.at(0));
    // `- -x` must not become the decrement `--x`.
    bool minus_minus = !operand.text.empty() && operand.text[0] == '-';
    if (operand.prec < kUnary || minus_minus) operand.text = "(" + operand.text + ")";
    return {spelling(e.unary_op) + operand.text, kUnary};
  }

  Rendered arithmetic(const Expr &e) {
    const int prec = precedence(e.binary_op);
    Rendered l = render(e.args.at(0));
    Rendered r = render(e.args.at(1));
    if (e.binary_op == BinaryOp::Div && e.args[0].type == Type::Int && e.args[1].type == Type::Int) {
      // C's int division, except that dividing by zero ends the actor in error, not the program.
      helpers_.divide = true;
      return {fmt::format("{}({}, {})", helpers_.divide_fn, l.text, r.text)};
    }
    // The model keeps the user's brackets as Paren nodes; these restore only what the tree
    // says (operators are left-associative).
    if (l.prec < prec) l.text = "(" + l.text + ")";
    if (r.prec <= prec) r.text = "(" + r.text + ")";
    return {fmt::format("{} {} {}", l.text, spelling(e.binary_op), r.text), prec};
  }

  /// String concatenation: numbers on either side become text, as the runtime converts them.
  Rendered join(const Expr &e) {
    const int prec = precedence(BinaryOp::Add);
    Rendered l = as_text(e.args.at(0));
    Rendered r = as_text(e.args.at(1));
    if (l.char_array && r.char_array) l.text = "std::string(" + l.text + ")";
    if (l.prec < prec) l.text = "(" + l.text + ")";
    if (r.prec <= prec) r.text = "(" + r.text + ")";
    return {fmt::format("{} + {}", l.text, r.text), prec};
  }

  Rendered as_text(const Expr &e) {
    if (e.type == Type::String) return render(e);
    const Expr &number = unbracketed(e);
    // An entry converts itself; anything computed goes through the runtime's conversion.
    if (number.kind == Expr::Kind::Config) return {entry(number, "std::string")};
    helpers_.text = true;
    return {fmt::format("{}({})", helpers_.text_fn, render(number).text)};
  }

  static const Expr &unbracketed(const Expr &e) { return e.kind == Expr::Kind::Paren ? unbracketed(e.args.at(0)) : e; }

  const model::Plan &plan_;
  FormulaHelpers &helpers_;
  bool reads_config_ = false;
};

const Expr &unbracketed(const Expr &e) { return e.kind == Expr::Kind::Paren ? unbracketed(e.args.at(0)) : e; }

/// A literal the runtime can hold as it is: `afp::in<float>(-60)` needs no lambda.
bool is_constant(const Expr &e) {
  switch (e.kind) {
  case Expr::Kind::Bool:
  case Expr::Kind::Int:
  case Expr::Kind::Float:
  case Expr::Kind::String: return true;
  case Expr::Kind::Unary: {
    const Expr &operand = e.args.at(0);
    return (operand.kind == Expr::Kind::Int || operand.kind == Expr::Kind::Float) &&
           operand.text.view().rfind('-', 0) != 0;
  }
  default: return false;
  }
}

}  // namespace

std::string in_argument(const model::Plan &plan, const model::Expr &formula, model::Type param,
                        FormulaHelpers &helpers) {
  const char *type = cpp_type(param);
  const Expr &f = unbracketed(formula);
  if (f.kind == Expr::Kind::Config)
    return fmt::format("afp::in<{}>(afp::entry({}))", type, c_string_literal(plan.config.at(f.config()).name));
  Formula lambda(plan, helpers);
  Rendered body = lambda.render(f);
  if (is_constant(f)) return fmt::format("afp::in<{}>({})", type, body.text);
  return fmt::format("afp::in<{}>([](const afp::ConfigView&{}) {{ return {}; }})", type,
                     lambda.reads_config() ? " c" : "", body.text);
}

std::string out_argument(const model::Plan &plan, const model::Expr &entry, model::Type param) {
  const Expr &e = unbracketed(entry);
  return fmt::format("afp::out<{}>({})", cpp_type(param), c_string_literal(plan.config.at(e.config()).name));
}

std::string initial_value(const model::Expr &literal, model::Type type) {
  switch (type) {
  case Type::Bool: return literal.bool_value ? "afp::Value(true)" : "afp::Value(false)";
  case Type::Int:
    return fmt::format("afp::Value({})", literal.text == "-2147483648" ? "-2147483647 - 1" : literal.text.c_str());
  case Type::Float: return fmt::format("afp::Value({})", float_value(literal));
  case Type::Double: return fmt::format("afp::Value({})", float_spelling(literal.text.str()));
  case Type::String: return fmt::format("afp::Value({})", c_string_literal(literal.text.str()));
  default: break;
  }
  return afp_type(type);  // objects have no literal: declared by type
}

}  // namespace gfec::cpp_backend
