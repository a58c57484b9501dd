// The one constant evaluator (compiler/constant.h): C's semantics for int, float and double,
// and the values the validator stores in the model for every later stage.
#include "../run/c_backend_support.h"
#include "constant.h"
#include "support.h"
#include "validate.h"

#include <catch2/catch.hpp>

#include <cfloat>
#include <climits>
#include <cstring>
#include <string>

using namespace gfec;
using constant::Fault;
using constant::Value;
using model::Type;

namespace {

constant::Outcome bin(BinaryOp op, const Value &a, const Value &b) { return constant::binary(op, a, b); }
Value i(std::int32_t v) { return Value::of_int(v); }
Value f(float v) { return Value::of_float(v); }
Value d(double v) { return Value::of_double(v); }

/// The same float, bit for bit (0.0f and -0.0f differ).
bool same_float(double a, float b) {
  float x = static_cast<float>(a);
  return std::memcmp(&x, &b, sizeof x) == 0;
}

}  // namespace

TEST_CASE("int arithmetic is C's: truncating division, remainder with the dividend's sign", "[constant]") {
  CHECK(bin(BinaryOp::Add, i(2), i(3)).value.i == 5);
  CHECK(bin(BinaryOp::Sub, i(2), i(3)).value.i == -1);
  CHECK(bin(BinaryOp::Mul, i(-4), i(3)).value.i == -12);
  CHECK(bin(BinaryOp::Div, i(-7), i(2)).value.i == -3);
  CHECK(bin(BinaryOp::Mod, i(-7), i(2)).value.i == -1);
  CHECK(bin(BinaryOp::Mod, i(7), i(-2)).value.i == 1);
  CHECK(bin(BinaryOp::Add, i(INT_MAX - 1), i(1)).value.i == INT_MAX);
  CHECK(bin(BinaryOp::Div, i(INT_MIN), i(1)).value.i == INT_MIN);
  CHECK(bin(BinaryOp::Add, i(1), i(2)).value.type == Type::Int);
}

TEST_CASE("int overflow, INT_MIN / -1 and INT_MIN % -1 are faults, not values", "[constant]") {
  CHECK(bin(BinaryOp::Add, i(INT_MAX), i(1)).fault == Fault::IntOverflow);
  CHECK(bin(BinaryOp::Sub, i(INT_MIN), i(1)).fault == Fault::IntOverflow);
  CHECK(bin(BinaryOp::Mul, i(65536), i(65536)).fault == Fault::IntOverflow);
  CHECK(bin(BinaryOp::Mul, i(-65536), i(32768)).value.i == INT_MIN);  // exactly INT_MIN fits
  CHECK(bin(BinaryOp::Div, i(INT_MIN), i(-1)).fault == Fault::IntOverflow);
  // The remainder would be 0, but C makes INT_MIN % -1 undefined as INT_MIN / -1 is.
  CHECK(bin(BinaryOp::Mod, i(INT_MIN), i(-1)).fault == Fault::IntOverflow);
  CHECK(bin(BinaryOp::Mod, i(INT_MAX), i(-1)).value.i == 0);
  CHECK(constant::unary(UnaryOp::Neg, i(INT_MIN)).fault == Fault::IntOverflow);
  CHECK(constant::unary(UnaryOp::Neg, i(INT_MAX)).value.i == -INT_MAX);
}

TEST_CASE("division by zero is a fault for ints and floating values alike", "[constant]") {
  CHECK(bin(BinaryOp::Div, i(1), i(0)).fault == Fault::DivisionByZero);
  CHECK(bin(BinaryOp::Mod, i(1), i(0)).fault == Fault::DivisionByZero);
  CHECK(bin(BinaryOp::Div, d(1), d(0)).fault == Fault::DivisionByZero);
  CHECK(bin(BinaryOp::Div, f(1), i(0)).fault == Fault::DivisionByZero);
  CHECK(bin(BinaryOp::Div, d(0), d(-0.0)).fault == Fault::DivisionByZero);
}

TEST_CASE("float operands compute in float, rounded after every operation", "[constant]") {
  // 0.1 converted to float, times 3, in float: C gives the float nearest 0.3 (0.300000012), not
  // the double 0.30000000000000004.
  const float tenth = static_cast<float>(0.1);
  auto r = bin(BinaryOp::Mul, f(tenth), i(3));
  REQUIRE(r);
  CHECK(r.value.type == Type::Float);
  volatile float three = 3.0f;  // keep the product a float computed at run time
  CHECK(same_float(r.value.f, tenth * three));
  CHECK(r.value.f != 0.1 * 3);
  // 2^24 + 1 rounds back to 2^24 in float: (2^24 + 1) - 2^24 is 0 in float, 1 in double.
  auto big = f(16777216.0f);
  auto sum = bin(BinaryOp::Add, big, i(1));
  REQUIRE(sum);
  CHECK(sum.value.f == 16777216.0);
  CHECK(bin(BinaryOp::Sub, sum.value, big).value.f == 0);
  CHECK(bin(BinaryOp::Sub, bin(BinaryOp::Add, d(16777216.0), i(1)).value, d(16777216.0)).value.f == 1);
  // Division rounds too: 1 / 3 in float is not 1 / 3 in double.
  auto third = bin(BinaryOp::Div, f(1), f(3));
  CHECK(same_float(third.value.f, 1.0f / three));
  CHECK(third.value.f != 1.0 / 3.0);
}

