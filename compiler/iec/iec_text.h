// Small pieces the IEC readers and their lowering share: IEC names compare case-insensitively
// (upper()), CASE and multi-name declarations need a copy of an expression (clone()), and an
// unknown name gets the nearest declared one as its did-you-mean (suggest_nearest()).
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "did_you_mean.h"

#include <fmt/format.h>

#include <string>
#include <string_view>

namespace gfec::iec {

/// `s` in upper case (ASCII): how IEC keywords and names compare.
std::string upper(std::string_view s);

/// A deep copy of `e`; names and spellings keep viewing the file's text and strings.
ast::ExprPtr clone(const ast::Expr &e);

/// Adds to `d` (an error at `wrong`) the nearest of `candidates` as a fix-it and a did-you-mean
/// note at its declaration; `name_of(c)` is a candidate's ast::Name. Returns whether one was near.
template <typename Items, typename NameOf>
bool suggest_nearest(Diagnostic &d, const ast::Name &wrong, const Items &candidates, NameOf name_of) {
  NearestName nearest(wrong.text, typo_limit(wrong.text.size()));
  const ast::Name *best = nullptr;
  for (const auto &c : candidates)
    if (nearest.offer(name_of(c).text)) best = &name_of(c);
  if (!best) return false;
  d.fix(wrong.range, std::string(best->text)).note(best->range, fmt::format("did you mean '{}'?", best->text));
  return true;
}

}  // namespace gfec::iec
