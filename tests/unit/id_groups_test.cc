// Items grouped by an id (compiler/id_groups.h): what the fsm checks, the activation bound and
// the C back end's hooks read as "the transitions leaving each state", without a vector each.
#include "id_groups.h"
#include "model.h"

#include <catch2/catch.hpp>

#include <utility>
#include <vector>

using namespace gfec;
using model::PlaceId;
using model::TransitionId;

namespace {

std::vector<std::size_t> positions(IdGroups<PlaceId, TransitionId>::Range r) {
  std::vector<std::size_t> out;
  for (TransitionId t : r) out.push_back(t.index());
  return out;
}

}  // namespace

TEST_CASE("id groups: each group keeps its items in the order given, groups without any are empty", "[id]") {
  // Transitions 0..5 leaving states 2, 0, 2, 3, 0, 2: declared interleaved, as in an fsm whose
  // transitions are not written state by state.
  const std::size_t from[] = {2, 0, 2, 3, 0, 2};
  std::vector<std::pair<PlaceId, TransitionId>> items;
  for (std::size_t t = 0; t < 6; ++t) items.emplace_back(PlaceId(from[t]), TransitionId(t));
  const IdGroups<PlaceId, TransitionId> leaving(5, items);
  CHECK(positions(leaving[PlaceId(0)]) == std::vector<std::size_t>{1, 4});
  CHECK(leaving[PlaceId(1)].empty());
  CHECK(positions(leaving[PlaceId(2)]) == std::vector<std::size_t>{0, 2, 5});
  CHECK(positions(leaving[PlaceId(3)]) == std::vector<std::size_t>{3});
  CHECK(leaving[PlaceId(4)].size() == 0);

  const IdGroups<PlaceId, TransitionId> none(3, {});
  for (std::size_t p = 0; p < 3; ++p) CHECK(none[PlaceId(p)].empty());
}
