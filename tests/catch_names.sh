#!/usr/bin/env bash
# Every Catch test must reach ctest: catch_discover_tests registers one ctest test per name, and a
# name holding ';' is split by CMake's list handling into names that match nothing — the test then
# "passes" without running (26 tests were hidden so until this check). Fails on such a name.
# Usage: catch_names.sh EXECUTABLE...
set -euo pipefail
bad=0
for exe in "$@"; do
  while IFS= read -r name; do
    case $name in
      *';'*) echo "$(basename "$exe"): test name holds ';' (ctest cannot run it): $name"; bad=1 ;;
    esac
  done < <("$exe" --list-test-names-only)
done
exit $bad
