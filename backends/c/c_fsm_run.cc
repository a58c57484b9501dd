// The run function of an fsm: one tick exactly as docs/language.md §7 says. The state is one
// number. In the readable form the transitions form one if/else-if chain in declaration order,
// so at most one fires and only those leaving the current state evaluate their condition. The
// scalable form (`auto` above kReadableMaxPlaces states) makes each part of the tick a switch on
// the state instead, split into parts above kSplitAbovePlaces states as the sequential sfc
// form's are (c_switch_run.h): a tick no longer tests the state once per transition, and a chain
// of 10,000 tests in one function took gcc -O2 24 s and 557 MB (docs/performance.md).
#include "c_emit.h"
#include "c_switch_run.h"

#include <fmt/format.h>

#include <optional>

namespace gfec::c_backend {

namespace {

class FsmRun : SwitchRun {
public:
  FsmRun(CodeWriter &w, const EngineContext &c) : SwitchRun(w, c) {}

  void emit() {
    if (split()) parts();
    head();
    auto body = w_.block("{");
    // The locals of the update (its temporaries, the state it starts from) open the block they
    // are used in: the function's, or the one a terminal state skips — the smallest scope
    // (cppcheck's variableScope), and declarations before statements (MISRA-minded C).
    if (!c_.has_terminal) locals();
    if (!uses_self()) {
      section("");
      w_.line("(void){}; /* the machine has neither transitions nor actions */", c_.self);
    }
    first_tick("/* First tick: the initial state enters */");
    // One exit (MISRA C:2012 rule 15.5): a terminal state skips the rest of the tick.
    std::optional<CodeWriter::Scope> running;  // the rest of the tick, skipped in a terminal state
    if (c_.has_terminal) {
      section("/* In a terminal state nothing happens any more */");
      w_.line("if ({} == 0) {{", c_.field(c_.status));
      running.emplace(w_, "}");
      started_ = false;
      locals();
    }
    count_time();
    transitions();
    exits_and_entries();
    hooks();
    checks();
    actions();
  }

private:
  std::string state() const override { return c_.field(c_.state); }
  std::string state_type() const override { return c_.place_type; }
  void move(model::PlaceId to) override {
    w_.line("{} = {};", state(), constant(to));
    model::Terminal terminal = c_.place(to).terminal;
    if (terminal != model::Terminal::None)
      w_.line("{} = {};", c_.field(c_.status), terminal == model::Terminal::Success ? 1 : -1);
  }
  /// Entering a terminal state also sets the status: its case moves itself.
  bool moves_by_table(model::PlaceId to) const override { return c_.place(to).terminal == model::Terminal::None; }
  /// The scalable form (c_layout.h): each part of the tick a switch on the state, not tests.
  bool switched() const { return c_.layout.form == Layout::Form::Sequential; }
  /// A state as a switch takes it: as it is, or as the number a part takes (its parameter type).
  /// The state as a switch reads it: as a number, not as its enumeration, whose every member a
  /// switch would otherwise have to name (clang's -Wswitch-enum: terminal states have no case).
  std::string number(const std::string &state) const {
    return fmt::format("({}){}", split() ? index_type() : "int", state);
  }

  void locals() {
    declarations();
    remember_state();
  }

  /// The conditions are rendered first: the temporaries they need belong to the whole update
  /// (the transitions are one if/else-if chain), declared at the top of its block. The switches
  /// render them in the cases; split, the tick needs what the update part says.
  void declarations() {
    if (switched()) {
      if (c_.chart.transitions.empty() || !split()) return;
      section("");
      w_.line("bool {}; /* the current state's update part says that its transition fired */", c_.fire);
      return;
    }
    for (const auto &t : c_.chart.transitions)
      conditions_.push_back(t.condition ? c_condition(c_, *t.condition, temps_, true, t.inputs.at(0)) : "");
    if (!temps_.pending()) return;
    section("");
    temps_.declare(w_);
  }

