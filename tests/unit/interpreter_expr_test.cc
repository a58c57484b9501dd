// The reference interpreter's expressions: C's types and conversions, evaluation order, and
// undefined behaviour reported where it happens instead of given a meaning.
#include "interpreter_support.h"

using namespace gfec;
using test::compile;
using test::run_log;
using test::ScriptedEnv;

namespace {

/// The arguments the chart's one action logs on its first tick.
std::string first_tick_calls(const std::string &action, const std::string &vars = "",
                             const std::string &iface = "interface Bot { void I(int v); void F(float v); "
                                                        "void D(double v); void B(bool v); float Sf(); int Si(); }") {
  auto c = compile("sfc E {\n" + vars + "\n  initial place A { " + action + " }\n}\n", iface);
  ScriptedEnv env(*c);
  env.script("Sf", {0.1}).script("Si", {7});
  std::string log = run_log(*c, env, 1);
  // Only the calls: drop "tick 1" and the "av" line.
  std::string calls;
  for (std::size_t at = 0, nl; (nl = log.find('\n', at)) != std::string::npos; at = nl + 1)
    if (log.compare(at, 5, "call ") == 0 || log.find("error", at) < nl) calls += log.substr(at, nl - at + 1);
  return calls;
}

}  // namespace

TEST_CASE("interpreter expressions: ints are C's 32-bit ints, truncating") {
  CHECK(first_tick_calls("I(7 / 2); I(-7 / 2); I(-7 % 3); I(7 % -3); I(2 + 3 * 4);") ==
        "call I(3)\ncall I(-3)\ncall I(-1)\ncall I(1)\ncall I(14)\n");
}

TEST_CASE("interpreter expressions: usual arithmetic conversions, literals are double") {
  // 0.1 is a double literal: F's argument is the double product rounded once to float.
  CHECK(first_tick_calls("F(Sf()); D(Sf()); D(0.1); I(Si() / 2 * 2.5); F(1 / 3); D(1.0 / 3);") ==
        "call Sf() = 0.100000001\ncall F(0.100000001)\n"
        "call Sf() = 0.100000001\ncall D(0.10000000149011612)\n"
        "call D(0.10000000000000001)\n"
        "call Si() = 7\ncall I(7)\n"
        "call F(0)\n"
        "call D(0.33333333333333331)\n");
}

TEST_CASE("interpreter expressions: float arithmetic rounds to float after each operation") {
  CHECK(first_tick_calls("x = Sf(); x = x * x; D(x); y = 0.1; y = y * y; D(y);", "var float x; var double y;") ==
        "call Sf() = 0.100000001\ncall D(0.010000000707805157)\ncall D(0.010000000000000002)\n");
}

TEST_CASE("interpreter expressions: a const float is a float") {
  CHECK(first_tick_calls("D(K);", "const float K = 0.1;") == "call D(0.10000000149011612)\n");
}

TEST_CASE("interpreter expressions: && and || short-circuit, other operands go left to right") {
  auto c = compile(R"(
sfc E {
  initial place A;
  place B;
  A -> B when (P(1) && P(2)) || (Q(3) + Q(4) > Q(5));
}
)",
                   "interface Bot { bool P(int n); int Q(int n); }");
  ScriptedEnv env(*c);
  env.script("P", {0, 1}).script("Q", {1});
  CHECK(run_log(*c, env, 2) == "tick 1\ncall P(1) = false\ncall Q(3) = 1\ncall Q(4) = 1\ncall Q(5) = 1\nav 0 1\n"
                               "tick 2\nav 0 1\n");
  ScriptedEnv yes(*c);
  yes.script("P", {1});
  CHECK(run_log(*c, yes, 1) == "tick 1\ncall P(1) = true\ncall P(2) = true\nav 0 1\n");
}

TEST_CASE("interpreter expressions: undefined behaviour stops the run where it happens") {
  CHECK(first_tick_calls("n = n * 65536; I(n);", "var int n = 65536;") ==
        "t.sfc:4:25: error: int overflow: 65536 * 65536 (undefined behaviour in C) during tick 1 [runtime]\n");
  CHECK(first_tick_calls("I(Si() / n);", "var int n = 0;") ==
        "call Si() = 7\n"
        "t.sfc:4:23: error: division by zero (undefined behaviour in C) during tick 1 [runtime]\n");
  // (A constant 3e9 is refused at compile time: validate, "hardening" tests.)
  CHECK(first_tick_calls("n = Si() * 5e8; I(n);", "var int n;") ==
        "call Si() = 7\n"
        "t.sfc:4:21: error: 3500000000 does not fit in an int (undefined behaviour in C) during tick 1 [runtime]\n");
}
