// Parsing a fragment of structured text that sits somewhere in a file: an expression (a
// transition's condition, an initial value) or a statement list (an action's body). The ST
// reader hands it slices of the .st file; the PLCopen XML reader the text of an <ST> or <inline>
// body, which may have been XML-unescaped, so fragment offsets are mapped back to file offsets
// through FragmentPlace, and every diagnostic points into the file as the user sees it.
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "source.h"

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gfec::iec {

/// Where a fragment's text lies in its file. Offset o of the fragment is at file offset
/// `b.second + (o - b.first)` for the last breakpoint b with b.first <= o. A fragment copied
/// verbatim needs one breakpoint {0, start}; one with XML entities unescaped adds a breakpoint
/// after each entity (`&lt;` of 4 bytes became `<` of 1: the next byte's file offset jumps by 3).
struct FragmentPlace {
  FileId file = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> breaks{{0, 0}};  ///< sorted by fragment offset

  /// A fragment that starts at file offset `start` and was copied unchanged.
  static FragmentPlace at(FileId file, std::uint32_t start) { return {file, {{0, start}}}; }
  /// The file offset of fragment offset `o`.
  std::uint32_t offset(std::uint32_t o) const;
  /// The file range of the fragment range [begin, end): the end maps as the byte before it, so a
  /// range ending on an unescaped entity covers the whole entity's spelling.
  SourceRange range(std::uint32_t begin, std::uint32_t end) const;
};

/// Parses `text` as one ST expression (nothing may follow it but blanks and comments). Names in
/// the result view `text`, which must outlive the tree (the source text, or a string kept in
/// ast::File::strings); a spelling the parser makes up (`16#FF` is the Int `255`) is kept in
/// `strings` (pass the file's ast::File::strings). Errors go to `diag` at file positions; null
/// when the fragment is not an expression gfec reads.
ast::ExprPtr parse_st_expression(std::string_view text, const FragmentPlace &place, std::deque<std::string> &strings,
                                 Diagnostics &diag);

/// Parses `text` as an ST statement list (assignments, IF/ELSIF/ELSE, CASE). As
/// parse_st_expression for names and errors; nullopt when a statement could not be read.
std::optional<ast::Block> parse_st_statements(std::string_view text, const FragmentPlace &place,
                                              std::deque<std::string> &strings, Diagnostics &diag);

}  // namespace gfec::iec