  bool uses_self() const {
    return !c_.chart.transitions.empty() || c_.needs_started || c_.has_timers || c_.has_terminal || any_actions();
  }

  /// `m->state == X_S`; an operand of `&&` takes it in parentheses (MISRA C:2012 rule 12.1).
  std::string in_state(model::PlaceId p) const {
    return fmt::format("{} == {}", c_.field(c_.state), c_.place_const.at(p));
  }

  void count_time() {
    if (!c_.has_timers) return;
    section("/* Count the ticks of the current state, if it has a timer */");
    if (switched()) {
      place_switch(time_switch(), number(state()));
      return;
    }
    for (model::PlaceId p : places())
      if (c_.place(p).timed) w_.line("if (({0}) && ({1} < UINT32_MAX)) {{ {1}++; }}", in_state(p), c_.timer_of(p));
  }

  /// The state at the start of the tick, for exits, entries and hooks (hooks only in a hooks
  /// build); declared with the update's other locals, at the top of its block (the first tick's
  /// entry code, which may come before, does not change the state).
  void remember_state() {
    if (c_.chart.transitions.empty() || (!c_.needs_snapshot() && !c_.hooks())) return;
    section("");
    if (!c_.needs_snapshot()) directive(w_, "#ifdef " + c_.hooks_macro);
    w_.line("{} {} = {}; /* the state at the start of the tick */", c_.place_type, c_.from, c_.field(c_.state));
    if (!c_.needs_snapshot()) directive(w_, "#endif");
  }

  void transitions() {
    if (c_.chart.transitions.empty()) return;
    section("/* Perform state update: the first transition leaving the current state whose condition");
    w_.line("   holds, in declaration order (one per tick) */");
    if (switched()) {
      place_switch(update_switch(), number(state()));
      return;
    }
    for (std::size_t i = 0; i < c_.chart.transitions.size(); ++i) {
      const auto &t = c_.chart.transitions[i];
      w_.line("/* {}: {} */", t.name, transition_label(c_, t));
      std::string test = in_state(t.inputs.at(0));
      if (t.condition) test = "(" + test + ") && " + conditions_.at(i);
      // Every transition's test is mapped to the chart: to its condition, or to the whole
      // transition when it has none (a debugger's `break chart.fsm:LINE` stops on it).
      w_.line_from(c_.model.sources(), t.condition ? t.condition->range : t.range);
      w_.line("{}if ({}) {{", i == 0 ? "" : "else ", test);
      w_.line_back();
      CodeWriter::Scope fire(w_, "}");
      model::PlaceId to = t.outputs.at(0);
      w_.line("{} = {};", c_.field(c_.state), c_.place_const.at(to));
      model::Terminal terminal = c_.place(to).terminal;
      if (terminal != model::Terminal::None)
        w_.line("{} = {};", c_.field(c_.status), terminal == model::Terminal::Success ? 1 : -1);
    }
    // An if/else-if chain ends in an else (MISRA C:2012 rule 15.7).
    if (c_.chart.transitions.size() > 1) {
      auto otherwise = w_.block("else {");
      w_.line("/* no transition fires: the state stays */");
    }
  }

  /// The exit block of the state left, then the entry block of the state entered (its timer at 0).
  void exits_and_entries() {
    if (!c_.needs_snapshot()) return;
    section("/* Leave the old state, enter the new one */");
    auto changed = w_.block(fmt::format("if ({} != {}) {{", c_.field(c_.state), c_.from));
    // Exit blocks that read activation see the state left as the current one.
    const bool swap = any_exits() && c_.exits_read_activity;
    if (swap) {
      w_.line("{} {} = {}; /* the state entered: current once the state left has exited */", c_.place_type, c_.to,
              c_.field(c_.state));
      w_.line("{} = {};", c_.field(c_.state), c_.from);
    }
    if (switched()) {
      PlaceSwitch exits = exit_switch();
      if (any(exits)) place_switch(exits, number(c_.from));
    } else {
      exit_blocks([this](model::PlaceId p) { return fmt::format("{} == {}", c_.from, c_.place_const[p]); });
    }
    if (swap) w_.line("{} = {};", c_.field(c_.state), c_.to);
    if (switched()) {
      PlaceSwitch entries = entry_switch();
      if (any(entries)) place_switch(entries, number(state()));
    } else {
      entry_blocks([this](model::PlaceId p) { return in_state(p); });
    }
    // The hooks go inside the same test: a second `if` on the same condition right after it is
    // what cppcheck calls a duplicate condition when the exit and entry code leave it alone.
    // Instances have no hooks (docs/c-engine.md).
    if (!c_.chart.transitions.empty() && c_.hooks()) {
      directive(w_, "#ifdef " + c_.hooks_macro);
      w_.line("/* Observation hooks: the state left and the state entered; the transitions leaving it */");
      hook_calls();
      directive(w_, "#endif");
    }
  }

