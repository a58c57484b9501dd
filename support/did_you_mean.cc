#include "did_you_mean.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

namespace gfec {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // The classic table, two rows back kept for transpositions ("flaot" is one typo from "float").
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), row(b.size() + 1);
  std::iota(previous.begin(), previous.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) row[j] = std::min(row[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, row);
  }
  return previous[b.size()];
}

std::size_t edit_distance_within(std::string_view a, std::string_view b, std::size_t k) {
  const std::size_t over = k + 1;
  if ((a.size() > b.size() ? a.size() - b.size() : b.size() - a.size()) > k) return over;
  // The rows live on the stack: the names compared are mostly at most kMaxSuggestedLength long.
  constexpr std::size_t kRow = 2 * kMaxSuggestedLength + 2;
  if (b.size() >= kRow || k >= kRow) return std::min(edit_distance(a, b), over);
  // Ukkonen's cut-off: a cell farther than k from the diagonal costs more than k, so each row is
  // computed only within k of it, and a row whose every cell is over k ends the search. Cells
  // just outside the band read as `over`; the three rows rotate, so the edges are reset each row.
  std::array<std::uint8_t, kRow> before{}, previous{}, row{};
  auto cap = [&](std::size_t v) { return static_cast<std::uint8_t>(std::min(v, over)); };
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = cap(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    const std::size_t lo = i > k ? i - k : 1, hi = std::min(b.size(), i + k);
    std::size_t least = over;
    if (lo == 1) least = row[0] = cap(i);
    else row[lo - 1] = cap(over);
    for (std::size_t j = lo; j <= hi; ++j) {
      std::size_t v = std::min<std::size_t>(
          {previous[j] + 1u, row[j - 1] + 1u, previous[j - 1] + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        v = std::min<std::size_t>(v, before[j - 2] + 1u);
      row[j] = cap(v);
      least = std::min<std::size_t>(least, row[j]);
    }
    if (hi < b.size()) row[hi + 1] = cap(over);
    if (least > k) return over;
    std::swap(before, previous);
    std::swap(previous, row);
  }
  return previous[b.size()];
}

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char &c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

bool begins(std::string_view longer, std::string_view shorter) {
  return longer.size() >= shorter.size() && longer.substr(0, shorter.size()) == shorter;
}

}  // namespace

bool NearestName::offer(std::string_view candidate) {
  if (name_.size() > kMaxSuggestedLength || ++offered_ > kMaxSuggestionCandidates) return false;
  if (found_ && best_ == 0 && best_affix_ && best_cased_ == 0) return false;  // nothing can beat it
  const std::string a = lower(name_), b = lower(candidate);
  // Within the best so far (a tie may still win on the later keys), never past the limit.
  const std::size_t d = edit_distance_within(a, b, std::min(best_, limit_));
  if (d > limit_ || d > best_) return false;
  const bool affix = !a.empty() && !b.empty() && (begins(a, b) || begins(b, a));
  if (d == best_ && found_ && (best_affix_ && !affix)) return false;
  const bool same_rank = d == best_ && found_ && best_affix_ == affix;
  const std::size_t cased = edit_distance_within(name_, candidate, same_rank ? best_cased_ : kMaxSuggestedLength);
  if (same_rank && cased >= best_cased_) return false;
  best_ = d;
  best_affix_ = affix;
  best_cased_ = cased;
  found_ = true;
  return true;
}

}  // namespace gfec
