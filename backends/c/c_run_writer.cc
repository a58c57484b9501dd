#include "c_run_writer.h"

#include "c_emit.h"

#include <fmt/format.h>

#include <optional>

namespace gfec::c_backend {

void RunWriter::head() {
  // --trace: the tick is file-local and X_run (c_trace.cc) runs it, then writes the frame.
  if (c_.traced()) w_.line("static void {}({} *{})", c_.step_fn, c_.struct_type, c_.self);
  else w_.line("{}void {}({} *{})", c_.linkage, c_.run_fn, c_.struct_type, c_.self);
}

void RunWriter::section(const std::string &comment) {
  if (started_) w_.blank();
  started_ = true;
  if (!comment.empty()) w_.line(std::string_view(comment));
}

void RunWriter::first_tick(const std::string &comment) {
  if (c_.chart.clock) {
    section("/* The clock: now() is this tick's number times the period */");
    w_.line("{} += 1;", c_.field(c_.clock));
  }
  if (!c_.needs_started) return;
  section(comment);
  auto scope = w_.block(fmt::format("if (!{}) {{", c_.field(c_.started)));
  std::vector<std::vector<std::string>> text;
  for (const auto &p : c_.chart.places)
    text.push_back(p.initial && has_code(p.entry) ? c_statements(c_, *p.entry, temps_) : std::vector<std::string>{});
  temps_.declare(w_);
  w_.line("{} = true;", c_.field(c_.started));
  for (std::size_t i = 0; i < c_.chart.places.size(); ++i) {
    const auto &p = c_.chart.places[i];
    if (p.initial && has_code(p.entry)) {
      w_.line("/* entry {} */", p.name);
      statements(*p.entry, text[i], {}, {});
    }
  }
}

void RunWriter::statements(const std::vector<model::Stmt> &stmts, const std::vector<std::string> &text,
                           const std::vector<std::string> &first, const std::vector<std::string> &last) {
  for (const auto &l : first) w_.line(std::string_view(l));
  emit_statements(w_, c_, stmts, text);
  w_.line_back();
  for (const auto &l : last) w_.line(std::string_view(l));
}

void RunWriter::block(const std::vector<model::Stmt> &stmts, const std::vector<std::string> &first,
                      const std::vector<std::string> &last) {
  CodeWriter::Scope scope(w_, "}");
  std::vector<std::string> text = c_statements(c_, stmts, temps_);
  temps_.declare(w_);
  statements(stmts, text, first, last);
}

void RunWriter::exit_blocks(const std::function<std::string(model::PlaceId)> &left) {
  for (model::PlaceId p : places())
    if (c_.runs_exit(p)) {
      w_.line("/* exit {} */", c_.place(p).name);
      w_.line("if ({}) {{", left(p));
      block(exit_of(p), c_.stop_call(p));
    }
}

void RunWriter::entry_blocks(const std::function<std::string(model::PlaceId)> &entered) {
  for (model::PlaceId p : places())
    if (c_.runs_entry(p) || c_.resets_timer(p)) {
      w_.line("/* {} {} */", c_.runs_entry(p) ? "entry" : "timer of", c_.place(p).name);
      w_.line("if ({}) {{", entered(p));
      block(entry_of(p), entry_first(p));
    }
}

void RunWriter::action_blocks(const std::string &comment, const std::function<std::string(model::PlaceId)> &active) {
  if (!any_actions()) return;
  section(comment);
  for (model::PlaceId p : places())
    if (c_.acts(p)) {
      w_.line("if ({}) {{", active(p));
      block(c_.place(p).action, {}, c_.tick_call(p));
    }
}

void RunWriter::named_actions() {
  using model::Qualifier;
  if (!c_.has_named_actions()) return;
  section("/* Named actions under their action control, in declaration order */");
  // Each term is bracketed; one alone is the whole test and needs no brackets.
  auto any = [](const std::vector<std::string> &terms) {
    if (terms.size() == 1 && terms[0].front() == '(' && terms[0].back() == ')')
      return terms[0].substr(1, terms[0].size() - 2);
    std::string s;
    for (const std::string &t : terms) s += (s.empty() ? "" : " || ") + t;
    return s;
  };
  // The sequential form's place number is an unsigned field: the constant is made one too, as
  // MISRA C:2012 rule 10.4 asks (the form's own test compares it with the enumeration constant).
  auto active = [this](model::PlaceId p) {
    if (c_.fsm || c_.layout.form != Layout::Form::Sequential) return c_.active_test("", p);
    return fmt::format("{} == ({}){}", c_.field(c_.current), uint_type(c_.layout.index_bits), c_.place_const[p]);
  };
  for (model::ActionId a : c_.chart.actions.ids()) {
    const model::Action &action = c_.chart.actions[a];
    if (action.associations.empty()) continue;  // held by no place: never runs
    std::vector<std::string> q, edge, set, reset, set_sd, set_sl;
    std::string held;
    // One duration per action for SD and for SL (the validator sees to it): their timer's.
    std::string sd_ticks, sl_ticks;
    for (const model::Association &as : action.associations) {
      const std::string x = "(" + active(as.place) + ")";
      const std::string was = c_.was_active[as.place].empty() ? "" : c_.field(c_.was_active[as.place]);
      const std::string ticks = std::to_string(as.ticks) + "u";
      held += fmt::format("{}{} in {}", held.empty() ? "" : ", ", model::qualifier_name(as.qualifier),
                          c_.place(as.place).name);
      switch (as.qualifier) {
      case Qualifier::N: q.push_back(x); break;
      case Qualifier::P: q.push_back(fmt::format("({} && !{})", x, was)); break;
      // `L 0` is never active (and `timer < 0u` would be a constant); `D 0` is active as N.
      case Qualifier::L:
        if (as.ticks > 0) q.push_back(fmt::format("({} && ({} < {}))", x, c_.timer_of(as.place), ticks));
        break;
      case Qualifier::D:
        q.push_back(as.ticks > 0 ? fmt::format("({} && ({} >= {}))", x, c_.timer_of(as.place), ticks) : x);
        break;
      case Qualifier::S: set.push_back(x); break;
      case Qualifier::R: reset.push_back(x); break;
      case Qualifier::P1: edge.push_back(fmt::format("({} && !{})", x, was)); break;
      // Initialisation activated an initial place: left in tick 1, it falls in tick 1.
      case Qualifier::P0:
        if (c_.place(as.place).initial) edge.push_back(fmt::format("(!{} && ({} || !{}))", x, was, c_.field(c_.acted)));
        else edge.push_back(fmt::format("(!{} && {})", x, was));
        break;
      // The stored flag, set once the place's timer reaches the duration (at once for `DS 0`).
      case Qualifier::DS:
        if (kept_as(as) == Keep::Set)
          set.push_back(as.ticks > 0 ? fmt::format("({} && ({} >= {}))", x, c_.timer_of(as.place), ticks) : x);
        break;
      case Qualifier::SD:
      case Qualifier::SL:
        switch (kept_as(as)) {
        case Keep::Set: set.push_back(x); break;  // `SD 0` is S, and so is an SL that never runs out
        case Keep::Sd:
          set_sd.push_back(x);
          sd_ticks = ticks;
          break;
        case Keep::Sl:
          set_sl.push_back(x);
          sl_ticks = ticks;
          break;
        default: break;  // `SL 0` is never active, nor is an SD the timers never reach
        }
        break;
      }
    }
    w_.line("/* {}: {} */", action.name, held);
    const std::string &stored = c_.action_stored[a], &last_q = c_.action_q[a];
    const std::string &sd = c_.action_sd[a], &sl = c_.action_sl[a];
    // The SD and SL timers count one more tick once their flag is set (0 in the tick of the set).
    for (const std::string *timed : {&sd, &sl})
      if (!timed->empty()) {
        const std::string timer = c_.field(timed == &sd ? c_.action_sd_timer[a] : c_.action_sl_timer[a]);
        w_.line("if ({} && ({} < UINT32_MAX)) {{ {}++; }}", c_.field(*timed), timer, timer);
      }
    // Reset dominates: this tick's sets first, then the reset. A set starts the SD or SL timer
    // only as the flag rises.
    if (!stored.empty() && !set.empty()) w_.line("if ({}) {{ {} = true; }}", any(set), c_.field(stored));
    for (const std::string *timed : {&sd, &sl}) {
      const std::vector<std::string> &sets = timed == &sd ? set_sd : set_sl;
      if (timed->empty() || sets.empty()) continue;
      const std::string flag = c_.field(*timed);
      w_.line("if (({}) && !{}) {{ {} = true; {} = 0u; }}", any(sets), flag, flag,
              c_.field(timed == &sd ? c_.action_sd_timer[a] : c_.action_sl_timer[a]));
    }
    if (!reset.empty()) {
      std::string clear;
      for (const std::string *flag : {&stored, &sd, &sl})
        if (!flag->empty()) clear += fmt::format(" {} = false;", c_.field(*flag));
      if (!clear.empty()) w_.line("if ({}) {{{} }}", any(reset), clear);
    }
    if (!stored.empty()) q.push_back(c_.field(stored));
    if (!sd.empty())
      q.push_back(fmt::format("({} && ({} >= {}))", c_.field(sd), c_.field(c_.action_sd_timer[a]), sd_ticks));
    if (!sl.empty())
      q.push_back(fmt::format("({} && ({} < {}))", c_.field(sl), c_.field(c_.action_sl_timer[a]), sl_ticks));
    // Q true, its final run as Q falls, or an edge of P1 / P0: one run at most.
    std::vector<std::string> runs;
    std::optional<CodeWriter::Scope> scope;
    if (!last_q.empty()) {
      w_.line("{");
      scope.emplace(w_, "}");
      w_.line("const bool {} = {};", c_.q, q.empty() ? "false" : any(q));
      runs = {c_.q, c_.field(last_q)};
    }
    runs.insert(runs.end(), edge.begin(), edge.end());
    if (runs.empty()) continue;  // only R: nothing to run
    if (!c_.action_a[a].empty()) {
      // The chart reads action flags: this control's outcome now, the body after every control.
      w_.line("{} = {};", c_.field(c_.action_a[a]), any(runs));
      if (!last_q.empty()) w_.line("{} = {};", c_.field(last_q), c_.q);
      continue;
    }
    w_.line_from(c_.model.sources(), action.name_range);
    w_.line("if ({}) {{", any(runs));
    w_.line_back();
    block(action.body);
    if (!last_q.empty()) w_.line("{} = {};", c_.field(last_q), c_.q);
  }
  for (model::ActionId a : c_.chart.actions.ids()) {
    if (c_.action_a[a].empty()) continue;
    w_.line_from(c_.model.sources(), c_.chart.actions[a].name_range);
    w_.line("if ({}) {{", c_.field(c_.action_a[a]));
    w_.line_back();
    block(c_.chart.actions[a].body);
  }
  for (model::PlaceId p : c_.was_active.ids())
    if (!c_.was_active[p].empty()) w_.line("{} = {};", c_.field(c_.was_active[p]), active(p));
  if (!c_.acted.empty()) w_.line("{} = true;", c_.field(c_.acted));
}

void RunWriter::hooks_section(const std::string &comment) {
  section("");
  directive(w_, "#ifdef " + c_.hooks_macro);
  w_.line(std::string_view(comment));
}

void RunWriter::activation_hooks(const std::string &loop, const std::string &i,
                                 const std::function<std::string(const std::string &)> &was) {
  for (bool gained : {false, true}) {
    auto each = w_.block(loop);
    w_.line("if (({} {} 0u) && ({}[{}] {} 0u)) {{ {}({}, ({}){}, {}); }}", was(i),
            gained ? "==" : "!=", c_.field(c_.av), i, gained ? "!=" : "==", c_.activated_fn, c_.self, c_.place_type, i,
            gained ? "true" : "false");
  }
}

void RunWriter::own(const std::function<model::PlaceId(model::TransitionId)> &owner) {
  std::vector<std::pair<model::PlaceId, model::TransitionId>> items;
  items.reserve(c_.chart.transitions.size());
  for (model::TransitionId t : c_.chart.transitions.ids()) items.emplace_back(owner(t), t);
  owned_ = IdGroups<model::PlaceId, model::TransitionId>(c_.chart.places.size(), items);
}

std::vector<std::string> RunWriter::conditions(const std::vector<model::TransitionId> &transitions, bool alone) {
  std::vector<std::string> text;
  for (model::TransitionId i : transitions) {
    const auto &t = c_.chart.transitions[i];
    if (!t.condition) text.emplace_back();
    else
      text.push_back(alone ? c_test(c_, *t.condition, temps_, true, tried_in(t))
                           : c_condition(c_, *t.condition, temps_, true, tried_in(t)));
  }
  return text;
}

void RunWriter::transition_test(const model::Transition &t, const std::string &inputs, const std::string &condition) {
  std::string test = inputs;
  if (t.condition) test += (test.empty() ? "" : " && ") + condition;
  // Mapped to the condition, or to the whole transition when it has none (docs/c-engine.md).
  w_.line_from(c_.model.sources(), t.condition ? t.condition->range : t.range);
  w_.line("if ({}) {{", test.empty() ? "true" : test);
  w_.line_back();
}

void RunWriter::case_block(model::PlaceId place, const std::vector<model::Stmt> &stmts,
                           const std::vector<std::string> &first, const std::vector<std::string> &last) {
  std::vector<std::string> text = c_statements(c_, stmts, temps_);
  in_case(constant(place), [&] {
    statements(stmts, text, first, last);
    w_.line("break;");
  });
}

void RunWriter::switch_end() {
  w_.line("default:");
  {
    auto in_default = w_.indented();
    w_.line("break;");
  }
  w_.line("}");
}

bool RunWriter::any_exits() const {
  for (model::PlaceId p : places())
    if (c_.runs_exit(p)) return true;
  return false;
}

bool RunWriter::any_actions() const {
  for (model::PlaceId p : places())
    if (c_.acts(p)) return true;
  return false;
}

namespace {
const std::vector<model::Stmt> kNoStatements;
}

const std::vector<model::Stmt> &RunWriter::exit_of(model::PlaceId p) const {
  return has_code(c_.place(p).exit) ? *c_.place(p).exit : kNoStatements;
}

const std::vector<model::Stmt> &RunWriter::entry_of(model::PlaceId p) const {
  return has_code(c_.place(p).entry) ? *c_.place(p).entry : kNoStatements;
}

std::vector<std::string> RunWriter::entry_first(model::PlaceId p) const {
  std::vector<std::string> first = c_.start_call(p);
  if (c_.resets_timer(p)) first.insert(first.begin(), fmt::format("{} = 0;", c_.timer_of(p)));
  return first;
}

}  // namespace gfec::c_backend