TEST_CASE("the usual arithmetic conversions pick the type", "[constant]") {
  CHECK(constant::common_type(Type::Int, Type::Int) == Type::Int);
  CHECK(constant::common_type(Type::Int, Type::Float) == Type::Float);
  CHECK(constant::common_type(Type::Float, Type::Double) == Type::Double);
  CHECK(constant::common_type(Type::Double, Type::Int) == Type::Double);
  // A float meets a double as the double of its exact value: 0.1f + 0.0 is not 0.1.
  auto r = bin(BinaryOp::Add, f(static_cast<float>(0.1)), d(0));
  CHECK(r.value.type == Type::Double);
  CHECK(r.value.f == static_cast<double>(static_cast<float>(0.1)));
  CHECK(r.value.f != 0.1);
  // An int meets a float as a float: 16777217 becomes 16777216.
  CHECK(bin(BinaryOp::Add, i(16777217), f(0)).value.f == 16777216.0);
}

TEST_CASE("a floating result that is not finite is a fault", "[constant]") {
  CHECK(bin(BinaryOp::Mul, d(DBL_MAX), i(2)).fault == Fault::NotFinite);
  CHECK(bin(BinaryOp::Mul, f(FLT_MAX), i(2)).fault == Fault::NotFinite);  // in float, as C
  CHECK(bin(BinaryOp::Mul, f(FLT_MAX), d(2)).value.f == 2.0 * FLT_MAX);   // in double: fits
}

TEST_CASE("comparisons and logic", "[constant]") {
  CHECK(bin(BinaryOp::Lt, i(-1), i(0)).value.b);
  CHECK(bin(BinaryOp::Ge, i(3), d(2.5)).value.b);
  CHECK(bin(BinaryOp::Eq, i(16777217), f(16777216.0f)).value.b);  // compared in float
  CHECK_FALSE(bin(BinaryOp::Eq, i(16777217), d(16777216.0)).value.b);
  CHECK_FALSE(bin(BinaryOp::Eq, f(static_cast<float>(0.1)), d(0.1)).value.b);
  CHECK(bin(BinaryOp::Ne, Value::of_bool(true), Value::of_bool(false)).value.b);
  CHECK(bin(BinaryOp::Lt, i(1), i(2)).value.type == Type::Bool);
  CHECK_FALSE(bin(BinaryOp::And, Value::of_bool(true), Value::of_bool(false)).value.b);
  CHECK(bin(BinaryOp::Or, Value::of_bool(false), Value::of_bool(true)).value.b);
  CHECK(constant::unary(UnaryOp::Not, Value::of_bool(false)).value.b);
  CHECK(bin(BinaryOp::And, i(1), Value::of_bool(true)).fault == Fault::BadOperands);
  CHECK(bin(BinaryOp::Mod, d(5), d(2)).fault == Fault::BadOperands);  // % takes ints only
}

TEST_CASE("literals are decimal ints up to INT_MAX and finite doubles", "[constant]") {
  CHECK(constant::int_literal("42") == 42);
  CHECK(constant::int_literal("010") == 10);  // no octal
  CHECK(constant::int_literal("2147483647") == INT_MAX);
  CHECK_FALSE(constant::int_literal("2147483648"));
  CHECK_FALSE(constant::int_literal("99999999999999999999999"));
  CHECK_FALSE(constant::int_literal("0x10"));
  CHECK_FALSE(constant::int_literal(""));
  CHECK(constant::float_literal("0.1") == 0.1);
  CHECK(constant::float_literal("1e-3") == 1e-3);
  CHECK(constant::float_literal("1e308") == 1e308);
  CHECK_FALSE(constant::float_literal("1e999"));
  CHECK_FALSE(constant::float_literal("1.5x"));
}

TEST_CASE("conversions are C's: truncation, rounding, and values that do not fit", "[constant]") {
  CHECK(constant::convert(d(-0.9), Type::Int).value.i == 0);
  CHECK(constant::convert(d(2.9), Type::Int).value.i == 2);
  CHECK(constant::convert(d(-2147483648.5), Type::Int).value.i == INT_MIN);
  CHECK(constant::convert(d(3e9), Type::Int).fault == Fault::DoesNotFit);
  CHECK(constant::convert(d(2147483648.0), Type::Int).fault == Fault::DoesNotFit);
  CHECK(constant::convert(d(1e39), Type::Float).fault == Fault::DoesNotFit);
  CHECK(constant::convert(d(0.1), Type::Float).value.f == static_cast<double>(static_cast<float>(0.1)));
  CHECK(constant::convert(i(16777217), Type::Float).value.f == 16777216.0);
  CHECK(constant::convert(i(7), Type::String).value.s == "7");
  CHECK(constant::convert(f(0.5f), Type::String).value.s == "0.5");
}

