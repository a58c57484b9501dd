// engine.h: everything the encapsulating code and the robot library need, and nothing else.
#include "c_emit.h"
#include "c_expr.h"
#include "c_floating_use.h"
#include "c_form.h"
#include "c_trace.h"
#include "naming/naming.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace gfec::c_backend {

namespace {

/// Lines `decl; /* comment */` with the comments in one column.
void aligned(CodeWriter &w, const std::vector<std::pair<std::string, std::string>> &rows) {
  std::size_t width = 0;
  for (const auto &r : rows) width = std::max(width, r.first.size());
  for (const auto &r : rows) w.line("{:<{}} /* {} */", r.first, width, r.second);
}

}  // namespace

void places_enum(CodeWriter &w, const EngineContext &c) {
  if (c.root)
    w.line("/* The {} of {} {}, in declaration order. */", c.fsm ? "states" : "places", c.fsm ? "fsm" : "sfc", c.type);
  else
    w.line("/* The {} of {} {}, in declaration order: the instance run by {}. */", c.fsm ? "states" : "places",
           c.fsm ? "fsm" : "sfc", c.chart.name, c.owner);
  auto members = w.block("typedef enum {", fmt::format("}} {};", c.place_type));
  for (const auto &name : c.place_const) w.line("{},", name);
  w.line("{}", c.place_count);
}

void transitions_enum(CodeWriter &w, const EngineContext &c) {
  w.line(c.root ? "/* Its transitions, in declaration order: the numbers the observation hooks pass. */"
                : "/* Its transitions, in declaration order. */");
  auto members = w.block("typedef enum {", fmt::format("}} {};", c.transition_type));
  // Written as the labels are made, not gathered first: a chart can have a million transitions.
  std::size_t width = 0;
  for (model::TransitionId t : c.chart.transitions.ids()) width = std::max(width, c.transition_const[t].size());
  for (model::TransitionId t : c.chart.transitions.ids())
    w.line("{},{:<{}} /* {} */", c.transition_const[t], "", width - c.transition_const[t].size(),
           transition_label(c, c.chart.transitions[t]));
  w.line("{}", c.transition_count);
}

void team_enum(CodeWriter &w, const EngineContext &c) {
  w.line("/* A team machine: up to {} agents run it side by side, one engine each. */", c.chart.team);
  w.line("enum {{ {} = {} }};", c.team_size, c.chart.team);
}

