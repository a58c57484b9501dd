// The fixed functions of the scalable form's sets (docs/c-engine.md), kept here as the C they
// are: one template each, in which the writer fills in the names this engine gave the functions
// (`@lowest@` and the like: names are handed out per engine so that none clashes with a chart's,
// c_context.cc).
#include "c_emit.h"

#include <cassert>
#include <string>
#include <string_view>
#include <utility>

namespace gfec::c_backend {
namespace {

// The helpers have one exit each and leave their parameters alone (MISRA C:2012 rules 15.5 and
// 17.8). The search for the next member ends by a flag; insert and erase leave their loop by one
// `break` (rule 15.4 allows one), which gcc compiles to 40 fewer instructions per tick of a small
// dense chart than a flag in the loop condition (docs/performance.md (b)).
constexpr std::string_view kSetFunctions = R"(/* The number of the lowest bit set in a word that is not 0. */
static uint32_t @lowest@(uint32_t word)
{
#if defined(__GNUC__) || defined(__clang__)
    uint32_t n = (uint32_t)__builtin_ctz(word);
#else
    uint32_t rest = word;
    uint32_t n = 0u;
    while ((rest & 1u) == 0u) {
        rest >>= 1;
        ++n;
    }
#endif
    return n;
}

/* The first member >= from of a set of `count` levels, looking from level `low` (0: members;
   1: words of level 0 that have members), or UINT32_MAX when there is none. */
static uint32_t @next@(const uint32_t *set, const uint32_t *levels, uint32_t count, uint32_t low, uint32_t from)
{
    uint32_t level = low;
    uint32_t i = from;
    uint32_t word = 0u;
    bool searching = true;
    bool found = false;
    while (searching) {
        if ((i >> 5) >= (levels[level + 1u] - levels[level])) {
            searching = false; /* past the last word of this level */
        } else {
            word = set[levels[level] + (i >> 5)] & (0xFFFFFFFFu << (i & 31u));
            if (word != 0u) {
                found = true;
                searching = false;
            } else if ((level + 1u) == count) {
                searching = false; /* the top level has nothing further */
            } else {
                i = (i >> 5) + 1u; /* the next word of this level: its bit one level up */
                ++level;
            }
        }
    }
    if (found) {
        i = (i & ~31u) | @lowest@(word);
        while (level > low) {
            --level;
            i = (i << 5) | @lowest@(set[levels[level] + i]);
        }
    } else {
        i = UINT32_MAX;
    }
    return i;
}

/* Adds a member, telling the levels above when its word stops being empty. */
static void @insert@(uint32_t *set, const uint32_t *levels, uint32_t count, uint32_t member)
{
    uint32_t i = member;
    uint32_t level;
    for (level = 0u; level < count; ++level) {
        uint32_t *word = &set[levels[level] + (i >> 5)];
        uint32_t was = *word;
        *word = was | (1u << (i & 31u));
        if (was != 0u) {
            break; /* the word had members: the levels above know of it already */
        }
        i >>= 5;
    }
}

/* Removes a member of level `low` (1: a word of level 0 that became empty), telling the levels
   above when a word becomes empty. */
static void @erase@(uint32_t *set, const uint32_t *levels, uint32_t count, uint32_t low, uint32_t member)
{
    uint32_t i = member;
    uint32_t level;
    for (level = low; level < count; ++level) {
        uint32_t *word = &set[levels[level] + (i >> 5)];
        *word &= ~(1u << (i & 31u));
        if (*word != 0u) {
            break; /* the word keeps members: the levels above stay as they are */
        }
        i >>= 5;
    }
}
)";

// Insertion sort: the lists are a tick's watched places, a handful at most.
constexpr std::string_view kSortFunction =
    R"(/* Sorts a short list of place numbers (the places that lost or gained activation in a tick). */
static void @sort@(@type@ *list, uint32_t n)
{
    uint32_t i;
    uint32_t j;
    for (i = 1; i < n; ++i) {
        @type@ key = list[i];
        for (j = i; (j > 0u) && (list[j - 1u] > key); --j) {
            list[j] = list[j - 1u];
        }
        list[j] = key;
    }
}
)";

/// `text` with each `@key@` replaced by its name.
std::string fill(std::string_view text, std::initializer_list<std::pair<std::string_view, std::string_view>> names) {
  std::string out;
  out.reserve(text.size() + 256);
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t open = text.find('@', at);
    if (open == std::string_view::npos) break;
    std::size_t close = text.find('@', open + 1);
    assert(close != std::string_view::npos);
    std::string_view key = text.substr(open + 1, close - open - 1);
    std::string_view name;
    for (const auto &[k, v] : names)
      if (k == key) name = v;
    assert(!name.empty());
    out.append(text.substr(at, open - at));
    out.append(name);
    at = close + 1;
  }
  out.append(text.substr(at));
  return out;
}

}  // namespace

void emit_set_functions(CodeWriter &w, const EngineContext &c) {
  w.raw(fill(kSetFunctions,
             {{"lowest", c.lowest_fn}, {"next", c.next_fn}, {"insert", c.insert_fn}, {"erase", c.erase_fn}}));
}

void emit_sort_function(CodeWriter &w, const EngineContext &c, const char *type) {
  w.raw(fill(kSortFunction, {{"sort", c.sort_fn}, {"type", type}}));
}

}  // namespace gfec::c_backend
