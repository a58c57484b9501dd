// Charts that the C engine's run tests and the reference interpreter's tests both run, each
// with its interface, so that the two sets of hand-written logs are about one machine.
#pragma once

namespace gfec::test::charts {

// if / else if / else in actions and entry and exit blocks (docs/language.md "if and else"),
// with calls in the conditions (one needs a temporary to keep them in order) and a timer.
inline const char *const kIfElse = R"(
interface Bot { bool X(); bool Y(); int N(); int M(); void A(); void B(int v); void C(); void D(); }
sfc Branches {
  period 10ms;
  var int k = 0;
  initial place P {
    entry { if (X()) { A(); } else { C(); } }
    if (N() + M() > 2) { B(N()); } else if (Y()) { if (X()) { C(); } k += 1; } else { D(); }
    if (elapsed(P) >= 20ms) { B(k); }
  }
  place Q { exit { if (Y()) { B(k); } } D(); }
  transition P -> Q when k >= 2;
  transition Q -> P when X();
})";

// fsm entry and exit (docs/language.md "fsm entry and exit"): the first tick runs the initial
// state's entry; a transition runs the old state's exit, then the new state's entry with its
// timer at 0, then (unless terminal) its action.
inline const char *const kFsmEntryExit = R"(
interface Bot {
  bool Go(); bool Back(); bool Fin();
  void EnterA(); void ExitA(); void DoA(); void EnterB(); void ExitB(); void DoB(); void Late();
}
fsm Doors {
  period 10ms;
  initial state A { entry { EnterA(); } DoA(); exit { ExitA(); } }
  state B {
    entry { EnterB(); if (elapsed(B) >= 10ms) { Late(); } }
    DoB();
    if (elapsed(B) >= 10ms) { Late(); }
    exit { ExitB(); }
  }
  success state Done;
  A -> B when Go();
  B -> A when Back();
  B -> Done when Fin();
})";

// A team of four (docs/language.md "Teams"): each agent counts the team in each state.
inline const char *const kCensus = R"(
interface Bot { bool Move(); void Count(int me, int go, int wait); }
fsm Census {
  team 4;
  initial state Go { Count(agent(), team(Go), team(Wait)); }
  state Wait { Count(agent(), team(Go), team(Wait)); }
  Go -> Wait when Move();
  Wait -> Go when Move();
})";

}  // namespace gfec::test::charts
