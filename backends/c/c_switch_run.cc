#include "c_switch_run.h"

#include "c_emit.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec::c_backend {

using model::PlaceId;
using model::TransitionId;

SwitchRun::SwitchRun(CodeWriter &w, const EngineContext &c) : RunWriter(w, c) {
  own([&c](TransitionId t) { return c.chart.transitions[t].inputs.front(); });
}

bool SwitchRun::any(const PlaceSwitch &s) const {
  for (PlaceId p : places())
    if (s.has(p)) return true;
  return false;
}

SwitchRun::PlaceSwitch SwitchRun::time_switch() {
  return {"time", [this](PlaceId p) { return c_.place(p).timed; },
          [this](PlaceId p) {
            w_.line("case {0}: if ({1} < UINT32_MAX) {{ {1}++; }} break;", constant(p), c_.timer_of(p));
          }};
}

std::vector<TransitionId> SwitchRun::tried(PlaceId p) const {
  std::vector<TransitionId> t;
  for (TransitionId i : owned(p)) {
    t.push_back(i);
    if (!c_.chart.transitions[i].condition) break;
  }
  return t;
}

SwitchRun::PlaceSwitch SwitchRun::update_switch() {
  return {"update", [this](PlaceId p) { return !owned(p).empty(); }, [this](PlaceId p) { update_case(p); }, split()};
}

PlaceId SwitchRun::single_move(PlaceId p) const {
  std::vector<TransitionId> ts = tried(p);
  if (!split() || ts.size() != 1) return {};
  PlaceId to = c_.chart.transitions[ts.front()].outputs.front();
  return moves_by_table(to) ? to : PlaceId();
}

void SwitchRun::update_case(PlaceId p) {
  std::vector<TransitionId> ts = tried(p);
  std::vector<std::string> test = conditions(ts, true);
  in_case(constant(p), [&] {
    if (single_move(p)) {
      // The part only tells whether the transition fires; the move is the run function's,
      // from a table. gcc -O2 compiles a case that only evaluates a condition into the part's
      // result in a third of the time and memory of one that moves (docs/performance.md).
      const auto &t = c_.chart.transitions[ts.front()];
      w_.line("/* {}: {} */", t.name, transition_label(c_, t));
      w_.line_from(c_.model.sources(), t.condition ? t.condition->range : t.range);
      w_.line("{} = {};", c_.fire, t.condition ? test.front() : "true");
      w_.line_back();
    } else {
      moves(ts, test);
    }
    w_.line("break;");
  });
}

void SwitchRun::moves(const std::vector<TransitionId> &ts, const std::vector<std::string> &test) {
  for (std::size_t k = 0; k < ts.size(); ++k) {
    const auto &t = c_.chart.transitions[ts[k]];
    w_.line("/* {}: {} */", t.name, transition_label(c_, t));
    if (!t.condition) {
      // Always fires (the last one tried()): no `if (true)`, whose condition would be invariant
      // (MISRA C:2012 rule 14.3); the move itself is mapped to the transition.
      w_.line_from(c_.model.sources(), t.range);
      move(t.outputs.front());
      w_.line_back();
      continue;
    }
    transition_test(t, "", test[k]);
    CodeWriter::Scope fires(w_, "}");  // the block transition_test opened
    move(t.outputs.front());
    w_.line("break;");
  }
}

SwitchRun::PlaceSwitch SwitchRun::exit_switch() {
  return {"exit", [this](PlaceId p) { return c_.runs_exit(p); },
          [this](PlaceId p) { case_block(p, exit_of(p), c_.stop_call(p)); }};
}

SwitchRun::PlaceSwitch SwitchRun::entry_switch() {
  return {"enter", [this](PlaceId p) { return c_.runs_entry(p) || c_.resets_timer(p); },
          [this](PlaceId p) { entry_case(p); }};
}

SwitchRun::PlaceSwitch SwitchRun::hook_switch() {
  return {"hook", [this](PlaceId p) { return !owned(p).empty(); },
          [this](PlaceId p) {
            std::string calls;
            for (TransitionId t : owned(p))
              calls += fmt::format(" {}({}, {});", c_.enabled_fn, c_.self, c_.transition_const[t]);
            w_.line("case {}:{} break;", constant(p), calls);
          }};
}

SwitchRun::PlaceSwitch SwitchRun::action_switch() {
  return {"act", [this](PlaceId p) { return c_.acts(p); },
          [this](PlaceId p) { case_block(p, c_.place(p).action, {}, c_.tick_call(p)); }};
}

