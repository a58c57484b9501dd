// Names in the generated C: every name the engine defines for its caller is one the naming
// policy lists (so the validator keeps interface functions off it), and a chart that uses
// tricky but legal names (the engine's internal names, its macros, the header's guard, the C
// library's functions with their own prototypes) compiles warning-free with gcc and clang, with
// the hooks and the checks, and its header as C++.
#include "../run/c_backend_support.h"
#include "naming/naming.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <regex>
#include <set>

using namespace cbt;

namespace {

/// The identifiers of the header's code (its comments left out) that begin with `prefix`.
std::set<std::string> identifiers(std::string header, const std::string &prefix) {
  for (std::size_t at; (at = header.find("/*")) != std::string::npos;) header.erase(at, header.find("*/", at) + 2 - at);
  std::set<std::string> names;
  static const std::regex word(R"(\b[A-Za-z_]\w*)");
  for (std::sregex_iterator it(header.begin(), header.end(), word), end; it != end; ++it)
    if (it->str().rfind(prefix, 0) == 0) names.insert(it->str());
  return names;
}

/// Compiles the engine with gcc and clang (-Werror) with and without the hooks and the checks
/// (and with the checks' assert off), and its header as C++ (strict and GNU, as g++ defaults).
void check_builds(const std::string &test, const std::vector<OutputFile> &files, const std::string &chart) {
  const std::string hooks = "-D" + chart + "_HOOKS", checks = "-D" + chart + "_CHECKS";
  check_compiles(test, files, "engine.c", {"", hooks + " " + checks, checks + " -DNDEBUG"});
  fs::path dir = scratch_dir(test + "_cpp");
  for (const auto &f : files) write_file(dir / f.path, f.contents);
  write_file(dir / "user.cpp", "#include \"engine.h\"\nint main() { return 0; }\n");
  for (const char *std : {"c++17", "gnu++17"}) {
    auto r =
        run_command(fmt::format("cd '{}' && g++ -std={} -Wall -Wextra -Wpedantic -Werror {} -c user.cpp -o /dev/null",
                                dir.string(), std, hooks),
                    dir / "build.log");
    INFO("g++ -std=" << std << "\n" << r.output);
    CHECK(r.status == 0);
  }
}

// An sfc with a sub-chart: interface functions, variables and parameters named like what the
// engine names itself, so that each of those has to move aside.
const char *kTrickySfc = R"(interface Tricky {
  void P_lowest();
  void P_A_init();
  void P_A_INSTANCE();
  bool ENGINE_H();
  void m();
  void add();
  void gfec_t1();
  void Motor(int P_HOOKS, float P_CHECKS, int ENGINE_H, int P_ASSERT_OFF, int ctx);
  void _lower(int _x);
}
sfc Q {
  var int P_HOOKS = 0;
  var int P_place = 1;
  initial place B { P_A_init(); P_HOOKS = P_place; }
}
sfc P {
  var int P_CHECKS = 1;
  var int P_place = 2;
  var int P_PLACE_COUNT = 3;
  var int ENGINE_H = 4;
  var float P_ASSERT_OFF = 0;
  var int P_TRANSITION_COUNT = 5;
  initial place A runs Q { P_lowest(); P_A_INSTANCE(); m(); add(); gfec_t1(); _lower(P_CHECKS); }
  place instance { Motor(1, 2.0, ENGINE_H, P_PLACE_COUNT, P_place); }
  place context;
  place place_name;
  place sort;
  A -> instance when active(A.B) && ENGINE_H() && P_ASSERT_OFF < 1.0;
  instance -> context;
  context -> place_name;
  place_name -> sort;
  sort -> A;
}
)";

// C library functions with the library's own prototypes (without --context, which would put
// the context before their parameters).
const char *kLibrary = R"(interface Lib {
  double sqrt(double x);
  int abs(int v);
  void abort();
  int isnan(double x);
  float sqrtf(float x);
}
sfc L {
  initial place A { if (isnan(sqrt(2.0)) != 0 || abs(-1) != 1) { abort(); } }
  place B;
  A -> B when sqrtf(4.0) > 1.0;
}
)";

// An fsm: its state field has the type P_place, and its success state a postcondition.
const char *kTrickyFsm = R"(interface Tricky {
  bool Done();
  void Go(int F_HOOKS);
}
fsm F {
  var int F_place = 0;
  var int F_ASSERT_OFF = 1;
  var int F_CHECKS = 2;
  var int F_TEAM_SIZE = 3;
  team 2;
  initial state Run { Go(F_place); }
  success state Ok post F_ASSERT_OFF == 1 && F_CHECKS == 2;
  Run -> Ok when Done() && F_TEAM_SIZE == 3;
}
)";

}  // namespace