namespace {

void state_struct(CodeWriter &w, const EngineContext &c) {
  // The instances' types first: the root's struct embeds them.
  for (const auto &s : c.sub)
    if (s) state_struct(w, *s);
  // An instance's enumerations come with its struct: an fsm instance's state field has their type.
  if (!c.root) {
    places_enum(w, c);
    w.blank();
    transitions_enum(w, c);
    w.blank();
  }
  if (c.root) {
    w.line("/* The state of one engine. The type is complete so that the caller can allocate it (several");
    bool io = false;
    for (const model::Var &v : c.chart.vars) io = io || v.role != model::VarRole::Local;
    if (io) {
      // docs/iec.md "The C engine of an imported program": the caller's part of the struct.
      w.line("   engines may run side by side); only the functions below use its fields, but for the");
      w.line("   inputs, which the caller sets before a tick, and the outputs, which it reads after. */");
    } else {
      w.line("   engines may run side by side); only the functions below use its fields. */");
    }
    w.line("typedef struct {0} {0};", c.type);
  } else {
    w.line("/* The state of the instance of {} run by {} (engine.c only uses it). */", c.chart.name, c.owner);
  }
  auto fields = w.block(fmt::format("{} {{", c.root ? "struct " + c.type : c.struct_type), "};");
  FieldRows rows;
  c.form().fields(c, rows);
  for (model::PlaceId p : c.chart.places.ids())
    if (c.place(p).timed)
      rows.emplace_back(fmt::format("uint32_t {};", c.timer_field[p]),
                        fmt::format("ticks {} has been active: elapsed({})", c.place(p).name, c.place(p).name));
  if (c.needs_started) rows.emplace_back(fmt::format("bool {};", c.started), "the first tick has run");
  if (c.chart.clock)
    rows.emplace_back(fmt::format("int64_t {};", c.clock), "ticks run: now() is this times the period");
  for (model::ActionId a : c.action_q.ids()) {
    const std::string &name = c.chart.actions[a].name.str();
    if (!c.action_stored[a].empty()) {
      // The qualifiers that set the one stored flag, each once: `S`, `DS`, `SD 0`, `SL` (one whose
      // limit the timers never reach).
      std::vector<std::string> by;
      for (const model::Association &as : c.chart.actions[a].associations) {
        if (kept_as(as) != Keep::Set) continue;
        std::string q = model::qualifier_name(as.qualifier);
        if (as.qualifier == model::Qualifier::SD) q += " 0";
        if (std::find(by.begin(), by.end(), q) == by.end()) by.push_back(q);
      }
      rows.emplace_back(fmt::format("bool {};", c.action_stored[a]),
                        fmt::format("action {} set ({}), until reset (R)", name, fmt::join(by, ", ")));
    }
    if (!c.action_sd[a].empty()) {
      rows.emplace_back(fmt::format("bool {};", c.action_sd[a]),
                        fmt::format("action {} set (SD), until reset (R)", name));
      rows.emplace_back(fmt::format("uint32_t {};", c.action_sd_timer[a]),
                        fmt::format("ticks since action {} was set (SD)", name));
    }
    if (!c.action_sl[a].empty()) {
      rows.emplace_back(fmt::format("bool {};", c.action_sl[a]),
                        fmt::format("action {} set (SL), until reset (R)", name));
      rows.emplace_back(fmt::format("uint32_t {};", c.action_sl_timer[a]),
                        fmt::format("ticks since action {} was set (SL)", name));
    }
    if (!c.action_q[a].empty())
      rows.emplace_back(fmt::format("bool {};", c.action_q[a]),
                        fmt::format("action {} was active (Q) in the last tick", name));
    if (!c.action_a[a].empty())
      rows.emplace_back(fmt::format("bool {};", c.action_a[a]),
                        fmt::format("action {} ran in the last tick: running({})", name, name));
  }
  for (model::PlaceId p : c.was_active.ids())
    if (!c.was_active[p].empty())
      rows.emplace_back(fmt::format("bool {};", c.was_active[p]),
                        fmt::format("{} was active at the last tick's action control", c.place(p).name));
  if (!c.acted.empty()) rows.emplace_back(fmt::format("bool {};", c.acted), "the first tick's action control has run");
  if (c.team()) {
    rows.emplace_back(fmt::format("int32_t {};", c.agent),
                      fmt::format("this engine's agent number (set by {})", c.set_agent_fn));
    rows.emplace_back(fmt::format("{} {}[{}];", c.report_type(), c.reports, c.team_size),
                      "by agent, the state it last reported; -1: none yet");
  }
  for (model::VarId v : c.chart.vars.ids()) {
    const model::Var &var = c.chart.vars[v];
    std::string what = var.role == model::VarRole::In ? fmt::format("in {}: the caller sets it before a tick", var.name)
                       : var.role == model::VarRole::Out
                           ? fmt::format("out {}: the caller reads it after a tick", var.name)
                       : var.role == model::VarRole::InOut
                           ? fmt::format("inout {}: the caller sets it before a tick and reads it after", var.name)
                           : fmt::format("var {}", var.name);
    if (var.type == model::Type::Time) what += " (a time: milliseconds)";
    rows.emplace_back(fmt::format("{} {};", c_type(var.type), c.var_field[v]), std::move(what));
  }
  for (model::PlaceId p : c.chart.places.ids())
    if (c.sub[p])
      rows.emplace_back(fmt::format("{} {};", c.sub[p]->struct_type, c.sub_field[p]),
                        fmt::format("the instance of {} that {} runs", c.sub[p]->chart.name, c.place(p).name));
  if (c.traced()) trace_fields(c, rows);
  if (c.has_context())
    rows.emplace_back(c.context_param(c.ctx_field) + ";",
                      c.root ? fmt::format("the context every interface call receives first ({})", c.set_context_fn)
                             : fmt::format("a copy of the root's context ({})", c.set_context_fn));
  aligned(w, rows);
  fields.end();
  if (!c.root) w.blank();
}

/// docs/c-engine.md "Team machines": the engine never sends or receives; its caller does.
void team_api(CodeWriter &w, const EngineContext &c) {
  const std::string &t = c.type;
  w.line("/* Team machine: {0}_init makes the engine agent 0 and forgets every report. Call", t);
  w.line("   {0}_set_agent after {0}_init; a number outside 0 ... {1} - 1 is ignored. */", t, c.team_size);
  w.line("void {0}({1} *m, int agent);", c.set_agent_fn, t);
  w.line("/* Agent `agent` is in state `state` (a {}_<state>): call it between ticks, when its state", t);
  w.line("   arrives. Ignored for the engine's own number, a number out of range and an invalid state. */");
  w.line("void {0}({1} *m, int agent, int state);", c.report_fn, t);
  w.line("/* team(S) of the chart: how many other agents last reported `state`. */");
  w.line("int32_t {0}(const {1} *m, int state);", c.team_fn, t);
}

/// --context: the setter and the getter (docs/c-engine.md "Instance context").
void context_api(CodeWriter &w, const EngineContext &c) {
  const std::string &t = c.type;
  w.line("/* The instance context: every interface function the engine calls (and its sub-charts'");
  w.line("   instances) receives it as its first argument. Set it before the first {}_run; {}_init", t, t);
  w.line("   leaves it as it is, so either may come first. */");
  w.line("void {}({} *m, {});", c.set_context_fn, t, c.context_param(c.ctx_param));
  w.line("/* The context last set: for the observation hooks and the caller. */");
  w.line("{}({});", c.context_param(c.context_fn), fmt::format("const {} *m", t));
}

/// --names: the declared names, for logging and tracing.
void names_api(CodeWriter &w, const EngineContext &c) {
  const std::string &t = c.type;
  const char *what = c.fsm ? "state" : "place";
  w.line("/* The declared name of a {0} (a {1}_<{0}>), or a null pointer for a number out of range. */", what, t);
  w.line("const char *{}(int place);", c.place_name_fn);
  w.line("/* The declared name of a transition (a {}_<transition>), or a null pointer out of range. */", t);
  w.line("const char *{}(int transition);", c.transition_name_fn);
}

/// A chart with sub-charts: the instances' numbers and the reader of their activation
/// (docs/c-engine.md "Sub-charts"), for a caller that shows where each instance is.
void instance_api(CodeWriter &w, const EngineContext &c) {
  const std::string &t = c.type;
  w.line("/* The sub-chart instances, depth first in declaration order. */");
  auto members = w.block("typedef enum {", fmt::format("}} {};", c.instance_type));
  std::vector<std::pair<std::string, std::string>> rows;
  std::string example;  // the first instance's first place names the numbering by example
  c.each_instance("", [&](const EngineContext &s, const std::string &) {
    rows.emplace_back(s.instance_const + ",", fmt::format("{}, run by {}", s.chart.name, s.owner));
    if (example.empty()) example = s.place_const.at(model::PlaceId(0));
  });
  aligned(w, rows);
  w.line("{}", c.instance_count);
  members.end();
  w.line("/* The activation of place `place` of instance `instance`, the place numbered as in that");
  w.line("   instance's enumeration ({}, ...), as {}_activation tells the root's:", example, t);
  w.line("   where the instance is while the place that runs it is active, else where its last tick");
  w.line("   left it. 0 for a number out of range. */");
  w.line("uint32_t {}(const {} *m, int instance, int place);", c.instance_activation_fn, t);
}

void api(CodeWriter &w, const EngineContext &c) {
  const std::string &t = c.type;
  w.line("/* Sets the initial {}; calls no code of the chart. */", c.fsm ? "state" : "marking");
  w.line("void {0}_init({0} *m);", t);
  if (c.chart.period_ms > 0)
    w.line("/* One tick ({}): call it every {} ms. */", c.fsm ? "docs/language.md 7" : "docs/language.md 5.1",
           c.chart.period_ms);
  else w.line("/* One tick ({}). */", c.fsm ? "docs/language.md 7" : "docs/language.md 5.1");
  w.line("void {0}_run({0} *m);", t);
  c.form().accessor_prototypes(w, c);
  if (c.team()) team_api(w, c);  // only an fsm is a team machine
  if (c.has_sub()) instance_api(w, c);
  if (c.has_context()) context_api(w, c);
  if (c.engine_options.names) names_api(w, c);
  if (c.traced()) trace_prototype(w, c);
}

void hooks(CodeWriter &w, const EngineContext &c) {
  directive(w, "#ifdef " + c.hooks_macro);
  w.line("/* Observation hooks (GFE_Activated, GFE_Enabled): an engine built with -D{} calls them and", c.hooks_macro);
  w.line("   the encapsulating code defines them. At the end of each tick's update, in declaration order:");
  w.line("   every {} that lost (active false), then gained (active true) its activation; then every",
         c.fsm ? "state" : "place");
  w.line("   transition whose inputs are all active now but were not at the start of the tick.");
  w.line("   The engine is read only (const): a hook observes, it does not steer. */");
  w.line("void {0}(const {1} *m, {2} place, bool active);", c.activated_fn, c.type, c.place_type);
  w.line("void {0}(const {1} *m, {2} transition);", c.enabled_fn, c.type, c.transition_type);
  directive(w, "#endif");
}

/// The parameters' names as the prototype writes them: the user's, but for one with a macro's
/// name (X_HOOKS, the include guard), which takes a trailing `_` free of the others ("" for a
/// parameter without a name).
std::vector<std::string> param_names(const EngineContext &c, const model::Function &f) {
  auto is_macro = [&](const std::string &n) {
    return std::find(c.macros.begin(), c.macros.end(), n) != c.macros.end();
  };
  naming::NameSpace names;
  for (const auto &m : c.macros) names.claim(m);
  for (const auto &p : f.params)
    if (!is_macro(p.name)) names.claim(p.name);
  std::vector<std::string> out;
  for (const auto &p : f.params) out.push_back(is_macro(p.name) ? names.take(p.name) : p.name);
  return out;
}

/// --context: the prototypes' first parameter, named apart from the function's own.
std::string context_first(const EngineContext &c, const std::vector<std::string> &params) {
  if (!c.has_context()) return "";
  std::string name = c.ctx_param;
  while (std::find(params.begin(), params.end(), name) != params.end()) name += '_';
  return c.context_param(name);
}

/// `struct motor *` names a tag: declared before the struct and the prototypes use it, so that
/// a prototype does not declare it in its own scope (gcc, clang: "will not be visible outside").
void context_tag(CodeWriter &w, const EngineContext &c) {
  if (c.context_type.tag.empty()) return;
  w.line("{} {}; /* the instance context's type (--context-type) */", c.context_type.tag_keyword, c.context_type.tag);
  w.blank();
}

void interface_functions(CodeWriter &w, const EngineContext &c) {
  // Grouped by interface, each group in the order the chart's function list gives.
  std::vector<std::string> interfaces;
  for (model::FunctionId f : c.functions) {
    const auto &name = c.model.functions.at(f).interface_name;
    if (std::find(interfaces.begin(), interfaces.end(), name) == interfaces.end()) interfaces.push_back(name);
  }
  const char *who = c.has_sub() ? "the chart and its sub-charts call" : "the chart calls";
  for (const auto &iface : interfaces) {
    w.blank();
    if (iface.empty()) w.line("/* Functions {}: the robot library defines them. */", who);
    else w.line("/* Functions of interface {} that {}: the robot library defines them. */", iface, who);
    for (model::FunctionId f : c.functions) {
      const auto &fn = c.model.functions.at(f);
      if (fn.interface_name != iface) continue;
      const std::vector<std::string> params = param_names(c, fn);
      w.line("{};", c_prototype(fn, context_first(c, params), params));
    }
  }
}

}  // namespace

