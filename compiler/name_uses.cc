#include "name_uses.h"

#include <algorithm>

namespace gfec {

std::vector<SourceRange> NameUses::of(const SourceRange &decl) const {
  std::vector<SourceRange> out;
  for (const NameUse &u : list)
    if (u.decl.file == decl.file && u.decl.begin == decl.begin) out.push_back(u.at);
  auto key = [](const SourceRange &r) { return std::make_pair(r.file, r.begin); };
  std::sort(out.begin(), out.end(), [&](const SourceRange &a, const SourceRange &b) { return key(a) < key(b); });
  out.erase(
      std::unique(out.begin(), out.end(), [&](const SourceRange &a, const SourceRange &b) { return key(a) == key(b); }),
      out.end());
  return out;
}

}  // namespace gfec
