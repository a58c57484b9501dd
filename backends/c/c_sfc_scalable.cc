// The scalable form of an sfc's engine (c_layout.h): a tick visits only the active part of the
// chart, and does exactly what docs/language.md §5.1 says, in the same order as the readable form:
// transitions in declaration order (conditions only of open ones), produced activation held
// back until the next tick, exits then entries in declaration order, then the actions of the
// active places in declaration order. The chart's code is the same readable C; only the
// bookkeeping around it differs.
#include "c_emit.h"
#include "c_switch_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <vector>

namespace gfec::c_backend {

namespace {

using model::PlaceId;
using model::TransitionId;

// ------------------------------------------------------------------------------ sequential

/// One place is ever active: the state is its number, and a tick is a switch on it. Above
/// kSplitAbovePlaces places each switch is split into parts (c_layout.h): file-local functions
/// of kPartPlaces places each, written before the run function, which calls the part that holds
/// the place through a table (a table, not a direct call: gcc would inline a function called
/// once back into one large function).
class SequentialRun : public SwitchRun {
public:
  SequentialRun(CodeWriter &w, const EngineContext &c) : SwitchRun(w, c) {}

  void emit() {
    if (split()) parts();
    head();
    auto body = w_.block("{");
    declarations();
    first_tick("/* First tick: the initial places enter */");
    count_time();
    transitions();
    exits_and_entries();
    hooks();
    actions();
    named_actions();
  }

private:
  std::string state() const override { return c_.field(c_.current); }
  std::string state_type() const override { return index_type(); }
  void move(PlaceId to) override { w_.line("{} = {};", state(), constant(to)); }

  void declarations() {
    if (c_.chart.transitions.empty()) {
      if (!any_actions() && !c_.needs_started && !c_.has_timers && !c_.has_named_actions()) {
        section("");
        w_.line("(void){}; /* the chart has neither transitions nor actions */", c_.self);
      }
      return;
    }
    const bool from = c_.needs_snapshot() || c_.hooks();
    if (!from && !split()) return;
    section("");
    if (split()) w_.line("bool {}; /* the active place's update part says that its transition fired */", c_.fire);
    if (!from) return;
    if (!c_.needs_snapshot()) directive(w_, "#ifdef " + c_.hooks_macro);
    w_.line("{} {} = {}; /* the active place at the start of the tick */", index_type(), c_.from, state());
    if (!c_.needs_snapshot()) directive(w_, "#endif");
  }

  void count_time() {
    if (!c_.has_timers) return;
    section("/* Count the ticks of the active place, if it has a timer */");
    place_switch(time_switch(), state());
  }

  /// The transitions leaving the active place, in declaration order; the first whose condition
  /// holds fires and the place's activation is gone: no later one is open.
  void transitions() {
    if (c_.chart.transitions.empty()) return;
    section("/* Perform state update: the transitions leaving the active place, in declaration order;");
    w_.line("   the first whose condition holds takes the activation */");
    place_switch(update_switch(), state());
  }

  void exits_and_entries() {
    if (!c_.needs_snapshot()) return;
    section("/* Leave the place left, then enter the place entered */");
    auto scope = w_.block(fmt::format("if ({} != {}) {{", state(), c_.from));
    PlaceSwitch exits = exit_switch(), entries = entry_switch();
    if (any(exits)) place_switch(exits, c_.from);
    if (any(entries)) place_switch(entries, state());
    // The hooks go inside the same test: a second `if` on the same condition right after it is
    // what cppcheck calls a duplicate condition when the exit and entry code leave it alone.
    // Instances have no hooks (docs/c-engine.md).
    if (hooks_transitions()) {
      directive(w_, "#ifdef " + c_.hooks_macro);
      w_.line("/* Observation hooks: the place left and the place entered; the transitions leaving it */");
      hook_calls();
      directive(w_, "#endif");
    }
  }

  void hooks() {
    if (!hooks_transitions() || c_.needs_snapshot()) return;
    hooks_section("/* Observation hooks: the place left and the place entered; the transitions leaving it */");
    {
      auto scope = w_.block(fmt::format("if ({} != {}) {{", state(), c_.from));
      hook_calls();
    }
    directive(w_, "#endif");
  }

  void hook_calls() {
    w_.line("{}({}, ({}){}, false);", c_.activated_fn, c_.self, c_.place_type, c_.from);
    w_.line("{}({}, ({}){}, true);", c_.activated_fn, c_.self, c_.place_type, state());
    place_switch(hook_switch(), state());
  }

