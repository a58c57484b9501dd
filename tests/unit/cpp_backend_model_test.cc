// The cpp back end on small plans written for one point each: what the wiring says for each
// kind of formula, names that C++ or the file already uses, several toolboxes, sub-plans used
// twice or nested, and what a plan without formulas leaves out. Where the point is that the
// output compiles, it is compiled (g++, against the skeletons of its toolboxes).
#include "../run/cpp_backend_support.h"

using namespace cppt;

namespace {

const char *kToolbox = R"(
toolbox Bot {
  actor Go(in float speed) -> ARRIVED | STUCK;
  actor Say(in string text) -> SAID;
  actor Count(in int n) -> COUNTED;
  supervisor Bump() events HIT;
}
)";

/// The wiring of plan text that imports "bot.toolbox".
std::string wiring(const std::string &plan, bool line_directives = false) {
  auto c = compile({{"bot.toolbox", kToolbox}, {"p.plan", plan}}, "p.plan", "p.cpp", false, line_directives);
  INFO(c->errors);
  REQUIRE(!c->diag.has_errors());
  REQUIRE(c->files.size() == 2);
  return c->files[0].contents;
}

/// Compiles generated wiring (files named as given) with the skeletons of the toolboxes it
/// uses, written beside it (g++, kStrictFlags and -Wshadow); returns what g++ said.
std::string compiles(const std::string &test, const std::map<std::string, std::string> &files,
                     const std::string &main) {
  auto c = compile(files, main, "p.cpp");
  INFO(c->errors);
  REQUIRE(!c->diag.has_errors());
  std::vector<OutputFile> out = c->files;
  for (const auto &[name, text] : files) {
    if (fs::path(name).extension() != ".toolbox") continue;
    auto skeleton = compile(files, name, fs::path(name).stem().string() + "_toolbox.h", true);
    out.insert(out.end(), skeleton->files.begin(), skeleton->files.end());
  }
  std::string dir = write_all(test, out);
  auto r = compile_object("g++", dir, "p.cpp", {}, "-Wshadow");
  return r.exit_code == 0 ? "" : r.out;
}

}  // namespace

TEST_CASE("cpp model: each kind of formula", "[cpp_backend]") {
  std::string w = wiring(R"(
import "bot.toolbox";
const int K = -2147483647 - 1;
plan P {
  config { float v = 1.5; int n; string s = "x"; }
  start a;
  actor a: Go(v) { ARRIVED -> b; STUCK -> b; }
  actor b: Go((v)) { ARRIVED -> c; STUCK -> c; }
  actor c: Go(-0.5) { ARRIVED -> d; STUCK -> d; }
  actor d: Go(2 * (v + 1) - n / 4) { ARRIVED -> e; STUCK -> e; }
  actor e: Say("a" + "b") { SAID -> f; }
  actor f: Say(s + 1.5 + n) { SAID -> g; }
  actor g: Say("n=" + (n + 1)) { SAID -> h; }
  actor h: Count(K) { COUNTED -> i; }
  actor i: Count(s) { COUNTED -> terminate; }
}
)");
  // An entry as it is, brackets or not, needs no lambda; nor does a constant.
  CHECK(w.find("std::make_unique<Go>(ee, afp::in<float>(afp::entry(\"v\"))));\n    auto* b") != std::string::npos);
  CHECK(w.find("\"b\", std::make_unique<Go>(ee, afp::in<float>(afp::entry(\"v\"))));") != std::string::npos);
  CHECK(w.find("std::make_unique<Go>(ee, afp::in<float>(-0.5)));") != std::string::npos);
  // Arithmetic as C computes it: brackets kept, int division through the checked helper.
  CHECK(w.find("afp::in<float>([](const afp::ConfigView& c) { return 2 * (c.get<float>(\"v\") + 1) - "
               "divide(c.get<int>(\"n\"), 4); })") != std::string::npos);
  // Two string literals cannot be added in C++: the first becomes a std::string.
  CHECK(w.find("afp::in<std::string>([](const afp::ConfigView&) { return std::string(\"a\") + \"b\"; })") !=
        std::string::npos);
  // Numbers joined to strings: an entry converts itself, anything else through text().
  CHECK(w.find("return c.get<std::string>(\"s\") + text(1.5) + c.get<std::string>(\"n\"); }") != std::string::npos);
  CHECK(w.find("return \"n=\" + text(c.get<int>(\"n\") + 1); }") != std::string::npos);
  // INT_MIN spelled so that it stays an int; a string entry into an int parameter is parsed at run time.
  CHECK(w.find("afp::in<int>((-2147483647 - 1))") != std::string::npos);
  CHECK(w.find("std::make_unique<Count>(ee, afp::in<int>(afp::entry(\"s\"))));") != std::string::npos);
  CHECK(w.find("std::string text(const afp::Value& number)") != std::string::npos);
  CHECK(w.find("int divide(int a, int b) {") != std::string::npos);
}

