// textDocument/hover: what the name at the cursor is, from its declaration in the syntax tree
// (outline.h) and the validator's resolution: an interface function's prototype and interface,
// a place's kind and actions, a var's or constant's type and initial value, a chart's
// interface (its places' kinds, vars and constants); or a built-in function's signature and
// meaning. Markdown, with chart text in `gfec` blocks.
#include "handlers/navigation.h"
#include "methods.h"
#include "outline.h"
#include "validate/names.h"

namespace gfec::lsp::handlers {

using nlohmann::json;

namespace {

/// `text` cut to its first `lines` lines (a "..." line says so).
std::string first_lines(std::string_view text, int lines) {
  std::string out;
  int n = 0;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t nl = text.find('\n', at);
    std::string_view line = text.substr(at, nl == std::string_view::npos ? std::string_view::npos : nl - at);
    if (++n > lines) return out + "...\n";
    out += std::string(line) + "\n";
    if (nl == std::string_view::npos) break;
    at = nl + 1;
  }
  return out;
}

std::string code(const std::string &text) {
  return "```gfec\n" + text + (text.empty() || text.back() != '\n' ? "\n" : "") + "```";
}

/// A chart's interface: what a chart that runs it, or a test of it, may name.
std::string chart_interface(const OutlineItem &chart) {
  std::string s = chart.detail + " " + chart.name + " {\n";
  for (const OutlineItem &c : chart.children) s += "  " + c.detail + " " + c.name + ";\n";
  return s + "}";
}

/// A built-in function of the chart language (docs/language.md §4, §9, §11, §14, §15): its
/// signature and what it gives, for a name no declaration resolves.
const char *builtin_doc(std::string_view name) {
  static const struct {
    const char *name, *doc;
  } kBuiltins[] = {
      {"elapsed", "`elapsed(P)`: the time place or state `P` has been active, in ticks (a `time` where one is meant)"},
      {"active", "`active(P)`: place or state `P` is active (`active(P.Q)`: in the chart `P` runs); of a named "
                 "action, its Q"},
      {"running", "`running(A)`: the body of named action `A` runs in this tick (IEC's `A.A`)"},
      {"succeeded", "`succeeded(P)`: `P` runs an fsm that is in a success state"},
      {"failed", "`failed(P)`: `P` runs an fsm that is in a failure state"},
      {"team", "`team(S)`: how many other agents last reported state `S`"},
      {"agent", "`agent()`: this engine's agent number"},
      {"now", "`now()`: the time of the tick, a `time`: the tick's number times the period"},
      {"abs", "`abs(x)`: the absolute value of `x`, of its type (IEC's ABS)"},
      {"min", "`min(a, b, ...)`: the least of its operands; the first of equal ones (IEC's MIN)"},
      {"max", "`max(a, b, ...)`: the greatest of its operands; the first of equal ones (IEC's MAX)"},
      {"limit", "`limit(mn, x, mx)`: `x` kept between `mn` and `mx`, `x > mn ? (x < mx ? x : mx) : mn` (IEC's LIMIT)"},
      {"sel", "`sel(g, a, b)`: `a` when `g` is false, `b` when it is true (IEC's SEL)"},
      {"mux", "`mux(k, a, b, ...)`: `a` when `k` is 0, `b` when 1, ...; 0 when `k` is out of range (IEC's MUX)"},
  };
  for (const auto &b : kBuiltins)
    if (name == b.name) return b.doc;
  return nullptr;
}

}  // namespace

json hover(Session &s, const json &params) {
  At at = name_at_request(s, params);
  if (!at.name) {
    // No declared name: a built-in function, if the word at the cursor is one.
    const Token t = at.doc.token_at(at.doc.offset_at(read_position(params.at("position"))));
    const char *doc = t.kind == Tok::Ident ? builtin_doc(t.text) : nullptr;
    if (!doc) return nullptr;
    return {{"contents",
             {{"kind", "markdown"}, {"value", "**built-in function** `" + std::string(t.text) + "`\n\n" + doc}}},
            {"range", at.doc.range(t.range)}};
  }
  const NameUse &u = *at.name;
  std::string header =
      "**" + std::string(validation::describe(u.kind)) + "** `" + std::string(at.doc.text_of(u.at)) + "`";
  std::string body;
  if (const ast::File *file = at.doc.syntax_of(u.decl.file)) {
    std::vector<OutlineItem> items = outline(*file);
    const OutlineItem *parent = nullptr;
    if (const OutlineItem *decl = declaration_named_at(items, u.decl, &parent)) {
      if (parent) header += " of " + parent->detail + " `" + parent->name + "`";
      if (u.kind == validation::Sym::Chart) body = code(chart_interface(*decl));
      else body = code(first_lines(at.doc.text_of(decl->range), 12));
    }
  }
  if (u.decl.file != u.at.file || !at.doc.compilation().sources.knows(u.decl.file)) {
    const auto &sources = at.doc.compilation().sources;
    if (sources.knows(u.decl.file)) header += "\n\ndeclared in `" + sources.file(u.decl.file).path() + "`";
  }
  return {{"contents", {{"kind", "markdown"}, {"value", body.empty() ? header : header + "\n\n" + body}}},
          {"range", at.doc.range(u.at)}};
}

void advertise_hover(json &caps) { caps["hoverProvider"] = true; }

}  // namespace gfec::lsp::handlers
