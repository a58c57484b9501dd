#!/usr/bin/env bash
# Configures (once) and builds gfec, the runtime, the simulator and the tests in build/.
#
# RelWithDebInfo with line tables only (-g1): backtraces, gdb's `bt` and the sanitizers' reports
# still name file and line, and the build takes about a third less time than with full debug
# information on a 2-core machine (docs/verification.md "The suite's cost"). For all of it: -DCMAKE_BUILD_TYPE=Debug.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -f build/build.ninja ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG"
fi
cmake --build build -j "$(nproc)"
