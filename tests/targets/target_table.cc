#include "target_table.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

namespace gfec::targets {

namespace {

std::string trim(const std::string &s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

bool number(const std::string &s, long &out) {
  if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos) return false;
  out = std::stol(s);
  return true;
}

}  // namespace

std::string Target::size_tool() const {
  const auto at = cc.rfind("gcc");
  return at == std::string::npos ? "size" : cc.substr(0, at) + "size" + cc.substr(at + 3);
}

std::string Target::emulator(const std::map<std::string, std::string> &vars) const {
  const std::string first = run.substr(0, run.find(' '));
  return expand(first, vars);
}

const Target *Table::find(const std::string &name) const {
  for (const auto &t : rows)
    if (t.name == name) return &t;
  return nullptr;
}

std::string Table::names() const {
  std::string out;
  for (const auto &t : rows) out += (out.empty() ? "" : ", ") + t.name;
  return out;
}

Table read_table(const std::string &path) {
  Table table;
  const auto slash = path.rfind('/');
  table.folder = slash == std::string::npos ? "." : path.substr(0, slash);
  std::ifstream in(path);
  if (!in) {
    table.error = fmt::format("{}: cannot read the target table", path);
    return table;
  }
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    std::vector<std::string> f;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, '|');) f.push_back(trim(cell));
    Target t;
    long bits = 0;
    if (f.size() != 9 || f[0].empty() || !number(f[1], bits) || (bits != 32 && bits != 64) || f[2].empty() ||
        f[6].find("{elf}") == std::string::npos || !number(f[7], t.ram) || !number(f[8], t.flash)) {
      table.error = fmt::format("{}:{}: a target is 9 fields separated by '|': name | double (32 or 64) | cc | "
                                "flags | link | support | run (with {{elf}}) | ram | flash",
                                path, n);
      return table;
    }
    if (table.find(f[0])) {
      table.error = fmt::format("{}:{}: target '{}' is given twice", path, n, f[0]);
      return table;
    }
    t.name = f[0];
    t.double_bits = static_cast<int>(bits);
    t.cc = f[2];
    t.flags = f[3];
    t.link = f[4];
    t.support = f[5];
    t.run = f[6];
    table.rows.push_back(t);
  }
  return table;
}

std::string expand(std::string text, const std::map<std::string, std::string> &vars) {
  for (const auto &[key, value] : vars) {
    const std::string mark = "{" + key + "}";
    for (auto at = text.find(mark); at != std::string::npos; at = text.find(mark, at + value.size()))
      text.replace(at, mark.size(), value);
  }
  return text;
}

}  // namespace gfec::targets
