// The command line as make and CMake pass it: gcc's -M flags before CLI11, diagnostics formats.
#include "options.h"

#include "c_engine_options.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace gfec;

namespace {

ParsedCommandLine parse(std::vector<const char *> args) {
  args.insert(args.begin(), "gfec");
  return parse_command_line(static_cast<int>(args.size()), args.data());
}

/// The C engine's own options as its option group read them (backend_registry.h).
c_backend::CEngineOptions c_engine(const ParsedCommandLine &cl) {
  for (const auto &given : cl.options.backend_options)
    if (std::string(given.backend->name) == "c") {
      EmitOptions emit;
      emit.backend = given.group->options();
      return backend_options<c_backend::CEngineOptions>(emit);
    }
  FAIL("the C back end declares no option group");
  return {};
}

}  // namespace

TEST_CASE("options: -MD -MF -MP -MT as gcc spells them") {
  auto cl = parse({"-MD", "-MF", "deps/x.d", "-MP", "-MT", "fw/engine.c", "x.sfc", "-o", "engine.c"});
  REQUIRE_FALSE(cl.exit_now);
  CHECK(cl.options.deps.write);
  CHECK(cl.options.deps.file == "deps/x.d");
  CHECK(cl.options.deps.phony);
  CHECK(cl.options.deps.targets == std::vector<DependencyTarget>{{"fw/engine.c", false}});
  CHECK(cl.options.inputs == std::vector<std::string>{"x.sfc"});
  CHECK(cl.options.output == "engine.c");

  auto attached = parse({"x.sfc", "-MMD", "-MFx.d", "-MTa", "-MTb"});
  REQUIRE_FALSE(attached.exit_now);
  CHECK(attached.options.deps.write);
  CHECK(attached.options.deps.file == "x.d");
  CHECK(attached.options.deps.targets == std::vector<DependencyTarget>{{"a", false}, {"b", false}});

  // -MQ, as gcc's: a target quoted for make, in order with the -MT ones.
  auto quoted = parse({"x.sfc", "-MD", "-MQ", "$(OBJ)/a b.c", "-MT$(OBJ)/c.c", "-MQd.c"});
  REQUIRE_FALSE(quoted.exit_now);
  CHECK(quoted.options.deps.targets ==
        std::vector<DependencyTarget>{{"$(OBJ)/a b.c", true}, {"$(OBJ)/c.c", false}, {"d.c", true}});
  CHECK_FALSE(attached.options.deps.phony);

  auto none = parse({"x.sfc"});
  CHECK_FALSE(none.options.deps.write);
}

TEST_CASE("options: bad -M flags are usage errors") {
  auto missing = parse({"x.sfc", "-MF"});
  CHECK(missing.exit_now);
  CHECK(missing.exit_code == 2);
  CHECK(missing.message.find("missing file after '-MF'") != std::string::npos);
  auto unknown = parse({"-MX", "x.sfc"});
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.message.find("unknown option '-MX'") != std::string::npos);
  auto check = parse({"--check", "-MD", "x.sfc"});
  CHECK(check.exit_code == 2);
  // After "--" everything is a file name, even one that starts like a flag.
  auto files = parse({"--check", "--", "-MD.sfc"});
  REQUIRE_FALSE(files.exit_now);
  CHECK(files.options.inputs == std::vector<std::string>{"-MD.sfc"});
  CHECK_FALSE(files.options.deps.write);
}

TEST_CASE("options: -fdiagnostics-format and -W take one value each, not the files after them") {
  auto cl = parse({"--check", "-fdiagnostics-format=sarif-file", "a.sfc", "-Wall", "b.sfc", "-Werror", "c.sfc"});
  REQUIRE_FALSE(cl.exit_now);
  CHECK(cl.options.diagnostics_format == DiagnosticsFormat::SarifFile);
  CHECK(cl.options.inputs == std::vector<std::string>{"a.sfc", "b.sfc", "c.sfc"});
  CHECK(cl.options.warnings.as_errors);
  CHECK(parse({"--check", "-fdiagnostics-format=json", "a.sfc"}).options.diagnostics_format == DiagnosticsFormat::Json);
  CHECK(parse({"--check", "-fdiagnostics-format=sarif-stderr", "a.sfc"}).options.diagnostics_format ==
        DiagnosticsFormat::SarifStderr);
  CHECK(parse({"--check", "-fdiagnostics-format=text", "a.sfc"}).options.diagnostics_format == DiagnosticsFormat::Text);
  auto bad = parse({"--check", "-fdiagnostics-format=xml", "a.sfc"});
  CHECK(bad.exit_code == 2);
  CHECK(bad.message == "gfec: error: unknown diagnostics format 'xml' (text, json, sarif-stderr, sarif-file)\n");
}

