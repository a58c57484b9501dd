// Random sfc charts for the tests that run engines against a reference (the C engine against
// the interpreter, the live trace's frames against the engine's own log).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace cbt {

/// A random sfc as chart text: a few places (some initial, some with actions, entry or exit
/// blocks), transitions with joins, forks, self-loops and conditions over sensing functions,
/// timers and a variable. Every fourth chart is sequential (one initial place, one place to
/// one place), which the scalable form compiles to a switch.
inline std::string random_sfc(unsigned seed) {
  std::mt19937 rng(seed);
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  const bool sequential = seed % 4 == 0;
  const int places = 2 + pick(8), transitions = 1 + pick(12);
  std::string s = "interface RandomBot {\n  bool B0();\n  bool B1();\n  bool B2();\n  int Level();\n"
                  "  void Act(int n);\n  void Beep();\n}\n\nsfc Random {\n  period 10ms;\n  var int n = 0;\n";
  for (int p = 0; p < places; ++p) {
    bool initial = sequential ? p == 0 : (p == 0 || pick(4) == 0);
    std::string body;
    if (pick(3) == 0) body += " entry { Beep(); }";
    if (pick(3) == 0) body += " exit { n += 1; }";
    if (pick(2) == 0) body += fmt::format(" Act({});", p);
    if (pick(5) == 0) body += " Act(n);";
    s += fmt::format("  {}place P{} {{{} }}\n", initial ? "initial " : "", p, body);
  }
  const char *conditions[] = {"", "B0()", "B1() && !B2()", "Level() > 1", "B2() || Level() == 0", "B0() && B1()"};
  for (int t = 0; t < transitions; ++t) {
    auto some = [&](int most) {
      std::vector<int> list;
      int n = sequential ? 1 : 1 + pick(most);
      while (static_cast<int>(list.size()) < n && static_cast<int>(list.size()) < places) {
        int p = pick(places);
        if (std::find(list.begin(), list.end(), p) == list.end()) list.push_back(p);
      }
      std::string text;
      for (int p : list) text += (text.empty() ? "P" : ", P") + std::to_string(p);
      return list.size() == 1 ? text : "(" + text + ")";
    };
    std::string in = some(2), out = some(3);
    std::string when =
        pick(4) == 0 ? fmt::format("elapsed(P{}) >= {}ms", pick(places), 10 * pick(5)) : conditions[pick(6)];
    s += fmt::format("  transition {} -> {}{};\n", in, out, when.empty() ? "" : " when " + when);
  }
  return s + "}\n";
}

}  // namespace cbt
