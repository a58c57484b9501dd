#!/usr/bin/env bash
# Rewrites the expected output of every case in tests/diagnostics/ with what the built gfec now
# prints: the block at the end of a case whose language has comments, the sidecar beside one
# whose language has none (CASE.expected, created when missing; tests/diagnostics/README.md).
# Review the result with `git diff tests/diagnostics` and the new files `git status` lists: that
# review is the point of these tests.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${GFEC_BUILD_DIR:-build}"
cmake --build "$build" --target gfec gfec_tests
GFEC_UPDATE_DIAGNOSTICS=1 "$build/tests/unit/gfec_tests" "[diagnostics_files]" >/dev/null
git status --short tests/diagnostics
