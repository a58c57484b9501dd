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

namespace {

/// The log of one tick of a chart whose initial place runs `action`, with `vars` declared.
std::string one_tick(const std::string &action, const std::string &vars) {
  auto c =
      compile("sfc E {\n" + vars + "\n  initial place A { " + action + " }\n}\n", "interface Bot { void I(int v); }");
  ScriptedEnv env(*c);
  interp::RenderOptions explained;
  explained.explain = true;  // the `set` lines
  return run_log(*c, env, 1, explained);
}

}  // namespace

TEST_CASE("interpreter expressions: sized integers are exact and stop the run where a value does not fit") {
  // In range: each type computes and prints its values whole (uint64 above INT64_MAX too).
  CHECK(one_tick("a = a + 1; b = b - 1; c = c * 2; d = d + 1;",
                 "var int8 a = 126; var uint8 b = 1; var int64 c = 900000000000000000; var uint64 d = 0;")
            .find("set a = 127\nset b = 0\nset c = 1800000000000000000\nset d = 1\n") != std::string::npos);
  struct Case {
    const char *vars, *action, *error;
  };
  const Case cases[] = {
      {"var int8 n = 127;", "n = n + 1;", "int8 overflow: 127 + 1 does not fit in 'int8'"},
      {"var int16 n = -32768;", "n = n - 1;", "int16 overflow: -32768 - 1 does not fit in 'int16'"},
      {"var int64 n = 900000000000000000;", "n = n * 11;",
       "int64 overflow: 900000000000000000 * 11 does not fit in 'int64'"},
      {"var uint8 n = 255;", "n += 1;", "uint8 overflow: 255 + 1 does not fit in 'uint8'"},
      {"var uint16 n = 0;", "n = n - 1;", "uint16 overflow: 0 - 1 does not fit in 'uint16'"},
      {"var uint32 n = 4294967295;", "n = n + 1;", "uint32 overflow: 4294967295 + 1 does not fit in 'uint32'"},
      {"var uint64 n = 0;", "n -= 1;", "uint64 overflow: 0 - 1 does not fit in 'uint64'"},
      {"var time t = 900000000000000ms;", "t = t * 20000;",
       "time overflow: 900000000000000ms * 20000 does not fit in 'time'"},
      {"var int n = 300; var int8 s;", "s = int8(n);", "int8(300): the value does not fit in 'int8'"},
      {"var double d = -0.5; var uint8 s;", "s = uint8(d - 0.5);", "uint8(-1): the value does not fit in 'uint8'"},
  };
  for (const Case &k : cases) {
    INFO(k.vars << " " << k.action);
    const std::string log = one_tick(k.action, k.vars);
    CHECK(log.find(k.error) != std::string::npos);
    CHECK(log.find("[runtime]") != std::string::npos);
  }
}

TEST_CASE("interpreter expressions: conversions round floating values to nearest, ties away from zero") {
  CHECK(one_tick("a = int16(d); b = int16(-d); c = int8(e); t = time(a) * 3; n = int(t);",
                 "var double d = 2.5; var float e = 1.49; var int16 a; var int16 b; var int8 c; var time t; var int n;")
            .find("set a = 3\nset b = -3\nset c = 1\nset t = T#9ms\nset n = 9\n") != std::string::npos);
}
