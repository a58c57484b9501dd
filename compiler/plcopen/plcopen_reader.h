// The PLCopen TC6 XML reader (docs/iec.md "PLCopen XML"): a project's PROGRAM POUs with SFC
// bodies, filled into the IEC program model (iec/iec_model.h) that the ST reader fills too, and
// lowered by the same lowering into the chart syntax tree.
#pragma once

#include "import_result.h"

#include <string>
#include <string_view>

namespace gfec {
class Diagnostics;
class FileSystem;
class SourceManager;
struct InputLanguage;
}  // namespace gfec

namespace gfec::plcopen {

/// PLCopen's row of the input-language table (plcopen_language.cc).
const InputLanguage &language();

/// Whether `text` is an XML document (it begins with markup). Every XML document of a .xml file
/// goes to the PLCopen reader, which says in one located error when its root is not a PLCopen
/// `project` (a Beremiz configuration, an SVG) — rather than reading it as chart text.
bool is_xml_document(std::string_view text);

/// The row's reader: the main file's projects' programs as charts.
void read_plcopen_program(const std::string &main_path, std::string text, const LoadOptions &options,
                          const FileSystem &fs, SourceManager &sources, Diagnostics &diag, LoadResult &result);

}  // namespace gfec::plcopen
