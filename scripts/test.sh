#!/usr/bin/env bash
# The whole test suite: builds, runs every ctest test (unit, golden, compile-and-run, runtime,
# end-to-end on the simulator), then the suites that need their own sanitizer builds. Each stage
# says how long it took (docs/verification.md "The suite's cost").
set -euo pipefail
cd "$(dirname "$0")/.."
stage() {
  local name=$1 start=$SECONDS
  shift
  echo "== $name"
  "$@"
  echo "== $name: $((SECONDS - start)) s"
}
stage build scripts/build.sh
stage ctest ctest --test-dir build --output-on-failure -j "$(nproc)"
for extra in tests/runtime/tsan.sh tests/sanitize.sh; do
  if [ -x "$extra" ]; then
    stage "$extra" "$extra"
  fi
done
echo "== the whole suite: $SECONDS s"
