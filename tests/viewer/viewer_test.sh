#!/usr/bin/env bash
# Runs the run viewer's browser test (viewer.test.js) when Debian's Chromium is installed; without
# it the test is reported skipped (exit 77, ctest's SKIP_RETURN_CODE), never passed; in CI (CI set) it fails.
# Usage: viewer_test.sh NODE TEST_JS   (environment: see viewer.test.js; CHROMIUM may name the browser)
set -euo pipefail
node=$1 test_js=$2
chromium=${CHROMIUM:-}
if [ -z "$chromium" ]; then
  for c in /usr/bin/chromium /usr/bin/chromium-browser; do
    if [ -x "$c" ]; then chromium=$c; break; fi
  done
fi
if [ -z "$chromium" ] || [ ! -x "$chromium" ]; then
  echo "VIEWER-SKIP: Chromium is not installed (scripts/install-deps.sh installs Debian's 'chromium')"
  # In CI a missing browser is a broken machine, not a skipped test.
  [ -n "${CI:-}" ] && exit 1
  exit 77
fi
export CHROMIUM=$chromium
exec "$node" --test --test-concurrency=1 "$test_js"
