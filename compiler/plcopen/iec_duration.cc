#include "plcopen/iec_duration.h"

#include <cctype>
#include <cstdlib>
#include <string>

namespace gfec::plcopen {

namespace {

std::string trimmed_upper(std::string_view text) {
  std::string s;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c)) && c != '_')
      s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

/// A number at `s[i]` (digits, optionally a fraction), advancing i.
std::optional<double> number(const std::string &s, std::size_t &i) {
  std::size_t b = i;
  while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) ++i;
  if (i == b || s.compare(b, i - b, ".") == 0) return std::nullopt;
  return std::strtod(s.substr(b, i - b).c_str(), nullptr);
}

/// `1M30S500MS`: IEC units D H M S MS US NS, largest first.
std::optional<double> iec_units(const std::string &s) {
  static const struct {
    const char *unit;
    double ms;
  } kUnits[] = {{"MS", 1}, {"US", 1e-3}, {"NS", 1e-6}, {"D", 86400000}, {"H", 3600000}, {"M", 60000}, {"S", 1000}};
  double total = 0;
  std::size_t i = 0;
  if (s.empty()) return std::nullopt;
  while (i < s.size()) {
    auto v = number(s, i);
    if (!v) return std::nullopt;
    bool found = false;
    for (const auto &u : kUnits) {
      std::string_view unit = u.unit;
      if (s.compare(i, unit.size(), unit) == 0) {
        total += *v * u.ms;
        i += unit.size();
        found = true;
        break;
      }
    }
    if (!found) return std::nullopt;
  }
  return total;
}

/// `PT0.01S`, `P1DT2H`: XML Schema's duration (no years or months: their length varies).
std::optional<double> xsd_duration(const std::string &s) {
  if (s.size() < 3 || s[0] != 'P') return std::nullopt;
  double total = 0;
  bool time = false;
  std::size_t i = 1;
  while (i < s.size()) {
    if (s[i] == 'T') {
      time = true;
      ++i;
      continue;
    }
    auto v = number(s, i);
    if (!v || i >= s.size()) return std::nullopt;
    char u = s[i++];
    if (u == 'D' && !time) total += *v * 86400000;
    else if (u == 'H' && time) total += *v * 3600000;
    else if (u == 'M' && time) total += *v * 60000;
    else if (u == 'S' && time) total += *v * 1000;
    else return std::nullopt;
  }
  return total;
}

/// `00:00:00.100000`: hours, minutes and seconds, as Beremiz writes a task's interval.
std::optional<double> clock_duration(const std::string &s) {
  double total = 0;
  std::size_t i = 0;
  for (double unit : {3600000.0, 60000.0}) {
    std::size_t b = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    if (i == b || i >= s.size() || s[i] != ':') return std::nullopt;
    total += std::strtod(s.substr(b, i - b).c_str(), nullptr) * unit;
    ++i;
  }
  auto seconds = number(s, i);
  if (!seconds || i != s.size()) return std::nullopt;
  return total + *seconds * 1000;
}

}  // namespace

std::optional<double> duration_ms(std::string_view text) {
  std::string s = trimmed_upper(text);
  for (std::string_view prefix : {"TIME#", "T#", "LTIME#", "LT#"})
    if (s.compare(0, prefix.size(), prefix) == 0) return iec_units(s.substr(prefix.size()));
  if (s.find(':') != std::string::npos) return clock_duration(s);
  return xsd_duration(s);
}

}  // namespace gfec::plcopen