  void actions() {
    if (!any_actions()) return;
    section(c_.has_sub() ? "/* Perform the action of the active place, then one tick of the instance it runs */"
                         : "/* Perform the action of the active place */");
    place_switch(action_switch(), state());
  }
};

// ------------------------------------------------------------------------------ sparse

/// Counters, the active places as bits with summary levels, lists of what changed.
class SparseRun : protected RunWriter {
public:
  SparseRun(CodeWriter &w, const EngineContext &c) : RunWriter(w, c) {
    own([&c](TransitionId t) { return c.layout.owner.at(t); });
  }

  void emit() {
    head();
    auto body = w_.block("{");
    declarations();
    first_tick("/* First tick: the initial places enter */");
    count_time();
    if (!l().place_driven) candidates();
    transitions();
    commit();
    exits_and_entries();
    hooks();
    actions();
    named_actions();
  }

private:
  const Layout &l() const { return c_.layout; }
  const char *place_type() const { return uint_type(l().index_bits); }
  std::string active_set() const {
    return fmt::format("{}, {}, {}u", c_.field(c_.active), c_.active_levels, l().active.levels());
  }
  std::string candidate_set() const {
    return fmt::format("{}, {}, {}u", c_.field(c_.candidates), c_.candidate_levels, l().candidates.levels());
  }
  bool has_transitions() const { return !c_.chart.transitions.empty(); }

  void declarations() {
    section("");
    const std::string &i = c_.i;
    // Stores that tell code analysers what is read come after every declaration (C90 and clang's
    // -Wdeclaration-after-statement: firmware teams build with it).
    std::vector<std::string> stores;
    if (has_transitions()) {
      w_.line("{} {}[{}]; /* the places that activation produced in this tick goes to */", place_type(), c_.add,
              l().add_capacity);
      w_.line("uint32_t {} = 0;", c_.add_n);
      // Only entries below add_n are read; code analysers cannot tell, and one store costs nothing.
      stores.push_back(
          fmt::format("{}[0] = 0; /* only the entries written are read (this says so to code analysers) */", c_.add));
    }
    if (has_transitions() && l().watch_capacity > 0) {
      w_.line("{} {}[{}]; /* watched places whose activation fell to 0 in this tick */", place_type(), c_.lost,
              l().lost_capacity);
      w_.line("uint32_t {} = 0;", c_.lost_n);
      w_.line("{} {}[{}]; /* watched places whose activation rose from 0 */", place_type(), c_.gained,
              l().gained_capacity);
      w_.line("uint32_t {} = 0;", c_.gained_n);
      // A list of one is not sorted, so nothing writes it before it is read: say to code
      // analysers that only the entries written are read.
      if (l().lost_capacity == 1 && l().gained_capacity == 1)
        stores.push_back(
            fmt::format("{0}[0] = 0; {1}[0] = 0; /* only the entries written are read */", c_.lost, c_.gained));
      else if (l().lost_capacity == 1)
        stores.push_back(fmt::format("{}[0] = 0; /* only the entries written are read */", c_.lost));
      else if (l().gained_capacity == 1)
        stores.push_back(fmt::format("{}[0] = 0; /* only the entries written are read */", c_.gained));
    }
    if (has_transitions() || any_actions()) {
      w_.line("uint32_t {}; /* a word of a set */", c_.word);
      w_.line("uint32_t {}; /* its bits */", c_.bits);
    }
    // An instance has no hooks: its place number is local to the commit loop (cppcheck).
    if (has_transitions()) {
      if (c_.hooks()) w_.line("uint32_t {};", c_.index);
      w_.line("uint32_t {};", i);
    }
    // The start of the tick: for conditions that read activation (docs/language.md, "Sub-charts"), and for hooks.
    const bool keep = c_.reads_start;
    if (keep || c_.hooks()) {
      if (!keep) directive(w_, "#ifdef " + c_.hooks_macro);
      w_.line("uint32_t {}[{}]; /* the active places at the start of the tick */", c_.before, l().active.words_at(0));
      if (!has_transitions()) {
        w_.line("uint32_t {};", c_.index);
        w_.line("uint32_t {};", i);
      }
      if (!keep) directive(w_, "#endif");
    }
    for (const auto &store : stores) w_.line("{}", store);
    if (keep || c_.hooks()) {
      if (!keep) directive(w_, "#ifdef " + c_.hooks_macro);
      {
        auto each = w_.block(fmt::format("for ({0} = 0; {0} < {1}u; ++{0}) {{", i, l().active.words_at(0)));
        w_.line("{}[{}] = {}[{}];", c_.before, i, c_.field(c_.active), i);
      }
      if (!keep) directive(w_, "#endif");
    }
    if (!has_transitions() && !any_actions() && !c_.needs_started && !c_.has_timers && !c_.has_named_actions())
      w_.line("(void){}; /* the chart has neither transitions nor actions */", c_.self);
  }

