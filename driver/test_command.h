// `gfec test FILE...`: runs the scenario tests (`test "NAME" of CHART { ... }`) of each file on
// the reference interpreter and on the generated C engine (docs/testing-charts.md).
#pragma once

#include <iosfwd>

namespace gfec {

/// argv[0] is "test". Diagnostics go to `err`, the summary line `N passed, M failed` last to
/// `out`; returns 0 when every test passed, 1 when one failed or a file has errors, 2 on usage
/// or I/O errors.
int test_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err);

}  // namespace gfec