TEST_CASE("cpp model: int literals are decimal, a leading zero is not octal", "[cpp_backend]") {
  std::string w = wiring(R"(
import "bot.toolbox";
plan P {
  config { int n = 010; }
  start a;
  actor a: Count(010) { COUNTED -> b; }
  actor b: Count(n + 010) { COUNTED -> c; }
  actor c: Say("n=" + 0010) { SAID -> terminate; }
}
)");
  // docs/language.md: 010 is ten; C++ would read the spelling as octal 8.
  CHECK(w.find("afp::in<int>(10)") != std::string::npos);
  CHECK(w.find("return c.get<int>(\"n\") + 10; }") != std::string::npos);
  CHECK(w.find("return \"n=\" + text(10); }") != std::string::npos);
  CHECK(w.find("afp::Value(10)") != std::string::npos);
  CHECK(w.find("010") == std::string::npos);
}

TEST_CASE("cpp model: a float config value is the double literal rounded to float, as C++ converts it",
          "[cpp_backend]") {
  std::string w = wiring(R"(
import "bot.toolbox";
plan P {
  config { float a = 1.00000005960464477550; float b = 0.1; float c = 30; double d = 0.1; }
  start go;
  actor go: Go(a + b + c) { ARRIVED -> terminate; STUCK -> terminate; }
}
)");
  // Through a double, 1 + 2^-24 (+ a little less than half a double's step) ties to even: 1.0f;
  // rounded to float directly it would be 1.00000012f.
  CHECK(w.find("plan->declare(\"a\", afp::Value(1.0f));") != std::string::npos);
  CHECK(w.find("plan->declare(\"b\", afp::Value(0.1f));") != std::string::npos);
  CHECK(w.find("plan->declare(\"c\", afp::Value(30.0f));") != std::string::npos);
  CHECK(w.find("plan->declare(\"d\", afp::Value(0.1));") != std::string::npos);
}

TEST_CASE("cpp model: a plan without computed text or int division defines no helpers", "[cpp_backend]") {
  std::string w = wiring(R"(
import "bot.toolbox";
plan P {
  config { float v = 1; }
  start a;
  actor a: Go(v / 2) { ARRIVED -> terminate; STUCK -> terminate; }
}
)");
  CHECK(w.find("namespace {") == std::string::npos);
  CHECK(w.find("return c.get<float>(\"v\") / 2; }") != std::string::npos);
  CHECK(w.find("#line") == std::string::npos);  // line directives off
}