void SwitchRun::place_switch(const PlaceSwitch &s, const std::string &value) {
  if (split()) {
    std::string call =
        fmt::format("{}[{} / {}u]({}, {})", c_.part_table(s.kind), value, c_.layout.part_places, c_.self, value);
    if (!s.moves) {
      w_.line("{};", call);
      return;
    }
    // The result in a variable of its own: the test of an `if` is essentially Boolean (MISRA
    // C:2012 rule 14.4), which cppcheck cannot tell of a call through a table.
    w_.line("{} = {};", c_.fire, call);
    auto fires = w_.block(fmt::format("if ({}) {{", c_.fire));
    w_.line("{0} = {1}[{0}];", state(), c_.part_next());
    return;
  }
  w_.line("switch ({}) {{", value);
  for (PlaceId p : places())
    if (s.has(p)) s.write(p);
  switch_end();
}

void SwitchRun::parts() {
  if (c_.has_timers) switch_parts(time_switch());
  if (!c_.chart.transitions.empty()) switch_parts(update_switch());
  if (c_.needs_snapshot()) {
    PlaceSwitch exits = exit_switch(), entries = entry_switch();
    if (any(exits)) switch_parts(exits);
    if (any(entries)) switch_parts(entries);
  }
  if (hooks_transitions()) {
    directive(w_, "#ifdef " + c_.hooks_macro);
    switch_parts(hook_switch());
    directive(w_, "#endif");
  }
  if (any_actions()) switch_parts(action_switch());
}

void SwitchRun::switch_parts(const PlaceSwitch &s) {
  const std::size_t n = c_.part_count(), size = c_.layout.part_places;
  w_.line("/* The {} switch, in parts of {} places (docs/c-engine.md, \"Large charts\") */", s.kind, size);
  for (std::size_t k = 0; k < n; ++k) {
    w_.line("static {} {}({} *{}, {} {})", s.moves ? "bool" : "void", c_.part_fn(s.kind, k), c_.struct_type, c_.self,
            index_type(), c_.index);
    {
      auto body = w_.block("{");
      if (s.moves) w_.line("bool {} = false;", c_.fire);
      w_.line("(void){}; /* not every part reads the engine */", c_.self);
      bool cases = false;
      for (std::size_t p = k * size; p < std::min((k + 1) * size, c_.chart.places.size()); ++p)
        cases = cases || s.has(PlaceId(p));
      if (!cases) {  // a switch needs two clauses (MISRA C:2012 rule 16.6): no place here has one
        w_.line("(void){}; /* no place of this part has a case */", c_.index);
      } else {
        w_.line("switch ({}) {{", c_.index);
        for (std::size_t p = k * size; p < std::min((k + 1) * size, c_.chart.places.size()); ++p)
          if (s.has(PlaceId(p))) s.write(PlaceId(p));
        switch_end();
      }
      if (s.moves) w_.line("return {};", c_.fire);
    }
    w_.blank();
  }
  table(fmt::format("static {} (*const {}[{}])({} *, {})", s.moves ? "bool" : "void", c_.part_table(s.kind), n,
                    c_.struct_type, index_type()),
        n, [&](std::size_t k) { return c_.part_fn(s.kind, k); });
  if (!s.moves) return;
  w_.line("/* The place each place moves to when its update part says that its transition fired (a place");
  w_.line("   that moves itself, with several transitions to try or into a terminal state, has its own) */");
  table(fmt::format("static const {} {}[{}]", state_type(), c_.part_next(), c_.chart.places.size()),
        c_.chart.places.size(), [&](std::size_t k) {
          const PlaceId p(k);
          const PlaceId to = single_move(p);
          return constant(to ? to : p);
        });
}

void SwitchRun::table(const std::string &declaration, std::size_t n,
                      const std::function<std::string(std::size_t)> &item) {
  {
    auto rows = w_.block(fmt::format("{} = {{", declaration), "};");
    std::string row;
    for (std::size_t k = 0; k < n; ++k) {
      if (!row.empty()) row += ' ';
      row += item(k);
      if (k + 1 < n) row += ',';
      if (row.size() > 80 || k + 1 == n) {
        w_.line(std::string_view(row));
        row.clear();
      }
    }
  }
  w_.blank();
}

}  // namespace gfec::c_backend