TEST_CASE("options: gcc's warning and colour flags: -w, -Werror=NAME, -Wno-error=NAME, -fdiagnostics-color") {
  auto one = parse({"x.sfc", "-Wno-unreachable-place", "-Werror=unreachable-place", "-Wno-error=conflict", "-Werror"});
  REQUIRE_FALSE(one.exit_now);
  const WarningOptions &w = one.options.warnings;
  CHECK(w.is_on(Warning::UnreachablePlace));  // -Werror=NAME turns it back on, as gcc
  CHECK(w.is_error(Warning::UnreachablePlace));
  CHECK_FALSE(w.is_error(Warning::Conflict));  // -Wno-error=NAME wins over -Werror
  CHECK(w.is_error(Warning::DeadTransition));

  auto only = parse({"x.sfc", "-Werror=dead-transition"});
  CHECK(only.options.warnings.is_error(Warning::DeadTransition));
  CHECK_FALSE(only.options.warnings.is_error(Warning::UnreachablePlace));

  auto quiet = parse({"x.sfc", "-Wall", "-w"});
  REQUIRE_FALSE(quiet.exit_now);
  for (int i = 0; i < static_cast<int>(Warning::Count_); ++i) CHECK_FALSE(quiet.options.warnings.enabled[i]);

  CHECK(parse({"x.sfc"}).options.color == ColorMode::Auto);
  CHECK(parse({"x.sfc", "-fdiagnostics-color"}).options.color == ColorMode::Always);
  CHECK(parse({"x.sfc", "-fdiagnostics-color=always"}).options.color == ColorMode::Always);
  CHECK(parse({"x.sfc", "-fdiagnostics-color=never"}).options.color == ColorMode::Never);
  CHECK(parse({"x.sfc", "-fdiagnostics-color=always", "-fno-diagnostics-color"}).options.color == ColorMode::Never);
  CHECK(parse({"x.sfc", "-fdiagnostics-color=never", "-fdiagnostics-color=auto"}).options.color == ColorMode::Auto);
  auto bad = parse({"x.sfc", "-fdiagnostics-color=sometimes"});
  CHECK(bad.exit_code == 2);
  CHECK(bad.message.find("unknown colour mode 'sometimes'") != std::string::npos);
  CHECK(parse({"x.sfc", "-Werror=no-such-warning"}).exit_code == 2);

  CHECK(parse({"x.sfc"}).options.line_numbers);
  CHECK_FALSE(parse({"x.sfc", "-fno-diagnostics-show-line-numbers"}).options.line_numbers);
  CHECK(parse({"x.sfc", "-fdiagnostics-parseable-fixits"}).options.parseable_fixits);
}

TEST_CASE("options: no file is gcc's 'no input files' and the ways to run gfec, not a CLI11 message") {
  for (auto cl : {parse({}), parse({"--check"}), parse({"-Wall"})}) {
    CHECK(cl.exit_now);
    CHECK(cl.exit_code == 2);
    CHECK(cl.message.rfind("gfec: fatal error: no input files\n", 0) == 0);
    CHECK(cl.message.find("gfec run CHART --inputs") != std::string::npos);
    CHECK(cl.message.find("--analyze") != std::string::npos);
    CHECK(cl.message.find("is required") == std::string::npos);
  }
  auto help = parse({"--help"});
  CHECK(help.exit_code == 0);
  CHECK(help.message.find("gfec run CHART") != std::string::npos);
  CHECK(help.message.find("--analyze") != std::string::npos);
  // One usage block (ours), not CLI11's "Usage: gfec [OPTIONS] [files...]" as well.
  size_t usages = 0;
  for (size_t at = help.message.find("Usage:"); at != std::string::npos; at = help.message.find("Usage:", at + 1))
    ++usages;
  CHECK(usages == 1);
  for (const char *words : {"gfec test FILE", "-x LANG", "chart text", "Documentation: man gfec; cli.md"})
    CHECK(help.message.find(words) != std::string::npos);
}

