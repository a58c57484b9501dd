// The limits on the sub-chart instances a compiled chart embeds and on how deep they nest
// (compiler/validate/subcharts.cc, docs/hierarchy.md, docs/security.md): counted per chart once,
// saturating, reported at the root.
#include "validate_fixture.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;
using test::Validated;

namespace {

/// Only the first line of each diagnostic and note ("file:line:col: error: ... [name]").
std::string headlines(const std::string &printed) {
  std::string out;
  for (std::size_t at = 0, nl; (nl = printed.find('\n', at)) != std::string::npos; at = nl + 1)
    if (printed.compare(at, 2, "t.") == 0 || printed.compare(at, 4, "lib.") == 0)
      out += printed.substr(at, nl - at + 1);
  return out;
}

/// Charts P0 .. P{levels-1}: each but the last has two places that both run the next, so P0
/// embeds 2 + 4 + ... + 2^(levels-1) = 2^levels - 2 instances. One chart a line.
std::string binary_tower(int levels, const std::string &prefix = "P") {
  std::string s;
  for (int i = 0; i + 1 < levels; ++i)
    s += "sfc " + prefix + std::to_string(i) + " { initial place A runs " + prefix + std::to_string(i + 1) +
         "; place B runs " + prefix + std::to_string(i + 1) + "; A -> B when Black(); }\n";
  s += "sfc " + prefix + std::to_string(levels - 1) + " { initial place A; }\n";
  return s;
}

}  // namespace

TEST_CASE("sub-chart instances: up to the limit compiles, one more is an error at the root", "[validate][subcharts]") {
  // P0 embeds 2^16 - 2 = 65534; Top adds one for P0 and one for Leaf: 65536, the limit.
  const std::string tower = binary_tower(16);
  const std::string at_limit = "import \"bot.iface\";\nsfc Leaf { initial place A; }\n" + tower +
                               "sfc Top { initial place A runs P0; place B runs Leaf; A -> B when Black(); }\n";
  Validated ok({{"t.sfc", at_limit}, {"bot.iface", test::kBot}});
  CHECK(ok.text() == "");

  const std::string over = "import \"bot.iface\";\nsfc Leaf { initial place A; }\n" + tower +
                           "sfc Top { initial place A runs Leaf; place B runs P0; place C runs Leaf; A -> B when "
                           "Black(); B -> C when White(); }\n";
  Validated r({{"t.sfc", over}, {"bot.iface", test::kBot}});
  // Reported once, at Top (P0 .. P15 are run by charts of the file), with the place that
  // brings the most: B, not the first place.
  CHECK(headlines(r.text()) ==
        "t.sfc:19:5: error: sfc 'Top' embeds 65537 sub-chart instances, more than the 65536 gfec compiles "
        "[subchart-instances]\n"
        "t.sfc:19:51: note: place 'B' runs 'P0', which brings the most: 65535 ('P0' and the 65534 it embeds)\n");
}

TEST_CASE("sub-chart instances: counted once per chart and saturating", "[validate][subcharts]") {
  // 2^70 instances: counting them one by one would never end, and 64 bits would overflow.
  Validated r({{"t.sfc", "import \"bot.iface\";\n" + binary_tower(70)}, {"bot.iface", test::kBot}});
  CHECK(headlines(r.text()) ==
        "t.sfc:2:5: error: sfc 'P0' embeds at least 4611686018427387904 sub-chart instances, more than the 65536 "
        "gfec compiles [subchart-instances]\n"
        "t.sfc:2:31: note: place 'A' runs 'P1', which brings the most: at least 4611686018427387904\n");
}

namespace {

/// Charts C0 .. C{n}, each running the next from its one place: C0 embeds n instances, n levels
/// deep. One chart a line.
std::string chain(int n) {
  std::string s = "import \"bot.iface\";\n";
  for (int i = 0; i < n; ++i)
    s += "sfc C" + std::to_string(i) + " { initial place A runs C" + std::to_string(i + 1) + "; }\n";
  return s + "sfc C" + std::to_string(n) + " { initial place A; }\n";
}

}  // namespace

TEST_CASE("sub-chart instances: up to 200 levels deep compile, deeper is an error at the root",
          "[validate][subcharts]") {
  Validated at_limit({{"t.sfc", chain(200)}, {"bot.iface", test::kBot}});
  CHECK(at_limit.text() == "");
  Validated over({{"t.sfc", chain(201)}, {"bot.iface", test::kBot}});
  CHECK(headlines(over.text()) ==
        "t.sfc:2:5: error: sfc 'C0' nests sub-chart instances 201 levels deep, more than the 200 gfec compiles "
        "[subchart-depth]\n"
        "t.sfc:2:31: note: place 'A' runs 'C1', which goes the deepest: 201 levels ('C1' and the 200 below it)\n");
  // A long chain of charts, far fewer instances than the limit: its depth is the error, found
  // without recursion (no stack to run out of).
  Validated deep({{"t.sfc", chain(20000)}, {"bot.iface", test::kBot}});
  CHECK(headlines(deep.text()) ==
        "t.sfc:2:5: error: sfc 'C0' nests sub-chart instances 20000 levels deep, more than the 200 gfec compiles "
        "[subchart-depth]\n"
        "t.sfc:2:31: note: place 'A' runs 'C1', which goes the deepest: 20000 levels ('C1' and the 19999 below it)\n");
  // The note names the place that goes the deepest, not the first place; the depth is the longest
  // way down, however many instances.
  Validated branch({{"t.sfc", chain(200) + "sfc Top { initial place X runs C200; place Y runs C0; X -> Y when "
                                           "Black(); }\n"},
                    {"bot.iface", test::kBot}});
  CHECK(headlines(branch.text()) ==
        "t.sfc:203:5: error: sfc 'Top' nests sub-chart instances 201 levels deep, more than the 200 gfec compiles "
        "[subchart-depth]\n"
        "t.sfc:203:51: note: place 'Y' runs 'C0', which goes the deepest: 201 levels ('C0' and the 200 below it)\n");
}

TEST_CASE("sub-chart instances: only what the main file compiles counts", "[validate][subcharts]") {
  // An imported tower that nothing runs is no error; the main file's chart that runs it is.
  const std::string lib = "import \"bot.iface\";\n" + binary_tower(17, "Q");
  Validated unused(
      {{"t.sfc", "import \"lib.sfc\";\nsfc Main { initial place A; }\n"}, {"lib.sfc", lib}, {"bot.iface", test::kBot}});
  CHECK(unused.text() == "");
  Validated used({{"t.sfc", "import \"lib.sfc\";\nfsm Main { initial state A runs Q0; success state B; A -> B when "
                            "Black(); }\n"},
                  {"lib.sfc", lib},
                  {"bot.iface", test::kBot}});
  CHECK(headlines(used.text()) ==
        "t.sfc:2:5: error: fsm 'Main' embeds 131071 sub-chart instances, more than the 65536 gfec compiles "
        "[subchart-instances]\n"
        "t.sfc:2:33: note: state 'A' runs 'Q0', which brings the most: 131071 ('Q0' and the 131070 it embeds)\n");
}
