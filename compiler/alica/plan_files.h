// The files of an ALICA plan: which file a reference names, where that file is, reading it once,
// and the element a reference "File.ext#id" points at. The first of the ALICA reader's three jobs
// (reader_context.h lists them); it knows nothing of charts, only of files, ids and references,
// and reports what it cannot find where the reference is written.
#pragma once

#include "alica/json_tree.h"
#include "diagnostics.h"
#include "file_system.h"
#include "import_result.h"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gfec::alica {

/// ".pml" for "plans/Master.pml".
std::string extension_of(const std::string &path);

/// "Behaviours/GoTo.beh#1544160969061" -> file and id; "#42" names the same file.
struct Ref {
  std::string file;
  std::string id;
};
std::optional<Ref> split_ref(std::string text);

/// An id written as a number, a string of digits or "#digits" (the XML era's spelling).
std::optional<std::string> id_of(const JsonValue *v);

/// One JSON file read.
struct Doc {
  std::string path;
  FileId file = 0;
  std::optional<JsonValue> root;  ///< empty: malformed (already reported)
  std::map<std::string, const JsonValue *> by_id;
};

/// Where `v` is written, for diagnostics.
inline SourceRange range(const Doc &d, const JsonValue &v) { return {d.file, v.begin, v.end}; }

/// How much a reference matters: a task names only an entry point's label, so a task file
/// that cannot be found is a warning, not an error.
enum class Need { Element, LabelOnly };

/// What a reference resolves to: the file and the element in it (both null when it does not).
struct Resolved {
  Doc *doc = nullptr;
  const JsonValue *object = nullptr;
};

/// Every file one compilation reads for ALICA, by normal path. Each file read becomes a file of
/// the loaded program (`result.paths`, `result.program.files`), in the order first reached.
class PlanFiles {
public:
  PlanFiles(const LoadOptions &options, const FileSystem &fs, SourceManager &sources, Diagnostics &diag,
            LoadResult &result)
      : options_(options), fs_(fs), sources_(sources), diag_(diag), result_(result) {}

  /// Adds the file `path` with `text` and parses it; XML or malformed JSON is reported, and the
  /// Doc then has no root.
  Doc *open(const std::string &path, std::string text);

  /// The element a reference "File.ext#id" in `from` names, or nothing (reported at `at`).
  Resolved resolve(const std::string &text, Doc &from, const SourceRange &at, Need need = Need::Element);

  /// Every file read whose JSON parsed, in the order they were added.
  std::vector<const Doc *> parsed() const;

private:
  Doc *find_doc(const std::string &file, const Doc &from, const SourceRange &at, const std::string &id, Need need);
  Doc *holding(const std::string &path, const std::string &id);
  std::vector<std::string> candidates(const std::string &file, const Doc &from) const;
  std::optional<std::string> search_below(const std::string &file, const Doc &from);
  void suggest_file(Diagnostic &d, const std::string &file, const std::vector<std::string> &tried,
                    const std::string &from);

  const LoadOptions &options_;
  const FileSystem &fs_;
  SourceManager &sources_;
  Diagnostics &diag_;
  LoadResult &result_;
  std::map<std::string, std::unique_ptr<Doc>> docs_;
  std::set<std::string> missing_;                          ///< files reported as not found (by the first path tried)
  std::map<std::string, std::vector<std::string>> trees_;  ///< search_below: root -> files below it
  std::set<std::string> trees_listed_;
};

}  // namespace gfec::alica
