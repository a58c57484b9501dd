#include "period_text.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>
#include <string>
#include <utility>

namespace gfec {

std::optional<double> parse_period(std::string_view s) {
  auto lower = [](char c) { return static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c); };
  auto starts = [&](std::string_view prefix) {
    if (s.size() < prefix.size()) return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
      if (lower(s[i]) != prefix[i]) return false;
    return true;
  };
  // IEC's TIME literal: parts from days down to milliseconds, `_` between digits, any case.
  const bool iec = starts("t#") || starts("time#");
  if (iec) s.remove_prefix(starts("t#") ? 2 : 5);
  static const std::pair<std::string_view, double> kUnits[] = {
      {"ms", 1}, {"d", 86400000}, {"h", 3600000}, {"m", 60000}, {"s", 1000}};
  double ms = 0;
  std::size_t i = 0, parts = 0;
  while (i < s.size()) {
    std::string number;
    while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.' || (iec && s[i] == '_')))
      if (s[i++] != '_') number += s[i - 1];
    if (number.empty() || number.front() == '.' || number.back() == '.' ||
        std::count(number.begin(), number.end(), '.') > 1)
      return std::nullopt;
    std::string unit;
    while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) unit += lower(s[i++]);
    const auto u = std::find_if(std::begin(kUnits), std::end(kUnits), [&](const auto &k) { return k.first == unit; });
    // The chart language writes one number in ms or s (docs/language.md); IEC any of its units.
    if (u == std::end(kUnits) || (!iec && (parts > 0 || (unit != "ms" && unit != "s")))) return std::nullopt;
    ms += std::stod(number) * u->second;
    ++parts;
  }
  if (parts == 0 || !std::isfinite(ms) || ms <= 0) return std::nullopt;
  return ms;
}

}  // namespace gfec
