// Typed ids and the tables they index (compiler/id.h, docs/architecture.md "The model refers
// by typed ids"): none is a state of its own, an id indexes its own table only, and a table
// reads as a sequence.
#include "id.h"
#include "model.h"
#include "small_list.h"

#include <catch2/catch.hpp>

#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <unordered_set>
#include <vector>

using namespace gfec;
using model::ChartId;
using model::PlaceId;

template <typename T, typename I, typename = void> struct Indexable : std::false_type {};
template <typename T, typename I> struct Indexable<T, I, std::void_t<decltype(std::declval<T &>()[std::declval<I>()])>>
    : std::true_type {};

// A place's id does not index the charts, and no int becomes an id by itself.
static_assert(Indexable<Table<ChartId, int>, ChartId>::value);
static_assert(!Indexable<Table<ChartId, int>, PlaceId>::value);
static_assert(!Indexable<IdMap<ChartId, int>, PlaceId>::value);
static_assert(!Indexable<IdMap<ChartId, int>, std::size_t>::value, "an IdMap is indexed by its id only");
static_assert(std::is_invocable_v<decltype(&Table<ChartId, int>::contains), const Table<ChartId, int> &, ChartId>);
static_assert(!std::is_invocable_v<decltype(&Table<ChartId, int>::contains), const Table<ChartId, int> &, PlaceId>);
static_assert(!std::is_convertible_v<int, PlaceId>);
static_assert(!std::is_convertible_v<PlaceId, std::size_t>);
static_assert(!std::is_convertible_v<PlaceId, ChartId>);
static_assert(sizeof(PlaceId) == 4, "as small as the int it replaced");

TEST_CASE("An id is none until given a position, and orders by position with none last") {
  PlaceId none;
  CHECK_FALSE(none);
  CHECK_FALSE(none.valid());
  CHECK(none == PlaceId::none());
  PlaceId zero(0), two(2);
  CHECK(zero);
  CHECK(zero.index() == 0);
  CHECK(two.index() == 2);
  CHECK(zero != two);
  CHECK(zero < two);
  CHECK(two > zero);
  CHECK(zero <= zero);
  CHECK(two >= zero);
  CHECK(two < none);
  CHECK(std::set<PlaceId>{two, none, zero} == std::set<PlaceId>{zero, two, none});
  CHECK(*std::set<PlaceId>{two, none, zero}.begin() == zero);
  std::unordered_set<PlaceId> hashed{zero, two, PlaceId(2)};
  CHECK(hashed.size() == 2);
  CHECK(hashed.count(two) == 1);
  CHECK(hashed.count(none) == 0);
}

TEST_CASE("A table is indexed by its id, knows its ids, and reads as a sequence") {
  Table<PlaceId, std::string> places;
  CHECK(places.next_id() == PlaceId(0));
  places.push_back("A");
  places.push_back("B");
  places.emplace_back("C");
  REQUIRE(places.size() == 3);
  CHECK(places[PlaceId(1)] == "B");
  CHECK(places.at(PlaceId(2)) == "C");
  CHECK(places[std::size_t{0}] == "A");
  CHECK_THROWS_AS(places.at(PlaceId(3)), std::out_of_range);
  CHECK(places.contains(PlaceId(2)));
  CHECK_FALSE(places.contains(PlaceId(3)));
  CHECK_FALSE(places.contains(PlaceId()));
  CHECK(places.id_of(places[PlaceId(2)]) == PlaceId(2));
  CHECK(places.next_id() == PlaceId(3));
  std::vector<PlaceId> ids;
  for (PlaceId p : places.ids()) ids.push_back(p);
  CHECK(ids == std::vector<PlaceId>{PlaceId(0), PlaceId(1), PlaceId(2)});
  std::string all;
  for (const std::string &name : places) all += name;
  CHECK(all == "ABC");
  places[PlaceId(0)] = "Z";
  CHECK(places.front() == "Z");
  CHECK(places.back() == "C");
}

TEST_CASE("A table of bools and an IdMap keep one value per element, indexed by id") {
  Table<ChartId, bool> ok;
  ok.push_back(true);
  ok.push_back(false);
  CHECK(ok[ChartId(0)]);
  CHECK_FALSE(ok[ChartId(1)]);
  ok[ChartId(1)] = true;
  CHECK(ok[ChartId(1)]);

  IdMap<PlaceId, int> marks(3, 7);
  CHECK(marks.size() == 3);
  marks[PlaceId(1)] = 1;
  CHECK(marks.values() == std::vector<int>{7, 1, 7});
  CHECK(marks.at(PlaceId(2)) == 7);
  CHECK_THROWS_AS(marks.at(PlaceId(3)), std::out_of_range);
  int sum = 0;
  for (PlaceId p : marks.ids()) sum += marks[p];
  CHECK(sum == 15);
  marks.assign(2, 0);
  CHECK(marks.values() == std::vector<int>{0, 0});
}

TEST_CASE("A SmallList of ids keeps two inline and grows onto the heap, copying and moving") {
  model::PlaceList list{PlaceId(4), PlaceId(1)};
  CHECK(list.size() == 2);
  CHECK(list.front() == PlaceId(4));
  CHECK(list.back() == PlaceId(1));
  for (std::size_t i = 2; i < 10; ++i) list.push_back(PlaceId(i * 10));
  REQUIRE(list.size() == 10);
  CHECK(list[9] == PlaceId(90));
  model::PlaceList copy = list;
  CHECK(copy == list);
  model::PlaceList moved = std::move(copy);
  CHECK(moved == list);
  CHECK(copy.empty());  // NOLINT(bugprone-use-after-move): a moved-from list is empty
  model::PlaceList none;
  CHECK(none.empty());
  none = list;
  CHECK(none.size() == 10);
}

TEST_CASE("An expression answers the id of its kind and refers to what it is given") {
  model::Expr var;
  var.kind = model::Expr::Kind::Var;
  CHECK_FALSE(var.var());  // refers to nothing yet
  var.refer_to(model::VarId(3));
  CHECK(var.var() == model::VarId(3));
  model::Expr timer;
  timer.kind = model::Expr::Kind::Elapsed;
  timer.refer_to(PlaceId(5));
  CHECK(timer.place() == PlaceId(5));
  timer.refer_to(PlaceId());
  CHECK_FALSE(timer.place());
}
