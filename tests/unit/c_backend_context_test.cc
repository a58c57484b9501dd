// The instance context and the name table of the C engine (docs/c-engine.md "Instance context",
// "Names"): with --context every interface call receives the engine's context first, so two
// engines of one chart drive two devices; with --names X_place_name and X_transition_name give
// the declared names. Engines are compiled with gcc and clang at -std=c99 -Wall -Wextra
// -Wpedantic -Werror and run against harnesses written by hand; the expected logs follow from
// the language's tick order (docs/language.md 5.1, 7, "Sub-charts"), never from an engine's output.
#include "../run/c_backend_support.h"
#include "c_context_type.h"

#include <catch2/catch.hpp>

using namespace cbt;
using gfec::c_backend::ContextType;

namespace {

/// The chart of tests/golden/c/rover_context.sfc: sfc Roam { Cruise; Avoid runs fsm Escape }.
std::string rover_chart() { return read_file(fs::path(GFEC_SOURCE_DIR) / "tests/golden/c/rover_context.sfc"); }

/// Two rovers, each with its own sensor readings by tick and its own log of what it was told to
/// do. One engine of Roam each, given its rover as context; every tick runs both engines. The
/// harness prints each rover's log on a line of its own; every tick begins with `|`.
const char *kTwoRovers = R"C(#include "engine.h"

#include <stdio.h>
#include <string.h>

struct rover {
    const int *blocked; /* Blocked() by tick */
    const int *range;   /* Range() by tick */
    int tick;
    char log[1024];
};

static void note(struct rover *r, const char *text)
{
    if (strlen(r->log) + strlen(text) < sizeof r->log) {
        strcat(r->log, text);
    }
}

bool Blocked(struct rover *r)
{
    note(r, " Blocked");
    return r->blocked[r->tick] != 0;
}

int Range(struct rover *r)
{
    note(r, " Range");
    return r->range[r->tick];
}

void Drive(struct rover *r, int speed)
{
    char text[32];
    sprintf(text, " Drive(%d)", speed);
    note(r, text);
}

void Turn(struct rover *r, int dir)
{
    char text[32];
    sprintf(text, " Turn(%d)", dir);
    note(r, text);
}

void Lamp(struct rover *r, bool on)
{
    note(r, on ? " Lamp(on)" : " Lamp(off)");
}

int main(void)
{
    static const int a_blocked[7] = {0, 1, 1, 1, 0, 0, 0};
    static const int a_range[7] = {0, 5, 30, 0, 0, 0, 0};
    static const int b_blocked[7] = {1, 1, 0, 0, 0, 0, 0};
    static const int b_range[7] = {50, 0, 0, 0, 0, 0, 0};
    static struct rover a, b;
    Roam ea, eb;
    int tick;
    a.blocked = a_blocked;
    a.range = a_range;
    b.blocked = b_blocked;
    b.range = b_range;
    /* Either order: _init leaves the context as it is. */
    Roam_init(&ea);
    Roam_set_context(&ea, &a);
    Roam_set_context(&eb, &b);
    Roam_init(&eb);
    if (Roam_context(&ea) != &a || Roam_context(&eb) != &b) {
        printf("Roam_context does not return the context set\n");
        return 1;
    }
    for (tick = 0; tick < 7; ++tick) {
        a.tick = tick;
        b.tick = tick;
        note(&a, " |");
        note(&b, " |");
        Roam_run(&ea);
        Roam_run(&eb);
    }
    printf("a:%s\nb:%s\n", a.log, b.log);
    return 0;
}
)C";

/// Compiles `files` with `harness` (as harness.c) with gcc and clang at kStrictFlags plus
/// `defines`, runs it, and returns its output, which must be the same for both.
std::string build_and_run(const std::string &test, const std::vector<OutputFile> &files, const std::string &harness,
                          const std::string &defines = "") {
  REQUIRE(files.size() == 2);
  fs::path dir = scratch_dir(test);
  for (const auto &f : files) write_file(dir / base_name(f.path), f.contents);
  write_file(dir / "harness.c", harness);
  std::string first;
  for (const auto &cc : c_compilers()) {
    auto build = run_command(fmt::format("cd '{}' && {} {} {} harness.c {} -o run-{}", dir.string(), cc, kStrictFlags,
                                         defines, base_name(files[0].path), cc),
                             dir / ("build-" + cc + ".log"));
    INFO(cc << " " << defines << " in " << dir.string() << ":\n" << build.output);
    REQUIRE(build.status == 0);
    auto run = run_command(fmt::format("cd '{}' && ./run-{}", dir.string(), cc), dir / ("run-" + cc + ".log"));
    INFO(run.output);
    REQUIRE(run.status == 0);
    if (first.empty()) first = run.output;
    else CHECK(run.output == first);
  }
  return first;
}

}  // namespace

