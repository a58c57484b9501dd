// The standard function blocks of IEC 61131-3 (docs/iec.md "The standard blocks"), predefined in
// every program that names one: their text is chart text compiled into gfec, read as one more file.
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "source.h"

#include <string_view>
#include <vector>

namespace gfec {

/// Whether `name` is a standard block's (TON, CTU, ...: upper case, as IEC writes them).
bool is_standard_block(std::string_view name);

/// The standard blocks' names, for did-you-mean.
std::vector<std::string_view> standard_block_names();

/// The chart text that declares the standard blocks.
const char *standard_blocks_text();

/// When some `var` of `program` has the type of a standard block that no file declares, parses
/// the standard blocks into one more file of the program (its blocks marked standard).
void add_standard_blocks(ast::Program &program, SourceManager &sources, Diagnostics &diag);

}  // namespace gfec
