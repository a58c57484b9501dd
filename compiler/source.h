// Source files and ranges: every token, AST node, model element and diagnostic points here.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace gfec {

using FileId = std::uint32_t;

struct InputLanguage;

/// A half-open byte range [begin, end) in one source file.
struct SourceRange {
  FileId file = 0;
  std::uint32_t begin = 0;
  std::uint32_t end = 0;

  /// The range covering both `this` and `other` (same file assumed).
  SourceRange to(const SourceRange &other) const { return {file, begin, other.end}; }
};

/// A 1-based line and column; columns count bytes, as gcc does.
struct LineCol {
  std::uint32_t line = 1;
  std::uint32_t col = 1;
};

/// One file's text, kept for the whole compilation so diagnostics can quote it.
class SourceFile {
public:
  SourceFile(std::string path, std::string text, const InputLanguage &language);

  const std::string &path() const { return path_; }
  const std::string &text() const { return text_; }
  LineCol line_col(std::uint32_t offset) const;
  /// The text of 1-based line `line`, without its newline.
  std::string_view line_text(std::uint32_t line) const;
  std::uint32_t line_count() const { return static_cast<std::uint32_t>(line_starts_.size()); }
  /// The language the file was read as (compiler/input_languages.h): whether its ranges are
  /// chart text a back end may quote as written, or point into another syntax (ALICA's JSON).
  const InputLanguage &language() const { return *language_; }

private:
  std::string path_;
  std::string text_;
  const InputLanguage *language_;
  std::vector<std::uint32_t> line_starts_;
};

/// Owns every file read in one compilation; FileIds index it.
class SourceManager {
public:
  /// A file of chart text: the parser's, and every file made up by a test or a tool.
  FileId add(std::string path, std::string text);
  FileId add(std::string path, std::string text, const InputLanguage &language);
  const SourceFile &file(FileId id) const { return *files_.at(id); }
  std::size_t size() const { return files_.size(); }
  /// Whether `id` is one of the files here: a model made by hand has ranges into none.
  bool knows(FileId id) const { return id < files_.size(); }
  /// A manager without files, for a model that has no sources.
  static const SourceManager &empty();

  LineCol begin_of(const SourceRange &r) const { return file(r.file).line_col(r.begin); }
  LineCol end_of(const SourceRange &r) const { return file(r.file).line_col(r.end); }

private:
  std::vector<std::unique_ptr<SourceFile>> files_;
};

}  // namespace gfec