TEST_CASE("cpp model: handles give way to the names the file uses", "[cpp_backend]") {
  std::map<std::string, std::string> files{{"bot.toolbox", kToolbox}, {"p.plan", R"(
import "bot.toolbox";
plan P {
  config { int n = 3; }
  supervise Bump: Bump() { HIT -> terminate; }
  start Go;
  actor Go: Go(1) { ARRIVED -> text; STUCK -> Bot; }
  actor text: Say("n=" + (n + 1)) { SAID -> divide; }
  actor divide: Count(n / 2) { COUNTED -> ee; }
  actor ee: Count(1) { COUNTED -> make_P; }
  actor make_P: Count(2) { COUNTED -> c; }
  actor c: Count(n + 1) { COUNTED -> Bot; }
  actor Bot: Count(3) { COUNTED -> terminate; }
}
)"}};
  auto c = compile(files, "p.plan", "p.cpp", false, false);
  INFO(c->errors);
  REQUIRE(!c->diag.has_errors());
  const std::string &w = c->files[0].contents;
  // Instance names (what traces show) stay; the C++ handles take a trailing `_`.
  CHECK(w.find("auto* Bump_ = plan->add_supervisor(\"Bump\", std::make_unique<Bump>(ee));") != std::string::npos);
  CHECK(w.find("auto* Go_ = plan->add_actor(\"Go\", std::make_unique<Go>(ee, afp::in<float>(1)));") !=
        std::string::npos);
  CHECK(w.find("auto* text_ = plan->add_actor(\"text\"") != std::string::npos);
  CHECK(w.find("auto* divide_ = plan->add_actor(\"divide\"") != std::string::npos);
  CHECK(w.find("auto* ee_ = plan->add_actor(\"ee\"") != std::string::npos);
  CHECK(w.find("auto* make_P_ = plan->add_actor(\"make_P\"") != std::string::npos);
  CHECK(w.find("auto* Bot_ = plan->add_actor(\"Bot\"") != std::string::npos);
  CHECK(w.find("auto* c_ = plan->add_actor(\"c\", std::make_unique<Count>(ee,") != std::string::npos);
  CHECK(w.find("plan->define_subsequent(Go_, Go::STUCK, Bot_);") != std::string::npos);
  CHECK(compiles("model-handles", files, "p.plan") == "");
}

TEST_CASE("cpp model: a plan over two toolboxes takes both environments", "[cpp_backend]") {
  std::map<std::string, std::string> files{{"bot.toolbox", kToolbox},
                                           {"arm.toolbox", "toolbox Arm { actor Grip(in float force) -> HELD; }"},
                                           {"hold.plan",
                                            "import \"arm.toolbox\";\n"
                                            "plan Hold { start grip; actor grip: Grip(2) { HELD -> terminate; } }\n"},
                                           {"p.plan", R"(
import "bot.toolbox";
import "hold.plan";
plan P {
  start go;
  actor go: Go(1) { ARRIVED -> hold; STUCK -> terminate; }
  actor hold: Hold() { OK -> terminate; INTERRUPTED -> terminate; ERROR -> terminate; }
}
)"}};
  auto c = compile(files, "p.plan", "p.cpp", false, false);
  INFO(c->errors);
  REQUIRE(!c->diag.has_errors());
  const std::string &w = c->files[0].contents;
  const std::string &h = c->files[1].contents;
  // Toolboxes in declaration order (the order the model knows them): Bot, then Arm.
  CHECK(h.find("#include \"bot_toolbox.h\"\n#include \"arm_toolbox.h\"\n") != std::string::npos);
  CHECK(h.find("std::unique_ptr<afp::Plan> make_P(Bot& ee_Bot, Arm& ee_Arm);") != std::string::npos);
  // The sub-plan takes only the environment it uses.
  CHECK(w.find("std::unique_ptr<afp::Plan> make_Hold(Arm& ee_Arm) {") != std::string::npos);
  CHECK(w.find("std::make_unique<Grip>(ee_Arm, afp::in<float>(2))") != std::string::npos);
  CHECK(w.find("std::make_unique<Go>(ee_Bot, afp::in<float>(1))") != std::string::npos);
  CHECK(w.find("std::make_unique<afp::SubPlan>(make_Hold(ee_Arm))") != std::string::npos);
  CHECK(compiles("model-two-toolboxes", files, "p.plan") == "");
}

TEST_CASE("cpp model: sub-plans are defined once, before their users, each in the file", "[cpp_backend]") {
  std::map<std::string, std::string> files{{"bot.toolbox", kToolbox}, {"p.plan", R"(
import "bot.toolbox";
plan Inner { start c; actor c: Count(1) { COUNTED -> terminate; } }
plan Middle { start i; actor i: Inner() { OK -> terminate; INTERRUPTED -> terminate; ERROR -> terminate; } }
plan P {
  start m;
  actor m: Middle() { OK -> again; INTERRUPTED -> terminate; ERROR -> terminate; }
  actor again: Middle() { OK -> inner; INTERRUPTED -> terminate; ERROR -> terminate; }
  actor inner: Inner() { OK -> terminate; INTERRUPTED -> terminate; ERROR -> terminate; }
}
)"}};
  // Three plans in one file: P is chosen as `--chart P` chooses it.
  MemoryFileSystem mem;
  for (const auto &[path, text] : files) mem.add(path, text);
  pipeline::Compilation c{pipeline::FrontEndOptions{}};
  c.front_end("p.plan", mem);
  REQUIRE(!c.diag.has_errors());
  pipeline::SelectionRequest request;
  request.name = "P";
  REQUIRE(c.select(request).plan);
  EmitOptions o;
  o.output_path = "p.cpp";
  o.source_name = "p.plan";
  o.line_directives = false;
  o.plan = c.selection.plan;
  auto out = emit_to_memory(*make_cpp_backend(), c.model, o);
  const std::string &w = out[0].contents;
  auto inner = w.find("std::unique_ptr<afp::Plan> make_Inner(Bot& ee) {");
  auto middle = w.find("std::unique_ptr<afp::Plan> make_Middle(Bot& ee) {");
  auto top = w.find("std::unique_ptr<afp::Plan> make_P(Bot& ee) {");
  REQUIRE(inner != std::string::npos);
  REQUIRE(middle != std::string::npos);
  REQUIRE(top != std::string::npos);
  CHECK(inner < middle);
  CHECK(middle < top);
  CHECK(w.find("std::unique_ptr<afp::Plan> make_Inner(", inner + 1) == std::string::npos);  // defined once
  CHECK(w.rfind("}  // namespace", top) != std::string::npos);      // the sub-plans are internal
  CHECK(out[1].contents.find("make_Middle") == std::string::npos);  // the header declares only P
}

TEST_CASE("cpp model: file-level verbatim code is copied after the includes, imports' first", "[cpp_backend]") {
  // docs/language.md §6: the blocks go to the top of the generated file, for #includes, as an
  // engine's do; the plan's was dropped once. The toolbox's block comes first (imported files
  // first), then the plan's, before the factory that could use them.
  const std::map<std::string, std::string> files = {
      {"bot.toolbox", std::string("%{\n#include <climits>\n%}\n") + kToolbox},
      {"p.plan", "import \"bot.toolbox\";\n%{\n#include <cmath>\nstatic_assert(INT_MAX > 0, \"from the toolbox\");\n"
                 "static_assert(sizeof(std::sqrt(2.0)) == sizeof(double), \"from the plan\");\n%}\n"
                 "plan P {\n  start a;\n  actor a: Say(\"x\") { SAID -> terminate; }\n}\n"}};
  auto c = compile(files, "p.plan", "p.cpp", false, true);
  REQUIRE(!c->diag.has_errors());
  const std::string &w = c->files[0].contents;
  const auto toolbox_include = w.find("#include \"bot_toolbox.h\"");
  const auto climits = w.find("#include <climits>");
  const auto cmath = w.find("#include <cmath>");
  const auto factory = w.find("make_P(");
  REQUIRE(toolbox_include != std::string::npos);
  CHECK(toolbox_include < climits);
  CHECK(climits < cmath);
  CHECK(cmath < factory);
  CHECK(w.find("#line 3 \"p.plan\"\n#include <cmath>") != std::string::npos);  // the user's line
  CHECK(compiles("plan_verbatim", files, "p.plan") == "");
}

TEST_CASE("cpp model: a file-level const float is a float in formulas, as in C", "[cpp_backend]") {
  // (double)A is 0.10000000149011612 in C: written `0.1` it would be 0.1, and A * v a double
  // product of the wrong value.
  std::string w = wiring(R"(
import "bot.toolbox";
const float A = 0.1;
const double D = 0.1;
plan P {
  config { float v = 3; }
  start a;
  actor a: Go(A) { ARRIVED -> b; STUCK -> terminate; }
  actor b: Go(A * v + D) { ARRIVED -> terminate; STUCK -> terminate; }
}
)");
  CHECK(w.find("afp::in<float>(0.1f)") != std::string::npos);
  CHECK(w.find("return 0.1f * c.get<float>(\"v\") + 0.1; }") != std::string::npos);
}