  void count_time() {
    if (!c_.has_timers) return;
    section("/* Count the ticks of the active places that have a timer */");
    for (PlaceId p : places())
      if (c_.place(p).timed)
        w_.line("if (({0} != 0u) && ({1} < UINT32_MAX)) {{ {1}++; }}", c_.av_of(p), c_.timer_of(p));
  }

  /// `for` over the members of a set, word by word: `bits` holds the members left in word `w`,
  /// and the switch is on the member's number; `cases` writes its cases.
  template <typename Cases> void for_members(const std::string &set, const std::string &words, Cases cases) {
    const std::string &w = c_.word, &b = c_.bits;
    auto each_word = w_.block(fmt::format(
        "for ({0} = {1}({2}, 1u, 0u); {0} != UINT32_MAX; {0} = {1}({2}, 1u, {0} + 1u)) {{", w, c_.next_fn, set));
    auto each_bit = w_.block(fmt::format("for ({0} = {1}[{2}]; {0} != 0u; {0} &= {0} - 1u) {{", b, words, w));
    w_.line("switch (({} << 5) | {}({})) {{", w, c_.lowest_fn, b);
    cases();
    switch_end();
  }

  /// Not place-driven: the transitions owned by the active places become candidates, which are
  /// then tried in declaration order.
  void candidates() {
    if (!has_transitions()) return;
    section("/* The transitions that may be open: those of the active places */");
    for_members(active_set(), c_.field(c_.active), [&] {
      for (PlaceId p : places()) {
        std::string marks;
        for (TransitionId t : owned(p))
          marks += fmt::format(" {}({}, {});", c_.insert_fn, candidate_set(), c_.transition_const[t]);
        if (!marks.empty()) w_.line("case {}:{} break;", constant(p), marks);
      }
    });
  }

  /// Step 2, one block per transition as in the readable form. A counter that falls to 0 leaves
  /// the active set at once: the place has no open transition left this tick.
  void transition_block(TransitionId index, const std::string &condition) {
    const auto &t = c_.chart.transitions[index];
    w_.line("/* {}: {} */", t.name, transition_label(c_, t));
    std::string inputs;
    for (PlaceId p : t.inputs) inputs += (inputs.empty() ? "(" : " && (") + c_.av_of(p) + " != 0u)";
    transition_test(t, inputs, condition);
    CodeWriter::Scope scope(w_, "}");  // the block transition_test opened
    // One side effect per statement (MISRA C:2012 rule 13.3): the decrement, then its test.
    for (PlaceId p : t.inputs) {
      std::string lost = c_.watched(p) ? fmt::format(" {0}[{1}] = {2}; {1}++;", c_.lost, c_.lost_n, constant(p)) : "";
      w_.line("{}--;", c_.av_of(p));
      w_.line("if ({} == 0u) {{ {}({}, 0u, {});{} }}", c_.av_of(p), c_.erase_fn, active_set_args(), constant(p), lost);
    }
    for (PlaceId q : t.outputs) w_.line("{0}[{1}] = {2}; {1}++;", c_.add, c_.add_n, constant(q));
  }
  std::string active_set_args() const {
    return fmt::format("{}, {}, {}u", c_.field(c_.active), c_.active_levels, l().active.levels());
  }

