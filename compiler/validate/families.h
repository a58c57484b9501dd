// The passes of the validator, one family of checks per file; validate.cc runs them in order.
#pragma once

#include "validate/context.h"
#include "validate/expr.h"

#include <cstddef>

namespace gfec::validation {

/// symbols.cc: declares every top-level name of every file (so any file may use any other's),
/// file by file in program order, each file's declarations in textual order.
void collect_symbols(Context &cx);

/// validate_interface.cc: interface functions (their prototypes are checked here) and
/// file-level constants (folded later, on first use or by fold_file_consts).
void declare_interface(Context &cx, const ast::Interface &iface);
void declare_file_const(Context &cx, const ast::ValueDecl &decl);
void fold_file_consts(Context &cx);
/// Once every global name is declared: no interface function has a name the C engine of a
/// chart defines (`P_init` for a chart P).
void check_engine_names(Context &cx);

/// validate_chart.cc: a chart's name now; its body later, once every global name is known.
void declare_chart(Context &cx, ast::Chart &chart);
void validate_chart(Context &cx, model::ChartId index);

/// subcharts.cc: resolves every `runs`, reports charts that run themselves and sub-chart
/// periods that disagree with their parents', and fills Context::runs and inherited_period.
void resolve_subcharts(Context &cx);

/// validate_sfc.cc and validate_fsm.cc: the rules of each kind, run by validate_chart once the
/// chart's names, bodies and conditions are lowered. `watch` began with the chart: its
/// warnings are given only if it has no errors.
void check_sfc(Context &cx, ChartScope &chart, const ErrorWatch &watch);
/// named_actions.cc: the named actions of a chart and the associations of its places (§14).
void check_named_actions(Context &cx, ChartScope &chart);
void check_fsm(Context &cx, ChartScope &chart, const ErrorWatch &watch);

/// validate_toolbox.cc: a toolbox and its templates, checked and lowered at once (they use no
/// other name).
void declare_toolbox(Context &cx, const ast::Toolbox &toolbox);
/// Once every global name is declared: the C++ classes of toolboxes (their environments and
/// templates) clash with no other global C++ name (a plan's factory, another toolbox's class).
void check_toolbox_classes(Context &cx);

/// validate_plan.cc
void declare_plan(Context &cx, const ast::Plan &plan);
void validate_plan(Context &cx, model::PlanId index);
/// Reports every plan that contains itself, directly or through sub-plans.
void check_plan_recursion(Context &cx);
/// Reports a config entry that a plan and a sub-plan it runs declare with different types (an
/// error) or different initial values (-Wconfig-initial).
void check_shared_config(Context &cx);

/// Lowers the condition of transition `index` (the sfc and fsm checks, once the places' bodies
/// are lowered).
void lower_transition_condition(Context &cx, ChartScope &chart, std::size_t index);

/// Resolves the input and output places of transition `index` into its model transition, with
/// the family's rules (validate_sfc.cc, validate_fsm.cc), and frees their names. Called as each
/// model transition is made, before any body is lowered: a chart of a million places then never
/// holds the names and the model's lists at once (docs/performance.md).
void resolve_sfc_places(Context &cx, ChartScope &chart, std::size_t index);
void resolve_fsm_places(Context &cx, ChartScope &chart, std::size_t index);

/// Whether a condition is constant, and its value (no condition is `when true`).
std::optional<bool> constant_condition(const HeapOptional<model::Expr> &condition, const model::Model &model);

}  // namespace gfec::validation
