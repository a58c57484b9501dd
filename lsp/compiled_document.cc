#include "compiled_document.h"

#include "session.h"

namespace gfec::lsp {

CompiledDocument::CompiledDocument(const Session &session, const std::string &uri, const std::string &path,
                                   const pipeline::FrontEndOptions &options, const FileSystem &files)
    : session_(session), uri_(uri), path_(path), compilation_(std::make_unique<pipeline::Compilation>(options)) {
  compilation_->front_end(path, files);
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
  return range_json(sources.file(r.file).text(), r.begin, r.end);
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
  return false;
}

}  // namespace gfec::lsp
