// What a reader of an input language is given and fills (compiler/input_languages.h): the
// options of the load, and the syntax tree of every file it read. Readers include this, not the
// loader, which only chooses among them.
#pragma once

#include "ast.h"
#include "source.h"

#include <optional>
#include <string>
#include <vector>

namespace gfec {

struct InputLanguage;

struct LoadOptions {
  std::vector<std::string> include_dirs;    ///< -I, searched after the importing file's folder
  const InputLanguage *language = nullptr;  ///< -x; null: the main file's own (input_language_of)
  /// --period in milliseconds: the scan period of every IEC program read, in place of its task's
  /// INTERVAL (docs/iec.md "Time"); a language without tasks refuses it (InputLanguage::reads_period).
  std::optional<double> period_ms;
};

/// An element of a file that is not chart text (an ALICA state, transition, plan...): where it
/// is and how to name it, so diagnostics about it can say which one (docs/alica.md).
struct SourceElement {
  SourceRange range;
  std::string description;  ///< e.g. "ALICA state 'Init' (id 1542881176280) of plan 'Master'"
};

struct LoadResult {
  ast::Program program;            ///< main file first, then imports in the order first reached
  std::vector<std::string> paths;  ///< the path of every file read, in the same order
  /// The paths an import looked for and found nothing at: a file appearing there (the language
  /// server's new buffer) changes the result, as a change of a file read does.
  std::vector<std::string> missing;
  bool main_unreadable = false;             ///< the main file itself could not be read (an I/O error)
  std::string main_unreadable_why;          ///< why not (FileText::why)
  const InputLanguage *language = nullptr;  ///< the main file's, once it was read
  std::vector<SourceElement> elements;      ///< ALICA input: every plan, state, transition... read
  /// The chart compiled when the main file declares several and --chart names none (the IEC
  /// PROGRAM that the file's one TASK runs, or a PLCopen file's tasks, docs/iec.md); empty: the default rule alone.
  std::string default_chart;
};

}  // namespace gfec