TEST_CASE("c engine context: two engines of one chart drive two rovers, each only its own", "[c_backend][context]") {
  // Rover a: cruises, is blocked in tick 2, backs off until the range opens (tick 3), spins
  // while still blocked (tick 4), is free in tick 5 and cruises again from tick 6. Rover b is
  // blocked at once, far from anything: it spins in the very first tick of its Escape.
  const std::string a = "a: |"
                        " Blocked Drive(2) |"                  // tick 1: Cruise: Bump not taken; Cruise's action
                        " Blocked Lamp(on) Range Drive(-1) |"  // 2: Bump; Avoid's entry; Escape's first tick: Reverse
                        " Range Turn(1) |"       // 3: Clear not yet (Escape runs); Reverse -> Spin, Spin's action
                        " Blocked Turn(1) |"     // 4: Spin stays (still blocked)
                        " Blocked{post} |"       // 5: Spin -> Free, success: no action
                        " Lamp(off) Drive(2) |"  // 6: Clear (succeeded at the start of the tick); Avoid's exit
                        " Blocked Drive(2)\n";   // 7: cruising
  const std::string b = "b: |"
                        " Blocked Lamp(on) Range Turn(1) |"  // tick 1: Bump; Escape: Reverse -> Spin at once (range 50)
                        " Blocked Turn(1) |"                 // 2: still blocked
                        " Blocked{post} |"                   // 3: Spin -> Free
                        " Lamp(off) Drive(2) |"              // 4: Clear
                        " Blocked Drive(2) |"
                        " Blocked Drive(2) |"
                        " Blocked Drive(2)\n";
  // Under Roam_CHECKS Free's postcondition !Blocked() is asserted on entering it: one more call,
  // on the rover of the engine that entered it.
  auto expected = [&](bool checks) {
    std::string log = a + b;
    for (std::size_t at; (at = log.find("{post}")) != std::string::npos;) log.replace(at, 6, checks ? " Blocked" : "");
    return log;
  };
  for (EngineForm form : {EngineForm::Readable, EngineForm::Scalable}) {
    auto compiled =
        compile_chart({{"rover.sfc", rover_chart()}}, "rover.sfc", "engine.c", true, form, "struct rover *");
    INFO(compiled->errors);
    REQUIRE(!compiled->diag.has_errors());
    const std::string name = form == EngineForm::Readable ? "rovers" : "rovers_scalable";
    CHECK(build_and_run(name, compiled->files, kTwoRovers) == expected(false));
    CHECK(build_and_run(name + "_checks", compiled->files, kTwoRovers, "-DRoam_CHECKS") == expected(true));
  }
}

TEST_CASE("c engine context: the split sequential form of a large chart passes it too", "[c_backend][context]") {
  // A ring of 1100 places (above the size where the sequential form is split into parts, as
  // docs/c-engine.md says), each stepping to the next while Go() holds and calling Step(i).
  const int n = 1100;
  std::string chart = "interface Line { bool Go(); void Step(int at); }\nsfc Ring {\n";
  for (int i = 0; i < n; ++i) chart += fmt::format("  {}place P{} {{ Step({}); }}\n", i == 0 ? "initial " : "", i, i);
  for (int i = 0; i < n; ++i) chart += fmt::format("  transition P{} -> P{} when Go();\n", i, (i + 1) % n);
  chart += "}\n";
  auto compiled = compile_chart({{"ring.sfc", chart}}, "ring.sfc", "engine.c", false, EngineForm::Auto, "int *");
  INFO(compiled->errors);
  REQUIRE(!compiled->diag.has_errors());
  REQUIRE(compiled->files[0].contents.find("_parts[") != std::string::npos);  // the split form
  // Two engines, contexts 1 and 2: the first steps every tick, the second every other tick.
  const char *harness = R"C(#include "engine.h"

#include <stdio.h>

static int ticks;

bool Go(int *who)
{
    return *who == 1 || ticks % 2 == 0;
}

void Step(int *who, int at)
{
    printf("%d:%d ", *who, at);
}

int main(void)
{
    static Ring one, two;
    int id_one = 1, id_two = 2;
    Ring_init(&one);
    Ring_init(&two);
    Ring_set_context(&one, &id_one);
    Ring_set_context(&two, &id_two);
    for (ticks = 0; ticks < 4; ++ticks) {
        Ring_run(&one);
        Ring_run(&two);
    }
    printf("\n");
    return 0;
}
)C";
  // Tick k (from 0): a transition fires and the new place acts in the same tick. Engine 1 is at
  // P1 after tick 0, P2, P3, P4; engine 2 moves on even ticks only: P1, P1, P2, P2.
  CHECK(build_and_run("ring_split", compiled->files, harness) == "1:1 2:1 1:2 2:1 1:3 2:2 1:4 2:2 \n");
}

