// The global symbol table: every top-level declaration of every file, declared before any
// body is checked, so a chart may call a function of a file imported after it.
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

std::vector<TopDecl> top_level_of(Context &cx, const ast::File &file) {
  std::vector<TopDecl> decls;
  for (const auto &i : file.interfaces) decls.push_back({i.range.begin, [&cx, &i] { declare_interface(cx, i); }});
  for (const auto &c : file.consts) decls.push_back({c.range.begin, [&cx, &c] { declare_file_const(cx, c); }});
  for (const auto &c : file.charts) decls.push_back({c.range.begin, [&cx, &c] { declare_chart(cx, c); }});
  for (const auto &t : file.toolboxes) decls.push_back({t.range.begin, [&cx, &t] { declare_toolbox(cx, t); }});
  for (const auto &p : file.plans) decls.push_back({p.range.begin, [&cx, &p] { declare_plan(cx, p); }});
  std::stable_sort(decls.begin(), decls.end(), [](const TopDecl &a, const TopDecl &b) { return a.begin < b.begin; });
  return decls;
}

} // namespace

void collect_symbols(Context &cx) {
  for (const auto &file : cx.program.files) {
    if (!file) continue;
    for (const TopDecl &d : top_level_of(cx, *file)) d.declare();
  }
}

} // namespace gfec::validation