TEST_CASE("c engine names: every name the engine defines for its caller is one the naming policy lists",
          "[c_backend][names]") {
  // Every feature that adds API: sub-charts, --context, --names; a team machine.
  auto sfc = compile_chart({{"t.sfc", "interface I { void f(); }\nsfc Q { initial place B; }\n"
                                      "sfc P { initial place A runs Q { f(); } place C; A -> C when active(A.B); }\n"}},
                           "t.sfc", "engine.c", true, EngineForm::Auto, "void *", true);
  auto fsm =
      compile_chart({{"t.fsm", "interface I { bool g(); }\nfsm P { team 2; initial state A; success state S post "
                               "true; A -> S when g(); }\n"}},
                    "t.fsm", "engine.c", true, EngineForm::Auto, "void *", true);
  for (const auto *c : {sfc.get(), fsm.get()}) {
    INFO(c->errors);
    REQUIRE(c->files.size() == 2);
    // The chart's places' and transitions' constants, and the sub-chart instance's names
    // (P_A_init, struct P_A, its enumerations), are not the caller's API.
    std::set<std::string> own;
    for (const auto &p : c->the_chart().places) own.insert("P_" + p.name.str());
    for (const auto &t : c->the_chart().transitions) own.insert("P_" + t.name.str());
    std::size_t api = 0;
    const auto header = std::find_if(c->files.begin(), c->files.end(), [](const OutputFile &f) {
      return f.path.size() > 2 && f.path.compare(f.path.size() - 2, 2, ".h") == 0;
    });
    REQUIRE(header != c->files.end());
    for (const std::string &name : identifiers(header->contents, "P_")) {
      if (own.count(name) || name.rfind("P_A_", 0) == 0) continue;
      INFO(name);
      CHECK(naming::engine_name("P", name) != nullptr);
      ++api;
    }
    CHECK(api >= 12);
  }
}

TEST_CASE("c engine names: tricky but legal names compile warning-free with gcc and clang, and as C++",
          "[c_backend][compile][names]") {
  for (EngineForm form : {EngineForm::Readable, EngineForm::Scalable}) {
    auto c = compile_chart({{"t.sfc", kTrickySfc}}, "t.sfc", "engine.c", true, form, "void *", true);
    INFO(c->errors);
    REQUIRE(c->files.size() == 2);
    check_builds(form == EngineForm::Readable ? "tricky_readable" : "tricky_scalable", c->files, "P");
  }
  auto f = compile_chart({{"t.fsm", kTrickyFsm}}, "t.fsm", "engine.c");
  INFO(f->errors);
  REQUIRE(f->files.size() == 2);
  check_builds("tricky_fsm", f->files, "F");
  auto lib = compile_chart({{"t.sfc", kLibrary}}, "t.sfc", "engine.c");
  INFO(lib->errors);
  REQUIRE(lib->files.size() == 2);
  CHECK(lib->errors.empty());  // no -Wlibrary-function: these are the library's prototypes
  check_builds("library", lib->files, "L");
}

TEST_CASE("c engine names: a variable named like the context's type keeps C++ reading the header",
          "[c_backend][compile][names]") {
  // The context is the struct's last field (`motor_t *ctx;`): a field `motor_t` before it would
  // change what motor_t means there, which C++ refuses.
  auto c = compile_chart({{"t.sfc", "interface I { void Go(int motor_t); }\n"
                                    "sfc P { var int motor_t = 1; initial place A { Go(motor_t); } }\n"}},
                         "t.sfc", "engine.c", true, EngineForm::Auto, "motor_t *");
  INFO(c->errors);
  REQUIRE(c->files.size() == 2);
  std::vector<OutputFile> files = c->files;
  files.push_back({"motor.h", "typedef struct motor motor_t;\n"});
  check_compiles("context_type_field", files, "engine.c", {"-include motor.h"});
  fs::path dir = scratch_dir("context_type_field_cpp");
  for (const auto &f : files) write_file(dir / f.path, f.contents);
  write_file(dir / "user.cpp", "#include \"motor.h\"\n#include \"engine.h\"\nint main() { return 0; }\n");
  auto r = run_command(
      fmt::format("cd '{}' && g++ -std=c++17 -Wall -Wextra -Wpedantic -Werror -c user.cpp -o /dev/null", dir.string()),
      dir / "build.log");
  INFO(r.output);
  CHECK(r.status == 0);
}

TEST_CASE("c engine names: a constant the C headers reserve moves aside and compiles", "[c_backend][compile][names]") {
  // A chart FLT's place MAX would be FLT_MAX, which <float.h> reserves with any '_' after it.
  auto c = compile_chart({{"t.sfc", "sfc FLT { initial place MAX; place DIG; MAX -> DIG; }\n"}}, "t.sfc", "engine.c");
  INFO(c->errors);
  REQUIRE(c->files.size() == 2);
  check_builds("float_h_constant", c->files, "FLT");
}
