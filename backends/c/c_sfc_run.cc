// The run function of an sfc: one tick exactly as docs/language.md §5.1 says, laid out as
// GFE's generated engines are (docs/c-engine.md "X_run for an sfc"): one conditional block per
// transition, then one per place. Every part that a chart does not use is left out, so it costs
// nothing.
#include "c_emit.h"
#include "c_run_writer.h"

#include <fmt/format.h>

namespace gfec::c_backend {

namespace {

class SfcRun : RunWriter {
public:
  SfcRun(CodeWriter &w, const EngineContext &c) : RunWriter(w, c) {}

  void emit() {
    head();
    auto body = w_.block("{");
    declarations();
    first_tick("/* First tick: the initial places enter */");
    count_time();
    transitions();
    commit();
    exits_and_entries();
    hooks();
    actions();
    named_actions();
  }

private:
  bool produces() const {
    for (const auto &t : c_.chart.transitions)
      if (!t.outputs.empty()) return true;
    return false;
  }

  bool uses_self() const {
    return !c_.chart.transitions.empty() || c_.needs_started || c_.has_timers || any_actions() ||
           c_.has_named_actions();
  }

  /// The start of the tick is kept: for exits and entries, for conditions that read activation
  /// (docs/language.md, "Sub-charts"), or in a hooks build for the hooks.
  bool snapshot() const { return c_.needs_snapshot() || c_.reads_start; }

  /// The locals, and the snapshot of the activation vector at the start of the tick (taken
  /// only when something compares it with the end; for the hooks only in a hooks build).
  void declarations() {
    section("");
    if (produces())
      w_.line("{} {}[{}] = {{0}}; /* activation produced in this tick */", c_.readable_counter(), c_.add,
              c_.place_count);
    // The conditions are rendered first: the temporaries they need belong to the whole function.
    for (const auto &t : c_.chart.transitions)
      conditions_.push_back(t.condition ? c_condition(c_, *t.condition, temps_, true) : "");
    temps_.declare(w_);
    if (snapshot() || c_.hooks()) {
      if (!snapshot()) directive(w_, "#ifdef " + c_.hooks_macro);
      w_.line("{} {}[{}]; /* the activation at the start of the tick */", c_.readable_counter(), c_.before,
              c_.place_count);
      // A loop, not memcpy: the engine stays freestanding (no <string.h>) in every mode.
      w_.line("for (int {0} = 0; {0} < (int){1}; ++{0}) {{ {2}[{0}] = {3}[{0}]; }}", c_.index, c_.place_count,
              c_.before, c_.field(c_.av));
      if (!snapshot()) directive(w_, "#endif");
    }
    if (!uses_self()) w_.line("(void){}; /* the chart has neither transitions nor actions */", c_.self);
  }

  /// Step 1: timers of the places active at the start of the tick (saturating, never wrapping).
  void count_time() {
    if (!c_.has_timers) return;
    section("/* Count the ticks of the active places that have a timer */");
    for (model::PlaceId p : places())
      if (c_.place(p).timed)
        w_.line("if (({0} != 0u) && ({1} < UINT32_MAX)) {{ {1}++; }}", c_.av_of(p), c_.timer_of(p));
  }

