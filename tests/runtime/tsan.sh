#!/bin/sh
# Builds runtime_tests with ThreadSanitizer in its own build directory and runs
# them; any data race fails the run. Usage: tests/runtime/tsan.sh [catch args]
#   BUILD_DIR  build directory (default: build-tsan at the top of the tree)
#   JOBS       parallel build jobs (default: 2)
set -eu

root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$root/build-tsan}

cmake -S "$root" -B "$build" -G Ninja \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGFEC_SANITIZE=thread -DGFEC_BUILD_SIM=OFF \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
cmake --build "$build" --target runtime_tests -j "${JOBS:-2}"

# halt_on_error: the first race ends the run with a non-zero status.
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ${TSAN_OPTIONS:-}" \
  "$build/tests/runtime/runtime_tests" "$@"
