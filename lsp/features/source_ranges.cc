#include "source_ranges.h"

namespace gfec::lsp {

const TextIndex &SourceRanges::index(FileId file) {
  auto it = indexes_.find(file);
  if (it == indexes_.end()) it = indexes_.emplace(file, TextIndex(sources_.file(file).text())).first;
  return it->second;
}

nlohmann::json SourceRanges::range(const SourceRange &r) {
  const TextIndex &i = index(r.file);
  return {{"start", to_json(i.position(r.begin))}, {"end", to_json(i.position(r.end))}};
}

}  // namespace gfec::lsp
