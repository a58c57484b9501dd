// ast::ExprList: the operands of a syntax-tree expression, one inline and more in a heap array.
#include "ast.h"

#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace gfec;

namespace {

ast::ExprPtr number(int i) {
  auto e = std::make_unique<ast::Expr>();
  e->kind = ast::Expr::Kind::Int;
  e->range.begin = static_cast<std::uint32_t>(i);
  return e;
}

/// The operands' markers in order.
std::vector<int> markers(const ast::ExprList &list) {
  std::vector<int> out;
  for (const ast::Expr *e : list) out.push_back(static_cast<int>(e->range.begin));
  return out;
}

std::vector<int> iota(int n) {
  std::vector<int> out;
  for (int i = 0; i < n; ++i) out.push_back(i);
  return out;
}

}  // namespace

TEST_CASE("ast::ExprList keeps its operands in order as it grows past each power of two") {
  ast::ExprList list;
  CHECK(list.empty());
  CHECK(list.begin() == list.end());
  for (int n = 1; n <= 33; ++n) {
    list.push_back(number(n - 1));
    REQUIRE(list.size() == static_cast<std::size_t>(n));
    CHECK(markers(list) == iota(n));
    CHECK(list.front()->range.begin == 0);
    CHECK(list.back()->range.begin == static_cast<std::uint32_t>(n - 1));
  }
  CHECK(list.at(32)->range.begin == 32);
  CHECK_THROWS_AS(list.at(33), std::out_of_range);
}

TEST_CASE("ast::ExprList from a vector, then appended to, moved and moved over") {
  for (int n : {0, 1, 2, 3, 4, 5}) {
    std::vector<ast::ExprPtr> items;
    for (int i = 0; i < n; ++i) items.push_back(number(i));
    ast::ExprList list(std::move(items));
    CHECK(markers(list) == iota(n));
    list.push_back(number(n));
    CHECK(markers(list) == iota(n + 1));

    ast::ExprList moved(std::move(list));
    CHECK(list.empty());  // NOLINT(bugprone-use-after-move): a moved-from list is empty
    CHECK(markers(moved) == iota(n + 1));

    ast::ExprList other;
    other.push_back(number(99));
    other = std::move(moved);  // frees 99, takes the rest
    CHECK(markers(other) == iota(n + 1));
    CHECK(moved.empty());  // NOLINT(bugprone-use-after-move)
  }
}

TEST_CASE("ast::ExprList owns a tree: nested operands go with their parent") {
  auto call = std::make_unique<ast::Expr>();
  call->kind = ast::Expr::Kind::Call;
  auto inner = std::make_unique<ast::Expr>();
  inner->kind = ast::Expr::Kind::Binary;
  inner->args.push_back(number(1));
  inner->args.push_back(number(2));
  call->args.push_back(std::move(inner));
  REQUIRE(call->args.size() == 1);
  CHECK(markers(call->args[0]->args) == std::vector<int>{1, 2});
  call.reset();  // the leak and address sanitizers of the sanitizer build check the frees
}
