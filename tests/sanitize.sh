#!/usr/bin/env bash
# CI's second full run: the whole test suite again, built with AddressSanitizer and
# UndefinedBehaviorSanitizer (any report fails the test that caused it). The simulator is left
# out: its physics library is not instrumented and its own tests run in the first pass.
#
#   tests/sanitize.sh            (scripts/test.sh calls it; the build goes to build-asan/)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${GFEC_ASAN_BUILD:-build-asan}
if [ ! -f "$build/build.ninja" ]; then
  # -Og -g1: reports name file and line; with the sanitizers' instrumentation gcc compiles -Og in
  # about half the time of -O1 (docs/verification.md "The suite's cost"), and the tests' time
  # goes to the C and C++ compilers they start, not to gfec.
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-Og -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-Og -g1 -DNDEBUG" \
    -DGFEC_SANITIZE=address,undefined -DGFEC_BUILD_SIM=OFF \
    -DCMAKE_CXX_FLAGS="-fno-sanitize-recover=undefined" -DCMAKE_C_FLAGS="-fno-sanitize-recover=undefined"
fi
cmake --build "$build" -j "$(nproc)"
# Leaks count as failures too; undefined behaviour stops the program with a stack trace.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
