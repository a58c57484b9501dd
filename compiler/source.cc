#include "source.h"

#include "input_languages.h"

#include <algorithm>

namespace gfec {

SourceFile::SourceFile(std::string path, std::string text, const InputLanguage &language)
    : path_(std::move(path)), text_(std::move(text)), language_(&language) {
  line_starts_.push_back(0);
  // Lines end with LF, CRLF or a lone CR (old Mac files): each is one line end.
  for (std::uint32_t i = 0; i < text_.size(); ++i)
    if (text_[i] == '\n' || (text_[i] == '\r' && (i + 1 == text_.size() || text_[i + 1] != '\n')))
      line_starts_.push_back(i + 1);
}

LineCol SourceFile::line_col(std::uint32_t offset) const {
  offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text_.size()));
  auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  auto line = static_cast<std::uint32_t>(it - line_starts_.begin());
  return {line, offset - line_starts_[line - 1] + 1};
}

std::string_view SourceFile::line_text(std::uint32_t line) const {
  if (line == 0 || line > line_starts_.size()) return {};
  std::uint32_t begin = line_starts_[line - 1];
  std::uint32_t end = line < line_starts_.size() ? line_starts_[line] : static_cast<std::uint32_t>(text_.size());
  std::string_view s(text_.data() + begin, end - begin);
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

FileId SourceManager::add(std::string path, std::string text) {
  return add(std::move(path), std::move(text), chart_text_language());
}

FileId SourceManager::add(std::string path, std::string text, const InputLanguage &language) {
  files_.push_back(std::make_unique<SourceFile>(std::move(path), std::move(text), language));
  return static_cast<FileId>(files_.size() - 1);
}

const SourceManager &SourceManager::empty() {
  static const SourceManager none;
  return none;
}

}  // namespace gfec
