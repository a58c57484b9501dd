// gfec's byte ranges as LSP ranges and locations, one TextIndex per file of a compilation
// (built on first use: a request touches a few files of many).
#pragma once

#include "source.h"
#include "text_index.h"

#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace gfec::lsp {

/// The URI a server gives a file's path (its documents' own URIs for open buffers).
using UriOf = std::function<std::string(const std::string &path)>;

class SourceRanges {
public:
  explicit SourceRanges(const SourceManager &sources) : sources_(sources) {}
  /// {start: {line, character}, end: {...}}.
  nlohmann::json range(const SourceRange &r);
  const TextIndex &index(FileId file);

private:
  const SourceManager &sources_;
  std::map<FileId, TextIndex> indexes_;
};

}  // namespace gfec::lsp
