// The C back end's choice of engine form and counter width (backends/c/c_layout.h): which form
// a chart gets, what it takes from the activation bound the analyses proved, the owners that let
// the scalable form try transitions from the active places, and the levels of its bitsets.
#include "../run/c_backend_support.h"

#include "c_layout.h"
#include "support.h"

#include <catch2/catch.hpp>

using namespace cbt;
using gfec::c_backend::bit_levels;
using gfec::c_backend::Layout;
using gfec::c_backend::plan_layout;

namespace {

/// A ring of n places, one of them initial.
ChartBuilder ring(int n) {
  ChartBuilder b("Ring", model::Chart::Kind::Sfc);
  for (int i = 0; i < n; ++i) b.place(fmt::format("P{}", i), i == 0);
  for (int i = 0; i < n; ++i) b.transition({fmt::format("P{}", i)}, {fmt::format("P{}", (i + 1) % n)});
  return b;
}

/// The chart with the facts the pipeline records (its activation bound), as a back end sees it.
const model::Chart &analysed(ChartBuilder &b) { return b.model().charts.front(); }

Layout layout_of(ChartBuilder &b, EngineForm form = EngineForm::Auto) {
  return plan_layout(analysed(b), form, std::vector<bool>(b.chart().places.size(), false));
}

}  // namespace

TEST_CASE("c layout: small charts stay readable, large ones become scalable", "[c_backend][layout]") {
  auto small = ring(static_cast<int>(gfec::c_backend::kReadableMaxPlaces));
  CHECK(layout_of(small).form == Layout::Form::Readable);
  CHECK(layout_of(small, EngineForm::Scalable).form == Layout::Form::Sequential);
  auto large = ring(static_cast<int>(gfec::c_backend::kReadableMaxPlaces) + 1);
  CHECK(layout_of(large).form == Layout::Form::Sequential);
  CHECK(layout_of(large, EngineForm::Readable).form == Layout::Form::Readable);
}

TEST_CASE("c layout: the sequential form is split in parts only above a size", "[c_backend][layout]") {
  auto at = ring(static_cast<int>(gfec::c_backend::kSplitAbovePlaces));
  CHECK(layout_of(at).part_places == 0);
  auto above = ring(static_cast<int>(gfec::c_backend::kSplitAbovePlaces) + 1);
  Layout l = layout_of(above);
  CHECK(l.form == Layout::Form::Sequential);
  CHECK(l.part_places == gfec::c_backend::kPartPlaces);
  CHECK(layout_of(above, EngineForm::Readable).part_places == 0);
}

TEST_CASE("c layout: an fsm's scalable form is the sequential one, split above the same size", "[c_backend][layout]") {
  auto chain = [](int n) {
    ChartBuilder b("Chain", model::Chart::Kind::Fsm);
    for (int i = 0; i < n; ++i) b.place(fmt::format("S{}", i), i == 0);
    for (int i = 0; i + 1 < n; ++i) b.transition({fmt::format("S{}", i)}, {fmt::format("S{}", i + 1)});
    return b;
  };
  auto small = chain(static_cast<int>(gfec::c_backend::kReadableMaxPlaces));
  CHECK(layout_of(small).form == Layout::Form::Readable);
  CHECK(layout_of(small, EngineForm::Scalable).form == Layout::Form::Sequential);
  auto at = chain(static_cast<int>(gfec::c_backend::kSplitAbovePlaces));
  CHECK(layout_of(at).form == Layout::Form::Sequential);
  CHECK(layout_of(at).part_places == 0);
  CHECK(layout_of(at, EngineForm::Readable).form == Layout::Form::Readable);
  auto above = chain(static_cast<int>(gfec::c_backend::kSplitAbovePlaces) + 1);
  for (EngineForm f : {EngineForm::Auto, EngineForm::Scalable}) {
    Layout l = layout_of(above, f);
    CHECK(l.form == Layout::Form::Sequential);
    CHECK(l.part_places == gfec::c_backend::kPartPlaces);
    CHECK(l.index_bits == 16);
  }
  CHECK(layout_of(above, EngineForm::Readable).part_places == 0);
}

TEST_CASE("c layout: a ring with one token is sequential and 1-bounded", "[c_backend][layout]") {
  auto b = ring(300);
  Layout l = layout_of(b);
  CHECK(l.form == Layout::Form::Sequential);
  CHECK(l.activation.bounded);
  CHECK(l.activation.place == 1);
  CHECK(l.index_bits == 16);  // 300 places do not fit a byte
}

TEST_CASE("c layout: a fork is bounded by its weights, counters are a byte", "[c_backend][layout]") {
  // Start -> (A0..A99); each Ai -> Bi -> Ai. Weights: Start 100, the rest 1: total 100. The
  // transitions have no condition, so the states explored are all of them: no place holds more
  // than 1 (analysis/activation_bounds.h keeps the tighter bound).
  ChartBuilder b("Fork", model::Chart::Kind::Sfc);
  b.place("Start", true);
  std::vector<std::string> branches;
  for (int i = 0; i < 100; ++i) {
    b.place(fmt::format("A{}", i));
    b.place(fmt::format("B{}", i));
    branches.push_back(fmt::format("A{}", i));
  }
  b.transition({"Start"}, branches);
  for (int i = 0; i < 100; ++i) {
    b.transition({fmt::format("A{}", i)}, {fmt::format("B{}", i)});
    b.transition({fmt::format("B{}", i)}, {fmt::format("A{}", i)});
  }
  // Up to 100 of its 201 places are active at once: `auto` keeps it readable (the scalable
  // form's bookkeeping costs more than it saves when so much is active), with byte counters.
  Layout readable = layout_of(b);
  CHECK(readable.form == Layout::Form::Readable);
  CHECK(readable.counter_bits == 8);
  Layout l = layout_of(b, EngineForm::Scalable);
  CHECK(l.form == Layout::Form::Sparse);
  CHECK(l.activation.bounded);
  CHECK(l.activation.place == 1);
  CHECK(l.activation.total == 100);
  CHECK(l.counter_bits == 8);
  CHECK_FALSE(l.saturate);
  CHECK(l.place_driven);
  // At most 100 transitions fire in a tick: the fork's 100 outputs and 99 more.
  CHECK(l.add_capacity == 199);
}

