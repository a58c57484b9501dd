#include "iec/st_fragment.h"

#include <algorithm>

namespace gfec::iec {

std::uint32_t FragmentPlace::offset(std::uint32_t o) const {
  auto it =
      std::upper_bound(breaks.begin(), breaks.end(), o,
                       [](std::uint32_t x, const std::pair<std::uint32_t, std::uint32_t> &b) { return x < b.first; });
  if (it == breaks.begin()) return o;  // no breakpoint before o: a place without one maps as is
  --it;
  return it->second + (o - it->first);
}

SourceRange FragmentPlace::range(std::uint32_t begin, std::uint32_t end) const {
  std::uint32_t b = offset(begin);
  std::uint32_t e = end > begin ? offset(end - 1) + 1 : b;
  return {file, b, std::max(b, e)};
}

}  // namespace gfec::iec
