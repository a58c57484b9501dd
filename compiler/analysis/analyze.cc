#include "analysis/analysis.h"

#include "analysis/passes.h"

namespace gfec::analysis {

namespace {

bool any_on(const Diagnostics &diag, std::initializer_list<Warning> ws) {
  for (Warning w : ws)
    if (diag.warning_options().is_on(w)) return true;
  return false;
}

void run(const model::Model &m, Diagnostics &diag, const Limits &limits, std::string &summary, bool everything) {
  const bool sfc =
      everything || any_on(diag, {Warning::UnsafePlace, Warning::UnboundedPlace, Warning::Deadlock, Warning::DeadJoin,
                                  Warning::UnjoinedFork, Warning::UnreachablePlace, Warning::DeadTransition});
  const bool fsm = everything || any_on(diag, {Warning::TrapState, Warning::ShadowedTransition});
  const bool plan = everything || any_on(diag, {Warning::UninitializedConfig, Warning::SupervisorRace});
  for (const auto &c : m.charts) {
    if (!c.in_main_file) continue;
    if (c.kind == model::Chart::Kind::Sfc && sfc) check_sfc(m, c, diag, limits, summary);
    if (c.kind == model::Chart::Kind::Fsm && fsm) check_fsm(m, c, diag, summary);
    if (everything || diag.warning_options().is_on(Warning::DeadTransition)) check_exclusive_states(m, c, diag);
  }
  for (const auto &p : m.plans)
    if (p.in_main_file && plan) check_plan(m, p, diag, summary);
}

}  // namespace

void analyze(const model::Model &model, Diagnostics &diag, const Limits &limits) {
  std::string ignored;
  run(model, diag, limits, ignored, false);
}

std::string analysis_report(const model::Model &model, Diagnostics &diag, const Limits &limits) {
  std::string summary;
  run(model, diag, limits, summary, true);
  return summary;
}

}  // namespace gfec::analysis
