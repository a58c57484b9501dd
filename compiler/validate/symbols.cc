// The global symbol table: every top-level declaration of every file, declared before any
// body is checked, so a chart may call a function of a file imported after it (or before).
#include "validate/families.h"

#include <algorithm>
#include <functional>

namespace gfec::validation {

namespace {

/// One top-level declaration, to be declared in textual order: then a duplicate's note always
/// points at the declaration that really comes first, whatever the kinds.
struct TopDecl {
  std::uint32_t begin;
  std::function<void()> declare;
};

std::vector<TopDecl> top_level_of(Context &cx, ast::File &file) {
  std::vector<TopDecl> decls;
  for (const auto &i : file.interfaces) decls.push_back({i.range.begin, [&cx, &i] { declare_interface(cx, i); }});
  for (const auto &c : file.consts) decls.push_back({c.range.begin, [&cx, &c] { declare_file_const(cx, c); }});
  for (auto &c : file.charts) decls.push_back({c.range.begin, [&cx, &c] { declare_chart(cx, c); }});
  for (const auto &t : file.toolboxes) decls.push_back({t.range.begin, [&cx, &t] { declare_toolbox(cx, t); }});
  for (const auto &p : file.plans) decls.push_back({p.range.begin, [&cx, &p] { declare_plan(cx, p); }});
  std::stable_sort(decls.begin(), decls.end(), [](const TopDecl &a, const TopDecl &b) { return a.begin < b.begin; });
  return decls;
}

}  // namespace

void collect_symbols(Context &cx) {
  // Model tables in program order (main file first): the order back ends emit.
  for (std::size_t i = 0; i < cx.program.files.size(); ++i) {
    if (!cx.program.files[i]) continue;
    cx.current_file = static_cast<int>(i);
    for (const TopDecl &d : top_level_of(cx, *cx.program.files[i])) d.declare();
  }
  // Names in dependency order (imports are reached after the file importing them): a name
  // that clashes with an imported one is reported in the importing file, where it was added.
  std::stable_sort(cx.global_names.begin(), cx.global_names.end(),
                   [](const auto &a, const auto &b) { return a.file > b.file; });
  for (const auto &g : cx.global_names) g.ns->declare(*g.name, g.kind, g.index, cx.diag);
  check_engine_names(cx);
  check_toolbox_classes(cx);
}

}  // namespace gfec::validation
