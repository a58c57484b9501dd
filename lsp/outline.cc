#include "outline.h"

#include <algorithm>

namespace gfec::lsp {

namespace {

// LSP 3.17 SymbolKind.
enum Kind {
  kModule = 2,
  kClass = 5,
  kMethod = 6,
  kField = 8,
  kInterface = 11,
  kFunction = 12,
  kVariable = 13,
  kConstant = 14,
  kObject = 19,
  kEnumMember = 22,
  kEvent = 24,
};

OutlineItem item(const ast::Name &name, std::string detail, int kind, SourceRange range) {
  OutlineItem i;
  i.name = std::string(name.text);
  i.detail = std::move(detail);
  i.kind = kind;
  i.selection = name.range;
  // A recovered syntax error may leave a range that does not hold its name; LSP requires it.
  i.range = range.file == name.range.file && range.begin <= name.range.begin && range.end >= name.range.end
                ? range
                : name.range;
  return i;
}

std::string signature(const ast::FunctionDecl &f) {
  std::string s = f.result.text + " (";
  for (std::size_t i = 0; i < f.params.size(); ++i) {
    if (i) s += ", ";
    s += f.params[i].type.text;
    if (f.params[i].name) s += " " + std::string(f.params[i].name->text);
  }
  return s + ")";
}

OutlineItem value(const ast::ValueDecl &v) {
  return item(v.name, (v.is_const ? "const " : "var ") + v.type.text, v.is_const ? kConstant : kVariable, v.range);
}

OutlineItem chart(const ast::Chart &c) {
  const bool fsm = c.kind == ast::Chart::Kind::Fsm;
  OutlineItem out = item(c.name, fsm ? "fsm" : "sfc", kClass, c.range);
  std::vector<OutlineItem> &kids = out.children;
  for (const auto &v : c.values) kids.push_back(value(v));
  for (const auto &p : c.places) {
    std::string detail = p.initial ? "initial " : "";
    if (p.terminal == ast::StateKind::Success) detail += "success ";
    if (p.terminal == ast::StateKind::Failure) detail += "failure ";
    detail += p.is_state ? "state" : "place";
    if (const ast::Name *runs = p.runs()) detail += " runs " + std::string(runs->text);
    kids.push_back(item(p.name, detail, kEnumMember, p.range));
  }
  for (const auto &t : c.transitions)
    if (t.named && !t.name.text.empty()) kids.push_back(item(t.name, "transition", kEvent, t.range));
  std::sort(kids.begin(), kids.end(), [](const auto &a, const auto &b) { return a.range.begin < b.range.begin; });
  return out;
}

}  // namespace

std::vector<OutlineItem> outline(const ast::File &file) {
  std::vector<OutlineItem> items;
  auto named = [](const ast::Name &n) { return !n.text.empty(); };
  for (const auto &c : file.consts)
    if (named(c.name)) items.push_back(value(c));
  for (const auto &i : file.interfaces) {
    if (!named(i.name)) continue;
    OutlineItem out = item(i.name, "interface", kInterface, i.range);
    for (const auto &f : i.functions)
      if (named(f.name)) out.children.push_back(item(f.name, signature(f), kFunction, f.range));
    items.push_back(std::move(out));
  }
  for (const auto &c : file.charts)
    if (named(c.name)) items.push_back(chart(c));
  for (const auto &t : file.toolboxes) {
    if (!named(t.name)) continue;
    OutlineItem out = item(t.name, "toolbox", kModule, t.range);
    for (const auto &tp : t.templates) {
      if (!named(tp.name)) continue;
      const char *what = tp.kind == ast::Template::Kind::Actor         ? "actor"
                         : tp.kind == ast::Template::Kind::Computation ? "computation"
                                                                       : "supervisor";
      out.children.push_back(item(tp.name, what, kMethod, tp.range));
    }
    items.push_back(std::move(out));
  }
  for (const auto &p : file.plans) {
    if (!named(p.name)) continue;
    OutlineItem out = item(p.name, "plan", kClass, p.range);
    for (const auto &block : p.config_blocks)
      for (const auto &e : block)
        if (named(e.name)) out.children.push_back(item(e.name, "config " + e.type.text, kField, e.range));
    for (const auto &a : p.actors)
      if (named(a.name))
        out.children.push_back(item(a.name, "actor " + std::string(a.template_name.text), kObject, a.range));
    items.push_back(std::move(out));
  }
  for (const auto &t : file.tests) {
    OutlineItem out;
    out.name = "test \"" + t.name + "\"";
    out.detail = "of " + std::string(t.chart.text);
    out.kind = kMethod;
    out.range = t.range;
    out.selection = t.name_range.file == t.range.file && t.name_range.end > t.name_range.begin ? t.name_range : t.range;
    items.push_back(std::move(out));
  }
  std::sort(items.begin(), items.end(), [](const auto &a, const auto &b) { return a.range.begin < b.range.begin; });
  return items;
}

const OutlineItem *declaration_named_at(const std::vector<OutlineItem> &items, const SourceRange &name,
                                        const OutlineItem **parent) {
  for (const OutlineItem &i : items) {
    if (i.selection.file == name.file && i.selection.begin == name.begin) return &i;
    for (const OutlineItem &child : i.children)
      if (child.selection.file == name.file && child.selection.begin == name.begin) {
        if (parent) *parent = &i;
        return &child;
      }
  }
  return nullptr;
}

}  // namespace gfec::lsp
