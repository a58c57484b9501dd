#!/usr/bin/env bash
# The whole test suite: builds, runs every ctest test (unit, golden, compile-and-run, runtime,
# end-to-end on the simulator), then the suites that need their own sanitizer builds.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
for extra in tests/runtime/tsan.sh tests/sanitize.sh; do
  if [ -x "$extra" ]; then
    echo "== $extra"
    "$extra"
  fi
done
