// Writing outputs so that a failed or interrupted compile never leaves a half-written file:
// each output goes to a temporary file beside it, renamed into place only when all are written.
#pragma once

#include "backend.h"

#include <string>
#include <vector>

namespace gfec {

/// Writes every file or none; on failure returns a message naming the file and the reason.
std::string write_atomically(const std::vector<OutputFile> &files);

} // namespace gfec
