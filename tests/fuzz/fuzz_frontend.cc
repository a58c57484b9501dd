// libFuzzer target over the whole front end: loader (imports), lexer, parser, validator, the
// diagnostics printer, and — for inputs that validate — the reference interpreter, the
// analyses and the back ends. It traps on a crash, and also on a broken promise: an error
// without a location inside a file, a model whose indices point nowhere, a back end whose
// output changes from one run to the next.
//
// The input is the main file `fuzz.sfc`; after a line `%%%` the rest is `b.sfc`, which the
// main file may import (so is the main file itself, for cycles). docs/verification.md says
// how to build and run it; replay_main.cc runs saved inputs as a ctest.
#include "fuzz_support.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  gfec::fuzz::check_one(std::string(reinterpret_cast<const char *>(data), size));
  return 0;
}
