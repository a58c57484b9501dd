// The standard functions abs, min, max, limit, sel and mux (docs/language.md §4, "Standard
// functions"): the validator's typing and errors, constant folding, the interpreter's values and
// order of evaluation, and the ST reader's IEC spellings (positional and formal inputs).
#include "iec/st_fragment.h"
#include "interpreter_support.h"
#include "validate_fixture.h"

#include <catch2/catch.hpp>

#include <deque>
#include <string>

using namespace gfec;
using test::compile;
using test::kBot;
using test::run_log;
using test::ScriptedEnv;
using test::Validated;

namespace {

/// The diagnostics of a chart whose one place runs `action`, with `vars` declared.
std::string errors_of(const std::string &vars, const std::string &action) {
  Validated r({{"t.sfc", "import \"bot.iface\";\nsfc S {\n  period 10ms;\n" + vars + "\n  initial place A { " + action +
                             " }\n}\n"},
               {"bot.iface", kBot}});
  return r.text();
}

/// The calls (and a run-time error) of the chart's first tick.
std::string first_tick(const std::string &action, const std::string &vars = "") {
  auto c = compile("sfc E {\n  period 10ms;\n" + vars + "\n  initial place A { " + action + " }\n}\n",
                   "interface Bot { void I(int v); void F(float v); void D(double v); void B(bool v); int Si(); "
                   "int Sj(); bool Sb(); }");
  ScriptedEnv env(*c);
  env.script("Si", {7}).script("Sj", {-3}).script("Sb", {1});
  std::string log = run_log(*c, env, 1);
  std::string calls;
  for (std::size_t at = 0, nl; (nl = log.find('\n', at)) != std::string::npos; at = nl + 1)
    if (log.compare(at, 5, "call ") == 0 || log.find("error", at) < nl) calls += log.substr(at, nl - at + 1);
  return calls;
}

/// An ST expression as the chart's call it becomes ("max(a, b)"), or the error it gives.
std::string st_call(const std::string &text) {
  std::deque<std::string> strings;
  Diagnostics diag;
  ast::ExprPtr e = iec::parse_st_expression(text, iec::FragmentPlace::at(0, 0), strings, diag);
  if (diag.has_errors()) return diag.all().at(0).message;
  if (!e || e->kind != ast::Expr::Kind::Call) return "?";
  std::string out = std::string(e->name.text) + "(";
  for (std::size_t i = 0; i < e->args.size(); ++i) {
    const ast::Expr &a = *e->args[i];
    out += (i ? ", " : "") + (a.kind == ast::Expr::Kind::Name ? std::string(a.name.text) : std::string(a.text()));
  }
  return out + ")";
}

}  // namespace

TEST_CASE("standard functions: the ST reader's IEC spellings", "[standard][iec]") {
  CHECK(st_call("MAX(a, b, 3)") == "max(a, b, 3)");
  CHECK(st_call("Abs(x)") == "abs(x)");
  // Formal inputs in any order go where the function takes them.
  CHECK(st_call("LIMIT(MX := 9, IN := x, MN := 0)") == "limit(0, x, 9)");
  CHECK(st_call("sel(IN1 := b, G := g, IN0 := a)") == "sel(g, a, b)");
  CHECK(st_call("MUX(K := k, IN0 := a, IN2 := c, IN1 := b)") == "mux(k, a, b, c)");
  CHECK(st_call("MIN(IN2 := b, IN1 := a)") == "min(a, b)");
  CHECK(st_call("LIMIT(MN := 0, x, 9)") == "the call of 'LIMIT' mixes formal ('IN := x') and positional arguments");
  CHECK(st_call("SEL(G := g, IN2 := a)") == "'SEL' has no input 'IN2' (its inputs: G, IN0, IN1)");
  CHECK(st_call("MAX(IN1 := a, IN1 := b)") == "input 'IN1' of 'MAX' is given twice");
  CHECK(st_call("MAX(IN1 := a, IN3 := b)") == "the call of 'MAX' leaves out an input (its inputs: IN1, IN2, ...)");
  CHECK(st_call("ABS(EN := go, IN := x)") == "'EN' of 'ABS' is not supported yet");
  // The other standard functions stay unread.
  CHECK(st_call("CONCAT(a, b)") ==
        "calling 'CONCAT' is not supported yet: gfec reads no functions or function blocks in structured text");
}

TEST_CASE("standard functions: values, and every operand once, in order", "[standard]") {
  CHECK(first_tick("I(max(Si(), Sj())); I(min(Sj(), Si(), 2)); I(limit(0, Sj(), 5)); I(abs(Sj()));") ==
        "call Si() = 7\ncall Sj() = -3\ncall I(7)\n"
        "call Sj() = -3\ncall Si() = 7\ncall I(-3)\n"
        "call Sj() = -3\ncall I(0)\n"
        "call Sj() = -3\ncall I(3)\n");
  // sel and mux evaluate every value, not only the one they choose (they are functions).
  CHECK(first_tick("I(sel(Sb(), Si(), Sj())); I(mux(2, Si(), Sj(), 9)); I(mux(3, 1, 2, 3)); I(mux(-1, 1, 2));") ==
        "call Sb() = true\ncall Si() = 7\ncall Sj() = -3\ncall I(-3)\n"
        "call Si() = 7\ncall Sj() = -3\ncall I(9)\n"
        "call I(0)\ncall I(0)\n");
  // The values mix as `a + b` would: an int and a double give a double.
  CHECK(first_tick("D(max(Si(), 7.5)); F(abs(-1.5)); B(mux(1, false, Sb()));", "") ==
        "call Si() = 7\ncall D(7.5)\ncall F(1.5)\ncall Sb() = true\ncall B(true)\n");
  // limit with its lowest above its highest gives the lowest, as MatIEC's LIMIT does.
  CHECK(first_tick("I(limit(10, Si(), 5)); I(limit(10, 20, 5));") == "call Si() = 7\ncall I(10)\ncall I(5)\n");
}

