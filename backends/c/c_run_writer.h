// What the three writers of a run function share (the readable sfc form, c_sfc_run.cc; the
// scalable form, c_sfc_scalable.cc; the fsm, c_fsm_run.cc): the function's head, its sections,
// the first tick, and the chart's blocks with the engine's lines around them. Each writer adds
// only what its form does differently: how a place's block is guarded (an `if` on its counter,
// on the state, or a `case` of a switch) and the bookkeeping of the tick.
#pragma once

#include "c_context.h"
#include "id_groups.h"
#include "c_expr.h"
#include "code_writer.h"

#include <functional>
#include <string>
#include <vector>

namespace gfec::c_backend {

class RunWriter {
protected:
  RunWriter(CodeWriter &w, const EngineContext &c) : w_(w), c_(c), temps_(c.temp_prefix) {}
  virtual ~RunWriter() = default;
  RunWriter(const RunWriter &) = delete;
  RunWriter &operator=(const RunWriter &) = delete;

  /// `void X_run(X *m)` (static for an instance); the caller opens the body.
  void head();
  /// Starts a section of the function body: a blank line before all but the first.
  void section(const std::string &comment);
  /// Step 0: the entry blocks of the initial places, once; `comment` heads the section.
  void first_tick(const std::string &comment);

  /// The chart's statements `stmts`, as c_statements() rendered them into `text`, with lines of
  /// engine code `first` before them and `last` after them, at the current indentation.
  void statements(const std::vector<model::Stmt> &stmts, const std::vector<std::string> &text,
                  const std::vector<std::string> &first, const std::vector<std::string> &last);
  /// The chart's statements as the body of the block just opened (their temporaries declared at
  /// its top), and its closing brace.
  void block(const std::vector<model::Stmt> &stmts, const std::vector<std::string> &first = {},
             const std::vector<std::string> &last = {});
  /// Every exit block, in declaration order, each under `if (<left(p)>) {`.
  void exit_blocks(const std::function<std::string(model::PlaceId)> &left);
  /// Every entry block (or timer reset), in declaration order, each under `if (<entered(p)>) {`.
  void entry_blocks(const std::function<std::string(model::PlaceId)> &entered);

  /// Every action block (and instance tick), in declaration order, each under `if (<active(p)>) {`;
  /// `comment` heads the section, if any place acts.
  void action_blocks(const std::string &comment, const std::function<std::string(model::PlaceId)> &active);

  /// Step 5: the named actions under their action control (docs/iec.md "Action control"), in
  /// action declaration order, from the places' states at the end of the tick; then each place an
  /// edge is taken of remembers its state for the next tick. Nothing without named actions.
  void named_actions();

  /// A section compiled only in a hooks build: `#ifdef X_HOOKS`, then `comment`; the caller
  /// writes the `#endif`.
  void hooks_section(const std::string &comment);
  /// The hooks of the places that lost, then of those that gained activation in the tick: two
  /// loops `loop` (their head, `for (...) {`) over the place number `i`; `was(i)`: the place's
  /// activation at the start of the tick, compared with 0u.
  void activation_hooks(const std::string &loop, const std::string &i,
                        const std::function<std::string(const std::string &)> &was);

  /// The chart's places, in declaration order: `for (model::PlaceId p : places())`.
  IdRange<model::PlaceId> places() const { return c_.chart.places.ids(); }
  /// Some place runs exit code (an exit block or stopping an instance).
  bool any_exits() const;
  /// Some place acts: runs an action block or ticks an instance.
  bool any_actions() const;
  /// A place's exit (entry) block, or an empty one: a reference, never a copy of the block.
  const std::vector<model::Stmt> &exit_of(model::PlaceId p) const;
  const std::vector<model::Stmt> &entry_of(model::PlaceId p) const;
  /// The engine's lines before a place's entry block: its timer reset, its instance started.
  std::vector<std::string> entry_first(model::PlaceId p) const;

  // ---- the cases of a switch (the scalable forms, a large fsm)

  /// Files each transition under the place that tries it (`owner`), in declaration order, so
  /// that the writers stay linear in the chart; owned() reads them.
  void own(const std::function<model::PlaceId(model::TransitionId)> &owner);
  IdGroups<model::PlaceId, model::TransitionId>::Range owned(model::PlaceId place) const { return owned_[place]; }
  /// The place a transition is tried in, when only one place is ever active; none otherwise.
  virtual model::PlaceId tried_in(const model::Transition &) const { return {}; }

  const std::string &constant(model::PlaceId place) const { return c_.place_const.at(place); }
  /// The conditions of `transitions`, rendered before the code around them is written.
  /// `alone`: each is the whole test of its `if` (no input counters to test first).
  std::vector<std::string> conditions(const std::vector<model::TransitionId> &transitions, bool alone = false);
  /// `if (<inputs> && (<condition>)) {` for transition `t`; `inputs`: the counter tests;
  /// `condition`: the condition as conditions() rendered it.
  void transition_test(const model::Transition &t, const std::string &inputs, const std::string &condition);

  /// `case X:`, and what `body` writes indented. A case whose chart code needs temporaries
  /// (c_expr.h; rendered before) is a block, `case X: {`, that declares them: a declaration
  /// cannot follow a label.
  template <typename Body> void in_case(const std::string &label, Body body) {
    const bool braced = temps_.pending();
    w_.line("case {}:{}", label, braced ? " {" : "");
    CodeWriter::Scope scope(w_, braced ? "}" : "");
    temps_.declare(w_);
    body();
  }
  /// `case X_P:` with the chart's statements (and lines of engine code `first` before them and
  /// `last` after them), then `break;`.
  void case_block(model::PlaceId place, const std::vector<model::Stmt> &stmts,
                  const std::vector<std::string> &first = {}, const std::vector<std::string> &last = {});
  /// A gained place's entry: the timer reset, the instance started, then the entry block.
  void entry_case(model::PlaceId p) { case_block(p, entry_of(p), entry_first(p)); }
  /// `default: break;` and the switch's end: its labels stand at its level.
  void switch_end();

  CodeWriter &w_;
  const EngineContext &c_;
  bool started_ = false;
  Temporaries temps_;

private:
  IdGroups<model::PlaceId, model::TransitionId> owned_;  // one array, not a vector a place
};

}  // namespace gfec::c_backend