TEST_CASE("c engine names: X_place_name and X_transition_name give the declared names", "[c_backend][names]") {
  const char *harness = R"C(#include "engine.h"

#include <stdio.h>

bool Blocked(void) { return false; }
int Range(void) { return 0; }
void Drive(int speed) { (void)speed; }
void Turn(int dir) { (void)dir; }
void Lamp(bool on) { (void)on; }

static const char *shown(const char *name)
{
    return name == NULL ? "(null)" : name;
}

int main(void)
{
    printf("%s %s %s %s|", shown(Roam_place_name(Roam_Cruise)), shown(Roam_place_name(Roam_Avoid)),
           shown(Roam_place_name(-1)), shown(Roam_place_name(Roam_PLACE_COUNT)));
    printf("%s %s %s %s\n", shown(Roam_transition_name(Roam_Bump)), shown(Roam_transition_name(Roam_Clear)),
           shown(Roam_transition_name(-1)), shown(Roam_transition_name(Roam_TRANSITION_COUNT)));
    return 0;
}
)C";
  for (EngineForm form : {EngineForm::Readable, EngineForm::Scalable}) {
    auto compiled = compile_chart({{"rover.sfc", rover_chart()}}, "rover.sfc", "engine.c", true, form, "", true);
    INFO(compiled->errors);
    REQUIRE(!compiled->diag.has_errors());
    CHECK(build_and_run(form == EngineForm::Readable ? "names" : "names_scalable", compiled->files, harness) ==
          "Cruise Avoid (null) (null)|Bump Clear (null) (null)\n");
  }
  // Without --names the engine carries no strings (the chart's names appear only in comments).
  auto plain = compile_chart({{"rover.sfc", rover_chart()}}, "rover.sfc", "engine.c", false);
  REQUIRE(!plain->diag.has_errors());
  CHECK(plain->files[0].contents.find("\"Cruise\"") == std::string::npos);
  CHECK(plain->files[1].contents.find("place_name") == std::string::npos);
}

TEST_CASE("c engine names: an fsm's states, and a chart without transitions", "[c_backend][names]") {
  const char *chart = R"C(
interface Bot { bool Done(); }
fsm Job {
  initial state Work;
  success state Finished;
  Work -> Finished when Done();
}
)C";
  const char *job_harness = R"C(#include "engine.h"

#include <stdio.h>

bool Done(void) { return true; }

int main(void)
{
    Job m;
    Job_init(&m);
    Job_run(&m);
    printf("%s %s %d\n", Job_place_name(Job_state(&m)), Job_transition_name(0), Job_place_name(2) == NULL);
    return 0;
}
)C";
  auto job = compile_chart({{"job.fsm", chart}}, "job.fsm", "engine.c", true, EngineForm::Auto, "", true);
  INFO(job->errors);
  REQUIRE(!job->diag.has_errors());
  REQUIRE(job->the_chart().name == "Job");
  CHECK(build_and_run("names_fsm", job->files, job_harness) == "Finished T0 1\n");
  // C has no empty array: a chart without transitions answers null for every number.
  auto idle = compile_chart({{"idle.sfc", "sfc Idle { initial place Only; }\n"}}, "idle.sfc", "engine.c", true,
                            EngineForm::Auto, "", true);
  INFO(idle->errors);
  REQUIRE(!idle->diag.has_errors());
  CHECK(build_and_run("names_empty", idle->files,
                      "#include \"engine.h\"\n\n#include <stdio.h>\n\nint main(void)\n{\n"
                      "    printf(\"%s %d\\n\", Idle_place_name(Idle_Only), Idle_transition_name(0) == NULL);\n"
                      "    return 0;\n}\n") == "Only 1\n");
}

