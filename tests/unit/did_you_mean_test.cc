// The did-you-mean of the support tier (support/did_you_mean.h): the edit distance, its banded
// form, and the choice of the nearest name.
#include "did_you_mean.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <vector>

using namespace gfec;

namespace {

/// The index of the nearest of `names` to `name` within `limit`, or -1.
int nearest(const std::string &name, const std::vector<std::string> &names, std::size_t limit) {
  NearestName n(name, limit);
  int best = -1;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (n.offer(names[i])) best = static_cast<int>(i);
  return best;
}

}  // namespace

TEST_CASE("did you mean: edit distance counts inserts, deletes, substitutions and swaps", "[support]") {
  CHECK(edit_distance("Left_IR_Blak", "Left_IR_Black") == 1);
  CHECK(edit_distance("flaot", "float") == 1);  // a swap of neighbours is one edit
  CHECK(edit_distance("", "abc") == 3);
  CHECK(edit_distance("abc", "") == 3);
  CHECK(edit_distance("kitten", "sitting") == 3);
  CHECK(edit_distance("same", "same") == 0);
}

TEST_CASE("did you mean: the banded edit distance is the distance, capped at the bound plus one", "[support]") {
  CHECK(edit_distance_within("kitten", "sitting", 3) == 3);
  CHECK(edit_distance_within("kitten", "sitting", 2) == 3);
  CHECK(edit_distance_within("flaot", "float", 0) == 1);
  CHECK(edit_distance_within("", "", 0) == 0);
  CHECK(edit_distance_within("a", "abcdefgh", 3) == 4);  // the length gap alone decides
  // Past the rows kept on the stack: the whole table, capped alike.
  const std::string long_a(300, 'x'), long_b = std::string(299, 'x') + "y";
  CHECK(edit_distance_within(long_a, long_b, 5) == 1);
  CHECK(edit_distance_within(long_a, std::string(300, 'y'), 5) == 6);
  // Random names over a small alphabet (so that transpositions and near misses are common),
  // every bound from 0 to past the distance: a deterministic sweep.
  std::uint32_t seed = 12345;
  auto next = [&] { return seed = seed * 1103515245u + 12345u, (seed >> 16) & 0x7fff; };
  auto word = [&] {
    std::string w(next() % 12, ' ');
    for (char &c : w) c = static_cast<char>('a' + next() % 3);
    return w;
  };
  for (int n = 0; n < 3000; ++n) {
    std::string a = word(), b = word();
    std::size_t d = edit_distance(a, b);
    for (std::size_t k = 0; k <= d + 1; ++k) {
      INFO(a << " / " << b << " k=" << k);
      REQUIRE(edit_distance_within(a, b, k) == std::min(d, k + 1));
    }
  }
}

TEST_CASE("did you mean: a typo may hold about a third of the name, at least one edit", "[support]") {
  CHECK(typo_limit(0) == 1);
  CHECK(typo_limit(1) == 1);
  CHECK(typo_limit(4) == 1);
  CHECK(typo_limit(5) == 2);
  CHECK(typo_limit(12) == 4);
}

TEST_CASE("did you mean: the nearest name within the limit, the first of equals", "[support]") {
  const std::vector<std::string> names{"speed", "laps", "lamp", "spend"};
  CHECK(nearest("lap", names, 1) == 1);      // "laps" and "lamp" are one edit away: the first wins
  CHECK(nearest("lmap", names, 1) == 2);     // a swap
  CHECK(nearest("sped", names, 1) == 0);     // "speed" before "spend", both one edit
  CHECK(nearest("spnd", names, 1) == 3);     // nearer than "speed" (two edits)
  CHECK(nearest("walk", names, 1) == -1);    // nothing within the limit
  CHECK(nearest("speeds", names, 0) == -1);  // a limit of 0 takes only the name itself
  CHECK(nearest("laps", names, 2) == 1);     // the name itself is distance 0 (callers skip it)
  NearestName n("spede", 2);
  CHECK(!n.found());
  CHECK(n.distance() == 3);
  CHECK(n.offer("spend"));    // two edits
  CHECK(!n.offer("speeds"));  // two edits too: not nearer
  CHECK(n.offer("speed"));    // one
  CHECK(n.found());
  CHECK(n.distance() == 1);
}

TEST_CASE("did you mean: a name too long, or candidates past the cap, cost nothing", "[support]") {
  // A name longer than kMaxSuggestedLength is never matched, not even by itself.
  const std::string longest(kMaxSuggestedLength, 'a'), over(kMaxSuggestedLength + 1, 'a');
  CHECK(NearestName(longest, 3).offer(longest + "b"));
  NearestName too_long(over, 3);
  CHECK(!too_long.offer(over));
  CHECK(!too_long.found());
  // Only the first kMaxSuggestionCandidates are weighed: a near one after them is not found.
  NearestName many("lamp", 1);
  bool any = false;
  for (std::size_t i = 0; i < kMaxSuggestionCandidates; ++i) any = many.offer("zzzzzzzz") || any;
  CHECK(!any);
  CHECK(!many.offer("lamps"));
  CHECK(!many.found());
}

TEST_CASE("did you mean: case is no edit, a name cut short is nearer than a substitution", "[support]") {
  CHECK(nearest("LED", {"Button", "Led"}, 1) == 1);               // capitals alone: distance 0
  CHECK(nearest("LED", {"led", "Led"}, 1) == 1);                  // equal ignoring case: fewer case changes wins
  CHECK(nearest("YellowOf", {"YellowOn", "YellowOff"}, 2) == 1);  // cut short, not a substitution
  CHECK(nearest("YellowOfff", {"YellowOn", "YellowOff"}, 3) == 1);
  CHECK(nearest("yelowon", {"YellowOff", "YellowOn"}, 2) == 1);  // ignoring case one edit, with it three
  NearestName n("Led", 1);
  CHECK(n.offer("LED"));
  CHECK(n.distance() == 0);
}
