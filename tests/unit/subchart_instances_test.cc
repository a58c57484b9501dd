// The limit on the sub-chart instances a compiled chart embeds (compiler/validate/subcharts.cc,
// docs/hierarchy.md, docs/security.md): counted per chart once, saturating, reported at the root.
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
  // P0 embeds 2^12 - 2 = 4094; Top adds one for P0 and one for Leaf: 4096, the limit.
  const std::string tower = binary_tower(12);
  const std::string at_limit = "import \"bot.iface\";\nsfc Leaf { initial place A; }\n" + tower +
                               "sfc Top { initial place A runs P0; place B runs Leaf; A -> B when Black(); }\n";
  Validated ok({{"t.sfc", at_limit}, {"bot.iface", test::kBot}});
  CHECK(ok.text() == "");

  const std::string over = "import \"bot.iface\";\nsfc Leaf { initial place A; }\n" + tower +
                           "sfc Top { initial place A runs Leaf; place B runs P0; place C runs Leaf; A -> B when "
                           "Black(); B -> C when White(); }\n";
  Validated r({{"t.sfc", over}, {"bot.iface", test::kBot}});
  // Reported once, at Top (P0 .. P11 are run by charts of the file), with the place that
  // brings the most: B, not the first place.
  CHECK(headlines(r.text()) ==
        "t.sfc:15:5: error: sfc 'Top' embeds 4097 sub-chart instances, more than the 4096 gfec compiles "
        "[subchart-instances]\n"
        "t.sfc:15:51: note: place 'B' runs 'P0', which brings the most: 4095 ('P0' and the 4094 it embeds)\n");
}

TEST_CASE("sub-chart instances: counted once per chart and saturating", "[validate][subcharts]") {
  // 2^70 instances: counting them one by one would never end, and 64 bits would overflow.
  Validated r({{"t.sfc", "import \"bot.iface\";\n" + binary_tower(70)}, {"bot.iface", test::kBot}});
  CHECK(headlines(r.text()) ==
        "t.sfc:2:5: error: sfc 'P0' embeds at least 4611686018427387904 sub-chart instances, more than the 4096 "
        "gfec compiles [subchart-instances]\n"
        "t.sfc:2:31: note: place 'A' runs 'P1', which brings the most: at least 4611686018427387904\n");
  // A long chain of charts, one instance each: counted without recursion (no stack to run out
  // of), 4096 deep is the limit, 20,000 deep over it.
  auto chain = [](int n) {
    std::string s = "import \"bot.iface\";\n";
    for (int i = 0; i < n; ++i)
      s += "sfc C" + std::to_string(i) + " { initial place A runs C" + std::to_string(i + 1) + "; }\n";
    return s + "sfc C" + std::to_string(n) + " { initial place A; }\n";
  };
  Validated at_limit({{"t.sfc", chain(4096)}, {"bot.iface", test::kBot}});
  CHECK(at_limit.text() == "");
  Validated deep({{"t.sfc", chain(20000)}, {"bot.iface", test::kBot}});
  CHECK(headlines(deep.text()) ==
        "t.sfc:2:5: error: sfc 'C0' embeds 20000 sub-chart instances, more than the 4096 gfec compiles "
        "[subchart-instances]\n"
        "t.sfc:2:31: note: place 'A' runs 'C1', which brings the most: 20000 ('C1' and the 19999 it embeds)\n");
}

TEST_CASE("sub-chart instances: only what the main file compiles counts", "[validate][subcharts]") {
  // An imported tower that nothing runs is no error; the main file's chart that runs it is.
  const std::string lib = "import \"bot.iface\";\n" + binary_tower(13, "Q");
  Validated unused(
      {{"t.sfc", "import \"lib.sfc\";\nsfc Main { initial place A; }\n"}, {"lib.sfc", lib}, {"bot.iface", test::kBot}});
  CHECK(unused.text() == "");
  Validated used({{"t.sfc", "import \"lib.sfc\";\nfsm Main { initial state A runs Q0; success state B; A -> B when "
                            "Black(); }\n"},
                  {"lib.sfc", lib},
                  {"bot.iface", test::kBot}});
  CHECK(headlines(used.text()) ==
        "t.sfc:2:5: error: fsm 'Main' embeds 8191 sub-chart instances, more than the 4096 gfec compiles "
        "[subchart-instances]\n"
        "t.sfc:2:33: note: state 'A' runs 'Q0', which brings the most: 8191 ('Q0' and the 8190 it embeds)\n");
}