namespace {

/// The engine computes as the language does only where float is IEEE binary32 and double
/// binary64 (docs/targets.md): elsewhere (avr-gcc's double is 32 bits) it does not compile,
/// rather than compute other values.
void exact_types(CodeWriter &w, const EngineContext &c) {
  const FloatingUse use = floating_use(c);
  if (!use.float_type && !use.double_type) return;
  directive(w, "#include <float.h>");
  w.blank();
  w.line("/* The floating types as the language has them (docs/targets.md): a compiler whose types differ");
  w.line("   refuses the engine. (FLT_MANT_DIG is C99's own; a checker that reads no <float.h> skips this.) */");
  if (use.float_type) {
    directive(w, "#if defined(FLT_MANT_DIG) && ((FLT_RADIX != 2) || (FLT_MANT_DIG != 24) || (FLT_MAX_EXP != 128) || "
                 "(FLT_MIN_EXP != -125))");
    directive(w, fmt::format("#error \"{}: its float must be IEEE binary32, which this compiler's float is not: see "
                             "docs/targets.md in gfec's documentation\"",
                             c.type));
    directive(w, "#endif");
  }
  if (use.double_type) {
    directive(w, "#if defined(DBL_MANT_DIG) && ((FLT_RADIX != 2) || (DBL_MANT_DIG != 53) || (DBL_MAX_EXP != 1024) || "
                 "(DBL_MIN_EXP != -1021))");
    directive(
        w, fmt::format("#error \"{}: its double must be IEEE binary64, which this compiler's double is not (avr-gcc's "
                       "is 32 bits): see docs/targets.md in gfec's documentation\"",
                       c.type));
    directive(w, "#endif");
  }
}

}  // namespace

