// IEC structured text's row of the input-language table (compiler/input_languages.h).
#include "iec/lower.h"
#include "iec/st_reader.h"
#include "input_languages.h"

namespace gfec::iec {

const InputLanguage &st_language() {
  static const InputLanguage row{
      "iec-st",
      "IEC 61131-3 structured text with SFC",
      {{".st", "an IEC 61131-3 structured-text program"}},
      nullptr,  // the extension decides
      read_st_program,
      false,  // its ranges are ST: back ends print expressions from the model, in chart syntax
      "//",   // IEC's third edition comment, which the reader accepts: diagnostic tests use it
      nullptr,
  };
  return row;
}

void read_st_program(const std::string &main_path, std::string text, const LoadOptions &, const FileSystem &,
                     SourceManager &sources, Diagnostics &diag, LoadResult &result) {
  result.paths.push_back(main_path);
  result.program.files.push_back(std::make_unique<ast::File>());
  ast::File &file = *result.program.files.back();
  file.id = sources.add(main_path, std::move(text), st_language());
  const std::string &t = sources.file(file.id).text();  // names view it: it outlives the tree
  Project project;
  read_st(t, file.id, file.strings, diag, project);
  lower(std::move(project), file, diag);
}

}  // namespace gfec::iec
