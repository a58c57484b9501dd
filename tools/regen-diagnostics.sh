#!/usr/bin/env bash
# Rewrites the expected block at the end of every case in tests/diagnostics/ with what the
# built gfec now prints. Review the result with `git diff tests/diagnostics`: that review is the
# point of these tests.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${GFEC_BUILD_DIR:-build}"
cmake --build "$build" --target gfec gfec_tests
GFEC_UPDATE_DIAGNOSTICS=1 "$build/tests/unit/gfec_tests" "[diagnostics_files]" >/dev/null
git status --short tests/diagnostics
