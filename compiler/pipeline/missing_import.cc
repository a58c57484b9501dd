#include "pipeline/missing_import.h"

#include "diagnostics.h"
#include "parser.h"
#include "source.h"

#include <algorithm>
#include <filesystem>

namespace gfec {

MissingImportFinder::MissingImportFinder(const FileSystem &fs, const std::string &main_path,
                                         std::vector<std::string> include_dirs)
    : fs_(fs) {
  // The folders an import searches, in its order: the importing file's, then each -I.
  std::string own = std::filesystem::path(main_path).parent_path().generic_string();
  folders_.push_back(own.empty() ? "." : own);
  for (std::string &dir : include_dirs)
    if (std::find(folders_.begin(), folders_.end(), dir) == folders_.end()) folders_.push_back(std::move(dir));
}

void MissingImportFinder::scan() {
  declared_.emplace();
  std::size_t read = 0;
  for (const std::string &folder : folders_) {
    for (const std::string &name : fs_.list(folder)) {
      if (std::filesystem::path(name).extension() != ".iface") continue;
      if (read++ == kMaxFiles) return;
      FileText text = fs_.read((std::filesystem::path(folder) / name).generic_string());
      if (!text || text->size() > kMaxBytes) continue;
      // A scratch parse: this file's own errors belong to whoever imports it, not to this note.
      SourceManager sources;
      Diagnostics quiet;
      FileId id = sources.add(name, std::move(*text));
      std::unique_ptr<ast::File> file = parse_file(sources, id, quiet);
      if (!file) continue;
      for (const ast::Interface &interface : file->interfaces)
        for (const ast::FunctionDecl &f : interface.functions) {
          std::vector<std::string> &files = (*declared_)[std::string(f.name.text)];
          if (std::find(files.begin(), files.end(), name) == files.end()) files.push_back(name);
        }
    }
  }
}

std::vector<std::string> MissingImportFinder::operator()(const std::string &function) {
  if (!declared_) scan();
  auto it = declared_->find(function);
  return it == declared_->end() ? std::vector<std::string>{} : it->second;
}

}  // namespace gfec
