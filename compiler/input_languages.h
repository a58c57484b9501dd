// The input languages, one row each (as GCC's lang-specs.h): how a file of the language is
// recognised, the reader that turns it into the syntax tree, how its text may be quoted and how
// a line comment begins. The loader dispatches through this table, -x names a row, and the
// diagnostic test files ask it for comment syntax. Each reader defines its row beside itself;
// the built-in rows are listed in input_languages.cc, and a test may register one of its own
// (docs/architecture.md "Adding an input language").
#pragma once

#include "import_result.h"

#include <string>
#include <string_view>
#include <vector>

namespace gfec {

class Diagnostics;
class FileSystem;
class SourceManager;

/// A file extension of a language, and what a file of it is, for messages.
struct FileType {
  std::string_view extension;  ///< with its dot: ".pml"
  std::string_view what;       ///< "an ALICA plan"
  /// A main file, the kind one compiles (a chart, an ALICA plan); false: a file read because a
  /// main file refers to it (an interface, a toolbox, an ALICA behaviour). The ALICA reader says
  /// so when given one; the diagnostic test files take only main files as cases.
  bool main = true;
};

/// Reads the main file (whose text is `text`) and whatever it refers to into `result`: the main
/// file's tree first, then the others in the order first reached.
using ReadProgram = void (*)(const std::string &main_path, std::string text, const LoadOptions &options,
                             const FileSystem &fs, SourceManager &sources, Diagnostics &diag, LoadResult &result);

struct InputLanguage {
  std::string_view name;     ///< -x NAME
  std::string_view summary;  ///< for -x's help: "ALICA JSON plans"
  std::vector<FileType> file_types;
  /// Whether a file of one of `file_types` is this language's, from its text: for an extension
  /// several languages share (PLCopen's plain .xml). Null: the extension decides.
  bool (*sniff)(std::string_view text) = nullptr;
  ReadProgram read = nullptr;
  /// The file's ranges are chart text: a back end may quote them as written (labels,
  /// --emit=chart). False: they point into another syntax (an ALICA plan's JSON), so the back
  /// ends print expressions from the model, and diagnostics name the element (annotate).
  bool chart_text = true;
  /// How a line comment begins ("//"): a diagnostic test file (tests/diagnostics/) writes its
  /// expected output in such comments. Empty: the language has none; the expected output is in
  /// a sidecar file beside the case (tests/diagnostics/README.md).
  std::string_view line_comment;
  /// Run once the front end is done, or stopped, and again after the analyses: adds to the
  /// diagnostics from index `first` on what only the reader knows (which ALICA element a
  /// location is in); those before `first` have been annotated already. Null: nothing to add.
  void (*annotate)(Diagnostics &diag, const LoadResult &loaded, std::size_t first) = nullptr;
  /// Whether the reader takes LoadOptions::period_ms (an IEC program's period comes from its
  /// task, which the command line may override); false: --period is an error, as chart text
  /// declares its own `period` and an ALICA plan has none.
  bool reads_period = false;

  /// The entry of `file_types` for `path`'s extension, or null.
  const FileType *file_type(const std::string &path) const;
};

/// Every language: chart text (the default) first, then the others in the order registered.
const std::vector<const InputLanguage *> &input_languages();

/// Chart text (sfc, fsm, plan, ...): the language of a file no other row claims.
const InputLanguage &chart_text_language();

/// The language -x NAME names, or null.
const InputLanguage *find_input_language(std::string_view name);

/// The language of the file `path` whose text is `text`: the row listing its extension (when
/// several do, the one whose sniff accepts the text, else the one without a sniff), or chart
/// text when none does.
const InputLanguage &input_language_of(const std::string &path, std::string_view text);

/// The -x names, sorted: what -x accepts and its error lists.
std::vector<std::string> input_language_names();

/// For -x's help: "alica (ALICA JSON plans) or gfec (chart text)".
std::string input_languages_help();

/// Adds a row for as long as this object lives: a language of a test's own, or one a tool
/// links in. Rows are not copied: `language` must outlive the registration.
class InputLanguageRegistration {
public:
  explicit InputLanguageRegistration(const InputLanguage &language);
  ~InputLanguageRegistration();
  InputLanguageRegistration(const InputLanguageRegistration &) = delete;
  InputLanguageRegistration &operator=(const InputLanguageRegistration &) = delete;

private:
  const InputLanguage &language_;
};

}  // namespace gfec
