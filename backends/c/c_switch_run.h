// What the two engines with one active place share (the sequential sfc form, c_sfc_scalable.cc;
// the fsm, c_fsm_run.cc): the state is one place number, and each part of a tick is a switch on
// it (the sequential form's always; an fsm's above kSplitAbovePlaces states). Above that size
// each switch is written as file-local part functions of kPartPlaces places, called through a
// table (docs/c-engine.md, "Large charts"): gcc's time and memory on one function with a case
// per place grow faster than the chart (docs/performance.md, "gcc on large engines").
#pragma once

#include "c_run_writer.h"

#include <functional>
#include <string>
#include <vector>

namespace gfec::c_backend {

class SwitchRun : protected RunWriter {
protected:
  SwitchRun(CodeWriter &w, const EngineContext &c);

  /// A switch on a place number: `kind` names its parts (EngineContext::kPartKinds); `has(p)`: place
  /// `p` has a case, which `write(p)` writes.
  struct PlaceSwitch {
    const char *kind;
    std::function<bool(model::PlaceId)> has;
    std::function<void(model::PlaceId)> write;
    /// The split update switch: its parts return whether the place's one transition fired, and
    /// the run function moves to the place the table part_next() holds for it.
    bool moves = false;
  };

  // ---- what the form says about its state
  /// The field that holds the active place (an lvalue), and its C type.
  virtual std::string state() const = 0;
  virtual std::string state_type() const = 0;
  /// The lines that move the state to `to` when a transition fires.
  virtual void move(model::PlaceId to) = 0;
  /// Whether the split form may move to `to` by the table alone (no line but the move itself).
  virtual bool moves_by_table(model::PlaceId) const { return true; }

  model::PlaceId tried_in(const model::Transition &t) const override { return t.inputs.front(); }

  bool split() const { return c_.layout.part_places > 0; }
  /// The parts' parameter: a place number.
  const char *index_type() const { return uint_type(c_.layout.index_bits); }
  bool any(const PlaceSwitch &s) const;

  // ---- the switches of a tick, and whether the run function uses them (their parts exist only
  // then: an unused static function is a warning)
  PlaceSwitch time_switch();
  PlaceSwitch update_switch();
  PlaceSwitch exit_switch();
  PlaceSwitch entry_switch();
  PlaceSwitch hook_switch();
  PlaceSwitch action_switch();
  bool hooks_transitions() const { return !c_.chart.transitions.empty() && c_.hooks(); }

  /// `switch (value) { <the cases> }`, or in the split form the call of the part holding `value`.
  void place_switch(const PlaceSwitch &s, const std::string &value);
  /// The split form: each switch the run function uses, as parts and their table (before the
  /// run function).
  void parts();

private:
  /// The transitions leaving a place, in declaration order, up to the first that always fires
  /// (the ones after it are never open).
  std::vector<model::TransitionId> tried(model::PlaceId p) const;
  /// Where the split form moves the place `p` to when its part says that its transition fired:
  /// the one transition it tries, if it tries one; otherwise it moves itself.
  model::PlaceId single_move(model::PlaceId p) const;
  void update_case(model::PlaceId p);
  /// The transitions `ts` tried in turn, the first that fires moving the state.
  void moves(const std::vector<model::TransitionId> &ts, const std::vector<std::string> &test);
  void switch_parts(const PlaceSwitch &s);
  /// `<declaration> = { <items> };`, the items several to a line.
  /// `declaration = { item(0), ... item(n-1) };`, the items filled into lines of about 80 columns.
  void table(const std::string &declaration, std::size_t n, const std::function<std::string(std::size_t)> &item);
};

}  // namespace gfec::c_backend
