// Writing outputs so that a failed or interrupted compile never leaves a half-written file, and
// never writes over an input, a special file or one file twice (safe_output.h says how).
#pragma once

#include "backend.h"

#include <string>
#include <vector>

namespace gfec {

/// Writes every file or none; on failure returns a message naming the file and the reason.
/// `inputs`: the files this run read, which no output may replace.
std::string write_atomically(const std::vector<OutputFile> &files, const std::vector<std::string> &inputs);

}  // namespace gfec