TEST_CASE("options: --context, --context-type and --names, the C engine's options") {
  auto plain = parse({"x.sfc"});
  CHECK(c_engine(plain).context_type.empty());
  CHECK_FALSE(c_engine(plain).names);
  auto context = parse({"--context", "x.sfc", "--names"});
  REQUIRE_FALSE(context.exit_now);
  CHECK(c_engine(context).context_type == "void *");
  CHECK(c_engine(context).names);
  CHECK(context.options.inputs == std::vector<std::string>{"x.sfc"});  // --context takes no value
  // A type implies --context; spacing is normalised as engine.h writes it.
  CHECK(c_engine(parse({"--context-type=struct  motor*", "x.sfc"})).context_type == "struct motor *");
  CHECK(c_engine(parse({"--context-type", "uint8_t", "x.sfc"})).context_type == "uint8_t");
  CHECK(c_engine(parse({"--context", "--context-type=const struct bus *", "x.sfc"})).context_type ==
        "const struct bus *");
  // Only a type's words and stars: nothing that would put code into engine.h.
  for (const char *bad : {"--context-type=int; int x", "--context-type=void (*)(void)", "--context-type=* *",
                          "--context-type=9lives *"}) {
    INFO(bad);
    auto r = parse({bad, "x.sfc"});
    CHECK(r.exit_now);
    CHECK(r.exit_code == 2);
    CHECK(r.message.rfind("gfec: error: --context-type", 0) == 0);
  }
  // Words and stars that are no type an engine can store, assign and return: each refused with
  // its reason (they gave an engine that did not compile).
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"void", "'void' has no values: a context of no type is 'void *'"},
      {"const", "the type cannot be 'const' itself"},
      {"const int", "the type cannot be 'const' itself"},
      {"int *const", "the type cannot be 'const' itself"},
      {"volatile int", "the type cannot be 'volatile' itself"},
      {"int *restrict", "the type cannot be 'restrict' itself"},
      {"static int", "'static' is not part of a type name"},
      {"extern struct m *", "'extern' is not part of a type name"},
      {"struct", "'struct' needs its tag"},
      {"struct *", "'struct' needs its tag"},
      {"int * int", "no words after its last '*' but qualifiers"},
  };
  for (const auto &[type, why] : refused) {
    INFO(type);
    const std::string option = "--context-type=" + type;
    auto r = parse({option.c_str(), "x.sfc"});
    CHECK(r.exit_code == 2);
    CHECK(r.message.rfind("gfec: error: --context-type '" + type + "': ", 0) == 0);
    CHECK(r.message.find(why) != std::string::npos);
  }
}

TEST_CASE("options: a misspelt option gets a did-you-mean") {
  auto chek = parse({"--chek", "x.sfc"});
  CHECK(chek.exit_code == 2);
  CHECK(chek.message.find("gfec: note: did you mean '--check'?") != std::string::npos);
  auto emit = parse({"--emti=svg", "x.sfc"});
  CHECK(emit.message.find("did you mean '--emit'?") != std::string::npos);
  auto far = parse({"--zzzzzz", "x.sfc"});
  CHECK(far.exit_code == 2);
  CHECK(far.message.find("did you mean") == std::string::npos);
}

TEST_CASE("options: --period reads a chart duration or an IEC TIME literal, and nothing else") {
  CHECK(parse_period("10ms") == 10.0);
  CHECK(parse_period("1.5s") == 1500.0);
  CHECK(parse_period("T#10ms") == 10.0);
  CHECK(parse_period("time#1s500ms") == 1500.0);
  CHECK(parse_period("T#1m2s") == 62000.0);
  CHECK(parse_period("T#1_000ms") == 1000.0);
  for (const char *bad :
       {"", "10", "0ms", "-5ms", "T#", "T#0s", "10m", "1s500ms", "1.5.0s", ".5s", "10ms ", "1_000ms", "T#10x", "T#-1s"})
    CHECK_FALSE(parse_period(bad));
  ParsedCommandLine cl = parse({"x.st", "--period", "T#20ms"});
  REQUIRE_FALSE(cl.exit_now);
  CHECK(cl.options.period_ms == 20.0);
  cl = parse({"x.st", "--period", "20"});
  CHECK(cl.exit_now);
  CHECK(cl.exit_code == 2);
  CHECK(cl.message.find("--period '20' is not a duration above 0") != std::string::npos);
}
