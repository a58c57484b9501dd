// gfec monitor: decodes a live trace stream of a C engine built with --trace (docs/live.md).
#pragma once

#include <iosfwd>

namespace gfec {

int monitor_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err);

}  // namespace gfec
