// IEC structured text's row of the input-language table (compiler/input_languages.h).
#include "iec/lower.h"
#include "iec/iec_text.h"
#include "iec/st_reader.h"
#include "input_languages.h"

#include <algorithm>
#include <cctype>

namespace gfec::iec {

const InputLanguage &st_language() {
  static const InputLanguage row{
      "iec-st",
      "IEC 61131-3 structured text with SFC",
      {{".st", "an IEC 61131-3 structured-text program"},
       {".ST", "an IEC 61131-3 structured-text program"}},  // as some Windows tools name them
      nullptr,                                              // the extension decides
      read_st_program,
      false,  // its ranges are ST: back ends print expressions from the model, in chart syntax
      "//",   // IEC's third edition comment, which the reader accepts: diagnostic tests use it
      nullptr,
      true,  // --period overrides the TASK's INTERVAL
  };
  return row;
}

void read_st_program(const std::string &main_path, std::string text, const LoadOptions &options, const FileSystem &,
                     SourceManager &sources, Diagnostics &diag, LoadResult &result) {
  result.paths.push_back(main_path);
  result.program.files.push_back(std::make_unique<ast::File>());
  ast::File &file = *result.program.files.back();
  file.id = sources.add(main_path, std::move(text), st_language());
  const std::string &t = sources.file(file.id).text();  // names view it: it outlives the tree
  Project project;
  read_st(t, file.id, file.strings, diag, project);
  // Several PROGRAMs: the one the file's tasks run is compiled unless --chart names another
  // (docs/iec.md); none or several run: --chart decides.
  std::vector<std::string_view> run;
  std::size_t programs = 0;
  for (const Pou &p : project.pous) {
    if (p.kind != PouKind::Program) continue;
    ++programs;
    const std::string name = upper(p.name.text);
    for (const Task &task : project.tasks)
      for (const ast::Name &n : task.programs)
        if (upper(n.text) == name && std::find(run.begin(), run.end(), p.name.text) == run.end())
          run.push_back(p.name.text);
  }
  if (programs > 1 && run.size() == 1) result.default_chart = std::string(run.front());
  lower(std::move(project), file, diag, options.period_ms);
}

}  // namespace gfec::iec