  /// Step 2: one block per transition, in declaration order. `&&` short-circuits, so the
  /// condition is evaluated only if the transition is open, and left to right. The input counters
  /// themselves serve as `avail` (they only decrease here); produced activation waits in add[].
  void transitions() {
    if (c_.chart.transitions.empty()) return;
    section("/* Perform state update: transitions in declaration order; the activation they produce");
    w_.line("   waits in {}[] and cannot be consumed before the next tick */", c_.add);
    for (std::size_t i = 0; i < c_.chart.transitions.size(); ++i) {
      const auto &t = c_.chart.transitions[i];
      w_.line("/* {}: {} */", t.name, transition_label(c_, t));
      std::string test;
      for (model::PlaceId p : t.inputs) test += (test.empty() ? "(" : " && (") + c_.av_of(p) + " != 0u)";
      if (t.condition) test += (test.empty() ? "" : " && ") + conditions_.at(i);
      // Every transition's test is mapped to the chart: to its condition, or to the whole
      // transition when it has none (an unconditional join), so that a debugger's
      // `break chart.sfc:LINE` stops on it.
      w_.line_from(c_.model.sources(), t.condition ? t.condition->range : t.range);
      w_.line("if ({}) {{", test.empty() ? "true" : test);
      w_.line_back();
      CodeWriter::Scope fire(w_, "}");
      for (model::PlaceId p : t.inputs) w_.line("{}--;", c_.av_of(p));
      for (model::PlaceId p : t.outputs) w_.line("{}[{}]++;", c_.add, c_.place_const.at(p));
    }
  }

  /// Step 3a: AV := avail + add.
  void commit() {
    if (!produces()) return;
    section("/* Commit the activation produced in this tick */");
    for (model::PlaceId p : places())
      if (c_.is_output[p]) w_.line("{} += {}[{}];", c_.av_of(p), c_.add, c_.place_const[p]);
  }

  /// Step 3b: comparing the start of the tick with its end, all exits, then all entries. A place
  /// that lost and regained activation in the tick is active at both ends: nothing runs.
  void exits_and_entries() {
    if (!c_.needs_snapshot()) return;
    section("/* Places that lost their activation exit, then places that gained it enter */");
    exit_blocks([this](model::PlaceId p) {
      return fmt::format("({}[{}] != 0u) && ({} == 0u)", c_.before, c_.place_const[p], c_.av_of(p));
    });
    entry_blocks([this](model::PlaceId p) {
      return fmt::format("({}[{}] == 0u) && ({} != 0u)", c_.before, c_.place_const[p], c_.av_of(p));
    });
  }

  /// The observation hooks, compiled only with -DX_HOOKS.
  void hooks() {
    if (!c_.hooks()) return;
    hooks_section("/* Observation hooks: places that lost, then gained activation; transitions open from now on */");
    // A loop over the numbers (a test per place would repeat the exit, entry and enabled tests,
    // which cppcheck reports as duplicate conditions); the number is converted to the enum type
    // the hook takes.
    const std::string &b = c_.before, &i = c_.index;
    activation_hooks(fmt::format("for (int {0} = 0; {0} < (int){1}; ++{0}) {{", i, c_.place_count), i,
                     [&](const std::string &place) { return fmt::format("{}[{}]", b, place); });
    for (model::TransitionId t : c_.chart.transitions.ids()) {
      const auto &inputs = c_.chart.transitions[t].inputs;
      std::string was, is;
      for (model::PlaceId p : inputs) {
        const std::string &k = c_.place_const[p];
        was += fmt::format("{}({}[{}] != 0u)", was.empty() ? "" : " && ", b, k);
        is += fmt::format(" && ({} != 0u)", c_.av_of(p));
      }
      // Not all inputs were active, all are now.
      if (inputs.size() == 1) was = fmt::format("({}[{}] == 0u)", b, c_.place_const[inputs[0]]);
      else if (!was.empty()) was = "!(" + was + ")";
      if (!was.empty()) w_.line("if ({}{}) {{ {}({}, {}); }}", was, is, c_.enabled_fn, c_.self, c_.transition_const[t]);
    }
    directive(w_, "#endif");
  }

  /// Step 4: every active place runs its action block once, in declaration order.
  void actions() {
    action_blocks(c_.has_sub() ? "/* Perform place actions, each followed by one tick of the instance the place runs */"
                               : "/* Perform place actions */",
                  [this](model::PlaceId p) { return fmt::format("{} != 0u", c_.av_of(p)); });
  }

  std::vector<std::string> conditions_;  ///< by transition, rendered by declarations()
};

}  // namespace

void emit_sfc_run(CodeWriter &w, const EngineContext &c) { SfcRun(w, c).emit(); }

}  // namespace gfec::c_backend
