#include "input_languages.h"

#include "alica/alica_reader.h"
#include "iec/st_reader.h"
#include "plcopen/plcopen_reader.h"

#include <algorithm>
#include <filesystem>

namespace gfec {

namespace {

/// The table: the built-in rows, each defined beside its reader, then any registered.
std::vector<const InputLanguage *> &rows() {
  static std::vector<const InputLanguage *> table = {
      &chart_text_language(),  // compiler/loader.cc
      &alica::language(),      // compiler/alica/alica_language.cc
      &iec::st_language(),     // compiler/iec/st_language.cc
      &plcopen::language(),    // compiler/plcopen/plcopen_language.cc
  };
  return table;
}

}  // namespace

const FileType *InputLanguage::file_type(const std::string &path) const {
  const std::string ext = std::filesystem::path(path).extension().string();
  for (const FileType &t : file_types)
    if (!ext.empty() && t.extension == ext) return &t;
  return nullptr;
}

const std::vector<const InputLanguage *> &input_languages() { return rows(); }

const InputLanguage *find_input_language(std::string_view name) {
  for (const InputLanguage *l : rows())
    if (l->name == name) return l;
  return nullptr;
}

const InputLanguage &input_language_of(const std::string &path, std::string_view text) {
  const InputLanguage *by_extension = nullptr;
  for (const InputLanguage *l : rows()) {
    if (!l->file_type(path)) continue;
    if (!l->sniff) {
      if (!by_extension) by_extension = l;
    } else if (l->sniff(text)) {
      return *l;  // the text says it is this language's
    }
  }
  return by_extension ? *by_extension : chart_text_language();
}

std::vector<std::string> input_language_names() {
  std::vector<std::string> names;
  for (const InputLanguage *l : rows()) names.emplace_back(l->name);
  std::sort(names.begin(), names.end());
  return names;
}

std::string input_languages_help() {
  std::vector<const InputLanguage *> sorted = rows();
  std::sort(sorted.begin(), sorted.end(),
            [](const InputLanguage *a, const InputLanguage *b) { return a->name < b->name; });
  std::string text;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if (i > 0) text += i + 1 == sorted.size() ? " or " : ", ";
    text += std::string(sorted[i]->name) + " (" + std::string(sorted[i]->summary) + ")";
  }
  return text;
}

InputLanguageRegistration::InputLanguageRegistration(const InputLanguage &language) : language_(language) {
  rows().push_back(&language_);
}

InputLanguageRegistration::~InputLanguageRegistration() {
  auto &table = rows();
  table.erase(std::remove(table.begin(), table.end(), &language_), table.end());
}

}  // namespace gfec
