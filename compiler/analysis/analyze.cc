#include "analysis/analysis.h"

#include "analysis/passes.h"

#include <cctype>

namespace gfec::analysis {

namespace {

bool any_on(const Diagnostics &diag, std::initializer_list<Warning> ws) {
  for (Warning w : ws)
    if (diag.warning_options().is_on(w)) return true;
  return false;
}

bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

void run(const model::Model &m, Diagnostics &diag, const Limits &limits, std::string &summary, bool everything) {
  const bool sfc = everything || any_on(diag, {Warning::UnsafePlace, Warning::UnboundedPlace, Warning::Deadlock,
                                               Warning::DeadJoin, Warning::UnjoinedFork, Warning::UnreachablePlace,
                                               Warning::DeadTransition});
  const bool fsm = everything || any_on(diag, {Warning::TrapState, Warning::ShadowedTransition});
  const bool plan = everything || any_on(diag, {Warning::UninitializedConfig, Warning::SupervisorRace});
  for (const auto &c : m.charts) {
    if (!c.in_main_file) continue;
    if (c.kind == model::Chart::Kind::Sfc && sfc) check_sfc(m, c, diag, limits, summary);
    if (c.kind == model::Chart::Kind::Fsm && fsm) check_fsm(m, c, diag, summary);
  }
  for (const auto &p : m.plans)
    if (p.in_main_file && plan) check_plan(m, p, diag, summary);
}

} // namespace

SourceRange name_in(const model::Model &m, SourceRange decl, const std::string &name) {
  if (!m.sources || decl.file >= m.sources->size() || name.empty()) return decl;
  const std::string &text = m.sources->file(decl.file).text();
  std::size_t end = std::min<std::size_t>(decl.end, text.size());
  for (std::size_t at = text.find(name, decl.begin); at != std::string::npos && at + name.size() <= end;
       at = text.find(name, at + 1)) {
    bool starts = at == 0 || !is_word(text[at - 1]);
    bool ends = at + name.size() >= text.size() || !is_word(text[at + name.size()]);
    if (starts && ends) return {decl.file, static_cast<std::uint32_t>(at), static_cast<std::uint32_t>(at + name.size())};
  }
  return decl;
}

void analyze(const model::Model &model, Diagnostics &diag, const Limits &limits) {
  std::string ignored;
  run(model, diag, limits, ignored, false);
}

std::string analysis_report(const model::Model &model, Diagnostics &diag, const Limits &limits) {
  std::string summary;
  run(model, diag, limits, summary, true);
  return summary;
}

} // namespace gfec::analysis
