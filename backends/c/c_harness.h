// The one writer of a C program around a generated C engine: the interface functions the engine
// calls (each logs its call and returns the value its input source gives), one engine per agent,
// and a loop that runs them tick by tick and prints a log. `gfec test`, the compile-and-run
// unit tests and the target runners differ only in the options below.
//
// The program comes in two files, so that no file sees both the engine's header (the
// interface's prototypes) and the C library's (an interface function may be called `remove` or
// `abs`):
//   glue.c    includes the engine's header and no library header: the interface functions, the
//             engines, what a record prints, and (Table inputs) main itself;
//   harness.c the C library's side: output through stdio and the inputs read from stdin. Empty
//             with Output::Putc, whose program needs no C library at all.
// Every name of the harness's own begins with a prefix that begins no interface function's name.
#pragma once

#include "backend.h"
#include "interpreter/value.h"
#include "model.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gfec::c_backend {

/// How the sensing functions get their values.
enum class HarnessInputs {
  /// `gfec test`'s exchange (driver/test_engine.h): stdin holds `set A F VALUE` (agent A, -1 for
  /// every agent; F the function's index in the model) and `tick` lines.
  Steps,
  /// The compile-and-run tests': one stdin line per tick, naming what holds during it: `F`
  /// returns 1, `F=12.5` returns 12.5, a function not named returns 0. One agent.
  Script,
  /// Compiled in as a static const table of every tick's values (HarnessOptions::table); the
  /// program runs exactly that many ticks. What a target runner needs: no input at all.
  Table,
};

/// What the program prints.
enum class HarnessLog {
  /// `gfec test`'s records (driver/test_engine.h): after _init and after every tick, each
  /// agent's av, inst, state, var and timer lines, then `end`; every call as `call F(args)`.
  Records,
  /// The interpreter's observable log, unindented (docs/verification.md "The log",
  /// compiler/interpreter/event_log.h) and, built with -DX_HOOKS, its hooks layer: what `gfec
  /// run --observable` prints for the same inputs, line for line.
  Observable,
  /// The log the compile-and-run tests' expectations are written in (tests/run): `cond F -> 1`,
  /// `act G(0.6)` (%g), `av A B:2` (active places by name), `state S status 0`, `hook gained P`;
  /// built with -DHARNESS_INSTANCES also each sub-chart instance's active places. One engine,
  /// driven as any chart's even for a team machine (no agent number, no exchange).
  Compact,
};

/// Where the log goes.
enum class HarnessOutput {
  Stdio,  ///< printf to stdout (harness.c), flushed after every tick
  /// One character at a time through `int PUTC(int)`, which the program declares and the user
  /// links (a target's UART): numbers are formatted by the program itself, exactly as printf
  /// would, so the log is the same. No C library is used.
  Putc,
};

/// Table inputs: what each sensing function returns.
struct HarnessTable {
  std::uint64_t ticks = 0;
  /// What `function` returns to agent `agent` during tick `tick` (from 1), a value of its result
  /// type; every call in that tick gets the same value.
  std::function<interp::Value(model::FunctionId function, std::uint64_t tick, int agent)> value;
  /// What the caller sets input `var` (an `in` variable, docs/language.md §14) to before tick
  /// `tick`, a value of its type; none: it keeps its value. Unset: inputs are never set.
  std::function<std::optional<interp::Value>(const model::Var &var, std::uint64_t tick)> input;
};

struct HarnessOptions {
  HarnessInputs inputs = HarnessInputs::Steps;
  HarnessLog log = HarnessLog::Records;
  HarnessOutput output = HarnessOutput::Stdio;
  std::string header = "engine.h";    ///< the engine's header, as glue.c includes it
  int agents = 1;                     ///< engines side by side (a team machine's agents, 1 else)
  HarnessTable table;                 ///< HarnessInputs::Table
  std::string putc = "harness_putc";  ///< HarnessOutput::Putc: the function that writes a character
  /// Stdio output, the engine made with a context (`--context`, a `void *`): engine k gets
  /// a device of its own, and every interface function checks it received the device of the
  /// engine that runs (else it prints `wrong context` and the program exits with 3).
  bool context = false;
};

struct HarnessSources {
  std::string glue;  ///< glue.c
  std::string main;  ///< harness.c, empty when the program needs no C library
};

/// The program around the engine of `chart`, emitted with `emit` (the names the C back end chose
/// depend on it). Throws std::invalid_argument for options that do not go together.
HarnessSources write_harness(const model::Model &model, model::ChartId chart, const EmitOptions &emit,
                             const HarnessOptions &options);

/// The C library functions (and `main`) the program calls with `options`: an interface function
/// may not have one of these names, as the program would call it instead.
std::vector<std::string> harness_library_names(const HarnessOptions &options);

/// The interface functions the engine's header declares: those of the chart and of every chart
/// its places run (sub-charts), in model order.
std::vector<model::FunctionId> engine_functions(const model::Model &model, model::ChartId root);

}  // namespace gfec::c_backend
