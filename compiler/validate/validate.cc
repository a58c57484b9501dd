// The validator's entry point: the passes in order. Names first (every file's), then each
// chart and plan against them, then what needs every plan lowered.
#include "validate.h"

#include "scenario/scenario.h"
#include "scenario/validate_tests.h"
#include "validate/blocks.h"
#include "validate/families.h"

#include <fmt/format.h>

namespace gfec {

namespace {

/// File-level %{ %} blocks: dependencies first (imports are reached after the file importing
/// them, so reverse program order), the main file last.
void collect_verbatims(validation::Context &cx) {
  const auto &files = cx.program.files;
  for (auto it = files.rbegin(); it != files.rend(); ++it) {
    if (!*it) continue;
    for (const ast::Verbatim &v : (*it)->verbatims) {
      cx.diag.warning(Warning::Verbatim, v.range, "verbatim code is copied unchecked: gfec cannot check it");
      cx.model.verbatims.push_back({v.text, v.range, v.range.begin + 2});  // the lexer's range starts at `%{`
    }
  }
}

/// A constant of the main file that nothing reads (-Wunused-const): one of a chart, or one at
/// file level when the file declares a chart or plan. An interface's or toolbox's constants are
/// there for the files importing it, so a file declaring only those is not warned about. Not
/// after errors.
void warn_unused_consts(validation::Context &cx) {
  const ast::File *main = cx.program.files.empty() ? nullptr : cx.program.files.front().get();
  // After an error a constant may be unread because its use was refused (`N()` of a constant):
  // the warning would only repeat the error.
  if (!main || cx.diag.has_errors()) return;
  const bool compiled = !main->charts.empty() || !main->plans.empty() || !main->tests.empty();
  for (model::ConstId k : cx.model.consts.ids()) {
    const model::Const &c = cx.model.consts[k];
    const validation::ConstSource &source = cx.consts[k];
    if (source.used || source.state == validation::ConstSource::State::Failed) continue;
    if (c.range.file != cx.model.main_file || (!c.chart && !compiled)) continue;
    cx.diag.warning(Warning::UnusedConst, source.decl ? source.decl->name.range : c.range,
                    fmt::format("constant '{}' is never used", c.name));
  }
}

}  // namespace

model::Model validate(ast::Program &program, const SourceManager &sources, Diagnostics &diag) {
  scenario::Suite tests;
  return validate(program, sources, diag, tests);
}

model::Model validate(ast::Program &program, const SourceManager &sources, Diagnostics &diag, scenario::Suite &tests,
                      const ValidateOptions &options) {
  model::Model model;
  model.set_sources(sources);
  if (!program.files.empty() && program.files.front()) model.main_file = program.files.front()->id;
  validation::Context cx(program, sources, diag, model);
  cx.keep_tree = options.keep_tree;
  cx.declaring_files = options.declaring_files;
  cx.uses = options.name_uses;
  for (validation::Namespace *ns : {&cx.c_names, &cx.plan_names, &cx.interfaces, &cx.toolboxes}) ns->uses = cx.uses;

  validation::collect_symbols(cx);
  validation::collect_blocks(cx);
  collect_verbatims(cx);
  validation::fold_file_consts(cx);
  validation::resolve_subcharts(cx);
  for (model::ChartId c : model.charts.ids()) validation::validate_chart(cx, c);
  validation::validate_unused_blocks(cx);
  for (model::PlanId p : model.plans.ids()) validation::validate_plan(cx, p);
  validation::check_plan_recursion(cx);
  validation::check_shared_config(cx);
  validation::validate_tests(cx, tests);
  warn_unused_consts(cx);
  return model;
}

}  // namespace gfec
