// "The compilation of this document": an open document run through the compiler's pipeline
// (compiler/pipeline/compilation.h) with its syntax tree kept, and the helpers every request
// handler needs to turn its answers into LSP (ranges in any file it read, locations, the
// offset of a position). Handlers never parse: whatever they tell comes from here.
#pragma once

#include "pipeline/compilation.h"
#include "positions.h"
#include "source_ranges.h"
#include "token.h"

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace gfec::lsp {

class Session;

class CompiledDocument {
public:
  /// Loads and validates the document; the static analyses are left to analyze().
  CompiledDocument(const Session &session, const std::string &uri, const std::string &path,
                   const pipeline::FrontEndOptions &options, const FileSystem &files);

  /// Runs the static analyses if they have not run (Compilation::analyze).
  void analyze() { compilation_->analyze(); }
  bool analysis_pending() const { return compilation_->analysis_pending(); }
  /// Whether the analyses reported anything: the diagnostics published before they ran are
  /// not all there are.
  bool analyses_reported() const { return compilation_->diag.all().size() > front_end_diagnostics_; }

  const std::string &uri() const { return uri_; }
  const std::string &path() const { return path_; }
  /// The pipeline's state: sources, diagnostics, the syntax tree (loaded.program), the model.
  /// The front end stops at the first stage with errors, so the model may be partial.
  const pipeline::Compilation &compilation() const { return *compilation_; }
  /// The document's own file (the main file); its text is the buffer compiled.
  FileId main_file() const { return main_; }
  bool has_main() const { return has_main_; }
  const std::string &text() const;

  /// The byte offset in the main file of an LSP position.
  std::size_t offset_at(Position p) const { return has_main_ ? ranges_.index(main_).offset(p) : 0; }
  /// A SourceRange as an LSP Range (in its own file's text).
  nlohmann::json range(const SourceRange &r) const;
  /// A SourceRange as an LSP Location: the URI of its file (an open buffer's own URI) and range.
  nlohmann::json location(const SourceRange &r) const;
  /// The URI of a file this compilation read.
  std::string uri_of(FileId file) const;
  /// Whether the compilation read the file at `path` (normalised), or an import looked for it
  /// there and found nothing: it must be redone when that file's buffer opens or changes.
  bool reads(const std::string &path) const;

  // ---- the element at a position
  /// The name written at `p` in the document, as the validator resolved it (a declaration or a
  /// use; name_uses.h), or null: no name there, or the validator did not run (a syntax error).
  const NameUse *name_at(Position p) const;
  /// The token of the document's text over byte `offset`, lexed by the compiler's lexer (a
  /// keyword, an identifier...); Tok::End if none.
  Token token_at(std::size_t offset) const;
  /// The syntax tree of the file `file` (null if it did not parse into one).
  const ast::File *syntax_of(FileId file) const;
  /// The source text of `r`.
  std::string_view text_of(const SourceRange &r) const;

private:
  const Session &session_;
  std::string uri_, path_;
  std::unique_ptr<pipeline::Compilation> compilation_;
  FileId main_ = 0;
  bool has_main_ = false;
  std::size_t front_end_diagnostics_ = 0;  ///< how many diagnostics there were before the analyses
  /// Line indexes of the files read, built on first use and kept with this compilation (one
  /// per document version): a position costs a binary search, not a scan from the text's start.
  mutable SourceRanges ranges_;
};

}  // namespace gfec::lsp
