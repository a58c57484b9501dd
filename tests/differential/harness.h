// Differential testing: each random case goes through the real pipeline (chart text -> front
// end -> validator -> model), then both through the reference interpreter and through the C
// back end, whose engine is compiled by each configured compiler and run by the C driver.
// The two logs must be identical, line for line.
#pragma once

#include "backend.h"
#include "random_chart.h"

#include <memory>
#include <string>
#include <vector>

namespace gfec::diff {

/// One way of building the engines: compiler, flags (all warnings are errors), hooks or not.
struct Config {
  std::string name;  ///< e.g. "gcc -O2 -std=c11"
  std::string command;
  bool hooks = false;
};

/// gcc and clang at -O0 and -O2, C99 and C11, with and without hooks; one with ASan+UBSan.
std::vector<Config> default_configs(const std::vector<std::string> &compilers);

struct Prepared;  // the compiled chart and its expected logs

struct Case {
  int id = 0;
  GChart chart;
  GTrace trace;
  std::string text, csv;
  std::shared_ptr<Prepared> prepared;
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
};
const char *verdict_name(Verdict v);

struct Outcome {
  Verdict verdict = Verdict::Pass;
  std::string detail;    ///< diagnostics, compiler output, or the actual log
  std::string expected;  ///< the interpreter's log (for mismatches)
};

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
