// The generated C engine under `gfec test` (docs/testing-charts.md "How the C engine is run"):
// the C back end's engine for the test's chart, plus the harness that backends/c/c_harness.h
// writes for it (glue.c and harness.c, with Steps inputs and Records), built with the system C compiler ($CC, else
// `cc`) once per distinct engine and run once per test.
//
// The exchange is plain text. The runner writes the test's steps to the harness's stdin, one a
// line: `set A F VALUE` (A the agent, -1 for every agent; F the function's index in the model;
// VALUE as the engines print it) and `tick`. The harness prints, after _init and after every
// tick:
//
//   tick                     (before a tick's calls; absent for the snapshot after _init)
//   agent 1                  a team machine: the lines that follow are this agent's
//   call Motor(1, 0.5)       every interface call, in order, formatted as `gfec run` prints it
//   av 1 0 1 0               the activation of each place (X_activation)
//   inst 0 1 0               each sub-chart instance's activation (X_instance_activation)
//   state 2 0                fsm only: X_state and X_status
//   var 0 3                  each variable, by index, formatted like `call` arguments
//   timer 1 5                each timed place's timer, in ticks
//   end
//
// Lines it does not know (a verbatim block's printf, say) are ignored.
#pragma once

#include "backend.h"
#include "model.h"
#include "scenario/reference_run.h"
#include "scenario/scenario.h"

#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace gfec {

/// Builds engines into one temporary folder, removed with the object.
class EngineBuilds {
public:
  EngineBuilds();
  ~EngineBuilds();
  EngineBuilds(const EngineBuilds &) = delete;
  EngineBuilds &operator=(const EngineBuilds &) = delete;

  struct Build {
    std::string program;  ///< the harness executable, or "" when it could not be built
    std::string error;    ///< why not
  };

  /// The harness for chart `chart` of `model` (generated from `source_name`) running `agents`
  /// engines side by side (a team machine; else 1): built on first use, then reused for every
  /// engine with the same generated code. Thread-safe.
  Build get(const model::Model &model, model::ChartId chart, const std::string &source_name, int agents);

  /// Runs `test` on a built harness; `id` names its input and output files. The records of
  /// the ticks in `keep` are kept (null: every tick's).
  scenario::Run run(const Build &build, const model::Model &model, const scenario::Test &test, int id,
                    scenario::KeptTicks keep);

  /// Chooses the compiler of the host harness (docs/testing-charts.md "The C compiler"): the first
  /// of $HOST_CC, $CC and `cc` that builds a program this machine runs (an exported cross
  /// compiler's does not). False when none does; `notes` says what was tried and why not.
  bool choose_compiler(std::vector<std::string> &notes);
  const std::string &compiler() const { return cc_; }

  bool ok() const { return !folder_.empty(); }
  const std::string &folder() const { return folder_; }

private:
  std::string cc_ = "cc";

private:
  std::string folder_;
  std::mutex mutex_;
  std::map<std::size_t, Build> builds_;  ///< by hash of the generated engine and harness
};

}  // namespace gfec
