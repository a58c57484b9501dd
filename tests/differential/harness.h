// Differential testing: each random case goes through the real pipeline (chart text -> front
// end -> validator -> model), then both through the reference interpreter and through the C
// back end, whose engine is compiled by each configured compiler and run by the C driver.
// The two logs must be identical, line for line.
#pragma once

#include "backend.h"
#include "random_chart.h"
#include "target_table.h"

#include <memory>
#include <utility>
#include <string>
#include <vector>

namespace gfec::diff {

/// One way of building the engines: compiler, flags (all warnings are errors), hooks or not.
/// On a target (tests/targets/targets.txt) each case is a program of its own, built with the
/// target's compiler (`command`: the compiler and its compile flags) and run by its emulator.
struct Config {
  Config() = default;
  Config(std::string name_, std::string command_, bool hooks_ = false)
      : name(std::move(name_)), command(std::move(command_)), hooks(hooks_) {}
  std::string name;  ///< e.g. "gcc -O2 -std=c11"
  std::string command;
  bool hooks = false;
  const targets::Target *target = nullptr;
  std::string target_folder;  ///< where the table is (the support files)
  std::string bin;            ///< the build tree, for {bin} in the target's run command
};

/// The target's compiler and flags, with every warning an error, in the compiler's default
/// dialect (gnu: what an Arduino or vendor build uses, and where gcc contracts a*b+c by default).
Config target_config(const targets::Target &t, const std::string &folder, const std::string &bin);

/// gcc and clang at -O0 and -O2, C99 and C11, with and without hooks; one with ASan+UBSan.
std::vector<Config> default_configs(const std::vector<std::string> &compilers);

struct Prepared;  // the compiled chart and its expected logs

struct Case {
  int id = 0;
  GChart chart;
  GTrace trace;
  std::string text, csv;
  std::shared_ptr<Prepared> prepared;
  /// A hand-written case (--chart): `text` and `csv` are given, `chart` and `trace` are not
  /// generated; prepare() fills in the root chart's name and the ticks (the trace's rows).
  bool given = false;
  std::string file;  ///< its chart file's name
};

/// Whether the case's engine is written in the scalable form (docs/c-engine.md) rather than the
/// readable one (an fsm's scalable form: a switch on the state).
bool scalable_form(const Case &c);

enum class Verdict {
  Pass,
  Invalid,       ///< gfec rejected the generated chart: a bug of the generator (or of gfec)
  Undefined,     ///< the interpreter found undefined behaviour: not a test, skipped
  Mismatch,      ///< the engine's log differs from the interpreter's
  CompileError,  ///< the engine did not compile warning-free
  Lint,          ///< cppcheck reports something in the engine
  Crash,         ///< the engine's program failed or timed out
  /// On a target: the program does not fit the part's flash or RAM (not a failure of the
  /// engine's meaning: counted and said, the case is run on a bigger part of the same core).
  TooBig,
  /// On a target whose `double` is not binary64, a chart that declares a double compiled: it
  /// must be refused at compile time (docs/targets.md), never run with other values.
  NotRefused,
};
const char *verdict_name(Verdict v);

struct Outcome {
  Verdict verdict = Verdict::Pass;
  std::string detail;    ///< diagnostics, compiler output, or the actual log
  std::string expected;  ///< the interpreter's log (for mismatches)
  bool refused = false;  ///< Pass on a target: refused at compile time, as it must be
};

/// A target case's engine, glue.c and a README with the commands that build and run it.
void save_target_program(const Case &c, const Config &config, const std::string &dir);

class Harness {
public:
  /// `work`: a scratch folder for engines and programs.
  explicit Harness(std::string work, bool verbose = false);

  /// Front end, validator, interpreter and back end for one case (in memory). Pass means
  /// ready to build; Invalid or Undefined say why not.
  Outcome prepare(Case &c) const;
  /// Builds every prepared case of `batch` with `config`, runs them and compares.
  std::vector<Outcome> run_batch(const std::vector<Case *> &batch, const Config &config, const std::string &tag) const;
  Outcome run_one(Case &c, const Config &config, const std::string &tag) const;
  /// One case as a program of its own on `config`'s target: the one harness writer's program
  /// (table inputs, observable log, character output), the target's support file, its emulator.
  /// Pass also when a chart declaring a double is refused where double is not binary64.
  Outcome run_on_target(Case &c, const Config &config, const std::string &tag) const;
  /// cppcheck over the engines of every prepared case of `batch` (warning, style, performance,
  /// portability): a finding fails its case.
  std::vector<Outcome> lint_batch(const std::vector<Case *> &batch, const std::string &tag) const;

  /// Writes a case's chart, trace, logs and engine to `dir` for a person to look at.
  void save(const Case &c, const Outcome &o, const Config &config, const std::string &dir) const;

private:
  std::string work_;
  bool verbose_;
};

}  // namespace gfec::diff
