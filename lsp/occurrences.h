// Where a declaration is named across files: in the open documents and in the chart files of
// the workspace folders that are not open (a `.test` file naming a chart, a chart calling an
// interface's function). Each file is compiled by the pipeline with its name uses recorded;
// the occurrences are the uses it resolved to the declaration. references and rename read it.
#pragma once

#include "compiled_document.h"

#include <map>
#include <string>
#include <vector>

namespace gfec::lsp {

class Session;

/// A declaration as any compilation can find it again: its file (normalised path) and where
/// its name begins there (buffers are shared, so every compilation reads the same text).
struct DeclarationKey {
  std::string path;
  std::uint32_t begin = 0;
};

DeclarationKey key_of(const CompiledDocument &doc, const SourceRange &decl);

/// One place a declaration is named: its URI and LSP range.
struct Occurrence {
  std::string uri;
  nlohmann::json range;
  bool declaration = false;
};

/// Every place `key`'s declaration is written, the declaration included, each once, in URI and
/// offset order. `name` is its name: a file whose text does not hold it is not compiled.
std::vector<Occurrence> occurrences(Session &session, const DeclarationKey &key, std::string_view name);

/// The chart files below the workspace folders (and the open documents), as paths.
std::vector<std::string> workspace_files(Session &session);

}  // namespace gfec::lsp
