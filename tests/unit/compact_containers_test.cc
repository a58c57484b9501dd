// The compact containers of the model and the tables (docs/performance.md, "(a) The compiler"):
// CompactString, CompactVector and NameIndex behave like the standard types they replace.
#include "compact_string.h"
#include "compact_vector.h"
#include "name_index.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cstring>
#include <deque>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace gfec;

TEST_CASE("CompactString keeps 14 characters inline and longer ones on the heap, NUL-terminated") {
  CHECK(sizeof(CompactString) == 16);
  for (std::size_t n : std::vector<std::size_t>{0, 1, 13, 14, 15, 16, 100, 5000}) {
    const std::string text(n, 'x');
    CompactString s(text);
    CHECK(s.size() == n);
    CHECK(s.empty() == (n == 0));
    CHECK(s == text);
    CHECK(std::strlen(s.c_str()) == n);
    CHECK(s.str() == text);
  }
}

TEST_CASE("CompactString copies, moves and assigns like std::string") {
  const std::string long_text = "a spelling longer than fourteen characters";
  for (const std::string &text : {std::string("42"), long_text}) {
    CompactString a(text);
    CompactString copy(a);
    CHECK(copy == a);
    CHECK(copy.data() != a.data());  // its own characters, not a shared block

    CompactString moved(std::move(a));
    CHECK(moved == text);
    CHECK(a.empty());  // NOLINT(bugprone-use-after-move): a moved-from string is empty

    CompactString assigned;
    assigned = moved;
    CHECK(assigned == text);
    assigned = std::move(moved);
    CHECK(assigned == text);
    const CompactString &same = assigned;
    assigned = same;  // self-assignment keeps the value
    CHECK(assigned == text);
    // Assigning a view of its own characters (a substring) is safe.
    assigned = assigned.view().substr(1);
    CHECK(assigned == text.substr(1));
  }
  CompactString s;
  s = std::string("0x10");
  CHECK(s == "0x10");
  s = "1e-3";
  CHECK(s == std::string("1e-3"));
  CHECK(s != "1e-4");
}

TEST_CASE("CompactString reads as a string_view, formats and concatenates") {
  CompactString s(std::string_view("P12"));
  CHECK(fmt::format("[{}]", s) == "[P12]");
  CHECK(fmt::format("[{:>5}]", s) == "[  P12]");
  CHECK(std::string("Ring_") + s == "Ring_P12");
  CHECK(s + "_x" == "P12_x");
  std::string_view v = s;
  CHECK(v == "P12");
  CHECK(CompactString(std::string_view("a")) != CompactString(std::string_view("b")));
}

TEST_CASE("CompactVector grows, copies deeply and moves without copying") {
  CHECK(sizeof(CompactVector<std::string>) == 16);
  CompactVector<std::string> v;
  CHECK(v.empty());
  CHECK(v.begin() == v.end());
  for (int i = 0; i < 1000; ++i) v.push_back(std::string(20, static_cast<char>('a' + i % 26)) + std::to_string(i));
  REQUIRE(v.size() == 1000);
  for (int i = 0; i < 1000; ++i) CHECK(v[static_cast<std::size_t>(i)].substr(20) == std::to_string(i));
  CHECK(v.front().substr(20) == "0");
  CHECK(v.back().substr(20) == "999");
  CHECK_THROWS_AS(v.at(1000), std::out_of_range);

  CompactVector<std::string> copy(v);
  CHECK(copy == v);
  copy[0] = "changed";
  CHECK(copy != v);
  CHECK(v[0].substr(20) == "0");

  const std::string *data = v.data();
  CompactVector<std::string> moved(std::move(v));
  CHECK(moved.data() == data);
  CHECK(v.empty());  // NOLINT(bugprone-use-after-move)
  copy = moved;
  CHECK(copy == moved);
  moved.clear();
  CHECK(moved.empty());
}

TEST_CASE("CompactVector appends a copy of its own element while it grows") {
  CompactVector<std::string> v{std::string(40, 'z')};
  for (int i = 0; i < 10; ++i) v.push_back(v.front());  // each growth moves the element copied
  CHECK(v.size() == 11);
  for (const std::string &s : v) CHECK(s == std::string(40, 'z'));
  CompactVector<std::string> from_vector(std::vector<std::string>{"a", "b"});
  CHECK(from_vector.size() == 2);
  CHECK(from_vector[1] == "b");
}

TEST_CASE("NameIndex finds every name of a growing table, and nothing else") {
  std::deque<std::string> names;
  NameIndex index;
  auto key = [&](std::uint32_t k) -> const std::string & { return names[k]; };
  CHECK(index.find("P0", key) == NameIndex::kNone);
  index.reserve(0);  // on an empty index: still empty
  CHECK(index.find("P0", key) == NameIndex::kNone);
  for (std::uint32_t k = 0; k < 5000; ++k) {
    // Room made halfway (and a smaller reserve after it, which must not shrink): the names in
    // the index move to their new slots and stay findable.
    if (k == 2500) index.reserve(5000);
    if (k == 2600) index.reserve(10);
    std::string name = "P" + std::to_string(k);
    CHECK(index.insert(name, k, key) == NameIndex::kNone);
    names.push_back(std::move(name));
    if (k == 2500)
      for (std::uint32_t j = 0; j <= k; ++j) CHECK(index.find("P" + std::to_string(j), key) == j);
  }
  for (std::uint32_t k = 0; k < 5000; ++k) CHECK(index.find("P" + std::to_string(k), key) == k);
  CHECK(index.find("P5000", key) == NameIndex::kNone);
  CHECK(index.find("", key) == NameIndex::kNone);
}

TEST_CASE("NameIndex::insert of a name held already returns its holder and records nothing") {
  std::deque<std::string> names;
  NameIndex index;
  auto key = [&](std::uint32_t k) -> const std::string & { return names[k]; };
  for (std::uint32_t k = 0; k < 100; ++k) {
    names.push_back("N" + std::to_string(k % 40));  // names 40..99 repeat 0..39
    const std::uint32_t held = index.insert(names.back(), k, key);
    CHECK(held == (k < 40 ? NameIndex::kNone : k % 40));
  }
  // Growing (16 → 128 slots on the way) kept the first holder of each name.
  for (std::uint32_t k = 0; k < 40; ++k) CHECK(index.find("N" + std::to_string(k), key) == k);
}