  void transitions() {
    if (!has_transitions()) return;
    if (l().place_driven) {
      section("/* Perform state update: the active places in declaration order, at each the transitions it");
      w_.line("   owns; owners follow the transitions' declaration order, so the transitions are tried in it.");
      w_.line("   The activation they produce waits in {}[] and cannot be consumed before the next tick */", c_.add);
      for_members(active_set(), c_.field(c_.active), [&] {
        for (PlaceId p : places()) {
          if (owned(p).empty()) continue;
          std::vector<std::string> test = conditions({owned(p).begin(), owned(p).end()});
          in_case(constant(p), [&] {
            for (std::size_t k = 0; k < owned(p).size(); ++k) transition_block(owned(p)[k], test[k]);
            w_.line("break;");
          });
        }
      });
      return;
    }
    section("/* Perform state update: the candidates in declaration order, each set emptied as it is read.");
    w_.line("   The activation they produce waits in {}[] and cannot be consumed before the next tick */", c_.add);
    const std::string &w = c_.word, &b = c_.bits;
    auto each_word =
        w_.block(fmt::format("for ({0} = {1}({2}, 1u, 0u); {0} != UINT32_MAX; {0} = {1}({2}, 1u, {0} + 1u)) {{", w,
                             c_.next_fn, candidate_set()));
    w_.line("{} = {}[{}];", b, c_.field(c_.candidates), w);
    w_.line("{}[{}] = 0u;", c_.field(c_.candidates), w);
    w_.line("{}({}, 1u, {});", c_.erase_fn, candidate_set(), w);
    auto each_bit = w_.block(fmt::format("for (; {0} != 0u; {0} &= {0} - 1u) {{", b));
    w_.line("switch (({} << 5) | {}({})) {{", w, c_.lowest_fn, b);
    for (TransitionId t : c_.chart.transitions.ids()) {
      std::vector<std::string> test = conditions({t});
      in_case(c_.transition_const[t], [&] {
        transition_block(t, test[0]);
        w_.line("break;");
      });
    }
    switch_end();
  }

  /// Step 3a: AV := avail + add. A place whose counter rises from 0 joins the active set.
  void commit() {
    if (!has_transitions()) return;
    section("/* Commit the activation produced in this tick */");
    const std::string &i = c_.i, &p = c_.index;
    auto scope = w_.block(fmt::format("for ({0} = 0; {0} < {1}; ++{0}) {{", i, c_.add_n));
    w_.line("{}{} = {}[{}];", c_.hooks() ? "" : "uint32_t ", p, c_.add, i);
    std::string av = fmt::format("{}[{}]", c_.field(c_.av), p);
    if (l().saturate) w_.line("if ({} == UINT32_MAX) {{ continue; }} /* saturated: see docs/c-engine.md */", av);
    // The counter never wraps: it is bounded by proof, or saturated above.
    w_.line("{}++;", av);
    auto joins = w_.block(fmt::format("if ({} == 1u) {{", av));
    w_.line("{}({}, {});", c_.insert_fn, active_set(), p);
    if (l().watch_capacity > 0)
      w_.line("if ({0}({1})) {{ {2}[{3}] = ({4}){1}; {3}++; }}", c_.watched_fn, p, c_.gained, c_.gained_n,
              place_type());
  }

  /// Step 3b: all exits, then all entries, each in declaration order. A watched place that was
  /// active at the start and is gained again must have fallen to 0 on the way: it is in both
  /// lists, and neither its exit nor its entry runs.
  void exits_and_entries() {
    if (!has_transitions() || l().watch_capacity == 0) return;
    section("/* Places that lost their activation exit, then places that gained it enter */");
    const std::string &i = c_.i, &j = c_.word;
    // A list of one is sorted.
    if (l().lost_capacity > 1) w_.line("{}({}, {});", c_.sort_fn, c_.lost, c_.lost_n);
    if (l().gained_capacity > 1) w_.line("{}({}, {});", c_.sort_fn, c_.gained, c_.gained_n);
    if (any_exits()) {
      auto scope = w_.block(fmt::format("for ({0} = 0; {0} < {1}; ++{0}) {{", i, c_.lost_n));
      w_.line("if ({}[{}[{}]] != 0u) {{ continue; }} /* lost and regained: still active */", c_.field(c_.av), c_.lost,
              i);
      w_.line("switch ({}[{}]) {{", c_.lost, i);
      for (PlaceId p : places())
        if (c_.runs_exit(p)) case_block(p, exit_of(p), c_.stop_call(p));
      switch_end();
    }
    w_.line("{} = 0;", j);
    auto scope = w_.block(fmt::format("for ({0} = 0; {0} < {1}; ++{0}) {{", i, c_.gained_n));
    w_.line("while (({0} < {1}) && ({2}[{0}] < {3}[{4}])) {{ ++{0}; }}", j, c_.lost_n, c_.lost, c_.gained, i);
    w_.line("if (({0} < {1}) && ({2}[{0}] == {3}[{4}])) {{ continue; }} /* lost and regained: no entry, the timer goes "
            "on */",
            j, c_.lost_n, c_.lost, c_.gained, i);
    w_.line("switch ({}[{}]) {{", c_.gained, i);
    for (PlaceId p : places())
      if (c_.runs_entry(p) || c_.resets_timer(p)) entry_case(p);
    switch_end();
  }

