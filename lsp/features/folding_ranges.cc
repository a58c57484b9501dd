#include "folding_ranges.h"

#include "lexed_text.h"
#include "text_index.h"

#include <algorithm>
#include <tuple>
#include <vector>

namespace gfec::lsp {

namespace {

struct Fold {
  std::uint32_t start, end;
  const char *kind;  // null: a block
};

/// Whether only white space precedes `offset` on its line.
bool starts_line(const TextIndex &index, std::uint32_t offset) {
  std::uint32_t b = index.line_start(index.position(offset).line);
  for (std::uint32_t i = b; i < offset; ++i)
    if (index.text()[i] != ' ' && index.text()[i] != '\t') return false;
  return true;
}

}  // namespace

nlohmann::json folding_ranges(std::string_view text) {
  const LexedText lexed = lex_text(text);
  const TextIndex index(text);
  std::vector<Fold> folds;

  // Blocks: the closing brace's line stays visible, as editors fold C.
  std::vector<std::uint32_t> open;
  for (const Token &t : lexed.tokens) {
    if (t.kind == Tok::LBrace) open.push_back(index.position(t.range.begin).line);
    if (t.kind == Tok::RBrace && !open.empty()) {
      std::uint32_t start = open.back(), end = index.position(t.range.begin).line;
      open.pop_back();
      if (end > start + 1 || (end == start + 1 && !starts_line(index, t.range.begin)))
        folds.push_back({start, starts_line(index, t.range.begin) ? end - 1 : end, nullptr});
    }
    // A verbatim block over several lines folds as a block does.
    if (t.kind == Tok::Verbatim) {
      std::uint32_t start = index.position(t.range.begin).line, end = index.position(t.range.end).line;
      if (end > start) folds.push_back({start, end, nullptr});
    }
  }

  // Comments: a block comment over several lines, or line comments on consecutive lines, each
  // alone on its line (a trailing comment belongs to its code).
  std::uint32_t run_start = 0, run_end = 0;
  bool in_run = false;
  auto close_run = [&] {
    if (in_run && run_end > run_start) folds.push_back({run_start, run_end, "comment"});
    in_run = false;
  };
  for (const ByteRange &c : lexed.comments) {
    std::uint32_t first = index.position(c.begin).line, last = index.position(c.end).line;
    bool line_comment = text.substr(c.begin, 2) == "//";
    if (!line_comment) {
      close_run();
      if (last > first) folds.push_back({first, last, "comment"});
      continue;
    }
    if (!starts_line(index, c.begin)) continue;
    if (in_run && first == run_end + 1) {
      run_end = first;
    } else {
      close_run();
      in_run = true, run_start = run_end = first;
    }
  }
  close_run();

  // Imports: `import "x";` statements on consecutive lines.
  std::uint32_t group_start = 0, group_end = 0;
  bool in_group = false;
  for (std::size_t i = 0; i < lexed.tokens.size(); ++i) {
    if (lexed.tokens[i].kind != Tok::KwImport) continue;
    std::uint32_t line = index.position(lexed.tokens[i].range.begin).line;
    if (in_group && line <= group_end + 1) {
      group_end = line;
    } else {
      if (in_group && group_end > group_start) folds.push_back({group_start, group_end, "imports"});
      in_group = true, group_start = group_end = line;
    }
  }
  if (in_group && group_end > group_start) folds.push_back({group_start, group_end, "imports"});

  std::sort(folds.begin(), folds.end(),
            [](const Fold &a, const Fold &b) { return std::tie(a.start, a.end) < std::tie(b.start, b.end); });
  nlohmann::json out = nlohmann::json::array();
  for (const Fold &f : folds) {
    nlohmann::json r = {{"startLine", f.start}, {"endLine", f.end}};
    if (f.kind) r["kind"] = f.kind;
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace gfec::lsp