std::string header_body(const EngineContext &c) {
  CodeWriter w(c.header_file, false);
  directive(w, "#include <stdbool.h>");
  directive(w, "#include <stdint.h>");
  exact_types(w, c);
  w.blank();
  directive(w, "#ifdef __cplusplus");
  w.line("extern \"C\" {");
  directive(w, "#endif");
  w.blank();
  places_enum(w, c);
  w.blank();
  transitions_enum(w, c);
  w.blank();
  if (c.team()) {
    team_enum(w, c);
    w.blank();
  }
  if (c.has_context()) context_tag(w, c);
  state_struct(w, c);
  w.blank();
  api(w, c);
  w.blank();
  hooks(w, c);
  interface_functions(w, c);
  w.blank();
  directive(w, "#ifdef __cplusplus");
  w.line("}");
  directive(w, "#endif");
  w.blank();
  directive(w, fmt::format("#endif /* {} */", c.guard));
  return w.take();
}

std::string fingerprint_of(const std::string &body) {
  std::uint32_t h = 2166136261u;  // FNV-1a: deterministic on every host, and cheap on a large header
  for (unsigned char ch : body) h = (h ^ ch) * 16777619u;
  return fmt::format("{:08x}", h);
}

/// docs/c-engine.md "Header and engine together": X_init and X_run carry the header's fingerprint
/// in their linker names, so a program compiled against another version of the header fails to
/// link, and the undefined name says what to do; engine.c refuses any header but its own.
void fingerprint_macros(CodeWriter &w, const EngineContext &c) {
  w.line("/* This header belongs with the {} generated with it. Code compiled against another version",
         base_name(c.source_file));
  w.line("   of it does not link (\"undefined reference to {}\"):", c.stamped(c.init_fn));
  w.line("   regenerate both files from the chart and rebuild. */");
  directive(w, fmt::format("#define {} 1", c.layout_macro()));
  directive(w, fmt::format("#define {} {}", c.init_fn, c.stamped(c.init_fn)));
  directive(w, fmt::format("#define {} {}", c.run_fn, c.stamped(c.run_fn)));
}

void emit_header(const EngineContext &c, const std::string &body, std::ostream &out) {
  CodeWriter w(out, c.header_file, false);
  w.line(std::string_view(banner(c)));
  directive(w, "#ifndef " + c.guard);
  directive(w, "#define " + c.guard);
  w.blank();
  fingerprint_macros(w, c);
  w.blank();
  w.raw(body);
}

}  // namespace gfec::c_backend