  /// The observation hooks, compiled only with -DX_HOOKS: the start of the tick against its
  /// end, place by place and transition by transition (a hooks build pays for the whole chart).
  void hooks() {
    if (!c_.hooks()) return;
    hooks_section("/* Observation hooks: places that lost, then gained activation; transitions open from now on */");
    const std::string &p = c_.index, &b = c_.before;
    auto was = [&](const std::string &place) {
      return fmt::format("(({}[{} >> 5] >> ({} & 31u)) & 1u)", b, place, place);
    };
    activation_hooks(fmt::format("for ({0} = 0; {0} < (uint32_t){1}; ++{0}) {{", p, c_.place_count), p, was);
    for (TransitionId t : c_.chart.transitions.ids()) {
      std::string before, now;
      for (PlaceId q : c_.chart.transitions[t].inputs) {
        before += fmt::format("{}({} != 0u)", before.empty() ? "" : " && ", was("(uint32_t)" + constant(q)));
        now += fmt::format(" && ({} != 0u)", c_.av_of(q));
      }
      w_.line("if (!({}){}) {{ {}({}, {}); }}", before, now, c_.enabled_fn, c_.self, c_.transition_const[t]);
    }
    directive(w_, "#endif");
  }

  /// Step 4: the active places in declaration order, each with actions running them once.
  void actions() {
    if (!any_actions()) return;
    section(c_.has_sub() ? "/* Perform place actions: the active places in declaration order, then their instances */"
                         : "/* Perform place actions: the active places in declaration order */");
    for_members(active_set(), c_.field(c_.active), [&] {
      for (PlaceId p : places())
        if (c_.acts(p)) case_block(p, c_.place(p).action, {}, c_.tick_call(p));
    });
  }
};

/// The file-local functions of the sparse form's sets, before _init.
void sparse_helpers(CodeWriter &w, const EngineContext &c) {
  const Layout &l = c.layout;
  auto table = [](const BitLevels &b) {
    std::string s;
    for (auto f : b.from) s += (s.empty() ? "" : ", ") + fmt::format("{}u", f);
    return s;
  };
  w.line("/* Sets of numbers ({}) as bits with summary levels:",
         l.place_driven ? "the active places" : "the active places, the candidate transitions");
  w.line("   bit j of a word of level k+1 says that word j of level k has members, so looking for the next");
  w.line("   member skips empty words. The tables say where each level's words begin; the last entry is");
  w.line("   the total. */");
  w.line("static const uint32_t {}[{}] = {{{}}};", c.active_levels, l.active.from.size(), table(l.active));
  if (!l.place_driven)
    w.line("static const uint32_t {}[{}] = {{{}}};", c.candidate_levels, l.candidates.from.size(), table(l.candidates));
  w.blank();
  emit_set_functions(w, c);
  if (c.chart.transitions.empty() || l.watch_capacity == 0) return;
  const char *type = uint_type(l.index_bits);
  // One watched place needs no sorting (and gcc -O2 would warn about the inlined loop over a
  // one-entry array, -Warray-bounds).
  if (l.lost_capacity > 1 || l.gained_capacity > 1) {
    w.blank();
    emit_sort_function(w, c, type);
  }
  w.blank();
  w.line("/* Whether a place runs exit or entry code, or resets its timer, when its activation changes. */");
  w.line("static bool {}(uint32_t place)", c.watched_fn);
  auto body = w.block("{");
  w.line("bool watched;");
  w.line("switch (place) {");  // the labels stand at the level of the switch
  for (PlaceId p : c.chart.places.ids())
    if (c.watched(p)) w.line("case {}:", c.place_const[p]);
  {
    auto in_case = w.indented();
    w.line("watched = true;");
    w.line("break;");
  }
  w.line("default:");
  {
    auto in_default = w.indented();
    w.line("watched = false;");
    w.line("break;");
  }
  w.line("}");
  w.line("return watched;");
}

}  // namespace

void emit_sparse_helpers(CodeWriter &w, const EngineContext &c) { sparse_helpers(w, c); }

void emit_sequential_run(CodeWriter &w, const EngineContext &c) { SequentialRun(w, c).emit(); }

void emit_sparse_run(CodeWriter &w, const EngineContext &c) { SparseRun(w, c).emit(); }

}  // namespace gfec::c_backend
