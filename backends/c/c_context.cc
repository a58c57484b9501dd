#include "c_context.h"

#include "c_expr.h"

#include "c_form.h"
#include "naming/naming.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <functional>
#include <set>
#include <stdexcept>
#include <utility>

namespace gfec::c_backend {

using model::PlaceId;

namespace {

/// Names unique within one C name space (the file's, a struct's, a function's), from the naming
/// policy (compiler/naming/): reserved words of C and C++ and the C headers' names never handed out.
using naming::NameSpace;

std::string guard_of(const std::string &header_base) {
  std::string g;
  for (unsigned char c : header_base) g += std::isalnum(c) ? static_cast<char>(std::toupper(c)) : '_';
  if (g.empty() || std::isdigit(static_cast<unsigned char>(g[0]))) g = "GFEC_" + g;
  return g;
}

void name_globals(EngineContext &c, NameSpace &globals, const EngineContext *root) {
  // Global names: every interface function the model knows, the engine's fixed API, then the
  // enumerations. The API names are the contract and never move; an enum constant that would
  // clash with one of them (a place called `init`) gets the trailing `_`. Sub-chart instances
  // come after the root (their names, chosen by the caller, give way to the root's).
  const std::string &t = c.type;
  if (c.root) {
    for (const auto &f : c.model.functions) globals.claim(f.name);
    globals.claim(t);
    // The names every engine (every team machine) has: naming's one list, which the validator
    // also reads to refuse a place that would take one.
    for (const naming::EngineName &e : naming::engine_names())
      if (e.always && (!e.team || c.chart.team > 0)) globals.claim(t + "_" + std::string(e.suffix));
    c.hooks_macro = t + "_HOOKS";
    c.checks_macro = t + "_CHECKS";
    c.assert_macro = t + "_ASSERT";
    c.assert_off_macro = t + "_ASSERT_OFF";
  } else {
    // No hooks in an instance; X_CHECKS of the root checks every instance's postconditions.
    c.hooks_macro = root->hooks_macro;
    c.checks_macro = root->checks_macro;
    c.assert_macro = root->assert_macro;
    c.assert_off_macro = root->assert_off_macro;
    c.set_context_fn = root->set_context_fn;
  }
  c.activated_fn = t + "_activated";
  c.enabled_fn = t + "_enabled";
  c.place_count = t + "_PLACE_COUNT";
  c.transition_count = t + "_TRANSITION_COUNT";
  // The enumerations' types (MISRA C:2012 wants named enum types, and a debugger prints a field
  // of such a type by its constant's name): API names of the root, like X_init.
  c.place_type = c.root ? t + "_place" : globals.take(t + "_place");
  c.transition_type = c.root ? t + "_transition" : globals.take(t + "_transition");
  if (c.root) {
    for (const auto *n : {&c.hooks_macro, &c.checks_macro, &c.assert_macro, &c.assert_off_macro, &c.activated_fn,
                          &c.enabled_fn, &c.place_count, &c.transition_count})
      globals.claim(*n);
    // The guard is the engine's own: it moves aside for an interface function `ENGINE_H`.
    c.guard = globals.take(c.guard);
    c.macros = {c.guard, c.hooks_macro, c.checks_macro, c.assert_macro, c.assert_off_macro};
  } else {
    c.macros = root->macros;
    c.place_count = globals.take(c.place_count);
    c.transition_count = globals.take(c.transition_count);
  }
  if (c.team()) {
    // The API names are the contract, like _init's; the validator keeps states off them.
    c.set_agent_fn = t + "_set_agent";
    c.report_fn = t + "_report";
    c.team_size = t + "_TEAM_SIZE";
    c.team_fn = t + "_team";
    for (const auto *n : {&c.set_agent_fn, &c.report_fn, &c.team_size, &c.team_fn}) globals.claim(*n);
  }
  if (c.root && c.has_context()) {
    c.set_context_fn = t + "_set_context";
    c.context_fn = t + "_context";
    globals.claim(c.set_context_fn);
    globals.claim(c.context_fn);
  }
  const bool has_sub =
      std::any_of(c.chart.places.begin(), c.chart.places.end(), [](const model::Place &p) { return p.runs.valid(); });
  if (c.root && has_sub) {
    c.instance_type = t + "_instance";
    c.instance_count = t + "_INSTANCE_COUNT";
    c.instance_activation_fn = t + "_instance_activation";
    for (const auto *n : {&c.instance_type, &c.instance_count, &c.instance_activation_fn}) globals.claim(*n);
  }
  if (c.root && c.engine_options.names) {
    c.place_name_fn = t + "_place_name";
    c.transition_name_fn = t + "_transition_name";
    globals.claim(c.place_name_fn);
    globals.claim(c.transition_name_fn);
  }
  if (c.traced()) {
    c.trace_write_fn = t + "_trace_write";
    globals.claim(c.trace_write_fn);
  }
  globals.reserve(c.chart.places.size() + c.chart.transitions.size());
  c.place_const.reserve(c.chart.places.size());
  c.transition_const.reserve(c.chart.transitions.size());
  for (const auto &p : c.chart.places) c.place_const.push_back(globals.take(t + "_" + p.name));
  for (const auto &tr : c.chart.transitions) c.transition_const.push_back(globals.take(t + "_" + tr.name));
  c.lowest_fn = globals.take(t + "_lowest");
  c.next_fn = globals.take(t + "_next");
  c.insert_fn = globals.take(t + "_insert");
  c.erase_fn = globals.take(t + "_erase");
  c.sort_fn = globals.take(t + "_sort");
  c.watched_fn = globals.take(t + "_watched");
  c.active_levels = globals.take(t + "_ACTIVE_LEVELS");
  c.candidate_levels = globals.take(t + "_CANDIDATE_LEVELS");
  if (c.traced()) {
    c.trace_frame_fn = globals.take(t + "_trace_frame");
    c.trace_put_fn = globals.take(t + "_trace_put");
    c.step_fn = globals.take(t + "_step");
  }
}

void name_fields(EngineContext &c) {
  NameSpace fields;
  // Never a macro's name (-DX_HOOKS would replace the field); nor, since C++ reads the header
  // too, a name the struct uses before its fields (C++: a member "changes the meaning" of it).
  for (const auto &m : c.macros) fields.claim(m);
  for (const auto *used : {&c.place_type, &c.transition_type, &c.place_count, &c.transition_count, &c.team_size})
    if (!used->empty()) fields.claim(*used);
  // The context's type (`motor_t *`) is the last field's.
  for (const auto &word : c.context_type.words) fields.claim(word);
  for (const auto &v : c.chart.vars) {
    // A block instance's member `t1.Q` (docs/language.md "Blocks") is the field `t1_Q`.
    std::string field = v.name;
    std::replace(field.begin(), field.end(), '.', '_');
    c.var_field.push_back(fields.take(std::move(field)));
  }
  c.av = fields.take("av");
  c.state = fields.take("state");
  c.status = fields.take("status");
  c.started = fields.take("started");
  if (c.chart.clock) c.clock = fields.take("clock");
  c.current = fields.take("current");
  c.active = fields.take("active");
  c.candidates = fields.take("candidates");
  if (c.team()) {
    c.agent = fields.take("agent");
    c.reports = fields.take("reports");
  }
  // Tables by place only when some place needs one: 32 bytes a place that a chart of a million
  // places without timers or sub-charts would spend on empty strings (docs/performance.md).
  const auto &places = c.chart.places;
  if (std::any_of(places.begin(), places.end(), [](const model::Place &p) { return p.timed; }))
    for (const auto &p : places) c.timer_field.push_back(p.timed ? fields.take("timer_" + p.name) : "");
  if (c.has_named_actions()) {
    // The previous Q of every action a Q can hold (not one held by P1, P0 and R only), the flags
    // of every stored qualifier it is held under (with their timers), the previous state of
    // every place an edge is taken of.
    IdMap<model::PlaceId, bool> edged(places.size(), false);
    bool initial_p0 = false;
    for (const model::Action &a : c.chart.actions) {
      bool q = false, stored = false, sd = false, sl = false, edge = false;
      for (const model::Association &as : a.associations) {
        const Keep k = kept_as(as);
        stored = stored || k == Keep::Set;
        sd = sd || k == Keep::Sd;
        sl = sl || k == Keep::Sl;
        q = q || k == Keep::Q || k == Keep::Set || k == Keep::Sd || k == Keep::Sl;
        const model::Qualifier qu = as.qualifier;
        if (qu == model::Qualifier::P || qu == model::Qualifier::P1 || qu == model::Qualifier::P0)
          edged[as.place] = true;
        edge = edge || qu == model::Qualifier::P1 || qu == model::Qualifier::P0;
        initial_p0 = initial_p0 || (qu == model::Qualifier::P0 && places[as.place].initial);
      }
      const std::string name = a.name.str();
      c.action_q.push_back(q ? fields.take("q_" + name) : "");
      c.action_a.push_back(c.chart.reads_action_flags && (q || edge) ? fields.take("a_" + name) : "");
      c.action_stored.push_back(stored ? fields.take("stored_" + name) : "");
      c.action_sd.push_back(sd ? fields.take("sd_" + name) : "");
      c.action_sd_timer.push_back(sd ? fields.take("sd_timer_" + name) : "");
      c.action_sl.push_back(sl ? fields.take("sl_" + name) : "");
      c.action_sl_timer.push_back(sl ? fields.take("sl_timer_" + name) : "");
    }
    for (model::PlaceId p : places.ids())
      c.was_active.push_back(edged[p] ? fields.take("was_" + places[p].name.str()) : "");
    if (initial_p0) c.acted = fields.take("acted");
  }
  if (c.has_context()) c.ctx_field = fields.take("ctx");
  if (c.traced()) {
    c.trace_tick = fields.take("trace_tick");
    c.trace_left = fields.take("trace_left");
    c.trace_prev = fields.take("trace_prev");
  }
  // The instances the places run: a field named after the place (`m->Search`), for debuggers.
  if (std::any_of(places.begin(), places.end(), [](const model::Place &p) { return p.runs.valid(); }))
    for (const auto &p : places) c.sub_field.push_back(p.runs ? fields.take(p.name.str()) : "");
}

void name_locals(EngineContext &c, const NameSpace &globals) {
  // Inside the file's names: a local never hides an interface function, an enum constant or a
  // helper of the engine that the function's code refers to.
  NameSpace locals(&globals);
  locals.claim(c.type);
  c.self = locals.take("m");
  c.add = locals.take("add");
  c.before = locals.take("before");
  c.from = locals.take("from");
  c.to = locals.take("to");
  c.index = locals.take("p");
  c.q = locals.take("q");
  if (c.has_context()) c.ctx_param = locals.take("ctx");
  if (c.engine_options.names) c.names = locals.take("names");
  const std::pair<const char *, std::string *> scalable[] = {
      {"add_n", &c.add_n}, {"lost", &c.lost}, {"lost_n", &c.lost_n}, {"gained", &c.gained}, {"gained_n", &c.gained_n},
      {"w", &c.word},      {"bits", &c.bits}, {"i", &c.i},           {"t", &c.t},           {"fire", &c.fire}};
  for (auto [name, field] : scalable) *field = locals.take(name);
  // The temporaries (gfec_t1, gfec_t2, ...): a prefix that no name the engine's code sees
  // continues with digits only, reserved in the same name space as the locals.
  c.temp_prefix = locals.reserve_numbered_prefix("gfec_t");
}

bool reads_input_activity(const EngineContext &c, const model::Expr &e);

bool reads_activity(const model::Expr &e) {
  using K = model::Expr::Kind;
  if (e.kind == K::Active || e.kind == K::Succeeded || e.kind == K::Failed) return true;
  for (const auto &a : e.args)
    if (reads_activity(a)) return true;
  return false;
}

bool reads_activity(const model::Stmt &s) {
  if (reads_activity(s.expr)) return true;
  for (const auto *block : {&s.then_block, &s.else_block})
    for (const auto &t : *block)
      if (reads_activity(t)) return true;
  return false;
}

void collect_facts(EngineContext &c) {
  const auto n = c.chart.places.size();
  c.is_input.assign(n, false);
  c.is_output.assign(n, false);
  for (const auto &t : c.chart.transitions) {
    for (PlaceId p : t.inputs) c.is_input.at(p) = true;
    for (PlaceId p : t.outputs) c.is_output.at(p) = true;
  }
  for (const auto &p : c.chart.places) {
    c.has_timers = c.has_timers || p.timed;
    c.has_post = c.has_post || (p.post.has_value() && p.terminal != model::Terminal::None);
    c.has_terminal = c.has_terminal || p.terminal != model::Terminal::None;
    c.needs_started = c.needs_started || (p.initial && has_code(p.entry));
  }
  for (const auto &t : c.chart.transitions)
    if (t.condition) c.reads_start = c.reads_start || reads_input_activity(c, *t.condition);
  for (const auto &p : c.chart.places)
    if (c.fsm && p.exit)
      for (const auto &s : *p.exit) c.exits_read_activity = c.exits_read_activity || reads_activity(s);
}

/// The expression reads, by active()/succeeded()/failed(), a place some transition consumes.
bool reads_input_activity(const EngineContext &c, const model::Expr &e) {
  using K = model::Expr::Kind;
  if (written_as_constant(c, e)) return false;  // the engine writes its value: it reads nothing
  PlaceId p;
  if (e.kind == K::Active && !e.path.empty()) p = e.path.front();
  else if (e.kind == K::Succeeded || e.kind == K::Failed) p = e.place();
  if (p && c.is_input.at(p)) return true;
  for (const auto &a : e.args)
    if (reads_input_activity(c, a)) return true;
  return false;
}

/// Stopping the chart's instance runs code: a place with an exit block, or one whose own
/// instance's stop runs code.
bool stop_runs_code(const EngineContext &c) {
  for (PlaceId p : c.chart.places.ids())
    if (has_code(c.place(p).exit) || (c.sub[p] && c.sub[p]->stop_code)) return true;
  return false;
}

void build(EngineContext &c, NameSpace &globals, const EngineContext *root);

/// The names of the split sequential form's parts (EngineContext::part_base): every one free, or the
/// base takes a trailing `_`, as an instance's prefix does.
void name_parts(EngineContext &c, NameSpace &globals) {
  auto each = [&](const std::function<bool(const std::string &)> &f) {
    bool all = f(c.part_next());
    for (const char *kind : EngineContext::kPartKinds) {
      all = all && f(c.part_table(kind));
      for (std::size_t k = 0; all && k < c.part_count(); ++k) all = f(c.part_fn(kind, k));
    }
    return all;
  };
  c.part_base = c.type;
  while (!each([&](const std::string &n) { return globals.free(n); })) c.part_base += '_';
  each([&](const std::string &n) {
    globals.claim(n);
    return true;
  });
}

/// The instance that place `p` of `c` runs: its names follow the path (`Patrol_Search`), and
/// move aside (a trailing `_`) if any of them is taken, so that the whole file stays unique.
std::unique_ptr<EngineContext> make_instance(const EngineContext &c, PlaceId p, NameSpace &globals,
                                             const EngineContext *root) {
  const model::Place &place = c.place(p);
  const model::Chart &chart = c.model.charts.at(place.runs);
  auto s = std::make_unique<EngineContext>(c.model, chart, c.options);
  s->root = false;
  std::string prefix = c.type + "_" + place.name;
  // The prefix itself is only a struct tag (tags have a name space of their own, so `struct
  // Patrol_Search` and the enum constant Patrol_Search coexist); two instances with one prefix
  // would share their function names, which are checked.
  auto is_free = [&](const std::string &x) {
    return globals.free(x + "_init") && globals.free(x + "_run") && globals.free(x + "_stop") &&
           globals.free(x + "_PLACE_COUNT") && globals.free(x + "_TRANSITION_COUNT");
  };
  while (!is_free(prefix)) prefix += '_';
  s->type = prefix;
  for (const char *api : {"_init", "_run", "_stop"}) globals.claim(prefix + api);
  s->instance_const = globals.take(prefix + "_INSTANCE");
  s->struct_type = "struct " + prefix;
  s->linkage = "static ";
  s->init_fn = prefix + "_init";
  s->run_fn = prefix + "_run";
  s->stop_fn = prefix + "_stop";
  s->place_count = prefix + "_PLACE_COUNT";
  s->transition_count = prefix + "_TRANSITION_COUNT";
  s->owner = fmt::format("{} {} of {}", c.fsm ? "state" : "place", place.name, c.root ? c.type : c.owner);
  s->stoppable = c.stoppable || c.is_input.at(p);
  s->source_file = c.source_file;
  s->header_file = c.header_file;
  s->guard = c.guard;
  build(*s, globals, root);
  return s;
}

void build(EngineContext &c, NameSpace &globals, const EngineContext *root) {
  c.fsm = c.chart.kind == model::Chart::Kind::Fsm;
  name_globals(c, globals, root ? root : &c);
  name_fields(c);
  name_locals(c, globals);
  collect_facts(c);
  for (PlaceId p : c.chart.places.ids())
    c.sub.push_back(c.place(p).runs ? make_instance(c, p, globals, root ? root : &c) : nullptr);
  c.stop_code = stop_runs_code(c);
  std::vector<bool> watched;
  for (PlaceId p : c.chart.places.ids()) watched.push_back(c.watched(p));
  c.layout = plan_layout(c.chart, c.options.engine, std::move(watched));
  if (c.layout.part_places > 0) name_parts(c, globals);
}

/// The interface functions of the chart and of every instance below it, each once, the chart's
/// own first.
void collect_functions(const EngineContext &c, std::vector<model::FunctionId> &out) {
  for (model::FunctionId f : c.chart.functions)
    if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
  for (const auto &s : c.sub)
    if (s) collect_functions(*s, out);
}

}  // namespace

std::string EngineContext::av_of(PlaceId p) const { return fmt::format("{}[{}]", field(av), place_const.at(p)); }

std::string EngineContext::timer_of(PlaceId p) const { return field(timer_field.at(p)); }

const char *EngineContext::report_type() const {
  // C's int8_t and int16_t hold -1 and up to 127 and 32767 states.
  const std::size_t n = chart.places.size();
  return n <= 127 ? "int8_t" : n <= 32767 ? "int16_t" : "int32_t";
}

bool EngineContext::runs_exit(PlaceId p) const {
  const EngineContext *s = sub_of(p);
  return is_input.at(p) && (has_code(place(p).exit) || (s && s->has_stop()));
}

bool EngineContext::runs_entry(PlaceId p) const {
  // An instance is started (reset) whenever its place gains activation.
  return is_output.at(p) && (has_code(place(p).entry) || sub_of(p));
}

std::vector<std::string> EngineContext::start_call(PlaceId p) const {
  const EngineContext *s = sub_of(p);
  if (!s) return {};
  return {fmt::format("{}(&{}); /* start the instance of {} */", s->init_fn, field(sub_field[p]), s->chart.name)};
}

std::vector<std::string> EngineContext::tick_call(PlaceId p) const {
  const EngineContext *s = sub_of(p);
  if (!s) return {};
  return {fmt::format("{}(&{}); /* one tick of the instance of {} */", s->run_fn, field(sub_field[p]), s->chart.name)};
}

std::vector<std::string> EngineContext::stop_call(PlaceId p) const {
  const EngineContext *s = sub_of(p);
  if (!s || !s->has_stop()) return {};
  return {fmt::format("{}(&{}); /* stop the instance of {} first */", s->stop_fn, field(sub_field[p]), s->chart.name)};
}

std::string EngineContext::count_text() const { return place_count; }

std::string EngineContext::member(const std::string &obj, const std::string &name) const {
  return obj.empty() ? field(name) : obj + "." + name;
}

std::string EngineContext::active_test(const std::string &obj, PlaceId p, bool at_start) const {
  return form().active_test(*this, obj, p, at_start);
}

bool EngineContext::resets_timer(PlaceId p) const { return is_output.at(p) && place(p).timed; }

bool EngineContext::needs_snapshot() const {
  for (PlaceId p : chart.places.ids())
    if (runs_exit(p) || runs_entry(p) || resets_timer(p)) return true;
  return false;
}

bool EngineContext::any_watched() const {
  for (PlaceId p : chart.places.ids())
    if (watched(p)) return true;
  return false;
}

std::unique_ptr<EngineContext> make_context(const model::Model &model, const model::Chart &chart,
                                            const EmitOptions &options) {
  auto c = std::make_unique<EngineContext>(model, chart, options);
  c->type = chart.name;
  c->struct_type = chart.name;
  c->init_fn = c->type + "_init";
  c->run_fn = c->type + "_run";
  c->source_file = options.output_path;
  c->header_file = base_name(replace_extension(options.output_path, ".h"));
  // `#include "..."` takes no escapes: a '"', a backslash, a control character or a trigraph
  // ("??-" is '~' in C99) in the header's name would name another file, or none.
  const bool control = std::any_of(c->header_file.begin(), c->header_file.end(),
                                   [](unsigned char ch) { return ch < 0x20 || ch == 0x7f; });
  if (control || c->header_file.find_first_of("\"\\") != std::string::npos ||
      c->header_file.find("??") != std::string::npos)
    throw std::runtime_error(
        "cannot name the header '" + c->header_file +
        "' in the engine's #include \"...\", which takes no '\"', '\\', control character or '?\?': choose another -o");
  c->guard = guard_of(c->header_file);
  NameSpace globals;
  build(*c, globals, nullptr);
  collect_functions(*c, c->functions);
  if (c->traced() && c->engine_options.trace_calls) {
    const std::string &t = c->type;
    c->calls_buffer = globals.take(t + "_trace_calls");
    c->calls_count = globals.take(t + "_trace_calls_n");
    c->calls_cut = globals.take(t + "_trace_calls_cut");
    c->call_record_fn = globals.take(t + "_trace_record");
    c->call_bytes_fn = globals.take(t + "_trace_record_bytes");
    c->zigzag_fn = globals.take(t + "_trace_zigzag");
    // Wrapped: the functions the tick calls; not one only a postcondition calls (X_CHECKS), which
    // the reference's log shows no call of either, and whose unused wrapper would be a warning.
    std::vector<bool> called(model.functions.size(), false);
    std::function<void(const model::Expr &)> expr = [&](const model::Expr &e) {
      if (e.kind == model::Expr::Kind::Call) called[e.function().index()] = true;
      for (const auto &a : e.args) expr(a);
    };
    std::function<void(const model::Stmt &)> stmt = [&](const model::Stmt &st) {
      expr(st.expr);
      for (const auto &x : st.then_block) stmt(x);
      for (const auto &x : st.else_block) stmt(x);
    };
    std::function<void(const EngineContext &)> chart = [&](const EngineContext &e) {
      for (const auto &p : e.chart.places) {
        for (const auto &st : p.action) stmt(st);
        for (const auto *block : {&p.entry, &p.exit})
          if (*block)
            for (const auto &st : **block) stmt(st);
      }
      for (const auto &tr : e.chart.transitions)
        if (tr.condition) expr(*tr.condition);
      for (const auto &sub : e.sub)
        if (sub) chart(*sub);
    };
    chart(*c);
    c->call_wrapper.assign(model.functions.size(), "");
    for (model::FunctionId f : c->functions)
      if (called[f.index()]) c->call_wrapper[f] = globals.take(t + "_traced_" + model.functions[f].name);
    // The instances call the root's wrappers.
    std::function<void(EngineContext &)> share = [&](EngineContext &e) {
      for (auto &s : e.sub)
        if (s) {
          s->call_wrapper = c->call_wrapper;
          share(*s);
        }
    };
    share(*c);
  }
  return c;
}

Keep kept_as(const model::Association &as) {
  using model::Qualifier;
  // Timers stop at UINT32_MAX ticks: a longer duration is never reached (docs/language.md §5.3).
  const bool beyond = as.ticks > 0xFFFFFFFFul;
  switch (as.qualifier) {
  case Qualifier::N:
  case Qualifier::P:
  case Qualifier::L:
  case Qualifier::D: return Keep::Q;
  case Qualifier::S: return Keep::Set;
  case Qualifier::R: return Keep::Reset;
  case Qualifier::P0:
  case Qualifier::P1: return Keep::Edge;
  // A flag that is only set and cleared by R, as S's is: one flag serves S, DS, SD 0 and an SL
  // that never runs out, as their OR is one flag set by any of them.
  case Qualifier::DS: return beyond ? Keep::Nothing : Keep::Set;
  case Qualifier::SD: return as.ticks == 0 ? Keep::Set : beyond ? Keep::Nothing : Keep::Sd;
  case Qualifier::SL: return as.ticks == 0 ? Keep::Nothing : beyond ? Keep::Set : Keep::Sl;
  }
  return Keep::Nothing;
}

}  // namespace gfec::c_backend