TEST_CASE("c engine context: the context's names give way to the chart's", "[c_backend][context]") {
  // A var `ctx`, parameters `ctx` and `ctx_`, a place `context` (X_context is the API's) and an
  // interface function whose name begins with ctx: all compile, nothing hides anything.
  const char *chart = R"C(
interface I { void Put(int ctx, int ctx_); bool ctx_ok(); }
sfc Clash {
  var int ctx = 1;
  initial place context { Put(ctx, 2); }
  place names;
  transition context -> names when ctx_ok();
}
)C";
  auto compiled =
      compile_chart({{"clash.sfc", chart}}, "clash.sfc", "engine.c", true, EngineForm::Auto, "void *", true);
  INFO(compiled->errors);
  REQUIRE(!compiled->diag.has_errors());
  const std::string &h = compiled->files[1].contents;
  CHECK(h.find("    int32_t ctx; ") != std::string::npos);  // the var keeps its name
  CHECK(h.find("    void *ctx_; ") != std::string::npos);   // the context's member gives way
  CHECK(h.find("void Put(void *ctx__, int32_t ctx, int32_t ctx_);") != std::string::npos);
  CHECK(h.find("bool ctx_ok(void *ctx);") != std::string::npos);
  CHECK(h.find("Clash_context_,") != std::string::npos);  // the place's constant gives way to the API
  const char *harness = R"C(#include "engine.h"

#include <stdio.h>

static int device;
static int steps;

void Put(void *ctx__, int ctx, int ctx_)
{
    if (ctx__ == &device) {
        ++steps;
    }
    (void)ctx;
    (void)ctx_;
}

bool ctx_ok(void *ctx)
{
    return ctx == &device && steps >= 2;
}

int main(void)
{
    Clash m;
    int tick;
    Clash_init(&m);
    Clash_set_context(&m, &device);
    for (tick = 0; tick < 3; ++tick) {
        Clash_run(&m);
    }
    printf("%d %s %s\n", steps, Clash_place_name(Clash_context_), Clash_place_name(Clash_names));
    return 0;
}
)C";
  // Ticks 1 and 2: ctx_ok() sees 0, then 1 step (false), and context's action steps; tick 3:
  // it sees 2 (true), names is active and does nothing.
  CHECK(build_and_run("context_clash", compiled->files, harness) == "2 context names\n");
}

TEST_CASE("c engine context: the type's tag is declared first, however it is qualified", "[c_backend][context]") {
  // `volatile const struct bus *`: without `struct bus;` before the prototypes each would declare
  // its own tag ("will not be visible outside of this definition"), an error under -Werror.
  ContextType t("volatile const struct bus *");
  CHECK(t.words == std::vector<std::string>{"volatile", "const", "struct", "bus"});
  CHECK(t.tag_keyword == "struct");
  CHECK(t.tag == "bus");
  CHECK(t.param("ctx") == "volatile const struct bus *ctx");
  CHECK(ContextType("bus_t").param("ctx") == "bus_t ctx");
  CHECK(ContextType("union u *").tag == "u");
  CHECK(ContextType("void *").tag.empty());
  // The same reader as the driver's check: spacing normalised, code refused.
  CHECK(ContextType("struct  motor*const*").param("m") == "struct motor *const *m");
  CHECK_THROWS_AS(ContextType("struct motor *const"), std::invalid_argument);  // cannot be assigned
  CHECK(ContextType("").spelling.empty());
  CHECK_THROWS_AS(ContextType("int; int x"), std::invalid_argument);

  const char *chart = "interface I { void Go(); }\nsfc Bus { initial place A { Go(); } }\n";
  auto compiled = compile_chart({{"bus.sfc", chart}}, "bus.sfc", "engine.c", true, EngineForm::Auto, t.spelling);
  INFO(compiled->errors);
  REQUIRE(!compiled->diag.has_errors());
  CHECK(compiled->files[1].contents.find("struct bus; /* the instance context's type (--context-type) */") !=
        std::string::npos);
  const char *harness = R"C(#include "engine.h"

#include <stdio.h>

struct bus {
    int calls;
};

void Go(volatile const struct bus *b)
{
    printf("%d ", b->calls);
}

int main(void)
{
    struct bus b = {7};
    Bus m;
    Bus_init(&m);
    Bus_set_context(&m, &b);
    Bus_run(&m);
    Bus_run(&m);
    printf("\n");
    return 0;
}
)C";
  CHECK(build_and_run("context_tag", compiled->files, harness) == "7 7 \n");
}
