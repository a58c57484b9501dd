#include "compiled_document.h"

#include "lexer.h"
#include "session.h"

namespace gfec::lsp {

CompiledDocument::CompiledDocument(const Session &session, const std::string &uri, const std::string &path,
                                   const pipeline::FrontEndOptions &options, const FileSystem &files)
    : session_(session), uri_(uri), path_(path), compilation_(std::make_unique<pipeline::Compilation>(options)),
      ranges_(compilation_->sources) {
  compilation_->load_and_validate(path, files);
  front_end_diagnostics_ = compilation_->diag.all().size();
  if (!compilation_->loaded.program.files.empty() && compilation_->loaded.program.files.front()) {
    main_ = compilation_->loaded.program.files.front()->id;
    has_main_ = true;
  } else if (compilation_->sources.size() > 0) {
    has_main_ = true;  // the first file read is the main file even when it did not parse
  }
}

const std::string &CompiledDocument::text() const {
  static const std::string empty;
  return has_main_ ? compilation_->sources.file(main_).text() : empty;
}

nlohmann::json CompiledDocument::range(const SourceRange &r) const {
  const auto &sources = compilation_->sources;
  if (!sources.knows(r.file)) return range_json("", 0, 0);
  return ranges_.range(r);
}

std::string CompiledDocument::uri_of(FileId file) const {
  const auto &sources = compilation_->sources;
  if (!sources.knows(file)) return uri_;
  if (file == main_) return uri_;
  return session_.uri_of_path(sources.file(file).path());
}

nlohmann::json CompiledDocument::location(const SourceRange &r) const {
  return {{"uri", uri_of(r.file)}, {"range", range(r)}};
}

bool CompiledDocument::reads(const std::string &path) const {
  const std::string wanted = normal_path(path);
  for (const auto &p : compilation_->loaded.paths)
    if (normal_path(p) == wanted) return true;
  // An import that found nothing at `path`: a buffer opened there makes the import resolve.
  for (const auto &p : compilation_->loaded.missing)
    if (normal_path(p) == wanted) return true;
  return false;
}

const NameUse *CompiledDocument::name_at(Position p) const {
  if (!has_main_) return nullptr;
  return compilation_->name_uses.at(main_, static_cast<std::uint32_t>(offset_at(p)));
}

Token CompiledDocument::token_at(std::size_t offset) const {
  if (!has_main_) return {};
  Diagnostics scratch;  // the file's lexical errors are reported by its compilation already
  Lexer lexer(compilation_->sources, main_, scratch);
  for (Token t = lexer.next(); t.kind != Tok::End; t = lexer.next()) {
    if (t.range.begin > offset) break;
    if (offset <= t.range.end && t.kind != Tok::Error) return t;
  }
  return {};
}

const ast::File *CompiledDocument::syntax_of(FileId file) const {
  for (const auto &f : compilation_->loaded.program.files)
    if (f && f->id == file) return f.get();
  return nullptr;
}

std::string_view CompiledDocument::text_of(const SourceRange &r) const {
  const auto &sources = compilation_->sources;
  if (!sources.knows(r.file)) return {};
  const std::string &text = sources.file(r.file).text();
  if (r.begin > r.end || r.end > text.size()) return {};
  return std::string_view(text).substr(r.begin, r.end - r.begin);
}

}  // namespace gfec::lsp