TEST_CASE("standard functions: abs of a type's lowest value stops the run", "[standard]") {
  CHECK(first_tick("n = abs(n);", "  var int8 n = -128;") ==
        "t.sfc:5:25: error: int8 overflow: abs(-128) does not fit in 'int8' during tick 1 [runtime]\n");
  CHECK(first_tick("n = abs(n - 1);", "  var int n = -2147483647;") ==
        "t.sfc:5:25: error: int overflow: abs(-2147483648) (undefined behaviour in C) during tick 1 [runtime]\n");
}

TEST_CASE("standard functions: constants fold", "[standard]") {
  CHECK(errors_of("  const int K = max(1, 7, 3) + abs(-2);\n  const int8 M = abs(int8(-128));", "Count();") ==
        "t.sfc:5:18: error: integer overflow in constant expression [not-constant]\n"
        "   const int8 M = abs(int8(-128));\n"
        "                  ^~~~~~~~~~~~~~~\n");
}

TEST_CASE("standard functions: wrong calls are located errors", "[standard]") {
  CHECK(errors_of("  var int n = 0;\n  var bool b = false;\n  var int16 s = 0;\n  var uint16 u = 0;",
                  "n = max(n); n = abs(b); n = sel(n, 1, 2); n = mux(1.5, 1, 2); n = limit(1, 2);\n"
                  "    s = max(s, u); n = min(n, b); max(n, 1); n = int(abs(s, s));") ==
        R"--(t.sfc:8:25: error: 'max' takes two or more values (have 1) [argument-count]
   initial place A { n = max(n); n = abs(b); n = sel(n, 1, 2); n = mux(1.5, 1, 2); n = limit(1, 2);
                         ^~~~~~
t.sfc:8:41: error: 'abs' takes a number, not 'bool' [type-mismatch]
   initial place A { n = max(n); n = abs(b); n = sel(n, 1, 2); n = mux(1.5, 1, 2); n = limit(1, 2);
                                         ^
t.sfc:8:53: error: the selector of 'sel' must be bool, not 'int' [type-mismatch]
   initial place A { n = max(n); n = abs(b); n = sel(n, 1, 2); n = mux(1.5, 1, 2); n = limit(1, 2);
                                                     ^
t.sfc:8:71: error: the selector of 'mux' must be an integer, not 'double' [type-mismatch]
   initial place A { n = max(n); n = abs(b); n = sel(n, 1, 2); n = mux(1.5, 1, 2); n = limit(1, 2);
                                                                       ^~~
t.sfc:8:87: error: 'limit' takes three values: the lowest, the value and the highest (have 2) [argument-count]
   initial place A { n = max(n); n = abs(b); n = sel(n, 1, 2); n = mux(1.5, 1, 2); n = limit(1, 2);
                                                                                       ^~~~~~~~~~~
t.sfc:9:16: error: the values of 'max' do not mix: 'int16' and 'uint16' [type-mismatch]
     s = max(s, u); n = min(n, b); max(n, 1); n = int(abs(s, s)); }
                ^
t.sfc:9:16: note: neither 'int16' nor 'uint16' holds every value of the other; convert one, e.g. 'int16(x)'
t.sfc:9:31: error: 'min' takes numbers or times, not 'bool' [type-mismatch]
     s = max(s, u); n = min(n, b); max(n, 1); n = int(abs(s, s)); }
                               ^
t.sfc:9:35: error: 'max()' as a statement has no effect [type-mismatch]
     s = max(s, u); n = min(n, b); max(n, 1); n = int(abs(s, s)); }
                                   ^~~~~~~~~
t.sfc:9:54: error: 'abs' takes one value (have 2) [argument-count]
     s = max(s, u); n = min(n, b); max(n, 1); n = int(abs(s, s)); }
                                                      ^~~~~~~~~
)--");
}

TEST_CASE("standard functions: an interface function of the same name is called instead", "[standard]") {
  // As in C, the declared function is what the call means; the built-in stays for every chart
  // that declares none.
  auto c = compile("sfc E {\n  period 10ms;\n  initial place A { I(max(1, 2)); }\n}\n",
                   "interface Bot { void I(int v); int max(int a, int b); }");
  ScriptedEnv env(*c);
  env.script("max", {40});
  CHECK(run_log(*c, env, 1).find("call max(1, 2) = 40\ncall I(40)\n") != std::string::npos);
}
