#include "dependency_file.h"

#include "backend.h"

#include <fmt/format.h>

namespace gfec {

namespace {

/// gcc wraps dependency lines at about this width, continuing them with " \".
constexpr std::size_t kLineWidth = 75;

void append_wrapped(std::string &out, std::size_t &column, const std::string &word) {
  if (column > 1 && column + word.size() + 1 > kLineWidth) {
    out += " \\\n ";
    column = 1;
  }
  out += ' ';
  out += word;
  column += word.size() + 1;
}

}  // namespace

std::string make_escape(const std::string &path) {
  std::string out;
  for (char c : path) {
    if (c == ' ' || c == '#' || c == '\t' || c == ':') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}

std::string make_unreadable(const std::string &path) {
  for (char c : path) {
    auto u = static_cast<unsigned char>(c);
    if (c == '\n') return "a newline";
    if (c == '\0') return "a NUL character";
    if ((u < 0x20 && c != '\t') || u == 0x7f) return fmt::format("the control character 0x{:02x}", u);
    if (c == ';' || c == '=' || c == '|' || c == '\\') return fmt::format("'{}'", c);
  }
  return {};
}

std::string dependency_rule(const std::vector<DependencyTarget> &targets, const std::vector<std::string> &deps,
                            bool phony) {
  std::string out;
  for (std::size_t i = 0; i < targets.size(); ++i)
    out += (i ? " " : "") + (targets[i].quoted ? make_escape(targets[i].name) : targets[i].name);
  out += ':';
  std::size_t column = out.size();
  for (const auto &d : deps) append_wrapped(out, column, make_escape(d));
  out += '\n';
  // -MP: with an empty rule per import, make does not fail on a deleted or renamed import
  // before gfec has had a chance to write a new dependency file without it.
  if (phony)
    for (std::size_t i = 1; i < deps.size(); ++i) out += "\n" + make_escape(deps[i]) + ":\n";
  return out;
}

std::string dependency_file_name(const DependencyOptions &deps, const std::string &primary_output) {
  return deps.file.empty() ? replace_extension(primary_output, ".d") : deps.file;
}

}  // namespace gfec
