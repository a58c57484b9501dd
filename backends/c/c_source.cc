// engine.c around the run function: includes, the chart file's verbatim code, _init and the
// accessors.
#include "c_emit.h"
#include "c_expr.h"
#include "c_floating_use.h"
#include "c_form.h"
#include "c_trace.h"

#include <fmt/format.h>

#include <utility>

namespace gfec::c_backend {

namespace {

/// Some context of the tree (the root or an instance at any depth) satisfies `test`.
template <typename Test> bool any_context(const EngineContext &c, const Test &test) {
  if (test(c)) return true;
  for (const auto &s : c.sub)
    if (s && any_context(*s, test)) return true;
  return false;
}

void includes(CodeWriter &w, const EngineContext &c) {
  directive(w, "#include " + c_string_literal(c.header_file));
  // The header found first may be a stale one (another folder on the include path): refuse it.
  directive(w, "#ifndef " + c.layout_macro());
  directive(w, "#error \"the header found is not the one generated with this file: regenerate both from the chart\"");
  directive(w, "#endif");
  // No hosted header in any mode (a freestanding C99 engine). The postconditions' checks (of the
  // root and of every instance) use X_ASSERT, which the user may define (before this point: on
  // the command line or in a verbatim block) to the firmware's own handler; by default it is
  // <assert.h>'s assert.
  if (any_context(c, [](const EngineContext &x) { return x.has_post; })) {
    w.blank();
    directive(w, "#ifdef " + c.checks_macro);
    directive(w, "#ifndef " + c.assert_macro);
    directive(w, "#include <assert.h>");
    directive(w, "#define " + c.assert_macro + "(cond) assert(cond)");
    directive(w, "#ifdef NDEBUG");
    directive(w, "#define " + c.assert_off_macro + " /* assert is off: skip the checks' temporaries too */");
    directive(w, "#endif");
    directive(w, "#endif");
    directive(w, "#endif");
  }
}

/// C lets a compiler fuse `a * b + c` into one multiply-add with one rounding (gcc does by
/// default outside ISO mode, on a Cortex-M4F or x86 with FMA); the language rounds after every
/// operation, as the interpreter does. clang obeys the standard pragma; gcc ignores it and takes
/// its own (which avr-gcc and arm-none-eabi-gcc understand too).
void no_contraction(CodeWriter &w, const EngineContext &c) {
  if (floating_use(c).rounding) {
    // T(x) of a floating x (docs/language.md §4), IEC's REAL_TO_INT: no <math.h> needed. The
    // difference of x and its truncation is exact, so the tie is decided exactly.
    w.blank();
    w.line("/* A floating value rounded to the nearest integer, ties away from zero (docs/language.md §4). */");
    w.line("static int64_t gfec_round(double x)");
    w.line("{");
    w.line("    int64_t t = (int64_t)x;");
    w.line("    double d = x - (double)t;");
    w.line("    return d >= 0.5 ? t + 1 : (d <= -0.5 ? t - 1 : t);");
    w.line("}");
  }
  if (!floating_use(c).arithmetic) return;
  w.blank();
  w.line("/* Floating arithmetic rounds after every operation, as the language computes it: no fused");
  w.line("   multiply-add (docs/targets.md). */");
  directive(w, "#if defined(__clang__)");
  directive(w, "#pragma STDC FP_CONTRACT OFF");
  directive(w, "#elif defined(__GNUC__)");
  directive(w, "#pragma GCC optimize(\"fp-contract=off\")");
  directive(w, "#endif");
}

/// The `%{ %}` blocks at file level (imports' first), where `#include`s for the chart's code go.
void verbatims(CodeWriter &w, const EngineContext &c) {
  for (const auto &v : c.model.verbatims) {
    w.blank();
    w.verbatim(c.model.sources(), v.range, v.text, v.code_begin);
    w.line_back();
  }
}

void init(CodeWriter &w, const EngineContext &c) {
  std::vector<std::string> initial;
  for (const auto &p : c.chart.places)
    if (p.initial) initial.push_back(p.name.str());
  std::string list;
  for (std::size_t i = 0; i < initial.size(); ++i)
    list += (i == 0 ? "" : i + 1 == initial.size() ? " and " : ", ") + initial[i];
  if (c.fsm) w.line("/* Initial state: {}. Calls no code of the chart. */", list);
  else
    w.line("/* Initial marking: {} {} active. Calls no code of the chart. */", list,
           initial.size() == 1 ? "is" : "are");
  w.line("{}void {}({} *{})", c.linkage, c.init_fn, c.struct_type, c.self);
  auto body = w.block("{");
  if (c.team()) w.line("int {};", c.index);
  c.form().init(w, c);
  for (model::PlaceId p : c.chart.places.ids())
    if (c.place(p).timed) w.line("{} = 0;", c.timer_of(p));
  if (c.needs_started) w.line("{} = false;", c.field(c.started));
  if (c.chart.clock) w.line("{} = 0;", c.field(c.clock));
  // Action control starts clear: no action stored or active, no place active before tick 1 (so
  // that an initial place rises in tick 1).
  for (model::ActionId a : c.action_q.ids()) {
    if (!c.action_stored[a].empty()) w.line("{} = false;", c.field(c.action_stored[a]));
    for (const std::string *timed : {&c.action_sd[a], &c.action_sl[a]})
      if (!timed->empty()) w.line("{} = false;", c.field(*timed));
    for (const std::string *timer : {&c.action_sd_timer[a], &c.action_sl_timer[a]})
      if (!timer->empty()) w.line("{} = 0u;", c.field(*timer));
    if (!c.action_q[a].empty()) w.line("{} = false;", c.field(c.action_q[a]));
    if (!c.action_a[a].empty()) w.line("{} = false;", c.field(c.action_a[a]));
  }
  for (model::PlaceId p : c.was_active.ids())
    if (!c.was_active[p].empty()) w.line("{} = false;", c.field(c.was_active[p]));
  if (!c.acted.empty()) w.line("{} = false;", c.field(c.acted));
  if (c.traced()) trace_init(w, c);
  if (c.team()) {
    w.line("{} = 0;", c.field(c.agent));
    auto each = w.block(fmt::format("for ({0} = 0; {0} < {1}; ++{0}) {{", c.index, c.team_size));
    w.line("{}[{}] = -1;", c.field(c.reports), c.index);
  }
  for (model::VarId v : c.chart.vars.ids()) {
    const auto &var = c.chart.vars[v];
    std::string value = var.init ? c_value(c, *var.init, var.type) : var.type == model::Type::Bool ? "false" : "0";
    w.line("{} = {};", c.field(c.var_field[v]), value);
  }
  // Every instance is reset, not only the initial places': none runs before its place gains
  // activation (which resets it again), and the whole state is defined from here on.
  for (model::PlaceId p : c.chart.places.ids())
    if (c.sub[p])
      w.line("{}(&{}); /* the instance of {} run by {} */", c.sub[p]->init_fn, c.field(c.sub_field[p]),
             c.sub[p]->chart.name, c.place(p).name);
}

/// An instance's stop (docs/language.md, "Sub-charts"): for each active place in declaration order, the stop of
/// the place's own instance, then the place's exit block; innermost first.
void stop(CodeWriter &w, const EngineContext &c) {
  w.line("/* Stops the instance of {} run by {}:", c.chart.name, c.owner);
  w.line("   each active {} in declaration order stops its own instance, then runs its exit block",
         c.fsm ? "state" : "place");
  w.line("   (innermost first). Leaves the state as it is. */");
  w.line("{}void {}({} *{})", c.linkage, c.stop_fn, c.struct_type, c.self);
  auto body = w.block("{");
  Temporaries temps(c.temp_prefix);
  for (model::PlaceId p : c.chart.places.ids()) {
    const auto &place = c.place(p);
    std::vector<std::string> first = c.stop_call(p);
    if (first.empty() && !has_code(place.exit)) continue;
    auto if_active = w.block(fmt::format("if ({}) {{", c.active_test("", p)));
    std::vector<model::Stmt> stmts = has_code(place.exit) ? *place.exit : std::vector<model::Stmt>{};
    std::vector<std::string> text = c_statements(c, stmts, temps);
    temps.declare(w);
    for (const auto &l : first) w.line(std::string_view(l));
    if (!stmts.empty()) w.line("/* exit {} */", place.name);
    emit_statements(w, c, stmts, text);
    w.line_back();
  }
}

/// An instance's code, its own instances' first (a static function is defined before its use):
/// enumerations, the sparse form's helpers, _init, _stop and _run.
void instance(CodeWriter &w, const EngineContext &c) {
  for (const auto &s : c.sub)
    if (s) instance(w, *s);
  w.line("/* ---- The instance of {} run by {} (its enumerations are in the header, with its struct) */", c.chart.name,
         c.owner);
  w.blank();
  c.form().helpers(w, c);
  init(w, c);
  w.blank();
  if (c.has_stop()) {
    stop(w, c);
    w.blank();
  }
  c.form().run(w, c);
  w.blank();
}

/// X_set_agent, X_report and X_team (docs/c-engine.md "Team machines").
void team_functions(CodeWriter &w, const EngineContext &c) {
  const std::string &t = c.type, &m = c.self;
  w.line("void {}({} *{}, int agent)", c.set_agent_fn, t, m);
  {
    auto body = w.block("{");
    auto valid = w.block(fmt::format("if ((agent >= 0) && (agent < {})) {{", c.team_size));
    w.line("{} = agent;", c.field(c.agent));
  }
  w.blank();
  w.line("void {}({} *{}, int agent, int state)", c.report_fn, t, m);
  {
    auto body = w.block("{");
    auto valid = w.block(
        fmt::format("if ((agent >= 0) && (agent < {}) && (agent != {}) && (state >= 0) && (state < (int){})) {{",
                    c.team_size, c.field(c.agent), c.place_count));
    w.line("{}[agent] = ({})state;", c.field(c.reports), c.report_type());
  }
  w.blank();
  w.line("int32_t {}(const {} *{}, int state)", c.team_fn, t, m);
  auto body = w.block("{");
  w.line("int agent;");
  w.line("int32_t n = 0;");
  {
    auto each = w.block(fmt::format("for (agent = 0; agent < {}; ++agent) {{", c.team_size));
    auto same =
        w.block(fmt::format("if ((agent != {}) && ({}[agent] == state)) {{", c.field(c.agent), c.field(c.reports)));
    w.line("++n;");
  }
  w.line("return n;");
}

/// X_instance_activation (docs/c-engine.md "Sub-charts"): a case per instance, each reading the
/// instance's state as its own form holds it.
void instance_activation(CodeWriter &w, const EngineContext &c) {
  w.line("uint32_t {}(const {} *{}, int instance, int place)", c.instance_activation_fn, c.type, c.self);
  auto body = w.block("{");
  w.line("uint32_t value = 0u;");
  // The labels stand at the level of the switch, what they run one level in.
  w.line("switch (instance) {");
  c.each_instance(c.self + "->", [&](const EngineContext &s, const std::string &member) {
    // As X_activation reads the root's, with if statements: MISRA C:2012 rule 10.6 forbids
    // assigning a conditional expression's narrow unsigned to the wider result.
    w.line("case {}:", s.instance_const);
    auto in_case = w.indented();
    const ActivationRead read = s.form().activation(s, member);
    {
      auto in_it = w.block(fmt::format("if ({}) {{", read.test));
      w.line("value = {};", read.value);
    }
    w.line("break;");
  });
  w.line("default:");
  {
    auto in_default = w.indented();
    w.line("break;");
  }
  w.line("}");
  w.line("return value;");
}

void accessors(CodeWriter &w, const EngineContext &c) {
  const std::string &t = c.type, &m = c.self;
  w.line("uint32_t {0}_activation(const {0} *{1}, int place)", t, m);
  {
    auto body = w.block("{");
    const ActivationRead read = c.form().activation(c, "");
    w.line("return ({}) ? {} : 0u;", read.test, read.value);
  }
  if (c.has_sub()) {
    w.blank();
    instance_activation(w, c);
  }
  c.form().accessors(w, c);
}

/// --context: X_set_context and X_context (docs/c-engine.md "Instance context"). Each instance
/// keeps a copy, so that its functions pass it as the root's do; the setter writes every copy.
void context_functions(CodeWriter &w, const EngineContext &c) {
  const std::string &t = c.type, &m = c.self;
  w.line("void {}({} *{}, {})", c.set_context_fn, t, m, c.context_param(c.ctx_param));
  {
    auto body = w.block("{");
    w.line("{} = {};", c.field(c.ctx_field), c.ctx_param);
    // `m->Search.ctx`, `m->Search.Inner.ctx`: parents first.
    c.each_instance(m + "->", [&](const EngineContext &s, const std::string &member) {
      w.line("{}.{} = {};", member, s.ctx_field, c.ctx_param);
    });
  }
  w.blank();
  w.line("{}(const {} *{})", c.context_param(c.context_fn), t, m);
  auto body = w.block("{");
  w.line("return {};", c.field(c.ctx_field));
}

/// --names: the declared names of the root's places and transitions (docs/c-engine.md).
void name_functions(CodeWriter &w, const EngineContext &c) {
  auto table = [&](const std::string &fn, const char *param, const std::string &count,
                   const std::vector<std::string> &names) {
    w.line("const char *{}(int {})", fn, param);
    auto body = w.block("{");
    if (names.empty()) {  // C has no empty array
      w.line("(void){};", param);
      w.line("return 0;");
    } else {
      {
        auto rows = w.block(fmt::format("static const char *const {}[{}] = {{", c.names, count), "};");
        for (const auto &n : names) w.line("{},", c_string_literal(n));
      }
      w.line("return {0} >= 0 && {0} < {1} ? {2}[{0}] : 0;", param, count, c.names);
    }
  };
  std::vector<std::string> places, transitions;
  for (const auto &p : c.chart.places) places.push_back(p.name.str());
  for (const auto &tr : c.chart.transitions) transitions.push_back(tr.name.str());
  table(c.place_name_fn, "place", c.place_count, places);
  w.blank();
  table(c.transition_name_fn, "transition", c.transition_count, transitions);
}

}  // namespace

std::string transition_label(const EngineContext &c, const model::Transition &t) {
  auto side = [&](const model::PlaceList &places) {
    std::string s;
    for (model::PlaceId p : places) s += (s.empty() ? "" : ", ") + c.place(p).name;
    return places.size() == 1 ? s : "(" + s + ")";
  };
  return side(t.inputs) + " -> " + side(t.outputs);
}

std::string banner(const EngineContext &c) {
  // A file name cannot be allowed to end the comment early.
  std::string source = c.options.source_name;
  for (std::size_t at; (at = source.find("*/")) != std::string::npos;) source.replace(at, 2, "* /");
  return fmt::format("/* Generated by gfec {} from {}. Do not edit: change the chart and regenerate. */", GFEC_VERSION,
                     source);
}

void directive(CodeWriter &w, const std::string &text) { w.raw(text + "\n"); }

void emit_source(const EngineContext &c, std::ostream &out) {
  CodeWriter w(out, c.source_file, c.options.line_directives);
  w.line(std::string_view(banner(c)));
  includes(w, c);
  no_contraction(w, c);
  verbatims(w, c);
  w.blank();
  if (!c.calls_buffer.empty()) {
    emit_trace_calls(w, c);
    w.blank();
  }
  for (const auto &s : c.sub)
    if (s) instance(w, *s);
  if (c.has_sub()) {
    w.line("/* ---- The compiled chart, {} */", c.chart.name);
    w.blank();
  }
  c.form().helpers(w, c);
  init(w, c);
  w.blank();
  if (c.team()) {
    team_functions(w, c);
    w.blank();
  }
  c.form().run(w, c);
  w.blank();
  accessors(w, c);
  if (c.has_context()) {
    w.blank();
    context_functions(w, c);
  }
  if (c.engine_options.names) {
    w.blank();
    name_functions(w, c);
  }
  if (c.traced()) {
    w.blank();
    emit_trace(w, c);
  }
}

}  // namespace gfec::c_backend