TEST_CASE("c layout: the lists of places that fell and rose are sized by consumption and production",
          "[c_backend][layout]") {
  // Start -> (A, B, C), all four watched: at most 3 places active (Start weighs 3). Only Start
  // is ever consumed, so at most one watched place falls to 0 in a tick; three can rise.
  ChartBuilder b("Spread", model::Chart::Kind::Sfc);
  b.place("Start", true);
  for (const char *p : {"A", "B", "C"}) b.place(p);
  b.transition({"Start"}, {"A", "B", "C"});
  Layout l = plan_layout(analysed(b), EngineForm::Scalable, std::vector<bool>(4, true));
  REQUIRE(l.form == Layout::Form::Sparse);
  CHECK(l.activation.total == 3);
  CHECK(l.watch_capacity == 3);
  CHECK(l.lost_capacity == 1);
  CHECK(l.gained_capacity == 3);
  // Nothing watched: no lists at all.
  Layout none = plan_layout(analysed(b), EngineForm::Scalable, std::vector<bool>(4, false));
  CHECK(none.watch_capacity == 0);
  CHECK(none.lost_capacity == 0);
  CHECK(none.gained_capacity == 0);
}

TEST_CASE("c layout: auto takes the scalable form for a large chart little of which is active", "[c_backend][layout]") {
  // 30 branches of 4 places forked from Start: at most 30 of 121 places active, under a quarter.
  ChartBuilder b("Sparse", model::Chart::Kind::Sfc);
  b.place("Start", true);
  std::vector<std::string> heads;
  for (int i = 0; i < 30; ++i) {
    for (int k = 0; k < 4; ++k) b.place(fmt::format("P{}_{}", i, k));
    heads.push_back(fmt::format("P{}_0", i));
  }
  b.transition({"Start"}, heads);
  for (int i = 0; i < 30; ++i)
    for (int k = 0; k < 4; ++k) b.transition({fmt::format("P{}_{}", i, k)}, {fmt::format("P{}_{}", i, (k + 1) % 4)});
  Layout l = layout_of(b);
  CHECK(l.activation.total == 30);
  CHECK(l.form == Layout::Form::Sparse);
}

TEST_CASE("c layout: a chart that pumps activation is unbounded, counters saturate", "[c_backend][layout]") {
  ChartBuilder b("Pump", model::Chart::Kind::Sfc);
  b.place("P", true);
  b.place("Q");
  b.transition({"P"}, {"P", "Q"});
  b.transition({"Q"}, {"P"});
  Layout l = layout_of(b, EngineForm::Scalable);
  CHECK(l.form == Layout::Form::Sparse);
  CHECK_FALSE(l.activation.bounded);
  CHECK(l.counter_bits == 32);
  CHECK(l.saturate);
  CHECK(l.add_capacity == 3);  // every transition may fire: all their outputs
}

TEST_CASE("c layout: joins and forks in balance give a bound of the initial weight", "[c_backend][layout]") {
  // A -> (B, C); (B, C) -> A: weights A 2, B 1, C 1; two initial places A and D (weight 1):
  // total 3. Each place holds at most 1 in every reachable state, the tighter bound kept.
  ChartBuilder b("Balance", model::Chart::Kind::Sfc);
  for (const char *p : {"A", "B", "C"}) b.place(p, std::string(p) == "A");
  b.place("D", true);
  b.transition({"A"}, {"B", "C"});
  b.transition({"B", "C"}, {"A"});
  Layout l = layout_of(b, EngineForm::Scalable);
  CHECK(l.activation.bounded);
  CHECK(l.activation.total == 3);
  CHECK(l.activation.place == 1);
}

TEST_CASE("c layout: owners follow declaration order, or candidates are needed", "[c_backend][layout]") {
  ChartBuilder b("Order", model::Chart::Kind::Sfc);
  for (const char *p : {"A", "B", "C"}) b.place(p, true);
  b.transition({"A"}, {"B"});
  b.transition({"C", "B"}, {"A"});  // owner B (the smallest input not before A)
  b.transition({"C"}, {"C"});
  Layout in_order = layout_of(b, EngineForm::Scalable);
  CHECK(in_order.place_driven);
  CHECK(in_order.owner.values() == test::ids<model::PlaceId>({0, 1, 2}));
  b.transition({"A"}, {"C"});  // back to A after C: no order of owners fits
  Layout out_of_order = layout_of(b, EngineForm::Scalable);
  CHECK_FALSE(out_of_order.place_driven);
  CHECK(out_of_order.candidates.words() > 0);
}

TEST_CASE("c layout: bitset levels end in one word", "[c_backend][layout]") {
  CHECK(bit_levels(1).from == std::vector<std::uint32_t>{0, 1, 2});
  CHECK(bit_levels(32).from == std::vector<std::uint32_t>{0, 1, 2});
  CHECK(bit_levels(33).from == std::vector<std::uint32_t>{0, 2, 3});
  CHECK(bit_levels(1000).from == std::vector<std::uint32_t>{0, 32, 33});
  CHECK(bit_levels(1000000).from == std::vector<std::uint32_t>{0, 31250, 32227, 32258, 32259});
}