  void hooks() {
    if (c_.chart.transitions.empty() || !c_.hooks() || c_.needs_snapshot()) return;
    hooks_section("/* Observation hooks: the state left and the state entered; the transitions leaving it */");
    {
      auto changed = w_.block(fmt::format("if ({} != {}) {{", c_.field(c_.state), c_.from));
      hook_calls();
    }
    directive(w_, "#endif");
  }

  void hook_calls() {
    w_.line("{}({}, {}, false);", c_.activated_fn, c_.self, c_.from);
    w_.line("{}({}, {}, true);", c_.activated_fn, c_.self, c_.field(c_.state));
    if (switched()) {
      place_switch(hook_switch(), number(state()));
      return;
    }
    // By the state they leave, as owned() files them: a scan of every transition for each state
    // was quadratic (a chain of 120,000 states took 44 s; docs/performance.md, "Long fsms").
    for (model::PlaceId p : places()) {
      if (owned(p).empty()) continue;
      std::string calls;
      for (model::TransitionId t : owned(p))
        calls += fmt::format(" {}({}, {});", c_.enabled_fn, c_.self, c_.transition_const[t]);
      w_.line("if ({}) {{{} }}", in_state(p), calls);
    }
  }

  /// A terminal state's postcondition, in a checks build. The run skips the tick once the
  /// machine is in a terminal state, so this holds only in the tick that entered it.
  void checks() {
    if (!c_.has_post) return;
    section("");
    directive(w_, "#ifdef " + c_.checks_macro);
    w_.line("/* Postconditions of the terminal states, checked on entering them */");
    for (model::PlaceId p : places()) {
      const auto &place = c_.place(p);
      if (place.terminal == model::Terminal::None || !place.post) continue;
      std::string check = c_assertion(c_, *place.post, temps_);
      auto in_it = w_.block(fmt::format("if ({}) {{", in_state(p)));
      // With temporaries the check is more than X_ASSERT(): when X_ASSERT is assert under
      // NDEBUG none of it is compiled; a user's X_ASSERT always gets it.
      const bool temporaries = temps_.pending();
      if (temporaries) {
        directive(w_, "#ifndef " + c_.assert_off_macro);
        temps_.declare(w_);
      }
      w_.line_from(c_.model.sources(), place.post->range);
      w_.line(std::string_view(check));
      w_.line_back();
      if (temporaries) directive(w_, "#endif");
    }
    directive(w_, "#endif");
  }

  void actions() {
    const char *comment = c_.has_sub()
                              ? "/* Perform the action of the current state, then one tick of the instance it runs */"
                              : "/* Perform the action of the current state */";
    if (!switched()) {
      action_blocks(comment, [this](model::PlaceId p) { return in_state(p); });
      return;
    }
    if (!any_actions()) return;
    section(comment);
    place_switch(action_switch(), number(state()));
  }

  std::vector<std::string> conditions_;  ///< by transition, rendered by declarations()
};

}  // namespace

void emit_fsm_run(CodeWriter &w, const EngineContext &c) { FsmRun(w, c).emit(); }

}  // namespace gfec::c_backend
