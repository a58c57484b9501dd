// Did-you-mean: how near a mistyped name is to the names it could have meant, and which of them
// is nearest. The validator (unknown names), the loader (missing imports), the options (unknown
// -W values) and the ALICA reader (references to missing files and ids) all choose this way;
// each decides only how far a typo may go and what the note says.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string_view>

namespace gfec {

/// Edit distance: insert, delete, substitute, or swap two neighbours; each costs 1.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// edit_distance(a, b) if it is at most k, else k + 1: the work is that of a band 2k + 1 wide,
/// and stops as soon as the distance must exceed k.
std::size_t edit_distance_within(std::string_view a, std::string_view b, std::size_t k);

/// Names longer than this get no did-you-mean (nobody mistypes a name that long by hand, and the
/// edit distance costs the product of the lengths).
constexpr std::size_t kMaxSuggestedLength = 64;

/// Of more candidates than this only the first are weighed: a did-you-mean over a folder of a
/// million files, or a chart of a million names, costs at most this many comparisons.
constexpr std::size_t kMaxSuggestionCandidates = 100000;

/// How many edits a typo of a name `length` long may hold: about a third of the name, at least
/// one; close enough to be a typo, far enough apart that short unrelated names are not offered.
constexpr std::size_t typo_limit(std::size_t length) { return std::max<std::size_t>(1, (length + 1) / 3); }

/// The nearest of candidates offered one by one to a name, at most `limit` edits from it. Nearest
/// is decided in this order, and of candidates equal in all three the first offered wins, so a
/// note is deterministic:
///   1. the edit distance ignoring ASCII case (`LED` is distance 0 from `Led`: a beginner's
///      capitals are the commonest slip);
///   2. one name begun by the other (`YellowOf` is `YellowOff` cut short, nearer than the
///      substitution `YellowOn`, which is as many edits away);
///   3. the edit distance with case (`LED`: `Led` before `led`).
/// Only a candidate that may be nearer costs work (the distance is computed within the best so
/// far), so thousands of near-identical names stay cheap. A candidate equal to the name is
/// distance 0 like any other: callers that never suggest the name itself skip it. A name longer
/// than kMaxSuggestedLength finds nothing, and only the first kMaxSuggestionCandidates offered are
/// weighed.
class NearestName {
public:
  NearestName(std::string_view name, std::size_t limit) : name_(name), limit_(limit), best_(limit + 1) {}

  /// Weighs `candidate`; true when it is the nearest so far (the caller keeps what it stands for).
  bool offer(std::string_view candidate);

  /// Whether some candidate was near enough, and how near the nearest is (ignoring case).
  bool found() const { return found_; }
  std::size_t distance() const { return best_; }

private:
  std::string_view name_;
  std::size_t limit_;
  std::size_t best_;         ///< the nearest distance so far (ignoring case), or the limit + 1
  bool best_affix_ = false;  ///< whether the nearest so far begins the name or the name begins it
  std::size_t best_cased_ = 0;
  std::size_t offered_ = 0;
  bool found_ = false;
};

}  // namespace gfec