TEST_CASE("floating values are spelled with the shortest digits of their type", "[constant]") {
  CHECK(constant::float_spelling(static_cast<float>(0.1) * 3.0f, Type::Float) == "0.3");
  CHECK(constant::float_spelling(static_cast<float>(0.1), Type::Double) == "0.10000000149011612");
  CHECK(constant::float_spelling(3, Type::Double) == "3.0");
  CHECK(constant::float_spelling(1e300, Type::Double) == "1e+300");
}

namespace {

struct Checked {
  test::Pipeline fe;
  model::Model &model = fe.model;
  explicit Checked(const std::string &text) : fe("t.sfc", test::files({{"t.sfc", text}})) {}
  const model::Const &constant(const std::string &name) const {
    for (const auto &c : model.consts)
      if (c.name == name) return c;
    FAIL("no constant " << name);
    return model.consts.front();
  }
};

const char *const kIface = "interface Bot { void Motor(int side, float speed); void Put(double v); }\n";

}  // namespace

TEST_CASE("the model keeps each literal's value next to its spelling", "[constant]") {
  Checked r(std::string(kIface) +
            "sfc S {\n  var int n = 010;\n  initial place P { Put(0.1); Motor(n + 7, 2.5); }\n}\n");
  REQUIRE(r.fe.text() == "");
  const auto &chart = r.model.charts.at(0);
  CHECK(chart.vars.at(0).init->int_value == 10);
  CHECK(chart.vars.at(0).init->text == "010");
  const auto &action = chart.places.at(0).action;
  CHECK(action.at(0).expr.args.at(0).float_value == 0.1);
  CHECK(action.at(0).expr.args.at(0).text == "0.1");
  const model::Expr &sum = action.at(1).expr.args.at(0);
  CHECK_FALSE(sum.folded);  // reads a var: computed on the robot
  CHECK(sum.args.at(1).int_value == 7);
}

TEST_CASE("constant expressions are folded once, with C's float rounding", "[constant]") {
  Checked r(std::string(kIface) + "const float A = 0.1;\n"
                                  "const double D = A * 3;\n"  // float arithmetic, then widened
                                  "const float BIG = 16777216;\n"
                                  "const float ZERO = BIG + 1 - BIG;\n"  // 0 in float, 1 in double
                                  "const double E = A;\n"                // the float 0.1f, not the double 0.1
                                  "const int K = (2 + 3) * 4;\n"
                                  "sfc S {\n  var int n = 0;\n  initial place P { Motor(n, (K - 1) / 2); }\n}\n");
  REQUIRE(r.fe.text() == "");
  const float tenth = static_cast<float>(0.1);
  volatile float three = 3.0f;
  CHECK(r.constant("A").value.text == "0.1");  // the user's spelling is kept
  CHECK(r.constant("D").value.float_value == static_cast<double>(tenth * three));
  CHECK(r.constant("D").value.text == "0.30000001192092896");
  CHECK(r.constant("ZERO").value.float_value == 0);
  CHECK(r.constant("E").value.float_value == static_cast<double>(tenth));
  CHECK(r.constant("K").value.int_value == 20);
  const model::Expr &arg = r.model.charts.at(0).places.at(0).action.at(0).expr.args.at(1);
  CHECK(arg.folded);
  CHECK(arg.int_value == 9);
  CHECK(arg.args.at(0).folded);  // (K - 1): the bracket carries its value too
  CHECK(arg.args.at(0).int_value == 19);
}

TEST_CASE("the C engine writes the folded values C would compute", "[constant]") {
  auto c = cbt::compile_chart(
      {{"t.sfc", std::string(kIface) + "const float A = 0.1;\n"
                                       "const double D = A * 3;\n"
                                       "const float BIG = 16777216;\n"
                                       "const float ZERO = BIG + 1 - BIG;\n"
                                       "sfc S {\n  var int n = 0;\n"
                                       "  initial place P { Motor(0, D); Motor(1, ZERO); }\n"
                                       "  place Q;\n  transition T: P -> Q when n >= 0 || n < (2 + 2);\n}\n"}},
      "t.sfc", "fold.c", false);
  REQUIRE(c->errors == "");
  REQUIRE_FALSE(c->files.empty());
  const std::string src = c->files.at(0).contents;
  // D (a double) meets a float parameter: written as the float it becomes (docs/targets.md).
  CHECK(src.find("Motor(0, 0.3f /* D */)") != std::string::npos);
  CHECK(src.find("Motor(1, 0.0f /* ZERO */)") != std::string::npos);
  // The folded `(2 + 2)` lets the writer see that the test always holds (c_expr.cc).
  CHECK(src.find("true /* always: n >= 0 || n < 4 */") != std::string::npos);
}
