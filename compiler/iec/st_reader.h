// The IEC 61131-3 structured-text reader: a .st file's PROGRAMs with their textual SFC, and the
// CONFIGURATION whose TASKs give their periods, read into the IEC model (iec_model.h) and lowered
// into the chart syntax tree (lower.h), so the validator, the model and every back end work
// unchanged. docs/iec.md says what is read and how it maps.
#pragma once

#include "diagnostics.h"
#include "file_system.h"
#include "iec/iec_model.h"
#include "import_result.h"

#include <deque>
#include <string>
#include <string_view>

namespace gfec::iec {

/// The IEC structured-text row of the input-language table (st_language.cc): `-x iec-st`, `.st`.
const InputLanguage &st_language();

/// Reads the POUs and configurations of the ST text `text` (of file `file`) into `project`.
void read_st(std::string_view text, FileId file, std::deque<std::string> &strings, Diagnostics &diag, Project &project);

/// The row's reader: the .st file in `main_path` as one ast::File with a chart per PROGRAM.
void read_st_program(const std::string &main_path, std::string text, const LoadOptions &options, const FileSystem &fs,
                     SourceManager &sources, Diagnostics &diag, LoadResult &result);

}  // namespace gfec::iec
